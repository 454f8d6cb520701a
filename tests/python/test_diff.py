"""pkmws diff: the areas of A ∩ B, A − B, B − A, A ∪ B against inclusion–exclusion
and against shapely on the WKT exports of A and B; the metric table against
`pkmws area` of each file; units and bad input refused in one line with no
file written; the figure's legend, classes and rendering."""
import json
import shutil
import subprocess

import pytest
import shapely.wkt

import svgfig
from conftest import SOURCE_DIR, run

DATA = SOURCE_DIR / "datasets"
A = DATA / "moma_m1_g0_l250.json"
B = DATA / "moma_m1_gp5_l195.json"
TOL = 1e-4  # WKT polyline deviation (mm)


def diff_json(a, b, *extra):
    return json.loads(run("diff", a, b, "--json", "--gci-cells", "16", *extra).stdout)


@pytest.fixture(scope="module")
def ab():
    return diff_json(A, B)


def metric(report, name):
    (m,) = [m for m in report["metrics"] if m["metric"] == name]
    return m


def test_inclusion_exclusion(ab):
    r = ab["regions"]
    area_a, area_b = metric(ab, "area")["a"], metric(ab, "area")["b"]
    both, a_only, b_only, either = (r[k]["area"] for k in ("a_and_b", "a_minus_b", "b_minus_a", "a_or_b"))
    assert ab["method"] == "exact"
    assert 0 < both < min(area_a, area_b) and a_only > 0 and b_only > 0  # the designs overlap partly
    assert area_a + area_b - both == pytest.approx(either, rel=1e-12)
    assert a_only + both == pytest.approx(area_a, rel=1e-12)
    assert b_only + both == pytest.approx(area_b, rel=1e-12)
    assert a_only + b_only + both == pytest.approx(either, rel=1e-12)


def test_areas_agree_with_shapely_on_the_wkt_exports(ab, tmp_path):
    polys = []
    for f in (A, B):
        out = tmp_path / (f.stem + ".wkt")
        run("export", f, "-f", "wkt", "--tolerance", TOL, "-o", out)
        polys.append(shapely.wkt.loads(out.read_text()))
    pa, pb = polys
    assert pa.is_valid and pb.is_valid
    # A polyline within TOL of every curve moves the area by at most TOL per unit of perimeter.
    slack = 2 * TOL * (pa.length + pb.length)
    r = ab["regions"]
    assert pa.intersection(pb).area == pytest.approx(r["a_and_b"]["area"], abs=slack)
    assert pa.difference(pb).area == pytest.approx(r["a_minus_b"]["area"], abs=slack)
    assert pb.difference(pa).area == pytest.approx(r["b_minus_a"]["area"], abs=slack)
    assert pa.union(pb).area == pytest.approx(r["a_or_b"]["area"], abs=slack)


def test_metric_changes_match_area_of_each_file(ab):
    ra = json.loads(run("area", A, "--json").stdout)
    rb = json.loads(run("area", B, "--json").stdout)
    m = metric(ab, "area")
    assert m["a"] == pytest.approx(ra["area"], rel=1e-13) and m["b"] == pytest.approx(rb["area"], rel=1e-13)
    assert m["change"] == pytest.approx(rb["area"] - ra["area"], rel=1e-12)
    assert metric(ab, "components")["a"] == len(ra["components"])
    rect_a = max(c["inscribed_rectangle"]["area"] for c in ra["components"])
    rect_b = max(c["inscribed_rectangle"]["area"] for c in rb["components"])
    assert metric(ab, "rectangle_area")["change"] == pytest.approx(rect_b - rect_a, rel=1e-5)
    circ_a = max(c["inscribed_circle"]["radius"] for c in ra["components"])
    assert metric(ab, "inscribed_circle")["a"] == pytest.approx(circ_a, rel=1e-4)
    # No criteria, no bodies: null with the reason; GCI in (0, 1] with its error.
    for name, word in (("limited_area", "criteria"), ("real_area", "bodies")):
        assert metric(ab, name)["a"] is None and word in metric(ab, name)["a_reason"]
    g = metric(ab, "gci")
    assert 0 < g["a"] <= 1 and 0 < g["b"] <= 1 and g["a_error"] >= 0


