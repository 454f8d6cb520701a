"""Every command's --json output against its schema in docs/schema/<command>.output.schema.json,
on every bundled dataset (docs/format.md (output vocabulary)).

Poses come from the file (`area` components, else `info` bounds); joint values
from `ik`. What does not apply to a file (no planar workspace, no bodies, no
criteria) is skipped only after checking the CLI's own one-line error."""
import json
import math

import jsonschema
import pytest

from conftest import DATASETS, SOURCE_DIR, run

SCHEMA_DIR = SOURCE_DIR / "docs" / "schema"
COMMANDS = ["ik", "dk", "eval", "info", "area", "levels", "explain", "export", "plot", "grid", "compare", "batch",
            "atlas", "diff", "optimize", "feasible", "chart"]
VALIDATORS = {c: jsonschema.Draft7Validator(json.loads((SCHEMA_DIR / f"{c}.output.schema.json").read_text()))
              for c in COMMANDS}
BOUND = "1"  # --max-time for certified work: the shape is checked, not the precision
CRITERION = {"max_pressure_angle_deg": "pressure_angle", "max_reaction_N": "reaction",
             "max_velocity_ratio": "velocity_ratio"}


def no_constant(name):
    raise AssertionError(f"{name} in a JSON report")


def valid(command, *args):
    return checked(command, args, run(command, *args, "--json", check=False))


def valid_or_refused(command, *args, words):
    """One run: the report validated against its schema, or None when the CLI
    refused the file with a one-line error containing one of `words`."""
    r = run(command, *args, "--json", check=False)
    if r.returncode == 2:
        assert any(w in r.stderr for w in words), r.stderr
        return None
    return checked(command, args, r)


def checked(command, args, r):
    assert r.returncode == 0, f"pkmws {command} {' '.join(map(str, args))}: {r.stderr.strip()}"
    j = json.loads(r.stdout, parse_constant=no_constant)
    errors = [f"{'/'.join(map(str, e.absolute_path))}: {e.message}" for e in VALIDATORS[command].iter_errors(j)]
    assert not errors, (command, args, errors[:5])
    return j


def refused(command, *args, says):
    r = run(command, *args, "--json", check=False)
    assert r.returncode == 2, (command, args, r.stdout[:200])
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("pkmws: error: ") and says in lines[0], r.stderr


def test_schemas_are_draft7_and_strict():
    for c in COMMANDS:
        s = json.loads((SCHEMA_DIR / f"{c}.output.schema.json").read_text())
        jsonschema.Draft7Validator.check_schema(s)
        assert s["$schema"] == "http://json-schema.org/draft-07/schema#"
        if c != "info":  # info: the document is checked by the kind's schema
            assert s.get("additionalProperties") is False, c


