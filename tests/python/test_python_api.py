"""The pkmws Python module (python/): every API call, numpy in/out, errors.

Needs the module on PYTHONPATH (CTest sets it to build/python)."""
import json
import math
import os
import sys
import pathlib
import subprocess

import numpy as np
import pytest

import pkmws
from conftest import CLI, SOURCE_DIR

DATA = SOURCE_DIR / "datasets"
M1 = DATA / "moma_m1_g0_l250.json"
M1_AREA = 36202.1833253496  # README, `pkmws area`


@pytest.fixture(scope="module")
def m1():
    return pkmws.load(M1)


def cli_error(*args):
    """The one line `pkmws ARGS` prints on stderr (without the `pkmws: error: ` prefix)."""
    r = subprocess.run([CLI, *map(str, args)], capture_output=True, text=True)
    assert r.returncode == 2, r
    line = r.stderr.strip()
    assert "\n" not in line
    return line.removeprefix("pkmws: error: ")


# ---------------------------------------------------------------- loading

def test_load_path_str_pathlike_and_dict(m1):
    assert m1.kind == "moma" and m1.dof == 2 and m1.units == "mm"
    assert m1.name.startswith("MOMA M1")
    assert [j["name"] for j in m1.joints] == ["p1", "p2"]
    assert all(j["unit"] == "mm" for j in m1.joints)
    assert pkmws.load(str(M1)).workspace().area == pytest.approx(M1_AREA, rel=1e-13)
    doc = json.loads(M1.read_text())
    d = pkmws.load(doc)
    assert d.path == "<dict>"
    assert d.workspace().area == pytest.approx(M1_AREA, rel=1e-13)
    assert d.document == doc
    assert "MOMA" in repr(d)


def test_joints_units_and_orientation():
    five = pkmws.load(DATA / "five_bar_dextar_pp.json")
    assert all(j["unit"] == "rad" for j in five.joints)
    rrp = pkmws.load(DATA / "three_rrp_mitsi.json")
    assert rrp.dof == 3
    assert rrp.orientation == pytest.approx(math.radians(20.0))


def test_bounds_contain_workspace(m1):
    (x0, y0), (x1, y1) = m1.bounds
    (a0, b0), (a1, b1) = m1.workspace().bbox
    assert x0 <= a0 and y0 <= b0 and a1 <= x1 and b1 <= y1


# ---------------------------------------------------------------- errors

def test_missing_file_same_message_as_cli(tmp_path):
    missing = tmp_path / "nope.json"
    with pytest.raises(ValueError) as e:
        pkmws.load(missing)
    assert str(e.value) == cli_error("info", missing)


def test_unknown_field_same_message_as_cli(tmp_path):
    doc = json.loads(M1.read_text())
    doc["legs"][1]["rod_lenght"] = doc["legs"][1].pop("rod_length")
    bad = tmp_path / "bad.json"
    bad.write_text(json.dumps(doc))
    with pytest.raises(ValueError) as e:
        pkmws.load(bad)
    assert str(e.value) == cli_error("info", bad)
    assert "legs[1].rod_lenght: unknown field" in str(e.value)
    with pytest.raises(ValueError, match=r"^<dict>: legs\[1\]\.rod_lenght: unknown field"):
        pkmws.load(doc)


def test_bad_inputs_raise_value_error(m1):
    with pytest.raises(ValueError, match="not a JSON document"):
        pkmws.load({"x": float("nan")})
    with pytest.raises(ValueError, match="expected a file path or a dict"):
        pkmws.load(42)
    with pytest.raises(ValueError, match="no such file"):
        pkmws.load("")
    with pytest.raises(ValueError, match="x: must be a finite number"):
        m1.inverse(float("nan"), 0.0)
    with pytest.raises(ValueError, match="q: expected 2 joint values"):
        m1.direct([1.0, 2.0, 3.0])
    with pytest.raises(ValueError, match="bound: expected 'inner' or 'outer'"):
        m1.workspace(bound="middle")
    with pytest.raises(ValueError, match="has no criteria limits"):
        m1.limited_area()


