"""pkmws chart: the drawn lines read back to the CSV values (per-panel
data-transform), one legend entry per file, marked x values as guides and in
bold in the Markdown tables, bounds as midpoint ± half-width enclosing them;
bad input is one line with no file written. The MOMA program-of-building
sweeps agree with `pkmws area` of the bundled datasets at 180/195/250 mm."""
import csv
import json
import re
import shutil
import subprocess

import pytest

import svgfig
from conftest import SOURCE_DIR, run

HEADER = "index,rod,status,area,width_lower,width_upper,reason\n"


def write_csv(path, rows):
    path.write_text(HEADER + "".join(f"{i},{x},{s},{a},{lo},{hi},\n" for i, (x, s, a, lo, hi) in enumerate(rows)))
    return path


@pytest.fixture
def sweeps(tmp_path):
    a = write_csv(tmp_path / "a.csv", [(150, "ok", 1000.0, 10, 12), (200, "ok", 1500.25, 11, 13),
                                       (250, "ok", 2100.5, 12, 14)])
    b = write_csv(tmp_path / "b.csv", [(150, "ok", 800.0, "", ""), (200, "failed", "", "", ""),
                                       (250, "ok", 1900.0, "", "")])
    return a, b


def test_lines_legend_and_marks(sweeps, tmp_path):
    a, b = sweeps
    fig = tmp_path / "fig.svg"
    run("chart", f"{a}=Alpha one", f"{b}=Beta", "--x", "rod", "--y", "area", "--y", "width",
        "--y-label", "area (mm²)", "--y-label", "width (mm)", "--mark", "200", "--mark-label", "bundled",
        "-o", fig)
    root = svgfig.load(fig)
    panels = svgfig.by_class(root, "panel", "g")
    assert len(panels) == 2
    x0, y0, sx, sy = map(float, panels[0].get("data-transform").split())
    lines = {pl.get("data-label"): [((px - x0) / sx, (y0 - py) / sy) for px, py in svgfig.points(pl.get("points"))]
             for pl in panels[0].iter(svgfig.NS + "polyline")}
    # Alpha: one line through the three designs; Beta: the failed design breaks it (two single points, no line).
    assert [p[0] for p in lines["Alpha one"]] == pytest.approx([150, 200, 250], abs=0.02 / sx)
    assert [p[1] for p in lines["Alpha one"]] == pytest.approx([1000.0, 1500.25, 2100.5], abs=0.02 / sy)
    beta = [pl for pl in panels[0].iter(svgfig.NS + "polyline") if pl.get("data-label") == "Beta"]
    assert len(beta) == 2
    # The bounds panel has Alpha only (Beta has no values there): midpoints drawn.
    x0, y0, sx, sy = map(float, panels[1].get("data-transform").split())
    (alpha,) = list(panels[1].iter(svgfig.NS + "polyline"))
    assert [(y0 - py) / sy for _, py in svgfig.points(alpha.get("points"))] == pytest.approx([11, 12, 13], abs=0.02 / sy)
    legend = svgfig.legend_texts(root)
    assert legend == ["Alpha one", "Beta", "bundled"]
    marks = [t.text for t in svgfig.by_class(root, "x-mark", "text")]
    assert marks == ["200", "200"]
    if shutil.which("rsvg-convert"):
        subprocess.run(["rsvg-convert", "-w", "800", str(fig), "-o", str(tmp_path / "fig.png")], check=True)


def test_markdown_tables(sweeps, tmp_path):
    a, b = sweeps
    md = tmp_path / "t.md"
    run("chart", f"{a}=Alpha", f"{b}=Beta", "--x", "rod", "--y", "area", "--y", "width", "--mark", "200,250",
        "--markdown", md)
    text = md.read_text()
    tables = [t for t in text.split("#### ") if t.strip()]
    assert len(tables) == 2
    rows = [ln for ln in tables[0].splitlines() if ln.startswith("|")]
    assert rows[0] == "| rod | 150 | **200** | **250** |"
    assert rows[2] == "| Alpha | 1000 | **1500** | **2100** |"  # %.0f: 2100.5 rounds to even
    assert rows[3] == "| Beta | 800 | – | **1900** |"
    assert "certified bounds" in tables[1] and "Beta" not in tables[1]
    cells = [c.strip().strip("*") for c in [ln for ln in tables[1].splitlines() if ln.startswith("| Alpha")][0].split("|")[2:-1]]
    for cell, (lo, hi) in zip(cells, [(10, 12), (11, 13), (12, 14)]):
        v, h = map(float, re.split(" ± ", cell))
        assert v - h <= lo and hi <= v + h and h <= (hi - lo)


def one_line_error(*args):
    r = run(*args, check=False)
    assert r.returncode == 2
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("pkmws: error: "), r.stderr
    return lines[0]


def test_bad_input(sweeps, tmp_path):
    a, _ = sweeps
    fig, md = tmp_path / "f.svg", tmp_path / "f.md"
    assert "--y" in one_line_error("chart", a, "--x", "rod", "--y", "volume", "-o", fig, "--markdown", md)
    assert "--x" in one_line_error("chart", a, "--x", "length", "--y", "area", "-o", fig)
    assert "-o" in one_line_error("chart", a, "--x", "rod", "--y", "area")
    two = tmp_path / "two.csv"
    two.write_text(HEADER + "0,150,ok,1,,,\n1,150,ok,2,,,\n")
    assert "second design" in one_line_error("chart", two, "--x", "rod", "--y", "area", "-o", fig)
    assert not fig.exists() and not md.exists()


@pytest.mark.parametrize("config,files", [("m2", "moma_m2_l{}.json"), ("m5_gp5_gm5", "moma_m5_gp5_gm5_l{}.json")])
def test_program_sweeps_match_the_bundled_datasets(tmp_path, config, files):
    spec = SOURCE_DIR / "examples" / "sweeps" / f"program_{config}.json"
    out = tmp_path / "p.csv"
    run("sweep", spec, "-o", out, "--no-timing")
    rows = {float(r["rod_length"]): r for r in csv.DictReader(out.open())}
    assert sorted(rows) == sorted(set(range(150, 301, 10)) | {195})
    for rod in (180, 195, 250):
        ref = json.loads(run("area", SOURCE_DIR / "datasets" / files.format(rod), "--json").stdout)
        assert float(rows[rod]["area"]) == pytest.approx(ref["area"], rel=1e-12)
        rect = max(c["inscribed_rectangle"]["area"] for c in ref["components"])
        assert float(rows[rod]["rectangle_area"]) == pytest.approx(rect, rel=2e-4)
