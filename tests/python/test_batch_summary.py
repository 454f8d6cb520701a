"""`pkmws batch` (what `make demo` runs) reports, for every bundled file, the
area or certified interval of `pkmws area --json`, and each figure's caption
states those numbers; every figure renders with rsvg-convert."""
import json
import subprocess

import pytest

from conftest import DATASETS, SOURCE_DIR, run
import svgfig

# One file of every kind (exact MOMA, certified biglide, criteria-limited
# five-bar, PAMINSA and biglide, machines with bodies, 3-DOF, no planar
# workspace): the whole of datasets/ takes `make demo` minutes, too long for a
# unit test; PKMWS_BATCH_ALL=1 runs every bundled file.
KINDS = ["moma_m3_l180", "biglide_real", "five_bar_dextar_pm_alpha40", "three_rpr_paminsa_phi25_r200",
         "biglide_simplified_vratio2", "machine_moma_m1", "three_rrp_mitsi", "three_rpr_prismatic",
         "five_bar_dextar_pp", "pi_joint_prototype"]
import os
if os.environ.get("PKMWS_BATCH_ALL") == "1":
    FILES = DATASETS
else:
    FILES = [SOURCE_DIR / "datasets" / f"{k}.json" for k in KINDS]


@pytest.fixture(scope="module")
def batch(tmp_path_factory):
    out = tmp_path_factory.mktemp("batch")
    r = run("batch", *FILES, "--out", out, timeout=1800)
    rows = json.loads((out / "summary.json").read_text())
    return out, rows, r.stdout, (out / "summary.md").read_text()


def close(a, b, rel=1e-9):
    return abs(a - b) <= rel * max(abs(a), abs(b))


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.stem)
def test_batch_row_equals_area_json(batch, path):
    out, rows, stdout, md = batch
    (row,) = [r for r in rows if r["file"] == str(path)]
    if "figure" not in row:
        # no planar workspace (a lone Pi-joint): area fails the same way
        assert run("area", path, "--json", check=False).returncode == 2
        return
    rep = json.loads(run("area", path, "--json").stdout)
    assert row["method"] == rep["method"]
    for key in ("area", "area_lower", "area_upper", "real_area_lower", "real_area_upper"):
        if key in rep:
            assert row[key] == rep[key], key
    assert "time_ms" in row
    # summary.md: the same area in the row of this file
    (line,) = [ln for ln in md.splitlines() if ln.startswith(f"| {path.stem} |")]
    cells = [c.strip() for c in line.split("|")]
    assert close(float(cells[4]), rep["area"], 1e-9)
    # the caption states the same numbers
    root = svgfig.load(out / row["figure"])
    nums = svgfig.numbers(svgfig.caption(root))
    if rep["method"] == "exact":
        assert any(close(x, rep["area"]) for x in nums), svgfig.caption(root)
    else:
        assert any(close(x, rep["area_lower"]) for x in nums), svgfig.caption(root)
        assert any(close(x, rep["area_upper"]) for x in nums), svgfig.caption(root)
    for key in ("real_area_lower", "real_area_upper"):
        if key in rep:
            assert any(close(x, rep[key]) for x in nums), key
    assert "seed" not in (out / row["figure"]).read_text().lower()
    png = out / (path.stem + ".png")
    r = subprocess.run(["rsvg-convert", "-w", "300", str(out / row["figure"]), "-o", str(png)],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr


def test_summary_names_its_time_column(batch):
    _, _, _, md = batch
    header = md.splitlines()[0]
    assert "compute time (ms)" in header
    assert "compute time: computation: workspace, area" in md