@pytest.mark.parametrize("bad", [np.zeros(5), np.zeros((5, 4)), np.zeros((2, 2, 2)), [[1, 2], [3]], "abc"])
def test_wrong_array_shapes(m1, bad):
    ws = m1.workspace()
    with pytest.raises(ValueError, match=r"^(points|poses): expected"):
        ws.contains(bad)
    with pytest.raises(ValueError, match=r"^poses: expected"):
        m1.inverse_many(bad)
    with pytest.raises(ValueError, match=r"^poses: expected"):
        m1.reachable(bad)


def test_model_errors_are_value_errors():
    pi = pkmws.load(DATA / "pi_joint_prototype.json")
    with pytest.raises(ValueError, match=r"pi_joint_prototype\.json: "):
        pi.workspace()
    real = pkmws.load(DATA / "biglide_real.json")
    with pytest.raises(ValueError, match="pass bound='inner' or bound='outer'"):
        real.workspace()


# ---------------------------------------------------------------- parameters

def test_parameters_get_set_in_place_and_copy(tmp_path):
    m = pkmws.load(M1)
    p = m.parameters
    assert p["legs[1].rod_length"] == 250
    assert "legs[0].stroke[1]" in p and "name" not in p
    assert p.as_dict()["legs[0].reference[0]"] == -100
    other = m.with_parameters({"legs[0].rod_length": 180, "legs[1].rod_length": 180})
    assert other.workspace().area == pytest.approx(21976.49, abs=0.01)  # README table
    assert m.parameters["legs[0].rod_length"] == 250  # with_parameters leaves m unchanged
    p.update({"legs[0].rod_length": 195, "legs[1].rod_length": 195})  # in place
    assert m.parameters["legs[1].rod_length"] == 195
    assert m.workspace().area == pytest.approx(25247.56, abs=0.01)
    # Errors: the loader's one line, the mechanism unchanged.
    with pytest.raises(ValueError) as e:
        m.parameters["legs[1].rod_length"] = -250.0
    doc = m.document
    doc["legs"][1]["rod_length"] = -250.0
    bad = tmp_path / "moma_m1_g0_l250.json"
    bad.write_text(json.dumps(doc))
    assert str(e.value).split(": ", 1)[1] == cli_error("info", bad).split(": ", 1)[1]
    assert m.parameters["legs[1].rod_length"] == 195
    with pytest.raises(ValueError, match=r"'legs\[1\]\.rod_lenght' is not a field of the file"):
        m.parameters["legs[1].rod_lenght"] = 1.0
    with pytest.raises(ValueError, match=r"'legs\[5\]\.rod_length' is not a field of the file"):
        m.parameters["legs[5].rod_length"]
    with pytest.raises(ValueError, match="is not a field path like"):
        m.parameters["legs[x]"]
    with pytest.raises(ValueError, match="is not a number"):
        m.parameters["legs[0].stroke"]
    with pytest.raises(ValueError, match="expected a number"):
        m.parameters["legs[0].rod_length"] = True
    with pytest.raises(ValueError, match=r"legs\[0\]\.branch: "):
        m.parameters["legs[0].branch"] = 1.5


# ---------------------------------------------------------------- kinematics

def test_inverse_direct_roundtrip(m1):
    sols = m1.inverse(0.0, -300.0)
    assert sols[0]["valid"] and len(sols) == 4
    q = sols[0]["joints"]
    poses = [s["pose"] for s in m1.direct(q) if s["valid"]]
    assert len(poses) == 1
    assert poses[0][0] == pytest.approx(0.0, abs=1e-9) and poses[0][1] == pytest.approx(-300.0)
    # A point outside the stroke: flagged, with the reason.
    assert not m1.inverse(0.0, -1000.0)[0]["valid"]
    assert m1.inverse(0.0, -1000.0)[0]["reason"]


def test_evaluate_angles_in_radians(m1):
    e = m1.evaluate(0.0, -300.0)[0]
    assert e["reachable"] and not e["singular"]
    assert all(0 <= a <= math.pi / 2 for a in e["pressure_angle"])
    assert "transmission_angle" in e["extra"] and e["extra"]["transmission_angle"] < math.pi


