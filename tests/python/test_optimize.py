"""pkmws optimize and pkmws feasible: the optimum against a closed form and
against an independent fine sweep, the optimum re-evaluated by other commands,
determinism, infeasible problems, one-line errors; the feasible boxes of a
sweep against the closed form of the same problem."""
import csv
import json

import numpy as np
import pytest

from conftest import SOURCE_DIR, run

BASE = SOURCE_DIR / "datasets" / "moma_m1_g0_l250.json"
RODS = ["legs[0].rod_length", "legs[1].rod_length"]
STROKES = ["legs[0].stroke[1]", "legs[1].stroke[1]"]
TASK = {"center": [0, -300], "size": [80, 40]}


def shortest_rod(h, margin):
    """MOMA M1 (guides at x = -100, 100 pointing down from y = 0, strokes [0, h],
    branch -1): a point deeper than the stroke is reached by leg i iff it is
    within the rod's length of the slider at the stroke's end (±100, -h). The
    task rectangle with a clearance `margin` fits iff every corner is within
    l - margin of both such sliders (it is far from the other boundaries)."""
    corners = np.array([[x, y] for x in (-40, 40) for y in (-320, -280)])
    sliders = np.array([[-100, -h], [100, -h]])
    d = np.linalg.norm(corners[:, None, :] - sliders[None, :, :], axis=2)
    return d.max() + margin


def write(tmp_path, name, doc):
    p = tmp_path / name
    p.write_text(json.dumps(doc))
    return p


def rod_spec(tmp_path, margin=5, **extra):
    doc = {"base": str(BASE),
           "parameters": [{"name": "rod", "path": RODS, "from": 150, "to": 250}],
           "objective": {"minimize": "rod"}, "constraints": [f"task_margin >= {margin}"], "task": TASK,
           "max_evaluations": 120}
    doc.update(extra)
    return write(tmp_path, "rod.json", doc)


def optimize_json(*args):
    return json.loads(run("optimize", *args, "--json").stdout)


def test_shortest_rods_match_the_closed_form(tmp_path):
    for margin in (0, 5, 12.5):
        j = optimize_json(rod_spec(tmp_path, margin))
        assert j["status"] == "converged" and j["feasible"]
        rod = j["parameters"][0]["value"]
        assert rod == pytest.approx(shortest_rod(200, margin), rel=1e-6)
        assert j["objective"]["value"] == rod
        c = j["constraints"][0]
        assert c["satisfied"] and c["margin"] >= 0 and c["value"] == pytest.approx(margin, abs=1e-6)
        assert j["evaluations"] <= 120 and sum(p["evaluations"] for p in j["phases"]) == j["evaluations"]
        assert [p["method"] for p in j["phases"]] == ["GN_DIRECT_L", "LN_COBYLA"]


def test_the_optimum_re_evaluated_by_other_commands(tmp_path):
    """--design writes the optimum as a mechanism file: `pkmws sweep` with the
    task finds the margin there, and `pkmws area` loads it."""
    design = tmp_path / "best.json"
    j = optimize_json(rod_spec(tmp_path), "--design", design)
    doc = json.loads(design.read_text())
    assert doc == j["document"]
    assert [leg["rod_length"] for leg in doc["legs"]] == [j["parameters"][0]["value"]] * 2
    check = write(tmp_path, "check.json", {
        "base": str(design), "parameters": [{"path": "legs[0].rod_length", "values": [doc["legs"][0]["rod_length"]]}],
        "metrics": ["task_fit"], "task": TASK})
    run("sweep", check, "-o", tmp_path / "check.csv")
    row = next(csv.DictReader(open(tmp_path / "check.csv")))
    assert row["status"] == "ok" and row["task_inside"] == "1"
    assert float(row["task_margin"]) >= 5 - 1e-9
    assert json.loads(run("area", design, "--json").stdout)["area"] > 0


