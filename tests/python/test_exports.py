"""Every export read back by third-party readers: GEOS (shapely) for WKT and
GeoJSON, ezdxf for DXF, rsvg-convert for SVG; areas compared with
`pkmws area --json`, for the bundled datasets and for seeded random MOMA and
five-bar designs (crank limits, equal and unequal links, every branch and
working mode, pinches, several components)."""
import json
import math
import random
import shutil
import subprocess
from concurrent.futures import ThreadPoolExecutor

import ezdxf
import pytest
import shapely.wkt
from shapely.geometry import shape
from shapely.validation import explain_validity

from conftest import DATASETS, run

FORMATS = ("svg", "dxf", "wkt", "geojson", "csv")
# Certified regions exported in the test (the level sets of the other
# criteria files take up to minutes each): one of each kind.
CERTIFIED = {
    "five_bar_dextar_pm_alpha40": [],   # criteria limits ([Briot] pressure angle)
    "biglide_real": [],                 # certified workspace (coupler-curve boundary)
    "machine_moma_m1": ["--real"],      # real workspace (bodies)
}
SLOW_CERTIFIED = ("_alpha", "three_rpr_paminsa_", "biglide_simplified_vratio2")


def area_json(path):
    return json.loads(run("area", path, "--json").stdout)


def check_polygons(geom, label):
    assert geom.is_valid, f"{label}: {explain_validity(geom)}"
    assert geom.geom_type in ("MultiPolygon", "GeometryCollection"), label


def export_polygons(tmp, path, stem, *extra):
    """(WKT geometry, GeoJSON geometry, GeoJSON properties) of one export."""
    wkt_path, gj_path = tmp / f"{stem}.wkt", tmp / f"{stem}.geojson"
    run("export", path, "-f", "wkt", "-o", wkt_path, *extra)
    run("export", path, "-f", "geojson", "-o", gj_path, *extra)
    text = wkt_path.read_text()
    assert "nan" not in text.lower() and "inf" not in text.lower()
    wkt = shapely.wkt.loads(text)
    doc = json.loads(gj_path.read_text())  # strict JSON: no NaN / Infinity
    feature = doc["features"][0]
    gj = shape(feature["geometry"])
    check_polygons(wkt, f"{stem} WKT")
    check_polygons(gj, f"{stem} GeoJSON")
    assert abs(wkt.area - gj.area) <= 1e-12 * max(gj.area, 1e-300)
    return wkt, gj, feature["properties"]


def check_exact_polygons(tmp, path, stem, exact_area):
    _, gj, props = export_polygons(tmp, path, stem)
    assert props["bound"] == "exact"
    bound = props["area_error_bound"]
    assert math.isfinite(bound) and bound >= 0
    assert abs(gj.area - exact_area) <= bound, (stem, gj.area, exact_area, bound)
    assert abs(props["area"] - exact_area) <= 1e-12 * exact_area
    return gj, props


def dxf_entities(path):
    doc = ezdxf.readfile(str(path))
    auditor = doc.audit()
    assert not auditor.has_errors, [str(e) for e in auditor.errors]
    return doc


def dxf_area(doc):
    """Green's theorem over LINE/ARC/CIRCLE entities chained into loops
    (BOUNDARY adds, HOLES subtracts)."""
    pieces, area = [], 0.0
    for e in doc.modelspace():
        hole = e.dxf.layer == "HOLES"
        if e.dxftype() == "CIRCLE":
            area += (-1 if hole else 1) * math.pi * e.dxf.radius ** 2
        elif e.dxftype() == "LINE":
            a, b = e.dxf.start, e.dxf.end
            pieces.append(((a.x, a.y), (b.x, b.y), None, hole))
        elif e.dxftype() == "ARC":
            c, r = e.dxf.center, e.dxf.radius
            a0, a1 = math.radians(e.dxf.start_angle), math.radians(e.dxf.end_angle)
            s = a1 - a0
            while s <= 0:
                s += 2 * math.pi
            while s > 2 * math.pi:
                s -= 2 * math.pi
            p = (c.x + r * math.cos(a0), c.y + r * math.sin(a0))
            q = (c.x + r * math.cos(a1), c.y + r * math.sin(a1))
            pieces.append((p, q, (c.x, c.y, r, s), hole))
        else:
            raise AssertionError(f"unexpected entity {e.dxftype()}")
    if not pieces:
        return area
    scale = max(max(abs(v) for pc in pieces for pt in pc[:2] for v in pt), 1e-300)
    eps = 1e-9 * scale
    near = lambda p, q: math.hypot(p[0] - q[0], p[1] - q[1]) <= eps
    used = [False] * len(pieces)
    for s0 in range(len(pieces)):
        if used[s0]:
            continue
        o = pieces[s0][0]
        twice, i, forward = 0.0, s0, True
        while True:
            used[i] = True
            a, b, arc, _ = pieces[i]
            frm, to = (a, b) if forward else (b, a)
            if arc:
                cx, cy, r, s = arc
                twice += ((cx - o[0]) * (to[1] - frm[1]) - (cy - o[1]) * (to[0] - frm[0])
                          + (1 if forward else -1) * r * r * s)
            else:
                twice += (frm[0] - o[0]) * (to[1] - o[1]) - (frm[1] - o[1]) * (to[0] - o[0])
            if near(to, o):
                break
            nxt = None
            for j, pc in enumerate(pieces):
                if used[j]:
                    continue
                if near(pc[0], to):
                    nxt, forward = j, True
                    break
                if near(pc[1], to):
                    nxt, forward = j, False
                    break
            assert nxt is not None, f"open DXF chain at {to}"
            i = nxt
        area += (-1 if pieces[s0][3] else 1) * abs(0.5 * twice)
    return area


