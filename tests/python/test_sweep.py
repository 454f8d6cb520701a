"""pkmws sweep: rows against single-design runs, determinism over threads and
shards, resume after an interruption, invalid and empty designs as rows."""
import csv
import json
import math
import subprocess
import time

import pytest

from conftest import CLI, SOURCE_DIR, run

BASE = SOURCE_DIR / "datasets" / "moma_m1_g0_l250.json"


def write_spec(tmp_path, **extra):
    spec = {
        "base": str(BASE),
        "parameters": [
            {"name": "rod_length", "path": ["legs[0].rod_length", "legs[1].rod_length"],
             "from": 150, "to": 300, "steps": 4},
            {"path": "legs[1].guide_angle_deg", "values": [265, 270, 275]},
        ],
        "metrics": ["area", "components", "inscribed_circle", "inscribed_rectangle"],
    }
    spec.update(extra)
    p = tmp_path / "spec.json"
    p.write_text(json.dumps(spec))
    return p


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def test_rows_match_single_design_runs(tmp_path):
    spec = write_spec(tmp_path)
    out = tmp_path / "out.csv"
    run("sweep", spec, "-o", out, "--json", tmp_path / "out.json")
    rows = read_csv(out)
    assert [int(r["index"]) for r in rows] == list(range(12))
    # Grid order: the first parameter varies slowest.
    assert [float(r["rod_length"]) for r in rows[:3]] == [150.0] * 3
    assert [float(r["legs[1].guide_angle_deg"]) for r in rows[:3]] == [265.0, 270.0, 275.0]
    base = json.loads(BASE.read_text())
    for r in rows:
        assert r["status"] == "ok", r
        doc = json.loads(json.dumps(base))
        for leg in doc["legs"]:
            leg["rod_length"] = float(r["rod_length"])
        doc["legs"][1]["guide_angle_deg"] = float(r["legs[1].guide_angle_deg"])
        f = tmp_path / f"d{r['index']}.json"
        f.write_text(json.dumps(doc))
        single = json.loads(run("area", f, "--json").stdout)
        assert float(r["area"]) == pytest.approx(single["area"], rel=1e-14)
        assert int(r["components"]) == len(single["components"])
        best = max(single["components"], key=lambda c: c["inscribed_rectangle"]["area"])
        assert float(r["rectangle_area"]) == pytest.approx(best["inscribed_rectangle"]["area"], rel=1e-12)
        assert float(r["rectangle_area"]) <= float(r["rectangle_area_upper"])
        assert float(r["rectangle_area"]) < float(r["area"])
    # l = 250, both guides at 270 deg: the bundled M1 file itself.
    m1 = json.loads(run("area", BASE, "--json").stdout)
    row = next(r for r in rows if float(r["rod_length"]) == 250 and float(r["legs[1].guide_angle_deg"]) == 270)
    assert float(row["area"]) == pytest.approx(m1["area"], rel=1e-15)
    data = json.loads((tmp_path / "out.json").read_text())
    assert len(data["rows"]) == 12 and data["rows"][0]["status"] == "ok"
    assert set(data["columns"]) <= set(data["rows"][0])


def test_threads_and_shards_give_the_same_file(tmp_path):
    spec = write_spec(tmp_path, metrics=["area", "components", "inscribed_rectangle"])
    serial, parallel = tmp_path / "s.csv", tmp_path / "p.csv"
    run("sweep", spec, "-o", serial, "--threads", "1", "--no-timing")
    run("sweep", spec, "-o", parallel, "--threads", "2", "--no-timing")
    assert serial.read_bytes() == parallel.read_bytes()
    shards = []
    for i in range(3):
        p = tmp_path / f"shard{i}.csv"
        run("sweep", spec, "-o", p, "--shard", f"{i}/3", "--no-timing")
        shards.append(p)
    merged = tmp_path / "merged.csv"
    run("sweep", "--merge", *shards, "-o", merged)
    assert merged.read_bytes() == serial.read_bytes()
    bad = run("sweep", "--merge", shards[0], shards[0], "-o", tmp_path / "x.csv", check=False)
    assert bad.returncode == 2 and "two shards" in bad.stderr
    assert not (tmp_path / "x.csv").exists()


