"""The pkmws Python module against independent computations: shapely (GEOS)
reads __geo_interface__, contains() against a numpy point-in-polygon test and
sampling, thread safety of workspace() in a thread pool, the matplotlib plot."""
import concurrent.futures
import math

import numpy as np
import pytest
import shapely.geometry
import shapely.wkt

import pkmws
from conftest import SOURCE_DIR

DATA = SOURCE_DIR / "datasets"
FILES = ["moma_m1_g0_l250", "moma_m3_l180", "five_bar_dextar_pp", "five_bar_pi_joint", "three_rrp_mitsi",
         "three_prp_example", "three_rpr_prismatic", "biglide_simplified"]


@pytest.mark.parametrize("name", FILES)
def test_geo_interface_is_valid_with_the_stated_area(name):
    ws = pkmws.load(DATA / f"{name}.json").workspace()
    geom = shapely.geometry.shape(ws)
    assert geom.is_valid, name
    assert geom.geom_type == "MultiPolygon"
    bound = ws.area_error_bound()
    assert abs(geom.area - ws.area) <= bound, (geom.area, ws.area, bound)
    # A coarser tolerance: still valid, still within its (larger) bound.
    tol = 1e-3 * math.dist(*ws.bbox)
    coarse = shapely.geometry.shape(ws.geo_interface(tol))
    assert coarse.is_valid and abs(coarse.area - ws.area) <= ws.area_error_bound(tol)


def test_geo_interface_splits_pinches_and_holes():
    # M3 with l = 180: two components (README); a region with a hole from booleans.
    m3 = pkmws.load(DATA / "moma_m3_l180.json").workspace()
    assert len(m3.components()) == 2
    assert len(shapely.geometry.shape(m3).geoms) == 2
    m1 = pkmws.load(DATA / "moma_m1_g0_l250.json")
    ws = m1.workspace()
    small = m1.with_parameters({"legs[0].rod_length": 200, "legs[1].rod_length": 200}).workspace()
    moved = m1.with_parameters({"legs[0].stroke[0]": 40, "legs[1].stroke[0]": 40,
                                "legs[0].stroke[1]": 160, "legs[1].stroke[1]": 160}).workspace()
    ring = ws - (small & moved)
    geom = shapely.geometry.shape(ring)
    assert geom.is_valid and abs(geom.area - ring.area) <= ring.area_error_bound()


def _inside_polygon(points, loops):
    """Even-odd point-in-polygon over closed polylines, vectorised in numpy."""
    inside = np.zeros(len(points), dtype=bool)
    px, py = points[:, 0][:, None], points[:, 1][:, None]
    for loop in loops:
        x0, y0 = loop[:, 0], loop[:, 1]
        x1, y1 = np.roll(x0, -1), np.roll(y0, -1)
        crosses = (y0 > py) != (y1 > py)
        with np.errstate(divide="ignore", invalid="ignore"):
            xs = x0 + (py - y0) * (x1 - x0) / (y1 - y0)
        inside ^= (np.count_nonzero(crosses & (px < xs), axis=1) % 2).astype(bool)
    return inside


@pytest.mark.parametrize("name", ["moma_m1_g0_l250", "moma_m3_l180", "five_bar_dextar_pp", "three_rrp_mitsi"])
def test_contains_matches_numpy_point_in_polygon(name):
    ws = pkmws.load(DATA / f"{name}.json").workspace()
    (x0, y0), (x1, y1) = ws.bbox
    rng = np.random.default_rng(7)
    pts = np.column_stack([rng.uniform(x0, x1, 4000), rng.uniform(y0, y1, 4000)])
    tol = 1e-7 * math.dist((x0, y0), (x1, y1))
    loops = ws.polyline(tol)
    got = ws.contains(pts)
    want = _inside_polygon(pts, loops)
    # Points within the polyline tolerance of the boundary may differ.
    poly = shapely.geometry.MultiLineString([np.vstack([l, l[:1]]) for l in loops])
    disagree = np.flatnonzero(got != want)
    for i in disagree:
        assert poly.distance(shapely.geometry.Point(pts[i])) <= 2 * tol
    assert len(disagree) <= 2


def test_area_by_sampling_agrees():
    ws = pkmws.load(DATA / "five_bar_dextar_pp.json").workspace()
    (x0, y0), (x1, y1) = ws.bbox
    n = 200_000
    rng = np.random.default_rng(11)
    pts = np.column_stack([rng.uniform(x0, x1, n), rng.uniform(y0, y1, n)])
    frac = ws.contains(pts).mean()
    estimate = frac * (x1 - x0) * (y1 - y0)
    sigma = math.sqrt(frac * (1 - frac) / n) * (x1 - x0) * (y1 - y0)
    assert abs(estimate - ws.area) <= 5 * sigma


def test_reachable_agrees_with_contains():
    m = pkmws.load(DATA / "moma_m1_g0_l250.json")
    ws = m.workspace()
    (x0, y0), (x1, y1) = ws.bbox
    rng = np.random.default_rng(3)
    pts = np.column_stack([rng.uniform(x0, x1, 5000), rng.uniform(y0, y1, 5000)])
    assert np.count_nonzero(ws.contains(pts) != m.reachable(pts)) <= 2