def check_dxf(path, units, exact_area, size):
    doc = dxf_entities(path)
    assert doc.header.get("$INSUNITS") == {"mm": 4, "m": 6}[units]
    for e in doc.modelspace():
        if e.dxftype() == "LINE":
            length = math.hypot(e.dxf.start.x - e.dxf.end.x, e.dxf.start.y - e.dxf.end.y)
            assert length > 1e-14 * size, f"degenerate LINE {length}"
        elif e.dxftype() == "ARC":
            assert e.dxf.start_angle != e.dxf.end_angle, "degenerate ARC"
            sweep = (e.dxf.end_angle - e.dxf.start_angle) % 360.0
            assert math.radians(sweep) * e.dxf.radius > 1e-14 * size, "degenerate ARC"
    if exact_area is not None:
        got = dxf_area(doc)
        assert abs(got - exact_area) <= 1e-9 * exact_area, (got, exact_area)


def check_csv(path, size):
    lines = path.read_text().splitlines()
    assert lines[0] == "component,loop,hole,kind,x0,y0,x1,y1,cx,cy,r,sweep_deg"
    for line in lines[1:]:
        f = line.split(",")
        assert len(f) == 12
        if f[3] == "segment":
            assert math.dist((float(f[4]), float(f[5])), (float(f[6]), float(f[7]))) > 1e-14 * size, line
        else:
            assert abs(math.radians(float(f[11]))) * float(f[10]) > 1e-14 * size, line


def check_svg_renders(path, tmp):
    text = path.read_text()
    assert "nan" not in text.lower() and "inf\"" not in text.lower()
    png = tmp / (path.stem + ".png")
    r = subprocess.run(["rsvg-convert", "-w", "200", "-o", str(png), str(path)], capture_output=True, text=True,
                       timeout=120)
    assert r.returncode == 0, r.stderr
    assert png.stat().st_size > 0


def bbox_size(geom):
    x0, y0, x1, y1 = geom.bounds
    return max(math.hypot(x1 - x0, y1 - y0), abs(x0), abs(y0), abs(x1), abs(y1))


# ------------------------------------------------------------ datasets

def dataset_kind(path):
    doc = json.loads(path.read_text())
    if doc["mechanism"] == "pi_joint":
        return "none"
    if path.stem in CERTIFIED or "criteria" in doc or path.stem == "biglide_real":
        return "certified"
    return "exact"


EXACT = [p for p in DATASETS if dataset_kind(p) == "exact"]


def check_exact_dataset(path, tmp):
    a = area_json(path)
    assert a["method"] == "exact"
    exact, units = a["area"], a["units"]
    gj, _ = check_exact_polygons(tmp, path, path.stem, exact)
    size = bbox_size(gj)
    run("export", path, "-f", "dxf", "-o", tmp / f"{path.stem}.dxf")
    check_dxf(tmp / f"{path.stem}.dxf", units, exact, size)
    run("export", path, "-f", "csv", "-o", tmp / f"{path.stem}.csv")
    check_csv(tmp / f"{path.stem}.csv", size)
    run("export", path, "-f", "svg", "--bare", "-o", tmp / f"{path.stem}_bare.svg")
    bare = (tmp / f"{path.stem}_bare.svg").read_text()
    assert f'width="' in bare and 'mm" height="' in bare
    check_svg_renders(tmp / f"{path.stem}_bare.svg", tmp)
    run("export", path, "-f", "svg", "-o", tmp / f"{path.stem}.svg")
    check_svg_renders(tmp / f"{path.stem}.svg", tmp)
    return path.stem


