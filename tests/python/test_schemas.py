"""The JSON Schemas of docs/schema/ against the loader (pkmws info).

Every bundled dataset validates against its kind's schema and loads. The
schemas are not vacuous: mutations of the datasets that the loader rejects
for an unknown field, a misspelt key (which the loader names, not the field it
misses), a missing required field, a wrong type or a negative length are
rejected by the schema too; and a mutation the schema rejects is
rejected by the loader (the schema is never stricter than pkmws)."""
import copy
import json
import pathlib
import tempfile

import jsonschema
import pytest

from conftest import DATASETS, SOURCE_DIR, run

SCHEMA_DIR = SOURCE_DIR / "docs" / "schema"
KINDS = ["moma", "five_bar", "biglide", "pi_joint", "three_rrp", "three_prp", "three_rpr"]


def schema_of(kind):
    return json.loads((SCHEMA_DIR / f"{kind}.schema.json").read_text(encoding="utf-8"))


VALIDATORS = {k: jsonschema.Draft7Validator(schema_of(k)) for k in KINDS}


def schema_accepts(doc):
    kind = doc.get("mechanism") if isinstance(doc, dict) else None
    validator = VALIDATORS.get(kind, VALIDATORS["moma"])  # an unknown kind fails `mechanism` of any schema
    return validator.is_valid(doc)


def pkmws_verdict(doc, tmp):
    """(accepted, stderr) of `pkmws info` on doc."""
    p = pathlib.Path(tmp) / "mutated.json"
    p.write_text(json.dumps(doc, ensure_ascii=False), encoding="utf-8")
    r = run("info", p, check=False)
    assert r.returncode in (0, 2), f"exit {r.returncode}: {r.stderr}"
    if r.returncode == 2:
        lines = r.stderr.strip().splitlines()
        assert len(lines) == 1 and f"{p}: " in lines[0], r.stderr
    return r.returncode == 0, r.stderr.strip()


def test_schemas_are_valid_draft7_and_strict():
    for kind in KINDS:
        s = schema_of(kind)
        jsonschema.Draft7Validator.check_schema(s)
        assert s["$schema"] == "http://json-schema.org/draft-07/schema#"

        def walk(node, where):
            if node.get("type") == "object" and "properties" in node:
                assert node.get("additionalProperties") is False, f"{kind}: {where} is not strict"
            for key, sub in node.get("properties", {}).items():
                if key != "source":
                    walk(sub, f"{where}.{key}")
            if isinstance(node.get("items"), dict):
                walk(node["items"], where + "[]")
            for alt in node.get("oneOf", []):
                walk(alt, where)

        walk(s, kind)


def test_every_kind_has_a_dataset():
    assert {json.loads(d.read_text())["mechanism"] for d in DATASETS} == set(KINDS)


@pytest.mark.parametrize("dataset", DATASETS, ids=lambda p: p.stem)
def test_dataset_matches_its_schema_and_loads(dataset):
    doc = json.loads(dataset.read_text(encoding="utf-8"))
    errors = [e.message for e in VALIDATORS[doc["mechanism"]].iter_errors(doc)]
    assert not errors, errors
    assert run("info", dataset, check=False).returncode == 0


def key_paths(node, prefix=()):
    """Every key path of a document (not descending into the free-form `source`)."""
    if isinstance(node, dict):
        for k, v in node.items():
            yield prefix + (k,)
            if k != "source" or prefix:
                yield from key_paths(v, prefix + (k,))
    elif isinstance(node, list):
        for i, v in enumerate(node):
            yield prefix + (i,)
            yield from key_paths(v, prefix + (i,))


def field_path(path):
    """pkmws's spelling of a path: legs[1].rod_length."""
    out = ""
    for p in path:
        out += f"[{p}]" if isinstance(p, int) else (f".{p}" if out else p)
    return out


def get(doc, path):
    for p in path:
        doc = doc[p]
    return doc


def schema_node(schema, path):
    """The subschema describing `path` (following properties, items and the non-null oneOf branch)."""
    node = schema
    for p in path:
        if "oneOf" in node:
            node = next(a for a in node["oneOf"] if a.get("type") != "null")
        node = node["properties"][p] if isinstance(p, str) else node["items"]
    return node


def is_required(schema, path):
    parent = schema_node(schema, path[:-1])
    if "oneOf" in parent:
        parent = next(a for a in parent["oneOf"] if a.get("type") != "null")
    return path[-1] in parent.get("required", [])


def other_type(value):
    if isinstance(value, bool) or value is None:
        return "x"
    if isinstance(value, (int, float)):
        return str(value)
    if isinstance(value, str):
        return 1
    if isinstance(value, list):
        return {"x": 1}
    return [1]


# Fields (and arrays whose elements are) lengths or magnitudes that must be > 0 or >= 0.
NON_NEGATIVE = {"rod_length", "half_width", "crank_length", "k", "l3", "l4", "radius", "length", "width",
                "force_N", "moment_Nm", "max_reaction_N", "max_velocity_ratio", "lead", "resolution_per_step",
                "max_speed", "max_force_N", "efficiency", "max_pressure_angle_deg"}
NON_NEGATIVE_ARRAYS = {"rods", "proximal", "distal", "crank_lengths"}


