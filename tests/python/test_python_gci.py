"""The sweep metric `gci` (mean of 1/κ over the exact workspace) against an
independent computation: κ from the Python module's evaluate_many on a fine
grid of points, masked by the exact region's membership test, averaged with
numpy. The stated error must cover the difference (within the fine grid's own
sampling error, estimated from two numpy resolutions)."""
import csv
import json

import numpy as np
import pytest

import pkmws
from conftest import SOURCE_DIR, run

DATA = SOURCE_DIR / "datasets"


def numpy_gci(mech, n):
    """Mean of 1/κ over the midpoints of an n x n grid on the workspace's bbox that lie in the exact region."""
    ws = mech.workspace()
    (x0, y0), (x1, y1) = ws.bbox
    xs = x0 + (np.arange(n) + 0.5) * (x1 - x0) / n
    ys = y0 + (np.arange(n) + 0.5) * (y1 - y0) / n
    pts = np.stack(np.meshgrid(xs, ys), axis=-1).reshape(-1, 2)
    inside = pts[ws.contains(pts)]
    cond = mech.evaluate_many(inside)["condition_number"]
    cond = cond[~np.isnan(cond)]  # the few points the double-precision IK puts just outside
    return float(np.mean(np.where(np.isinf(cond), 0.0, 1.0 / cond)))


def sweep_gci(tmp_path, dataset, path, value):
    spec = tmp_path / "gci.json"
    spec.write_text(json.dumps({"base": str(dataset), "parameters": [{"path": path, "values": [value]}],
                                "metrics": ["area", "gci"]}))
    out = tmp_path / "gci.csv"
    run("sweep", spec, "-o", out, "--no-timing", "--threads", "1")
    (row,) = list(csv.DictReader(out.open()))
    assert row["status"] == "ok", row
    return float(row["gci"]), float(row["gci_error"])


@pytest.mark.parametrize("dataset,path,value", [
    ("moma_m1_g0_l250.json", "legs[0].rod_length", 250),
    ("moma_m4_gm5_gp5_l195.json", "legs[0].rod_length", 195),
    ("five_bar_dextar_mm.json", "proximal[0]", 0.23),  # type-2 curves inside: 1/κ = 0 there
])
def test_gci_matches_a_fine_numpy_grid(tmp_path, dataset, path, value):
    gci, err = sweep_gci(tmp_path, DATA / dataset, path, value)
    mech = pkmws.load(DATA / dataset)
    fine, half = numpy_gci(mech, 1200), numpy_gci(mech, 600)
    assert 0.0 < gci < 1.0 and 0.0 <= err < 2e-3
    assert abs(gci - fine) <= err + 2 * abs(fine - half) + 1e-4, (gci, err, fine, half)


def test_gci_without_a_workspace_is_a_reason_not_a_crash(tmp_path):
    # A design whose rods cannot reach: empty workspace, a row with its status (no crash).
    spec = tmp_path / "gci.json"
    spec.write_text(json.dumps({"base": str(DATA / "moma_m1_g0_l250.json"),
                                "parameters": [{"name": "rod", "path": ["legs[0].rod_length", "legs[1].rod_length"],
                                                "values": [20, 250]}],
                                "metrics": ["gci"]}))
    out = tmp_path / "gci.csv"
    run("sweep", spec, "-o", out, "--no-timing")
    rows = list(csv.DictReader(out.open()))
    assert rows[0]["status"] == "empty" and rows[0]["gci"] == ""
    assert rows[1]["status"] == "ok" and rows[1]["gci"] != "" and rows[1]["reason"] == ""
