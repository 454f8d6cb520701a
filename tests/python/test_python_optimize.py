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