def test_machine_size_is_at_least_as_good_as_a_fine_sweep(tmp_path):
    """Minimise rods + stroke such that the largest inscribed rectangle has
    20000 mm²: the optimiser against the best feasible design of an
    independent 31 x 21 grid sweep (5 mm x 10 mm) of the same parameters."""
    spec = write(tmp_path, "size.json", {
        "base": str(BASE),
        "parameters": [{"name": "rod_length", "path": RODS, "from": 150, "to": 300},
                       {"name": "stroke", "path": STROKES, "from": 100, "to": 300}],
        "objective": {"minimize": {"rod_length": 1, "stroke": 1}},
        "constraints": ["rectangle_area >= 20000"], "rectangle_precision": 1e-4, "max_evaluations": 200})
    history = tmp_path / "history.csv"
    design = tmp_path / "best.json"
    j = optimize_json(spec, "--history", history, "--design", design)
    assert j["feasible"] and j["constraints"][0]["value"] >= 20000
    sweep = write(tmp_path, "sweep.json", {
        "base": str(BASE),
        "parameters": [{"name": "rod_length", "path": RODS, "from": 150, "to": 300, "steps": 31},
                       {"name": "stroke", "path": STROKES, "from": 100, "to": 300, "steps": 21}],
        "metrics": ["inscribed_rectangle"], "rectangle_precision": 1e-4})
    run("sweep", sweep, "-o", tmp_path / "sweep.csv")
    rows = [r for r in csv.DictReader(open(tmp_path / "sweep.csv"))
            if r["status"] == "ok" and float(r["rectangle_area"]) >= 20000]
    best = min(float(r["rod_length"]) + float(r["stroke"]) for r in rows)
    assert j["objective"]["value"] <= best + 1e-6, (j["objective"], best)
    # The history: every evaluation as a sweep row; the optimum is one of them.
    hist = list(csv.DictReader(open(history)))
    assert len(hist) == j["evaluations"] and [int(r["index"]) for r in hist] == list(range(len(hist)))
    assert any(float(r["rod_length"]) == j["parameters"][0]["value"] for r in hist)
    # `pkmws area` on the optimum's file: its rectangle (to 1e-6) holds the bound too.
    area = json.loads(run("area", design, "--json").stdout)
    rect = max(c["inscribed_rectangle"]["area"] for c in area["components"])
    assert rect >= 20000 * (1 - 1e-6)


def test_the_same_seed_gives_the_same_report(tmp_path):
    spec = rod_spec(tmp_path, **{"global": "crs2_lm", "seed": 7})
    a = run("optimize", spec, "--json", "--no-timing").stdout
    b = run("optimize", spec, "--json", "--no-timing").stdout
    assert a == b and "time_ms" not in a
    assert json.loads(a)["seed"] == 7 and json.loads(a)["phases"][0]["method"] == "GN_CRS2_LM"


def test_infeasible_everywhere_is_a_status_not_an_error(tmp_path):
    out = tmp_path / "out.json"
    r = run("optimize", rod_spec(tmp_path, 500, max_evaluations=30), "-o", out)
    assert "status: infeasible" in r.stdout and "no evaluated design satisfies every constraint" in r.stdout
    j = json.loads(out.read_text())
    assert j["status"] == "infeasible" and not j["feasible"] and j["feasible_evaluations"] == 0
    assert j["constraints"][0]["margin"] < 0 and not j["constraints"][0]["satisfied"]


