"""Figures agree with what they draw: the platform at the file's orientation,
the type-2 singular circle of that orientation, the rods of a dk assembly
mode at the rod length, band figures drawn as traced polygons with every band
in the legend, criteria-limited and machine figures with their certified
numbers (read back from the SVG with xml.etree; rendered with rsvg-convert)."""
import json
import math
import subprocess

import pytest

from conftest import SOURCE_DIR, run
import svgfig

DATA = SOURCE_DIR / "datasets"


def render(path, tmp_path):
    png = tmp_path / (path.stem + ".png")
    r = subprocess.run(["rsvg-convert", "-w", "400", str(path), "-o", str(png)], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    assert png.stat().st_size > 0


def area_json(path):
    return json.loads(run("area", path, "--json").stdout)


def with_orientation(src, phi_deg, tmp_path):
    doc = json.loads(src.read_text())
    doc["orientation_deg"] = phi_deg
    out = tmp_path / (src.stem + f"_phi{phi_deg}.json")
    out.write_text(json.dumps(doc))
    return out, doc


def rot(p, phi):
    c, s = math.cos(phi), math.sin(phi)
    return (c * p[0] - s * p[1], s * p[0] + c * p[1])


def tool_point(root):
    (tool,) = svgfig.by_class(root, "tool", "circle")
    return svgfig.to_model(root, float(tool.get("cx")), float(tool.get("cy")))


def platform_vertices(root):
    (poly,) = svgfig.by_class(root, "platform", "polygon")
    return [svgfig.to_model(root, *p) for p in svgfig.points(poly.get("points"))]


@pytest.mark.parametrize("name,phi_deg", [("three_rpr_prismatic.json", 10.0), ("three_rrp_mitsi.json", None)])
def test_platform_drawn_at_the_file_orientation(tmp_path, name, phi_deg):
    src = DATA / name
    if phi_deg is None:
        doc = json.loads(src.read_text())
        phi_deg = doc["orientation_deg"]
    else:
        src, doc = with_orientation(src, phi_deg, tmp_path)
    svg = tmp_path / "f.svg"
    run("export", src, "-f", "svg", "-o", svg)
    root = svgfig.load(svg)
    p = tool_point(root)
    _, _, s = svgfig.mapping(root)
    verts = platform_vertices(root)
    assert len(verts) == 3
    phi = math.radians(phi_deg)
    for v, b in zip(verts, doc["platform"]):
        want = rot(b, phi)
        got = (v[0] - p[0], v[1] - p[1])
        # two px decimals: 0.01 px in model units, plus the tool point's rounding
        assert math.dist(got, want) < 0.02 / s, (got, want)
    if doc["mechanism"] == "three_rrp":
        # the legs: three cranks besides the three platform sides, three sliders
        assert len(svgfig.by_class(root, "link", "line")) == 6
        assert len(svgfig.by_class(root, "slider", "rect")) == 3
    render(svg, tmp_path)


def singular_radii(root):
    radii = []
    for pl in svgfig.by_class(root, "singular", "polyline"):
        for q in svgfig.points(pl.get("points")):
            x, y = svgfig.to_model(root, *q)
            radii.append(math.hypot(x, y))
    return radii


@pytest.mark.parametrize("name", ["three_rpr_paminsa_phi25_r200.json", "three_rpr_paminsa_phi50_r110.json"])
def test_singular_circle_of_the_orientation(tmp_path, name):
    # [Briot]: for fixed phi the PAMINSA 3-RPR is type-2 singular on the circle
    # about O of radius sqrt(R_b^2 + R_p^2 - 2 R_b R_p cos phi).
    doc = json.loads((DATA / name).read_text())
    rb = math.hypot(*doc["base"][0])
    rp = math.hypot(*doc["platform"][0])
    phi = math.radians(doc["orientation_deg"])
    r = math.sqrt(rb * rb + rp * rp - 2 * rb * rp * math.cos(phi))
    assert abs(r - (rb - rp)) > 0.01  # the phi = 0 circle is distinguishable
    for args in (["export", DATA / name, "-f", "svg"],
                 ["levels", DATA / name, "--criterion", "reaction", "--levels", "50,100,200", "--svg"]):
        svg = tmp_path / "s.svg"
        run(*args, svg) if args[0] == "levels" else run(*args, "-o", svg)
        radii = singular_radii(svgfig.load(svg))
        assert len(radii) > 20
        assert max(abs(x - r) for x in radii) < 2e-3, (min(radii), max(radii), r)


def test_moma_dk_figures_draw_rods_of_the_file_length(tmp_path):
    src = DATA / "moma_m1_g0_l250.json"
    doc = json.loads(src.read_text())
    rod = doc["legs"][0]["rod_length"]
    prefix = tmp_path / "dk"
    out = json.loads(run("dk", src, "50", "150", "--json", "--svg", prefix).stdout)
    assert len(out["solutions"]) == 2
    for k, sol in enumerate(out["solutions"], start=1):
        root = svgfig.load(f"{prefix}_{k}.svg")
        links = svgfig.by_class(root, "link", "line")
        assert len(links) == 2, sol
        for ln in links:
            a = svgfig.to_model(root, float(ln.get("x1")), float(ln.get("y1")))
            b = svgfig.to_model(root, float(ln.get("x2")), float(ln.get("y2")))
            assert math.dist(a, b) == pytest.approx(rod, rel=2e-3), (k, a, b)
        # the sliders at the joint values given to dk (p1 = 50, p2 = 150 along the downward guides)
        ys = sorted(svgfig.to_model(root, float(r.get("x")) + 12, float(r.get("y")) + 7)[1]
                    for r in svgfig.by_class(root, "slider", "rect"))
        assert ys == pytest.approx([-150, -50], abs=0.5)


def legend_intervals(texts):
    out = []
    for t in texts:
        m = svgfig.re.search(r"\[([^,\]]+), ([^\]]+)\]", t)
        if m:
            out.append((t, m.group(1), m.group(2)))
    return out


@pytest.mark.parametrize("how", ["levels", "export"])
def test_band_figure_is_traced_small_and_complete(tmp_path, how):
    src = DATA / "five_bar_dextar_pm_alpha80.json"
    svg = tmp_path / "bands.svg"
    if how == "levels":
        run("levels", src, "--criterion", "pressure_angle", "--levels", "20,40,60,80", "--tolerance", "1e-5",
            "--svg", svg)
    else:
        run("export", src, "-f", "svg", "--criterion", "pressure_angle", "--levels", "20,40,60,80", "-o", svg)
    assert svg.stat().st_size < 300_000
    root = svgfig.load(svg)
    # no rectangle per cell: the bands are paths
    assert len(list(root.iter(svgfig.NS + "rect"))) < 30
    bands = svgfig.by_class(root, "band", "path")
    assert len(bands) == 4
    # axes, ticks and the scale bar of the workspace figures
    assert len(svgfig.by_class(root, "tick", "text")) >= 6
    assert svgfig.by_class(root, "scale-bar", "g")
    assert any("[m]" in (t.text or "") for t in svgfig.by_class(root, "axis-label", "text"))
    texts = svgfig.legend_texts(root)
    intervals = legend_intervals(texts)
    assert len(intervals) == 5  # four bands and the band above 80 deg
    assert any(t.startswith("> 80") for t, _, _ in intervals)
    for t, lo, hi in intervals:
        assert lo != hi, t
        assert float(lo) <= float(hi)
    # the bands nest: the drawn areas increase with the level
    areas = [svgfig.drawn_area_model(root, b) for b in bands]  # painter's order: the largest first
    assert areas == sorted(areas, reverse=True)
    assert areas[-1] > 0.05
    assert "[Briot]" in svgfig.caption(root) and "seed" not in svg.read_text().lower()
    render(svg, tmp_path)


def test_limited_export_fills_the_certified_region(tmp_path):
    src = DATA / "five_bar_dextar_pm_alpha40.json"
    svg = tmp_path / "lim.svg"
    run("export", src, "-f", "svg", "-o", svg)
    rep = area_json(src)
    root = svgfig.load(svg)
    cap = svgfig.caption(root)
    nums = svgfig.numbers(cap)
    assert any(abs(x - rep["area_lower"]) <= 1e-9 * rep["area_lower"] for x in nums), cap
    assert any(abs(x - rep["area_upper"]) <= 1e-9 * rep["area_upper"] for x in nums), cap
    assert "inner bound" in cap
    assert abs(0.4155807344 - rep["area"]) > 0.1  # the limited area, not the reachable one
    (lim,) = svgfig.by_class(root, "limited", "path")
    drawn = svgfig.drawn_area_model(root, lim)
    # the inner bound drawn: within the certified interval up to the drawing's rounding
    assert rep["area_lower"] * 0.995 <= drawn <= rep["area_upper"] * 1.001, (drawn, rep)
    render(svg, tmp_path)


@pytest.mark.parametrize("name", ["machine_moma_m3.json", "machine_five_bar_dextar.json"])
def test_machine_figure_draws_bodies_with_units(tmp_path, name):
    src = DATA / name
    svg = tmp_path / "m.svg"
    run("export", src, "-f", "svg", "-o", svg)
    root = svgfig.load(svg)
    unit = json.loads(src.read_text())["units"]
    texts = svgfig.legend_texts(root)
    if "moma" in name:
        assert len(svgfig.by_class(root, "housing")) == 2
        assert len(svgfig.by_class(root, "slider-block")) == 2
        assert any(t.startswith("housing (") and t.endswith(f" {unit} wide)") for t in texts), texts
        assert any(t.startswith("slider block (") and t.endswith(f" {unit})") for t in texts), texts
    assert svgfig.by_class(root, "platform-joint")
    inter = svgfig.by_class(root, "interference", "path")
    assert inter
    for p in inter:  # hatched, not translucent
        assert p.get("fill").startswith("url(#hatch")
        assert float(p.get("fill-opacity")) == 1.0
    numbered = [t for t in texts if svgfig.re.match(r"^\d+ ", t)]
    assert len(numbered) == len(inter)
    for t in numbered:
        assert t.endswith(f" {unit}²"), t
    # the tags of the pairs do not overlap
    boxes = []
    for g in svgfig.by_class(root, "tag", "g"):
        r = g.find(svgfig.NS + "rect")
        boxes.append(tuple(float(r.get(k)) for k in ("x", "y", "width", "height")))
    for i, a in enumerate(boxes):
        for b in boxes[i + 1:]:
            assert a[0] + a[2] <= b[0] or b[0] + b[2] <= a[0] or a[1] + a[3] <= b[1] or b[1] + b[3] <= a[1], (a, b)
    rep = area_json(src)
    nums = svgfig.numbers(svgfig.caption(root))
    for key in ("real_area_lower", "real_area_upper"):
        assert any(abs(x - rep[key]) <= 1e-9 * rep[key] for x in nums), key
    render(svg, tmp_path)