def test_every_exact_dataset_exports_valid_files(tmp_path):
    with ThreadPoolExecutor(2) as pool:
        done = list(pool.map(lambda p: check_exact_dataset(p, tmp_path), EXACT))
    assert len(done) == len(EXACT) and len(EXACT) > 40


def test_dataset_without_planar_workspace_gives_one_line(tmp_path):
    path = next(p for p in DATASETS if p.stem == "pi_joint_prototype")
    for fmt in FORMATS:
        out = tmp_path / f"pi.{fmt}"
        r = run("export", path, "-f", fmt, "-o", out, check=False)
        assert r.returncode == 2, (fmt, r.returncode, r.stderr)
        assert len(r.stderr.strip().splitlines()) == 1, r.stderr
        assert not out.exists()


def check_certified(stem, extra, tmp):
    path = next(p for p in DATASETS if p.stem == stem)
    a = area_json(path)
    real = "--real" in extra
    lower = a["real_area_lower"] if real else a["area_lower"]
    upper = a["real_area_upper"] if real else a["area_upper"]
    slack = 1e-12 * upper  # double rounding of the shoelace sums
    # Both bounds in GeoJSON (the area checks); WKT, DXF, CSV and SVG once each,
    # alternating the bound (every export rebuilds the certified region).
    sizes = {}
    for bound in ("inner", "outer"):
        out = tmp / f"{stem}_{bound}.geojson"
        run("export", path, "-f", "geojson", "--bound", bound, "-o", out, *extra)
        feature = json.loads(out.read_text())["features"][0]
        gj, props = shape(feature["geometry"]), feature["properties"]
        check_polygons(gj, f"{stem} {bound} GeoJSON")
        assert props["bound"] == bound
        assert props["area_lower"] <= props["area_upper"]
        if bound == "inner":
            assert gj.area <= lower + slack, (stem, gj.area, lower)
        else:
            assert gj.area >= upper - slack, (stem, gj.area, upper)
        if not real:
            # The level sets' enclosures follow the traced curves: within the
            # export's relative tolerance (1e-4) of its own bounds, where cell
            # boxes alone (a staircase) missed them by 1e-3 to 5e-3.
            gap = props["area_lower"] - gj.area if bound == "inner" else gj.area - props["area_upper"]
            assert -slack <= gap <= 1e-4 * props["area_upper"], (stem, bound, gap, props)
        sizes[bound] = bbox_size(gj)
    # The other formats once each (the criteria file only in DXF: its every
    # export rebuilds the certified region, ~10 s).
    formats = ["dxf"] if "criteria" in json.loads(path.read_text()) else ["wkt", "dxf", "csv", "svg"]
    if "wkt" in formats:
        run("export", path, "-f", "wkt", "--bound", "inner", "-o", tmp / f"{stem}.wkt", *extra)
        wkt = shapely.wkt.loads((tmp / f"{stem}.wkt").read_text())
        check_polygons(wkt, f"{stem} inner WKT")
        assert wkt.area <= lower + slack
    run("export", path, "-f", "dxf", "--bound", "outer", "-o", tmp / f"{stem}.dxf", *extra)
    check_dxf(tmp / f"{stem}.dxf", a["units"], None, sizes["outer"])
    assert "bound: outer enclosure" in (tmp / f"{stem}.dxf").read_text()
    if "csv" in formats:
        run("export", path, "-f", "csv", "--bound", "inner", "-o", tmp / f"{stem}.csv", *extra)
        check_csv(tmp / f"{stem}.csv", sizes["inner"])
    if "svg" in formats:
        run("export", path, "-f", "svg", "--bare", "--bound", "outer", "-o", tmp / f"{stem}.svg", *extra)
        check_svg_renders(tmp / f"{stem}.svg", tmp)
    # WKT and CSV carry no metadata: a certified region needs --bound.
    for fmt in ("wkt", "csv"):
        out = tmp / f"{stem}_nobound.{fmt}"
        r = run("export", path, "-f", fmt, "-o", out, *extra, check=False)
        assert r.returncode == 2 and "--bound" in r.stderr and not out.exists(), r.stderr
    return stem