@pytest.mark.parametrize("dataset", DATASETS, ids=lambda p: p.stem)
def test_every_command_json_matches_its_schema(dataset, tmp_path):
    doc = json.loads(dataset.read_text(encoding="utf-8"))
    info = valid("info", dataset)
    derived = info["derived"]
    dof = derived["dof"]
    kind_schema = jsonschema.Draft7Validator(json.loads((SCHEMA_DIR / f"{doc['mechanism']}.schema.json").read_text()))
    assert kind_schema.is_valid({k: v for k, v in info.items() if k != "derived"})
    names, units = derived["joint_names"], derived["joint_units"]
    assert list(units) == sorted(names) and all(u in ("deg", doc["units"]) for u in units.values())

    # area (bounded), and a pose inside the workspace when there is one
    pose = None
    if dof == 1:
        refused("area", dataset, "--max-time", BOUND, says="pi_joint")
        lo, hi = doc["theta_limits_deg"]
        pose = [str((lo + hi) / 2)]
    else:
        area = valid_or_refused("area", dataset, "--max-time", BOUND, words=("unbounded", "leg_limits"))
        if area is not None:
            assert area["units"] == doc["units"]
            if area["components"]:
                pose = area["components"][0]["inscribed_circle"]["center"]
        if pose is None:
            b = derived["bounds"]
            pose = [0.0, 0.0] if b is None else [(b["min"][0] + b["max"][0]) / 2, (b["min"][1] + b["max"][1]) / 2]
        pose = [repr(float(v)) for v in pose]

    # ik, eval at the pose (3-DOF: PHI defaults to the file's orientation_deg)
    ik = valid("ik", dataset, *pose)
    ev = valid("eval", dataset, *pose)
    for j in (ik, ev):
        assert j["joint_names"] == names and j["joint_units"] == units
    if dof == 3:
        assert valid("eval", dataset, *pose, ik["pose"][2]) == ev
    for s in ik["solutions"]:
        assert set(s["joints"]) <= set(names)
        assert len(s["mode"]) == (1 if dof == 1 else (3 if dof == 3 else 2))
    for m in ev["modes"]:
        if m["reactions_N"] is None:
            assert m["reactions_N_reason"]
    refused("ik", dataset, *pose, "1", "2", says="ik: expected ")

    # dk from the joint values of the first solution that has them
    q = next((s["joints"] for s in ik["solutions"] if s["valid"]), None) or \
        next((s["joints"] for s in ik["solutions"] if len(s["joints"]) == len(names)), None)
    if q is not None:
        values = [repr(q[n]) for n in names]
        dk = valid("dk", dataset, *values)
        assert dk["joints"].keys() == q.keys()
        if ik["solutions"][0]["valid"]:
            assert any(s["valid"] for s in dk["solutions"]) or dof == 1
    refused("dk", dataset, *(["1"] * (len(names) + 1)), says="dk: expected ")

    # grid, compare (exact reference only: a criteria file's certified reference is not bounded by --max-time)
    grid = valid_or_refused("grid", dataset, "--cells", "8", words=("unbounded", "leg_limits"))
    if grid is not None and "criteria" not in doc and "bodies" not in doc:
        # no exact reference: real-scheme biglide, Pi-joint
        valid_or_refused("compare", dataset, "--ladder", "8", "--depths", "2", "--budget", "1",
                         words=("not bounded by arcs and segments", "no planar workspace"))

    # export: the boundary as CSV (outer enclosure where certified)
    out = tmp_path / "ws.csv"
    if dof == 1:
        refused("export", dataset, "-f", "csv", "--bound", "outer", "-o", out, says="pi_joint")
        valid("plot", dataset, "--out", tmp_path)
    else:
        r = run("export", dataset, "-f", "csv", "--bound", "outer", "-o", out, "--max-time", BOUND, "--json",
                check=False)
        if r.returncode == 2:
            assert any(w in r.stderr for w in ("unbounded", "leg_limits", "--max-time")), r.stderr
        else:
            j = json.loads(r.stdout)
            assert not list(VALIDATORS["export"].iter_errors(j))
            assert out.exists()
        refused("plot", dataset, "--out", tmp_path, says="pi_joint")

    # levels: the file's own criteria, at their thresholds
    limits = [k for k in CRITERION if k in doc.get("criteria", {})]
    if limits:
        k = limits[0]
        j = valid_or_refused("levels", dataset, "--criterion", CRITERION[k], "--levels", doc["criteria"][k],
                             "--tolerance", "1e-2", "--max-time", BOUND, words=("leg_limits", "criterion", "--max-time"))
        if j is not None:
            assert j["units"] == doc["units"] and j["criterion_units"] in ("deg", "N", "V_i/V_y")

    # explain: files with bodies
    if "bodies" in doc:
        valid("explain", dataset, *pose[:2])
    else:
        refused("explain", dataset, *(pose[:2] if dof > 1 else ["0", "0"]), says="bodies")


def test_batch_and_atlas_json(tmp_path):
    files = [SOURCE_DIR / "datasets" / "moma_m1_g0_l250.json", SOURCE_DIR / "datasets" / "pi_joint_prototype.json"]
    j = valid("batch", *files, "--out", tmp_path / "batch")
    assert j["rows"] == json.loads((tmp_path / "batch" / "summary.json").read_text())
    csv = tmp_path / "sweep.csv"
    csv.write_text("index,status,a,b,area\n0,ok,1,1,1.0\n1,ok,2,1,2.0\n2,ok,1,2,3.0\n3,error,2,2,\n")
    a = valid("atlas", csv, "--x", "a", "--y", "b", "--metric", "area", "-o", tmp_path / "atlas.svg")
    assert a["cells_without_value"] == 1 and (tmp_path / "atlas.svg").exists()