def test_three_dof_phi_defaults_to_orientation():
    rrp = pkmws.load(DATA / "three_rrp_mitsi.json")
    c = rrp.workspace().inscribed_circle()["center"]
    assert rrp.inverse(*c) == rrp.inverse(c[0], c[1], rrp.orientation)
    assert rrp.inverse(*c)[0]["valid"]
    q = rrp.inverse(*c)[0]["joints"]
    poses = [s["pose"] for s in rrp.direct(q) if s["valid"]]
    assert any(abs(p[0] - c[0]) < 1e-7 and abs(p[1] - c[1]) < 1e-7 and abs(p[2] - rrp.orientation) < 1e-9
               for p in poses)


def test_vectorised_kinematics_match_scalar(m1):
    rng = np.random.default_rng(1)
    (x0, y0), (x1, y1) = m1.workspace().bbox
    pts = np.column_stack([rng.uniform(x0, x1, 200), rng.uniform(y0, y1, 200)])
    q, valid = m1.inverse_many(pts)
    assert q.dtype == np.float64 and q.shape == (200, 2) and valid.dtype == np.bool_ and valid.shape == (200,)
    for i in range(0, 200, 17):
        s = m1.inverse(*pts[i])[0]
        assert valid[i] == s["valid"]
        assert np.allclose(q[i], s["joints"])
    assert np.array_equal(valid, m1.reachable(pts))
    poses, ok = m1.direct_many(q[valid])
    assert poses.shape == (valid.sum(), 3) and ok.all()
    assert np.allclose(poses[:, :2], pts[valid], atol=1e-8)
    ev = m1.evaluate_many(pts)
    assert set(ev) == {"reachable", "jacobian_det", "condition_number", "singular", "pressure_angle",
                       "velocity_ratio"}
    assert np.array_equal(ev["reachable"], valid)
    assert ev["pressure_angle"].shape == (200, 2)
    assert np.isnan(ev["jacobian_det"][~valid]).all()
    i = int(np.flatnonzero(valid)[0])
    assert ev["jacobian_det"][i] == pytest.approx(m1.evaluate(*pts[i])[0]["jacobian_det"])
    # (N, 3): the third column is phi (ignored by a 2-DOF mechanism); int input is converted.
    q3, _ = m1.inverse_many(np.column_stack([pts, np.zeros(200)]))
    assert np.array_equal(q3, q)
    qi, _ = m1.inverse_many(np.array([[0, -300]], dtype=np.int32))
    assert qi.dtype == np.float64 and qi[0, 0] == pytest.approx(m1.inverse(0, -300)[0]["joints"][0])
    assert m1.reachable((0.0, -300.0)) is True


def test_non_contiguous_input(m1):
    ws = m1.workspace()
    rng = np.random.default_rng(2)
    big = rng.uniform(-200, 200, (300, 5))
    big[:, 3] -= 300
    view = big[::3, 2:4]  # strided rows, columns 2 and 3
    assert not view.flags.c_contiguous
    assert np.array_equal(ws.contains(view), ws.contains(np.ascontiguousarray(view)))
    assert np.array_equal(m1.reachable(view), m1.reachable(view.copy()))
    fortran = np.asfortranarray(view)
    assert np.array_equal(m1.inverse_many(fortran)[0], m1.inverse_many(view.copy())[0], equal_nan=True)


# ---------------------------------------------------------------- regions

def test_region_api(m1):
    ws = m1.workspace()
    assert ws.area == pytest.approx(M1_AREA, rel=1e-14)
    lo, hi = m1.workspace_area_bounds()
    assert lo <= ws.area <= hi
    comps = ws.components()
    assert len(comps) == 1 and comps[0].area == pytest.approx(ws.area)
    loops = ws.loops()
    assert len(loops) == 1 and not loops[0].hole
    kinds = {c.kind for c in loops[0].curves}
    assert kinds == {"arc"}  # four circular arcs (README)
    assert len(loops[0].curves) == 4
    assert loops[0].signed_area == pytest.approx(ws.area)
    polys = ws.polyline(0.01)
    assert len(polys) == 1 and polys[0].dtype == np.float64 and polys[0].shape[1] == 2
    x, y = polys[0][:, 0], polys[0][:, 1]
    shoelace = 0.5 * np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y)
    assert shoelace <= ws.area and shoelace == pytest.approx(ws.area, rel=1e-4)  # chords cut off a little
    assert ws.units == "mm" and "36202" in repr(ws)
    assert ws.default_tolerance() > 0


