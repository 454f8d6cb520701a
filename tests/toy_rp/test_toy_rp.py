"""A toy mechanism module (toy_rp.cpp: one RP leg, workspace an annulus) runs
through every generic subcommand of a CLI linked with it, and its numbers
agree with the closed form: area pi (R^2 - r^2), joints (atan2, |P - base|)."""
import json
import math
import os
import pathlib
import subprocess

import pytest

CLI = os.environ.get("PKMWS_TOY_CLI", "")
BASE = (10.0, -5.0)
R_IN, R_OUT = 20.0, 50.0
AREA = math.pi * (R_OUT**2 - R_IN**2)


def run(*args):
    r = subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, f"{args}: {r.stderr.strip()}"
    return r.stdout


@pytest.fixture()
def toy(tmp_path):
    if not CLI:
        pytest.skip("PKMWS_TOY_CLI not set (run through ctest)")
    f = tmp_path / "toy.json"
    f.write_text(json.dumps({"name": "toy RP leg", "mechanism": "toy_rp", "units": "mm",
                             "base": list(BASE), "stroke": [R_IN, R_OUT]}))
    return f


def test_area_is_the_annulus(toy):
    j = json.loads(run("area", toy, "--json"))
    assert abs(j["area"] - AREA) <= 1e-9 * AREA


def test_export_every_format(toy, tmp_path):
    for fmt in ["svg", "dxf", "wkt", "geojson", "csv"]:
        out = tmp_path / f"toy.{fmt}"
        run("export", toy, "--format", fmt, "-o", out)
        assert out.stat().st_size > 0
    shapely = pytest.importorskip("shapely.wkt")
    poly = shapely.loads((tmp_path / "toy.wkt").read_text())
    assert poly.is_valid
    assert abs(poly.area - AREA) <= 1e-3 * AREA


def test_ik_dk_eval_round_trip(toy):
    x, y = BASE[0] + 30.0, BASE[1] + 10.0
    ik = json.loads(run("ik", toy, x, y))
    joints = ik["solutions"][0]["joints"]
    values = list(joints.values()) if isinstance(joints, dict) else joints
    theta_deg, rho = values[0], values[1]
    assert abs(theta_deg - math.degrees(math.atan2(10.0, 30.0))) < 1e-9
    assert abs(rho - math.hypot(30.0, 10.0)) < 1e-9
    dk = json.loads(run("dk", toy, theta_deg, rho))
    pose = dk["solutions"][0]["pose"]
    assert abs(pose[0] - x) < 1e-9 and abs(pose[1] - y) < 1e-9
    ev = json.loads(run("eval", toy, x, y))
    assert ev["evaluations"][0]["reachable"] if "evaluations" in ev else True


def test_grid_and_compare_converge_to_the_area(toy):
    g = json.loads(run("grid", toy, "--cells", 400, "--json"))
    estimate = g.get("area", g.get("area_estimate"))
    assert abs(estimate - AREA) <= 0.01 * AREA
    c = json.loads(run("compare", toy, "--json"))
    assert abs(c["exact_area"] - AREA) <= 1e-9 * AREA if "exact_area" in c else True


def test_batch_writes_summary(toy, tmp_path):
    out = tmp_path / "batch"
    out.mkdir()
    run("batch", toy, "--out", out)
    summary = json.loads((out / "summary.json").read_text())
    text = json.dumps(summary)
    assert "toy RP leg" in text or "toy" in text
    assert any(p.suffix == ".svg" for p in out.iterdir())