def test_same_file_is_all_intersection():
    j = diff_json(A, A)
    r = j["regions"]
    assert r["a_minus_b"]["area"] == 0 and r["b_minus_a"]["area"] == 0
    assert r["a_and_b"]["area"] == pytest.approx(metric(j, "area")["a"], rel=1e-14)
    assert all(m["change"] in (0, None) for m in j["metrics"])


def test_bodies_give_real_area_bounds():
    j = diff_json(DATA / "machine_moma_m1.json", DATA / "machine_moma_m3.json")
    m = metric(j, "real_area")
    assert m["a_bounds"][0] <= m["a"] <= m["a_bounds"][1]
    assert m["change_bounds"][0] <= m["change"] <= m["change_bounds"][1]
    assert m["a_bounds"][1] <= metric(j, "area")["a"] * (1 + 1e-12)  # real ⊆ reachable


def test_certified_workspaces_state_bounds():
    j = diff_json(DATA / "biglide_real.json", DATA / "biglide_simplified.json")
    assert j["method"] == "certified" and j["a"]["method"] == "certified"
    r = j["regions"]
    for k in r:
        assert r[k]["area_lower"] <= r[k]["area"] <= r[k]["area_upper"]
    # Inclusion–exclusion holds between the bounds.
    a_lo, a_hi = metric(j, "area")["a_bounds"]
    b = metric(j, "area")["b"]
    assert r["a_or_b"]["area_lower"] <= a_hi + b - r["a_and_b"]["area_lower"] + 1e-6
    assert r["a_or_b"]["area_upper"] >= a_lo + b - r["a_and_b"]["area_upper"] - 1e-6


def one_line_error(*args):
    r = run(*args, check=False)
    assert r.returncode == 2, r.stdout[:300]
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("pkmws: error: "), r.stderr
    return lines[0]


def test_other_units_refused_in_one_line_no_file(tmp_path):
    doc = json.loads(A.read_text())
    doc["units"] = "m"
    other = tmp_path / "in_metres.json"
    other.write_text(json.dumps(doc))
    fig = tmp_path / "fig.svg"
    line = one_line_error("diff", A, other, "-o", fig)
    assert "units" in line and '"m"' in line and '"mm"' in line
    assert not fig.exists()


def test_bad_input_names_the_field_no_file(tmp_path):
    doc = json.loads(A.read_text())
    del doc["legs"][1]["rod_length"]
    bad = tmp_path / "bad.json"
    bad.write_text(json.dumps(doc))
    fig = tmp_path / "fig.svg"
    assert "legs[1].rod_length" in one_line_error("diff", A, bad, "-o", fig)
    assert not fig.exists()
    assert "missing.json" in one_line_error("diff", A, tmp_path / "missing.json")
    assert not list(tmp_path.glob("*.svg"))


def test_figure_legend_pieces_and_rendering(tmp_path):
    fig = tmp_path / "diff.svg"
    j = diff_json(A, B, "-o", fig)
    assert j["figure"] == str(fig)
    root = svgfig.load(fig)
    legend = svgfig.legend_texts(root)
    assert any(t.startswith("A only") for t in legend) and any(t.startswith("B only") for t in legend)
    assert any(t.startswith("A \u2229 B") for t in legend)
    fills = set()
    for cls, key in (("a-only", "a_minus_b"), ("b-only", "b_minus_a"), ("a-and-b", "a_and_b")):
        (el,) = svgfig.by_class(root, cls, "path")
        fills.add(el.get("fill"))
        # The drawn piece has the reported area (arcs read back from the SVG).
        assert svgfig.drawn_area_model(root, el) == pytest.approx(j["regions"][key]["area"], rel=1e-3)
    assert len(fills) == 3
    text = " ".join(t.text or "" for t in root.iter(svgfig.NS + "text"))
    assert "x [mm]" in text and "y [mm]" in text
    if shutil.which("rsvg-convert"):
        png = tmp_path / "diff.png"
        subprocess.run(["rsvg-convert", "-w", "1000", str(fig), "-o", str(png)], check=True)
        assert png.stat().st_size > 10000