def test_certified_enclosures_lie_on_the_right_side_of_the_bounds(tmp_path):
    with ThreadPoolExecutor(2) as pool:
        done = list(pool.map(lambda kv: check_certified(kv[0], kv[1], tmp_path), CERTIFIED.items()))
    assert len(done) == len(CERTIFIED)


def test_enclosure_whose_holes_touch_its_shell_twice_is_split(tmp_path):
    # DexTAR (-1, -1), alpha <= 80 deg: next to a base joint, cells touching
    # at corners leave a hole that touches the inner enclosure's shell at two
    # vertices, cutting its interior in two (GEOS: "Interior is
    # disconnected"); the export traces such rings again into two polygons.
    path = next(p for p in DATASETS if p.stem == "five_bar_dextar_mm_alpha80")
    out = tmp_path / "inner.geojson"
    run("export", path, "-f", "geojson", "--bound", "inner", "-o", out)
    feature = json.loads(out.read_text())["features"][0]
    gj, props = shape(feature["geometry"]), feature["properties"]
    check_polygons(gj, "mm_alpha80 inner GeoJSON")
    assert 0.0 <= props["area_lower"] - gj.area <= 1e-4 * props["area_upper"], (gj.area, props)


# ------------------------------------------------------- random designs

def random_moma(rng):
    d = rng.uniform(40, 150)
    shape_kind = rng.choice(["parallel", "parallel", "diverging", "axes", "free"])
    if shape_kind == "parallel":
        g = rng.uniform(-10, 10)
        angles = [270 + g, 270 + g]
    elif shape_kind == "diverging":
        angles = [270 + rng.uniform(-15, 15), 270 + rng.uniform(-15, 15)]
    elif shape_kind == "axes":  # M2 / M3-like: guides along the axes, several components possible
        angles = rng.choice([[270, 0], [180, 270], [0, 90], [270, 180]])
    else:
        angles = [rng.uniform(0, 360), rng.uniform(0, 360)]
    legs = []
    for k, x in enumerate((-d, d)):
        s0 = rng.choice([0, 0, rng.uniform(-50, 50)])
        legs.append({"reference": [round(x + rng.uniform(-20, 20), 3), round(rng.uniform(-20, 20), 3)],
                     "guide_angle_deg": round(angles[k], 3), "stroke": [round(s0, 3), round(s0 + rng.uniform(60, 300), 3)],
                     "rod_length": round(rng.choice([rng.uniform(100, 320), 250, 180]), 3),
                     "branch": rng.choice([-1, 1])})
    return {"name": "random moma", "mechanism": "moma", "units": "mm", "legs": legs}


def random_five_bar(rng):
    a = rng.uniform(30, 150)
    if rng.random() < 0.4:  # equal links (DexTAR-like)
        l1 = l2 = rng.uniform(150, 300)
        prox, dist = [l1, l1], [l2, l2]
    else:
        prox = [rng.uniform(120, 300), rng.uniform(120, 300)]
        dist = [rng.uniform(150, 320), rng.uniform(150, 320)]
    doc = {"name": "random five-bar", "mechanism": "five_bar", "units": "mm",
           "base": [[-round(a, 3), 0], [round(a, 3), 0]],
           "proximal": [round(v, 3) for v in prox], "distal": [round(v, 3) for v in dist],
           "working_mode": [rng.choice([-1, 1]), rng.choice([-1, 1])]}
    if rng.random() < 0.6:  # crank limits: pinches and several components
        lims = []
        for _ in range(2):
            lo = rng.choice([rng.uniform(-60, 120), 0, 10, 30])
            lims.append([round(lo, 3), round(lo + rng.choice([rng.uniform(40, 180), 90, 140]), 3)])
        doc["actuator_limits_deg"] = lims
    return doc


# The design of the issue: unequal links and crank limits, a pinch whose
# polygons GEOS used to reject ("Self-intersection at (149.282, -40.000)").
ISSUE_DESIGN = {"name": "issue five-bar", "mechanism": "five_bar", "units": "mm",
                "base": [[-80, 0], [80, 0]], "proximal": [200, 180], "distal": [250, 260],
                "working_mode": [1, -1], "actuator_limits_deg": [[30, 170], [10, 150]]}