@pytest.mark.parametrize("change, says", [
    ({"objective": {"maximise": "rod"}}, "objective.maximise: unknown field"),
    ({"constraints": ["task_margin > 5"]}, "constraints[0]: expected 'COLUMN >= NUMBER'"),
    ({"constraints": ["limited_task_margin >= 0"]}, "needs a base file with criteria"),
    ({"constraints": ["real_task_margin >= 0"]}, "needs a base file with bodies"),
    ({"objective": {"minimize": "volume"}}, "objective.minimize: 'volume' is neither a parameter"),
    ({"parameters": [{"name": "rod", "path": RODS, "from": 250, "to": 150}]}, "parameters[0].to: must be greater"),
    ({"parameters": [{"name": "rod", "path": "legs[0].rod_lenght", "from": 1, "to": 2}]}, "rod_lenght"),
    ({"seed": -1}, "seed: must be a non-negative integer"),
    ({"global": "annealing"}, "global"),
])
def test_bad_specs_are_one_line_and_exit_2(tmp_path, change, says):
    spec = rod_spec(tmp_path, **change)
    out = tmp_path / "out.json"
    r = run("optimize", spec, "-o", out, check=False)
    assert r.returncode == 2 and r.stdout == ""
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("pkmws: error: ") and says in lines[0], r.stderr
    assert not out.exists()


def test_feasible_boxes_match_the_closed_form(tmp_path):
    """Rods 150..250 every 10 mm: task_margin >= 5 holds from shortest_rod(200, 5)
    = 189.39 on (and up to about 281, beyond the range), so the one box is
    [190, 250]; with a stroke too, each stroke's threshold by the closed form."""
    sweep = write(tmp_path, "sweep.json", {
        "base": str(BASE), "parameters": [{"name": "rod", "path": RODS, "from": 150, "to": 250, "steps": 11}],
        "metrics": ["task_fit"], "task": TASK})
    run("sweep", sweep, "-o", tmp_path / "s.csv")
    j = json.loads(run("feasible", tmp_path / "s.csv", "--where", "task_margin >= 5", "--json").stdout)
    assert j["designs"] == 11 and j["feasible_designs"] == 7 and j["feasible_cells"] == 6
    assert j["boxes"] == [{"min": {"rod": 190.0}, "max": {"rod": 250.0}, "cells": 6}]

    strokes = [180, 190, 200, 210]
    sweep2 = write(tmp_path, "sweep2.json", {
        "base": str(BASE),
        "parameters": [{"name": "rod", "path": RODS, "from": 150, "to": 250, "steps": 21},
                       {"name": "stroke", "path": STROKES, "values": strokes}],
        "metrics": ["task_fit"], "task": TASK})
    run("sweep", sweep2, "-o", tmp_path / "s2.csv")
    svg = tmp_path / "boxes.svg"
    j = json.loads(run("feasible", tmp_path / "s2.csv", "--where", "task_margin >= 5", "--json", "--svg", svg,
                       "--csv", tmp_path / "boxes.csv").stdout)
    rods = np.linspace(150, 250, 21)
    feasible = {(r, h) for r in rods for h in strokes if r >= shortest_rod(h, 5)}
    assert j["feasible_designs"] == len(feasible)
    # The cells between strokes h0 < h1 start at the rods feasible for h0 (the shorter stroke needs longer rods).
    covered = set()
    for b in j["boxes"]:
        for r in rods:
            for h in strokes:
                if b["min"]["rod"] <= r <= b["max"]["rod"] and b["min"]["stroke"] <= h <= b["max"]["stroke"]:
                    covered.add((r, h))
    assert covered <= feasible
    for h0, h1 in zip(strokes, strokes[1:]):
        first = min(r for r in rods if r >= shortest_rod(h0, 5))
        assert (first, h0) in covered and (first, h1) in covered
    assert svg.read_text().startswith("<svg") and (tmp_path / "boxes.csv").read_text().startswith("box,cells,")


def test_feasible_errors(tmp_path):
    (tmp_path / "s.csv").write_text("index,a,status,m,reason\n0,1,ok,1,\n1,2,ok,2,\n")
    for args, says in ((["--where", "q >= 1"], "no column 'q'"), (["--where", "m = 1"], "--where: expected"),
                       (["--where", "m >= 1", "--svg", tmp_path / "x.svg"], "--svg: draws a sweep over two")):
        r = run("feasible", tmp_path / "s.csv", *args, check=False)
        assert r.returncode == 2 and says in r.stderr and len(r.stderr.strip().splitlines()) == 1, r.stderr