def mutations(doc):
    """(category, description, mutated document)."""
    d = copy.deepcopy(doc)
    d["colour"] = 1
    yield "unknown", "colour", d
    paths = list(key_paths(doc))
    for path in paths:
        value = get(doc, path)
        if isinstance(value, dict) and path[-1] != "source":
            d = copy.deepcopy(doc)
            get(d, path)["extra_field"] = 1
            yield "unknown", ".".join(map(str, path)) + ".extra_field", d
        where = ".".join(map(str, path))
        if isinstance(path[-1], str):
            d = copy.deepcopy(doc)
            del get(d, path[:-1])[path[-1]]
            yield "missing" if is_required(SCHEMAS[doc["mechanism"]], path) else "optional", where, d
            if path != ("mechanism",):
                d = copy.deepcopy(doc)
                parent = get(d, path[:-1])
                parent[path[-1] + "x"] = parent.pop(path[-1])
                yield "misspelt", field_path(path[:-1] + (path[-1] + "x",)), d
        if not (len(path) > 1 and path[0] == "source"):
            d = copy.deepcopy(doc)
            get(d, path[:-1])[path[-1]] = other_type(value)
            yield "type", where, d
        parent_key = path[-2] if len(path) > 1 else None
        if isinstance(value, (int, float)) and not isinstance(value, bool) and (
                path[-1] in NON_NEGATIVE or parent_key in NON_NEGATIVE_ARRAYS
                or (len(path) > 2 and path[-3] == "leg_limits" and path[-1] == 0)):
            d = copy.deepcopy(doc)
            get(d, path[:-1])[path[-1]] = -abs(value) - 1
            yield "negative", where, d


SCHEMAS = {k: schema_of(k) for k in KINDS}


def structure(doc):
    return (doc["mechanism"], frozenset(p for p in key_paths(doc) if not any(isinstance(x, int) and x > 0 for x in p)))


def representative_datasets():
    """One dataset per distinct structure (kind and set of key paths): every optional group appears."""
    seen, out = set(), []
    for d in DATASETS:
        doc = json.loads(d.read_text(encoding="utf-8"))
        s = structure(doc)
        if s not in seen:
            seen.add(s)
            out.append(d)
    return out


@pytest.mark.parametrize("dataset", representative_datasets(), ids=lambda p: p.stem)
def test_mutations_agree(dataset):
    doc = json.loads(dataset.read_text(encoding="utf-8"))
    counts = {}
    problems = []
    with tempfile.TemporaryDirectory() as tmp:
        for category, where, mutated in mutations(doc):
            counts[category] = counts.get(category, 0) + 1
            by_schema = schema_accepts(mutated)
            by_pkmws, message = pkmws_verdict(mutated, tmp)
            if category in ("unknown", "misspelt", "missing", "type", "negative"):
                if by_pkmws or by_schema:
                    problems.append(f"{category} {where}: pkmws {'accepts' if by_pkmws else 'rejects'}, "
                                    f"schema {'accepts' if by_schema else 'rejects'} ({message})")
                if category == "unknown" and "unknown field (expected one of: " not in message:
                    problems.append(f"{where}: message does not list the valid fields: {message}")
                if category == "misspelt" and f": {where}: unknown field (expected one of: " not in message:
                    problems.append(f"{where}: the misspelt key is not what the message names: {message}")
            else:  # an optional field removed: the schema must not be stricter than pkmws
                if by_pkmws and not by_schema:
                    problems.append(f"optional {where}: pkmws accepts, the schema rejects")
                if not by_pkmws and "missing required field" in message:
                    problems.append(f"optional {where}: pkmws requires it ({message}); the schema does not")
    assert not problems, "\n".join(problems)
    assert counts.get("unknown", 0) >= 1 and counts.get("missing", 0) >= 3 and counts.get("type", 0) >= 5, counts


# Rules only the loader can check (docs/format.md#json-schemas): the schema accepts these, pkmws does not.
LOADER_ONLY = [
    ("moma_m1_g0_l250", lambda d: d["legs"][0].__setitem__("stroke", [200, 0]), "legs[0].stroke"),
    ("biglide_real", lambda d: d["tool"].__setitem__("l4", 10), "tool.l4"),
    ("three_rrp_mitsi", lambda d: d.__setitem__("platform", d["platform"][::-1]), "platform"),
    ("machine_five_bar_dextar", lambda d: d["bodies"]["allowed_contacts"].append(["proximal1", "gearbox"]),
     "bodies.allowed_contacts[3]"),
    ("five_bar_pi_joint", lambda d: d["pi_joints"][0].__setitem__("stroke", [50, 232]), "pi_joints[0].stroke"),
]


@pytest.mark.parametrize("name,mutate,field", LOADER_ONLY, ids=[c[0] for c in LOADER_ONLY])
def test_loader_checks_what_the_schema_cannot(name, mutate, field):
    doc = json.loads((SOURCE_DIR / "datasets" / f"{name}.json").read_text(encoding="utf-8"))
    mutate(doc)
    with tempfile.TemporaryDirectory() as tmp:
        accepted, message = pkmws_verdict(doc, tmp)
    assert not accepted and field in message, message
    assert schema_accepts(doc)