def test_chart_json(tmp_path):
    one = tmp_path / "one.csv"
    one.write_text("index,x,status,area,area_lower,area_upper,reason\n0,1,ok,1.0,0.9,1.1,\n1,2,ok,2.0,1.9,2.1,\n")
    j = valid("chart", f"{one}=first", "--x", "x", "--y", "area", "--y", "area_lower", "--markdown", tmp_path / "t.md")
    assert j["sweeps"] == [{"csv": str(one), "label": "first", "metrics": ["area", "area_lower"]}]
    assert j["figure"] is None and j["figure_reason"] and j["markdown"] == str(tmp_path / "t.md")
    assert (tmp_path / "t.md").exists()
    refused("chart", one, "--x", "x", "--y", "nope", "-o", tmp_path / "c.svg", says="--y")


def test_diff_json(tmp_path):
    data = SOURCE_DIR / "datasets"
    j = valid("diff", data / "moma_m1_g0_l250.json", data / "moma_m1_gp5_l195.json", "--gci-cells", "16",
              "-o", tmp_path / "diff.svg")
    assert j["figure"] == str(tmp_path / "diff.svg") and (tmp_path / "diff.svg").exists()
    # bodies (real area bounds), criteria (limited area bounds), no figure (figure_reason)
    j = valid("diff", data / "machine_moma_m1.json", data / "moma_m1_g0_l250.json", "--gci-cells", "16")
    assert j["figure"] is None and "b_reason" in [m for m in j["metrics"] if m["metric"] == "real_area"][0]
    valid("diff", data / "five_bar_dextar_mm_alpha40.json", data / "five_bar_dextar_mm_alpha60.json",
          "--gci-cells", "16")
    refused("diff", data / "moma_m1_g0_l250.json", data / "five_bar_dextar_mm.json", says="units")
def test_optimize_and_feasible_json(tmp_path):
    base = SOURCE_DIR / "datasets" / "moma_m1_g0_l250.json"
    rods = ["legs[0].rod_length", "legs[1].rod_length"]
    task = {"center": [0, -300], "size": [80, 40]}
    spec = tmp_path / "optimize.json"
    spec.write_text(json.dumps({"base": str(base), "parameters": [{"name": "rod", "path": rods, "from": 150, "to": 250}],
                                "objective": {"minimize": "rod"}, "constraints": ["task_margin >= 5"], "task": task,
                                "max_evaluations": 30}))
    j = valid("optimize", spec)
    assert j["feasible"] and j["metrics"]["task_margin"] >= 5
    # No feasible design: null-free all the same (margins are negative numbers).
    spec.write_text(spec.read_text().replace("task_margin >= 5", "task_margin >= 500"))
    assert valid("optimize", spec)["status"] == "infeasible"
    # Designs that are not ok everywhere: rods too short to meet, the report says why.
    spec.write_text(json.dumps({"base": str(base), "parameters": [{"name": "rod", "path": rods, "from": 1, "to": 2}],
                                "objective": {"maximize": "area"}, "max_evaluations": 5}))
    j = valid("optimize", spec)
    assert j["design"]["status"] == "empty" and j["objective"]["value"] is None and j["objective"]["value_reason"]
    sweep = tmp_path / "sweep.json"
    sweep.write_text(json.dumps({"base": str(base), "metrics": ["task_fit"], "task": task,
                                 "parameters": [{"name": "rod", "path": rods, "from": 150, "to": 250, "steps": 3}]}))
    run("sweep", sweep, "-o", tmp_path / "s.csv")
    j = valid("feasible", tmp_path / "s.csv", "--where", "task_margin >= 5")
    assert j["designs"] == 3 and len(j["boxes"]) == 1