def test_resume_repeats_and_loses_nothing(tmp_path):
    spec = write_spec(tmp_path, metrics=["area", "components"])
    full = tmp_path / "full.csv"
    run("sweep", spec, "-o", full, "--no-timing")
    # An interrupted run: five finished rows and a sixth cut short by the kill.
    out = tmp_path / "out.csv"
    lines = full.read_text().splitlines()
    timed_run = tmp_path / "timed.csv"
    run("sweep", spec, "-o", timed_run)  # the partial file keeps the time column
    timed = timed_run.read_text().splitlines()
    partial = tmp_path / "out.csv.partial"
    partial.write_text("\n".join([timed[0]] + [timed[i] for i in (1, 4, 7, 8, 12)] + [timed[3][:20]]))
    refused = run("sweep", spec, "-o", out, check=False)
    assert refused.returncode == 2 and "--resume" in refused.stderr
    r = run("sweep", spec, "-o", out, "--resume", "--no-timing")
    assert "7 evaluated" in r.stdout  # 12 designs, 5 already done
    assert out.read_text().splitlines() == lines
    assert not partial.exists()


def test_a_killed_sweep_resumes(tmp_path):
    spec = write_spec(tmp_path, parameters=[
        {"name": "rod_length", "path": ["legs[0].rod_length", "legs[1].rod_length"],
         "from": 150, "to": 300, "steps": 40}], metrics=["area"])
    out = tmp_path / "out.csv"
    p = subprocess.Popen([CLI, "sweep", str(spec), "-o", str(out), "--threads", "1"],
                         stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    partial = tmp_path / "out.csv.partial"
    deadline = time.time() + 60
    while time.time() < deadline and (not partial.exists() or len(partial.read_text().splitlines()) < 4):
        time.sleep(0.01)
    p.kill()
    p.wait()
    if out.exists():  # it finished before the kill: nothing to resume
        return
    done = len(partial.read_text().splitlines()) - 1
    r = run("sweep", spec, "-o", out, "--resume", "--no-timing")
    evaluated = int(r.stdout.split(";")[1].split()[0])
    assert done - 1 <= 40 - evaluated <= done  # the row being written may have been cut
    full = tmp_path / "full.csv"
    run("sweep", spec, "-o", full, "--no-timing")
    assert out.read_bytes() == full.read_bytes()


def test_bad_designs_are_rows(tmp_path):
    spec = write_spec(tmp_path, parameters=[
        {"name": "rod_length", "path": ["legs[0].rod_length", "legs[1].rod_length"],
         "values": [-10, 40, 250]}])
    out = tmp_path / "out.csv"
    run("sweep", spec, "-o", out)
    rows = read_csv(out)
    assert [r["status"] for r in rows] == ["invalid", "empty", "ok"]
    assert "rod_length" in rows[0]["reason"] and "positive" in rows[0]["reason"]
    assert rows[0]["area"] == "" and rows[2]["area"] != ""


def test_sobol_designs_fill_the_box(tmp_path):
    spec = write_spec(tmp_path, sampling="sobol", samples=64, parameters=[
        {"path": "legs[0].rod_length", "from": 200, "to": 300},
        {"path": "legs[1].rod_length", "from": 200, "to": 300}], metrics=["area"])
    out = tmp_path / "out.csv"
    run("sweep", spec, "-o", out, "--no-timing")
    rows = read_csv(out)
    pts = [((float(r["legs[0].rod_length"]) - 200) / 100, (float(r["legs[1].rod_length"]) - 200) / 100) for r in rows]
    assert all(0 <= x < 1 and 0 <= y < 1 for x, y in pts)
    assert len(set(pts)) == 64
    # A (0, m, 2) net: every 1/8 x 1/8 cell holds exactly one of the 64 points.
    cells = {(int(x * 8), int(y * 8)) for x, y in pts}
    assert len(cells) == 64
    again = tmp_path / "again.csv"
    run("sweep", spec, "-o", again, "--no-timing")
    assert again.read_bytes() == out.read_bytes()


def test_task_fit_metric(tmp_path):
    m1 = json.loads(run("area", BASE, "--json").stdout)
    c = m1["components"][0]["inscribed_rectangle"]["box"]
    cx, cy = (c["min"][0] + c["max"][0]) / 2, (c["min"][1] + c["max"][1]) / 2
    spec = write_spec(tmp_path, parameters=[
        {"name": "rod_length", "path": ["legs[0].rod_length", "legs[1].rod_length"], "values": [200, 250]}],
        metrics=["task_fit"], task={"center": [cx, cy], "size": [20, 20]})
    out = tmp_path / "out.csv"
    run("sweep", spec, "-o", out)
    rows = read_csv(out)
    assert rows[1]["task_inside"] == "1" and float(rows[1]["task_margin"]) > 0
    assert float(rows[1]["task_area_outside"]) == 0


@pytest.mark.parametrize("change,field", [
    ({"parameters": []}, "parameters"),
    ({"parameters": [{"path": "legs[5].rod_length", "values": [1]}]}, "parameters[0].path"),
    ({"parameters": [{"path": "legs[0].rod_lenght", "values": [1]}]}, "parameters[0].path"),
    ({"metrics": ["volume"]}, "metrics[0]"),
    ({"metrics": ["task_fit"]}, "task"),
    ({"sampling": "sobol"}, "samples"),
    ({"colour": 1}, "colour"),
])
def test_bad_sweep_files(tmp_path, change, field):
    spec = write_spec(tmp_path, **change)
    out = tmp_path / "out.csv"
    r = run("sweep", spec, "-o", out, check=False)
    assert r.returncode == 2
    assert field in r.stderr and len(r.stderr.strip().splitlines()) == 1
    assert not out.exists()


def _raster_rectangle(poly, n):
    """Largest all-inside axis-aligned rectangle of an n x n raster of a
    shapely polygon (cells whose corners and centre are inside), by the
    histogram method: independent of pkmws's branch and bound."""
    import numpy as np
    from shapely import vectorized
    x0, y0, x1, y1 = poly.bounds
    xs, ys = np.linspace(x0, x1, n + 1), np.linspace(y0, y1, n + 1)
    gx, gy = np.meshgrid(xs, ys, indexing="ij")
    corner = vectorized.contains(poly, gx, gy)
    cx, cy = np.meshgrid((xs[:-1] + xs[1:]) / 2, (ys[:-1] + ys[1:]) / 2, indexing="ij")
    cell = corner[:-1, :-1] & corner[1:, :-1] & corner[:-1, 1:] & corner[1:, 1:] & vectorized.contains(poly, cx, cy)
    dx, dy = (x1 - x0) / n, (y1 - y0) / n
    height = [0] * n
    best = 0.0
    for j in range(n):
        for i in range(n):
            height[i] = height[i] + 1 if cell[i, j] else 0
        stack = []
        for i in range(n + 1):
            h = height[i] if i < n else 0
            while stack and height[stack[-1]] >= h:
                top = height[stack.pop()]
                left = stack[-1] + 1 if stack else 0
                best = max(best, top * dy * (i - left) * dx)
            stack.append(i)
    return best


def test_rectangle_at_any_angle_against_rasters_of_the_turned_workspace(tmp_path):
    import shapely.wkt
    from shapely import affinity
    spec = write_spec(tmp_path, metrics=["inscribed_rectangle", "inscribed_rectangle_any_angle"],
                      rectangle_precision=1e-4)
    spec_doc = json.loads(spec.read_text())
    spec_doc["parameters"] = [{"path": "legs[1].rod_length", "values": [180]},
                              {"path": "legs[1].guide_angle_deg", "values": [275]}]
    spec.write_text(json.dumps(spec_doc))
    out = tmp_path / "out.csv"
    run("sweep", spec, "-o", out)
    (row,) = read_csv(out)
    assert row["status"] == "ok", row
    turned, upper = float(row["turned_rectangle_area"]), float(row["turned_rectangle_area_upper"])
    angle = float(row["turned_rectangle_angle_deg"])
    assert 0.0 <= angle < 90.0
    assert float(row["turned_rectangle_width"]) * float(row["turned_rectangle_height"]) == pytest.approx(turned, rel=1e-12)
    assert turned >= float(row["rectangle_area"]) * (1 - 1e-9)  # never below the axis-aligned table
    assert upper - turned <= 1e-4 * upper * (1 + 1e-9)
    # The same design's boundary in WKT (polylines inside the exact region),
    # turned by -t for t every 3 deg and near the angle found: no raster
    # rectangle beats the bound, and the best of them comes close to the area.
    doc = json.loads(BASE.read_text())
    doc["legs"][1]["rod_length"] = 180.0
    doc["legs"][1]["guide_angle_deg"] = 275.0
    design = tmp_path / "d.json"
    design.write_text(json.dumps(doc))
    wkt = tmp_path / "w.wkt"
    run("export", design, "-f", "wkt", "-o", wkt, "--tolerance", "1e-3")
    ws = shapely.wkt.loads(wkt.read_text())
    n = 160
    w, h = float(row["turned_rectangle_width"]), float(row["turned_rectangle_height"])
    best = 0.0
    for t in [3.0 * k for k in range(30)] + [angle + 0.25 * k for k in range(-4, 5)]:
        p = affinity.rotate(ws, -t, origin=(0, 0))
        best = max(best, _raster_rectangle(p, n))
        x0, y0, x1, y1 = p.bounds
        # A rectangle snapped inward to the raster loses at most a cell's
        # width on each side.
        snap = 2 * (w + h) * max(x1 - x0, y1 - y0) / n
    assert best <= upper + snap
    assert turned <= best + 1.5 * snap
