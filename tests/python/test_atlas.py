"""pkmws atlas: contour maps of sweep CSVs. Isolines of a linear field must lie
on their straight lines; bands, labels, the best design and missing designs
are drawn; bad input is one line and exit 2."""
import re
import subprocess
import xml.etree.ElementTree as ET

from conftest import run

NS = {"s": "http://www.w3.org/2000/svg"}


def write_csv(path, rows):
    lines = ["index,a,b,status,z,time_ms,reason"]
    for k, (a, b, status, z) in enumerate(rows):
        lines.append(f"{k},{a},{b},{status},{'' if z is None else repr(z)},1.0,{'' if status == 'ok' else 'bad'}")
    path.write_text("\n".join(lines) + "\n")


def frame(root):
    r = next(e for e in root.iter("{http://www.w3.org/2000/svg}rect") if e.get("stroke") == "black")
    return tuple(float(r.get(k)) for k in ("x", "y", "width", "height"))


def test_isolines_of_a_linear_field_are_straight(tmp_path):
    xs = [0, 1, 2, 3, 4, 5]
    ys = [0, 0.5, 1.0, 1.5, 2.0]
    rows = [(x, y, "ok", x + 2 * y) for x in xs for y in ys]
    csv = tmp_path / "s.csv"
    write_csv(csv, rows)
    svg = tmp_path / "a.svg"
    run("atlas", csv, "--x", "a", "--y", "b", "--metric", "z", "-o", svg)
    root = ET.parse(svg).getroot()
    L, T, W, H = frame(root)
    lines = [p for p in root.iter("{http://www.w3.org/2000/svg}path") if p.get("fill") == "none"]
    assert lines, "no isolines"
    labels = {float(t.text.replace("\u2009", "").replace("\u2212", "-"))
              for t in root.iter("{http://www.w3.org/2000/svg}text")
              if t.get("stroke") == "white" and re.fullmatch(r"[\d.\u2009\u2212]+", t.text or "")}
    checked = 0
    for p in lines:
        pts = [tuple(map(float, m)) for m in re.findall(r"[ML]([-\d.]+) ([-\d.]+)", p.get("d"))]
        values = set()
        for px_, py_ in pts:
            x = (px_ - L) / W * 5
            y = (T + H - py_) / H * 2
            values.add(round(x + 2 * y, 1))
            checked += 1
        assert len(values) == 1, values  # one level per path, on its line (px rounded to 0.01)
        assert values.pop() in labels | {round(v, 1) for v in labels}
    assert checked > 10
    # Eight or so bands: one filled path each, plus the marker at the largest value.
    fills = [p for p in root.iter("{http://www.w3.org/2000/svg}path") if p.get("fill", "").startswith("#")]
    assert 4 <= len(fills) <= 12
    best = next(root.iter("{http://www.w3.org/2000/svg}circle"))
    assert abs(float(best.get("cx")) - (L + W)) < 0.01 and abs(float(best.get("cy")) - T) < 0.01
    assert subprocess.run(["rsvg-convert", "-o", str(tmp_path / "a.png"), str(svg)]).returncode == 0


def test_missing_designs_are_grey_and_the_minimum_can_be_marked(tmp_path):
    rows = [(x, y, "ok" if (x, y) != (1, 1) else "invalid", None if (x, y) == (1, 1) else (x - 2) ** 2 + y)
            for x in range(5) for y in range(4)]
    csv = tmp_path / "s.csv"
    write_csv(csv, rows)
    svg = tmp_path / "a.svg"
    run("atlas", csv, "--x", "a", "--y", "b", "--metric", "z", "-o", svg, "--minimize")
    text = svg.read_text()
    assert 'fill="#d9d9d9"' in text and "no design" in text
    assert "smallest: 0 at (2, 0)" in text


def test_bad_atlas_input(tmp_path):
    rows = [(x, y, "ok", float(x)) for x in range(3) for y in range(3)]
    csv = tmp_path / "s.csv"
    write_csv(csv, rows)
    out = tmp_path / "a.svg"
    r = run("atlas", csv, "--x", "a", "--y", "nope", "--metric", "z", "-o", out, check=False)
    assert r.returncode == 2 and "--y" in r.stderr and "nope" in r.stderr
    write_csv(csv, rows + [(0, 0, "ok", 1.0)])
    r = run("atlas", csv, "--x", "a", "--y", "b", "--metric", "z", "-o", out, check=False)
    assert r.returncode == 2 and "second design" in r.stderr
    write_csv(csv, [(x, 0, "ok", 1.0) for x in range(3)])
    r = run("atlas", csv, "--x", "a", "--y", "b", "--metric", "z", "-o", out, check=False)
    assert r.returncode == 2 and "2 x 2" in r.stderr
    assert not out.exists()
