"""The parameter model (`info --json` derived.parameters): every number of
every bundled file by field path, its value as the document states it, and
its unit as the field tables of docs/format.md state it."""
import json
import re

import pytest
from conftest import DATASETS, SOURCE_DIR, run

INTEGERS = ("branch", "working_mode", "sense", "reaction_legs")


def doc_units():
    """field name -> units stated in docs/format.md's field tables (those with a `unit` column)."""
    units = {}
    columns = None
    for line in (SOURCE_DIR / "docs/format.md").read_text().splitlines():
        if not line.startswith("|"):
            columns = None
            continue
        cells = [c.strip() for c in line.replace("\\|", "/").strip().strip("|").split("|")]
        if cells[0] == "field":
            columns = cells
            continue
        if not columns or "unit" not in columns or set(cells[0]) <= set("-"):
            continue
        for name in re.findall(r"`([^`]+)`", cells[0]):
            key = re.sub(r"\[i\]", "", name).split(".")[-1]
            units.setdefault(key, set()).add(cells[columns.index("unit")])
    return units


def model_unit(cell, length):
    """A unit column's words in the parameter model's words (None: not a unit)."""
    return {"": "1", "degree": "deg", "deg": "deg", "N": "N", "N m": "N m", "N·m": "N m", "length": length,
            "length/s": f"{length}/s"}.get(cell)


def walk(node, path=""):
    if isinstance(node, dict):
        for k, v in node.items():
            if path == "" and k == "source":
                continue
            yield from walk(v, f"{path}.{k}" if path else k)
    elif isinstance(node, list):
        for i, v in enumerate(node):
            yield from walk(v, f"{path}[{i}]")
    elif isinstance(node, (int, float)) and not isinstance(node, bool):
        yield path, node


def test_the_tables_give_units_for_the_common_fields():
    table = doc_units()
    for name, unit in [("rod_length", "length"), ("guide_angle_deg", "degree"), ("max_reaction_N", "N"),
                       ("max_speed", "length/s")]:
        assert unit in table[name], (name, table.get(name))


@pytest.mark.parametrize("path", DATASETS, ids=lambda p: p.stem)
def test_parameters_are_the_documents_numbers_with_documented_units(path):
    doc = json.loads(path.read_text())
    info = json.loads(run("info", path, "--json").stdout)
    params = info["derived"]["parameters"]
    assert {p["path"]: p["value"] for p in params} == dict(walk(doc))
    table = doc_units()
    checked = 0
    for p in params:
        name = re.sub(r"\[\d+\]", "", p["path"]).split(".")[-1]
        assert p["type"] == ("integer" if name in INTEGERS else "number"), p
        documented = {model_unit(c, doc["units"]) for c in table.get(name, ())} - {None}
        if documented:
            assert p["unit"] in documented, (p, documented)
            checked += 1
    # Only the `bodies` fields lack a unit column (their table gives kinds instead).
    assert checked == len([p for p in params if not p["path"].startswith("bodies.")])
