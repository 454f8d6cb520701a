"""pkmws.optimize from Python: the same report as `pkmws optimize --json`, a
spec as a dict (base as a path, a dict or a Mechanism) or a file, the
history, and ValueError with the command line's message."""
import json
import math

import pytest

import pkmws
from conftest import SOURCE_DIR, run

BASE = SOURCE_DIR / "datasets" / "moma_m1_g0_l250.json"


def spec(**extra):
    doc = {"base": str(BASE),
           "parameters": [{"name": "rod", "path": ["legs[0].rod_length", "legs[1].rod_length"], "from": 150, "to": 250}],
           "objective": {"minimize": "rod"}, "constraints": ["task_margin >= 5"],
           "task": {"center": [0, -300], "size": [80, 40]}, "max_evaluations": 100}
    doc.update(extra)
    return doc


def test_a_dict_gives_the_command_lines_report(tmp_path):
    r = pkmws.optimize(spec(), history=True)
    assert r["status"] == "converged"
    assert r["parameters"][0]["value"] == pytest.approx(math.hypot(140, 120) + 5, rel=1e-6)
    assert len(r["history"]) == r["evaluations"]
    assert {"index", "rod", "status", "task_margin", "time_ms", "reason"} <= set(r["history"][0])
    f = tmp_path / "spec.json"
    f.write_text(json.dumps(spec()))
    cli = json.loads(run("optimize", f, "--json").stdout)
    for key in ("status", "parameters", "constraints", "evaluations", "document", "metrics"):
        assert r[key] == cli[key], key
    assert pkmws.optimize(f)["parameters"] == cli["parameters"]


def test_the_base_as_a_mechanism_or_a_dict():
    m = pkmws.load(BASE)
    a = pkmws.optimize(spec(base=m))
    b = pkmws.optimize(spec(base=json.loads(BASE.read_text())))
    assert a["parameters"] == b["parameters"] and a["feasible"]


def test_errors_are_value_errors():
    with pytest.raises(ValueError, match="constraints\\[0\\]: expected 'COLUMN >= NUMBER'"):
        pkmws.optimize(spec(constraints=["task_margin = 5"]))
    with pytest.raises(ValueError, match="cannot open the optimisation file"):
        pkmws.optimize("/nonexistent/spec.json")
    with pytest.raises(ValueError, match="expected a file path or a dict"):
        pkmws.optimize(42)


def test_task_fit_limited_is_certified_on_the_task():
    """The sweep's limited_task_margin (the criteria hold on the task with that
    clearance) against the pressure angle sampled densely by evaluate_many:
    DexTAR (+1, +1), pressure angle <= 40 deg."""
    import numpy as np
    base = SOURCE_DIR / "datasets" / "five_bar_dextar_pp_alpha40.json"
    m = pkmws.load(base)
    limit = math.radians(40)

    def rows(center):
        return pkmws.sweep(base, [{"path": "distal[0]", "values": [0.23]}], metrics=["task_fit_limited"],
                           task={"center": center, "size": [0.1, 0.05]})[0]

    inside = rows([0, 0.2])
    assert inside["limited_task_inside"] == 1 and inside["limited_task_margin"] > 0
    d = inside["limited_task_margin"]
    rng = np.random.default_rng(1)
    task = np.column_stack([rng.uniform(-0.05, 0.05, 4000), rng.uniform(0.175, 0.225, 4000)])
    angle = rng.uniform(0, 2 * math.pi, 4000)
    near = task + 0.999 * d * rng.uniform(0, 1, (4000, 1)) * np.column_stack([np.cos(angle), np.sin(angle)])
    pts = np.vstack([task, near])
    e = m.evaluate_many(pts)
    assert e["reachable"].all()
    assert np.nanmax(e["pressure_angle"]) <= limit
    outside = rows([0, 0.3])
    assert outside["limited_task_inside"] == 0 and outside["limited_task_margin"] < 0
    assert m.evaluate_many(np.array([[0, 0.3]]))["pressure_angle"].max() > limit


def test_task_fit_real_lies_within_the_reachable_fit():
    """real ⊆ reachable: the task's clearance in the real workspace is at most
    its clearance in the reachable one (MOMA M1 machine with bodies)."""
    base = SOURCE_DIR / "datasets" / "machine_moma_m1.json"
    for center in ([0, -300], [0, -250], [0, -200]):
        r = pkmws.sweep(base, [{"path": "legs[0].rod_length", "values": [250]}], metrics=["task_fit", "task_fit_real"],
                        task={"center": center, "size": [40, 20]})[0]
        assert r["status"] == "ok"
        assert r["real_task_margin"] <= r["task_margin"] + 1e-9
        assert r["real_task_inside"] <= r["task_inside"]
        assert (r["real_task_margin"] >= 0) == (r["real_task_inside"] == 1)
