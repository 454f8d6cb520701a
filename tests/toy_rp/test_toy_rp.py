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
    ik = json.loads(run("ik", toy, x, y, "--json"))
    assert ik["joint_units"] == {"theta": "deg", "rho": "mm"}
    (solution,) = ik["solutions"]
    assert solution["valid"]
    theta_deg, rho = solution["joints"]["theta"], solution["joints"]["rho"]
    assert abs(theta_deg - math.degrees(math.atan2(10.0, 30.0))) < 1e-9
    assert abs(rho - math.hypot(30.0, 10.0)) < 1e-9
    dk = json.loads(run("dk", toy, theta_deg, rho, "--json"))
    pose = dk["solutions"][0]["pose"]
    assert abs(pose[0] - x) < 1e-9 and abs(pose[1] - y) < 1e-9
    ev = json.loads(run("eval", toy, x, y, "--json"))
    (mode,) = ev["modes"]
    assert mode["reachable"]
    assert abs(mode["jacobian_det"] + 1.0 / rho) < 1e-12  # det dq/dx = -1/rho
    # Outside the stroke: not valid, with the reason.
    far = json.loads(run("ik", toy, BASE[0] + 60.0, BASE[1], "--json"))
    assert not far["solutions"][0]["valid"] and far["solutions"][0]["reason"]


def test_grid_and_compare_converge_to_the_area(toy):
    g = json.loads(run("grid", toy, "--cells", 400, "--json"))
    assert g["kernel"] == "generic"
    assert abs(g["area"] - AREA) <= 0.01 * AREA
    assert g["points_tested"] == 400 * 400
    c = json.loads(run("compare", toy, "--json", "--ladder", 100, 400, 1600, "--depths", 4, 8))
    assert abs(c["exact_area"] - AREA) <= 1e-9 * AREA
    grids = [r for r in c["rows"] if r["method"] == "cartesian"]
    assert [r["cells_per_side"] for r in grids] == [100, 400, 1600]
    assert abs(grids[-1]["area"] - AREA) <= 1e-3 * AREA
    assert abs(grids[-1]["rel_error"] - abs(grids[-1]["area"] - AREA) / AREA) < 1e-9


def test_batch_writes_summary(toy, tmp_path):
    out = tmp_path / "batch"
    out.mkdir()
    run("batch", toy, "--out", out)
    rows = json.loads((out / "summary.json").read_text())
    rows = rows["rows"] if isinstance(rows, dict) else rows
    (row,) = rows
    assert row["mechanism"] == "toy_rp"
    assert abs(row["area"] - AREA) <= 1e-9 * AREA
    assert (out / pathlib.Path(row["figure"]).name).exists()