def test_thread_pool_gives_the_serial_areas():
    names = ["moma_m1_g0_l250", "moma_m3_l195", "moma_m5_gp5_gm5_l250", "five_bar_dextar_mp", "three_prp_example",
             "three_rpr_prismatic", "five_bar_pi_joint", "biglide_simplified"]
    mechs = [pkmws.load(DATA / f"{n}.json") for n in names]
    serial = [m.workspace().area for m in mechs]
    jobs = mechs * 4
    with concurrent.futures.ThreadPoolExecutor(max_workers=4) as pool:
        areas = list(pool.map(lambda m: m.workspace().area, jobs))
        inside = list(pool.map(lambda m: int(m.workspace().contains(np.array([[0.0, 0.0]] * 50)).sum()), jobs))
    assert areas == serial * 4
    assert inside == [int(m.workspace().contains(np.array([[0.0, 0.0]] * 50)).sum()) for m in mechs] * 4


def test_plot_draws_true_arcs(tmp_path):
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    import pkmws.plot

    m = pkmws.load(DATA / "moma_m1_g0_l250.json")
    ax = pkmws.plot.workspace(m)
    path = pkmws.plot.region_path(m.workspace())
    # Bézier arcs (CURVE4), not a polyline; the patch's area is the region's.
    assert (path.codes == path.CURVE4).any()
    poly = np.vstack(path.to_polygons(closed_only=True))
    x, y = poly[:, 0], poly[:, 1]
    assert 0.5 * abs(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y)) == pytest.approx(m.workspace().area, rel=1e-3)
    ax.figure.savefig(tmp_path / "ws.png")
    assert (tmp_path / "ws.png").stat().st_size > 1000
    ax2 = pkmws.plot.workspace(pkmws.load(DATA / "moma_m3_l180.json").workspace())
    assert ax2.patches


def test_grid_samplers_converge_to_the_exact_area():
    """Mechanism.grid (the `pkmws grid` baseline) against the exact area and the CLI."""
    import json
    import subprocess

    from conftest import CLI

    m = pkmws.load(SOURCE_DIR / "datasets" / "moma_m1_g0_l250.json")
    exact = m.workspace().area
    r = m.grid(400, certified_bounds=True, mask=True)
    assert r["kernel"] == "moma" and r["points_tested"] >= 400 * 400
    assert r["area_lower"] <= exact <= r["area_upper"]
    assert abs(r["area"] - exact) <= 0.01 * exact
    assert r["mask"].shape == (400, 400) and r["mask"].dtype.name == "uint8"
    assert int(r["mask"].sum()) == r["inside"]
    cli = json.loads(subprocess.run([CLI, "grid", str(SOURCE_DIR / "datasets" / "moma_m1_g0_l250.json"), "--cells", "400",
                                     "--json"], capture_output=True, text=True, check=True).stdout)
    assert cli["area"] == r["area"]
    polar = m.grid(200, sampler="polar")
    assert abs(polar["area"] - exact) <= 0.02 * exact
    adaptive = m.grid(32, sampler="adaptive", depth=6)
    assert adaptive["area_lower"] <= exact <= adaptive["area_upper"]
    with pytest.raises(ValueError, match="sampler"):
        m.grid(10, sampler="hexagonal")
    with pytest.raises(ValueError, match="cells"):
        m.grid(0)


def test_inscribed_rectangle_at_any_angle_through_python_and_the_cli(tmp_path):
    """M1 with gamma = -5 deg and 180 mm rods: the table turned by about 16.65 deg
    holds 12 % more than the best axis-aligned one. The corners lie in the
    workspace (shapely, on the exported polygon within 1e-4 mm of the arcs), form
    a rectangle of the stated area, and the CLI reports the same rectangle."""
    import json
    import subprocess
    from conftest import CLI
    path = DATA / "moma_m1_gm5_l180.json"
    ws = pkmws.load(str(path)).workspace()
    axis = ws.inscribed_rectangle(precision=1e-6)
    turned = ws.inscribed_rectangle(precision=1e-6, any_angle=True)
    assert turned["verified"] and turned["area"] <= turned["area_upper"] <= turned["area"] * (1 + 1e-6)
    assert turned["area"] > 1.1 * axis["area_upper"]
    assert math.degrees(turned["angle"]) == pytest.approx(16.65, abs=0.05)
    rect = shapely.geometry.Polygon(turned["corners"])
    assert rect.area == pytest.approx(turned["area"], rel=1e-9)
    # The polygon's chords are within 1e-4 mm of the arcs: inside up to that.
    outline = shapely.wkt.loads(ws.to_wkt(tolerance=1e-4))
    assert outline.buffer(2e-4).contains(rect)
    assert not outline.buffer(-0.5).contains(rect)  # and it touches the boundary
    assert ws.contains(np.array(turned["corners"])).all()
    with pytest.raises(ValueError, match="fixed orientation"):
        ws.inscribed_rectangle(width=50.0, any_angle=True)
    out = subprocess.run([str(CLI), "area", str(path), "--rectangle-angle", "any", "--rectangle-precision", "1e-6",
                          "--json"], capture_output=True, text=True, check=True)
    r = json.loads(out.stdout)["components"][0]["inscribed_rectangle"]
    assert r["area"] == pytest.approx(turned["area"], rel=1e-12)
    assert r["angle_deg"] == pytest.approx(math.degrees(turned["angle"]), rel=1e-12)
    assert np.allclose(r["corners"], turned["corners"], rtol=0, atol=1e-9)
    plain = json.loads(subprocess.run([str(CLI), "area", str(path), "--json"], capture_output=True, text=True,
                                      check=True).stdout)["components"][0]["inscribed_rectangle"]
    assert "angle_deg" not in plain and plain["area"] == pytest.approx(axis["area"], rel=1e-12)