def test_booleans(m1):
    a = m1.workspace()
    b = m1.with_parameters({"legs[0].reference[0]": -60, "legs[1].reference[0]": 140}).workspace()
    union, inter, diff, xor = a | b, a & b, a - b, a ^ b
    assert union.area == pytest.approx(a.area + b.area - inter.area, rel=1e-12)
    assert diff.area == pytest.approx(a.area - inter.area, rel=1e-12)
    assert xor.area == pytest.approx(union.area - inter.area, rel=1e-12)
    assert (a - a).empty and (a - a).area == 0


def test_inscribed(m1):
    ws = m1.workspace()
    c = ws.inscribed_circle()
    assert c["radius"] <= c["radius_upper"] and c["radius"] > 80
    assert ws.contains(c["center"])
    r = ws.inscribed_rectangle()
    assert r["verified"] and r["area"] <= r["area_upper"] <= r["area"] * (1 + 1e-5)
    (x0, y0), (x1, y1) = r["min"], r["max"]
    corners = np.array([[x0, y0], [x1, y0], [x1, y1], [x0, y1]])
    assert ws.contains(corners).all()
    sq = ws.inscribed_rectangle(aspect=1.0)
    assert sq["width"] == pytest.approx(sq["height"], rel=1e-9)
    assert pkmws.Region().inscribed_circle() is None


def test_exports_strings_and_files(m1, tmp_path):
    ws = m1.workspace()
    svg, dxf, wkt, gj, csv = ws.to_svg(), ws.to_dxf(), ws.to_wkt(), ws.to_geojson(), ws.to_csv()
    assert svg.lstrip().startswith("<") and "<path" in svg
    assert "ARC" in dxf and wkt.startswith("MULTIPOLYGON")
    props = json.loads(gj)["features"][0]["properties"]
    assert props["units"] == "mm" and props["area"] == pytest.approx(ws.area)
    assert csv.splitlines()[0].startswith("component,loop,hole,kind")
    for fmt in ("svg", "dxf", "wkt", "geojson", "csv"):
        out = tmp_path / f"ws.{fmt}"
        assert getattr(ws, f"to_{fmt}")(str(out)) is None
        assert out.read_text() == getattr(ws, f"to_{fmt}")()
    with pytest.raises(ValueError, match="tolerance"):
        ws.to_wkt(tolerance=1e-30)
    with pytest.raises(ValueError):
        ws.to_svg(str(tmp_path / "no_such_dir" / "x.svg"))


def test_certified_workspaces():
    real = pkmws.load(DATA / "biglide_real.json")
    inner, outer = real.workspace(bound="inner"), real.workspace(bound="outer")
    lo, hi = real.workspace_area_bounds()
    assert inner.area <= lo <= hi <= outer.area * (1 + 1e-12)
    assert 1056958.5 <= hi and lo <= 1056959.2  # README's certified bounds
    assert hi - lo <= 1e-6 * hi  # the coupler curves traced, not a quadtree


def test_limited_area_matches_cli():
    m = pkmws.load(DATA / "five_bar_dextar_pp_alpha40.json")
    assert m.has_criteria
    lo, hi = m.limited_area()
    assert lo <= hi and (hi - lo) <= 2e-6 * hi
    assert lo <= 0.2246443091 and 0.2246441686 <= hi  # meets the README bounds (both enclose the area)
    # The enclosure as regions (costly for DexTAR: a coarse biglide one).
    vratio = pkmws.load(DATA / "biglide_simplified_vratio2.json")
    inner = vratio.limited_workspace("inner", tolerance=1e-3)
    outer = vratio.limited_workspace("outer", tolerance=1e-3)
    # The exact area, 932941.5282957 mm² (W cut by the strips where both
    # ratios hold: they depend on y only), lies between the enclosures.
    assert 932941.0 * 0.999 < inner.area <= 932941.5283 and 932941.5282 <= outer.area