def check_design(doc, stem, tmp, full=True):
    path = tmp / f"{stem}.json"
    path.write_text(json.dumps(doc))
    r = run("area", path, "--json", check=False)
    if r.returncode == 2 and "empty" in r.stderr:
        return None  # the legs never meet: nothing to export
    assert r.returncode == 0, r.stderr
    a = json.loads(r.stdout)
    gj, props = check_exact_polygons(tmp, path, stem, a["area"])
    if full:  # DXF and CSV for a third of the designs (time)
        run("export", path, "-f", "dxf", "-o", tmp / f"{stem}.dxf")
        check_dxf(tmp / f"{stem}.dxf", "mm", a["area"], bbox_size(gj))
        run("export", path, "-f", "csv", "-o", tmp / f"{stem}.csv")
        check_csv(tmp / f"{stem}.csv", bbox_size(gj))
    return len(a["components"])


def test_issue_design_exports_valid_polygons(tmp_path):
    assert check_design(ISSUE_DESIGN, "issue", tmp_path) == 1


def test_random_designs_export_valid_polygons_within_their_bound(tmp_path):
    rng = random.Random(20261201)
    designs = []
    while len(designs) < 260:
        designs.append(random_moma(rng) if len(designs) % 2 else random_five_bar(rng))
    with ThreadPoolExecutor(2) as pool:
        results = list(pool.map(lambda kd: check_design(kd[1], f"d{kd[0]}", tmp_path, kd[0] % 3 == 0),
                                enumerate(designs)))
    exported = [c for c in results if c is not None]
    print(f"random designs: {len(exported)} exported of {len(designs)}, {sum(1 for c in exported if c > 1)} with several components")
    assert len(exported) >= 200, len(exported)
    assert sum(1 for c in exported if c > 1) >= 10  # several components
    assert sum(1 for d, c in zip(designs, results) if c is not None and "actuator_limits_deg" in d) >= 40


# ------------------------------------------------------------ refusals

@pytest.mark.parametrize("tolerance", ["0", "-1", "1e-300", "1e-15", "1e-12", "1e308", "inf", "nan"])
def test_tolerance_out_of_range_is_refused(tmp_path, tolerance):
    path = next(p for p in DATASETS if p.stem == "moma_m1_g0_l250")
    for fmt in ("wkt", "geojson"):
        out = tmp_path / f"t.{fmt}"
        r = run("export", path, "-f", fmt, "--tolerance", tolerance, "-o", out, check=False, timeout=60)
        assert r.returncode == 2, (tolerance, r.returncode, r.stderr)
        assert len(r.stderr.strip().splitlines()) == 1 and "--tolerance" in r.stderr, r.stderr
        assert not out.exists()


def test_small_tolerance_keeps_its_bound(tmp_path):
    # 1e-15 used to give a 4-vertex polygon (area 29 154.76 of 36 202.18) with a
    # bound of 1.2e-9; the smallest accepted tolerance must keep its bound.
    path = next(p for p in DATASETS if p.stem == "moma_m1_g0_l250")
    exact = area_json(path)["area"]
    r = run("export", path, "-f", "geojson", "--tolerance", "1e-15", "-o", tmp_path / "x.json", check=False)
    assert r.returncode == 2
    for tol in ("1e-6", "1e-4", "1"):
        run("export", path, "-f", "geojson", "--tolerance", tol, "-o", tmp_path / "t.json")
        f = json.loads((tmp_path / "t.json").read_text())["features"][0]
        g = shape(f["geometry"])
        assert g.is_valid
        assert abs(g.area - exact) <= f["properties"]["area_error_bound"]
        assert f["properties"]["tolerance"] == float(tol)


def test_non_finite_geometry_is_refused_without_a_file(tmp_path):
    big = {"name": "huge", "mechanism": "moma", "units": "mm", "legs": [
        {"reference": [-100, 0], "guide_angle_deg": 270, "stroke": [0, 1.797e308], "rod_length": 250, "branch": -1},
        {"reference": [100, 0], "guide_angle_deg": 270, "stroke": [0, 1.797e308], "rod_length": 250, "branch": -1}]}
    path = tmp_path / "huge.json"
    path.write_text(json.dumps(big))
    for fmt in FORMATS:
        for extra in ([], ["--bare"]) if fmt == "svg" else ([],):
            out = tmp_path / f"huge.{fmt}"
            r = run("export", path, "-f", fmt, "-o", out, *extra, check=False, timeout=120)
            if r.returncode == 0:
                text = out.read_text().lower()
                assert "nan" not in text and "inf" not in text.replace("$insunits", ""), fmt
                out.unlink()
            else:
                assert r.returncode == 2 and len(r.stderr.strip().splitlines()) == 1, (fmt, r.returncode, r.stderr)
                assert not out.exists()