def test_draw(m1):
    d = m1.draw(0.0, -300.0)
    assert len(d["links"]) >= 2 and d["tool"] == pytest.approx((0.0, -300.0))


# ---------------------------------------------------------------- sweep

def test_sweep_rows_match_the_cli(tmp_path):
    params = [{"name": "rod", "path": ["legs[0].rod_length", "legs[1].rod_length"], "values": [180, 195, 250, -1]}]
    rows = pkmws.sweep(M1, params, metrics=["area", "components"], threads=1)
    assert [r["index"] for r in rows] == [0, 1, 2, 3]
    assert [r["status"] for r in rows] == ["ok", "ok", "ok", "invalid"]
    assert rows[2]["area"] == pytest.approx(M1_AREA, rel=1e-13)
    assert rows[0]["area"] == pytest.approx(21976.49, abs=0.01)
    assert rows[3]["area"] is None and "must be positive" in rows[3]["reason"]
    assert list(rows[0]) == ["index", "rod", "status", "area", "area_lower", "area_upper", "components",
                             "time_ms", "reason"]
    # The same spec through the CLI.
    spec = tmp_path / "s.json"
    spec.write_text(json.dumps({"base": str(M1), "parameters": params, "metrics": ["area", "components"]}))
    out = tmp_path / "s.csv"
    subprocess.run([CLI, "sweep", spec, "-o", out, "--no-timing"], check=True, capture_output=True)
    lines = out.read_text().splitlines()
    header = lines[0].split(",")
    for line, row in zip(lines[1:], rows):
        fields = dict(zip(header, line.split(",", len(header) - 1)))
        if fields["area"]:
            assert float(fields["area"]) == row["area"]
    untimed = [{k: v for k, v in r.items() if k != "time_ms"} for r in pkmws.sweep(spec=spec, threads=2)]
    assert untimed == [{k: v for k, v in r.items() if k != "time_ms"} for r in rows]
    # From a Mechanism or a dict.
    m = pkmws.load(M1)
    rows2 = pkmws.sweep(m, params[:1], metrics=["area"], threads=2)
    assert [r["area"] for r in rows2] == [r["area"] for r in rows]


def test_sweep_errors():
    with pytest.raises(ValueError, match="unknown metric 'volume'"):
        pkmws.sweep(M1, [{"path": "legs[0].rod_length", "values": [200]}], metrics=["volume"])
    with pytest.raises(ValueError, match=r"'legs\[0\]\.rod' is not in the base file"):
        pkmws.sweep(M1, [{"path": "legs[0].rod", "values": [200]}])
    with pytest.raises(ValueError) as e:
        pkmws.sweep(M1, [{"path": "legs[0].rod", "values": [200]}])
    assert "pkmws-sweep-" not in str(e.value)  # no scratch file names
    assert "area" in pkmws.metric_names()


def test_cmake_install_puts_an_importable_package_in_site_packages(tmp_path):
    build_python = next((pathlib.Path(p) for p in os.environ.get("PYTHONPATH", "").split(os.pathsep)
                         if (pathlib.Path(p) / "pkmws" / "__init__.py").exists()), None)
    if build_python is None:
        pytest.skip("the module is not imported from a build tree")
    prefix = tmp_path / "prefix"
    subprocess.run(["cmake", "--install", str(build_python.parent), "--prefix", str(prefix)], check=True,
                   capture_output=True)
    inits = list(prefix.glob("lib/python3*/*-packages/pkmws/__init__.py"))
    assert len(inits) == 1, list(prefix.rglob("__init__.py"))
    site = inits[0].parents[1]
    assert (site / "pkmws" / "__init__.pyi").exists() and (site / "pkmws" / "plot.py").exists()
    env = dict(os.environ, PYTHONPATH=str(site))
    out = subprocess.run([sys.executable, "-c", f"import pkmws; print(pkmws.__file__); "
                          f"print(pkmws.load({str(M1)!r}).workspace().area)"],
                         env=env, check=True, capture_output=True, text=True).stdout.split()
    assert out[0].startswith(str(site)) and float(out[1]) == pytest.approx(M1_AREA, rel=1e-13)
