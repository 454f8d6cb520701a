"""Replays the fuzz regression corpus (tests/fuzz/README.md): every subcommand
on every corpus file gives a result or one line on stderr and exit status 2,
within a time bound, never a signal; JSON reports hold no null without its
reason."""
import json
import subprocess

import pytest

from conftest import CLI, SOURCE_DIR
from test_reliability import bare_nulls

CORPUS = sorted((SOURCE_DIR / "tests/fuzz/corpus").glob("*.json"))
BOUND = "1"  # --max-time of the certified commands (seconds)
TIMEOUT = 120  # a hang fails the test (sanitizer builds are ~10x slower)


def no_constant(name):
    raise AssertionError(f"{name} in a JSON report")


def commands(out):
    # (arguments after FILE, prints JSON?)
    return [
        (["info", "--json"], True),
        (["area", "--json", "--max-time", BOUND], True),
        (["export", "-f", "svg", "-o", out / "x.svg", "--max-time", BOUND], False),
        (["ik", "0", "0", "0", "--json"], True), (["ik", "0", "0", "--json"], True),
        (["eval", "0", "0", "0", "--json"], True), (["eval", "0.1", "-0.1", "--json"], True),
        (["dk", "0", "0", "0", "--json"], True), (["dk", "0.5", "-0.5", "--json"], True),
        (["grid", "--cells", "16", "--json"], True),
        (["levels", "--criterion", "pressure_angle", "--levels", "30,60", "--tolerance", "1e-3", "--json",
          "--max-time", BOUND], True),
        (["levels", "--criterion", "reaction", "--levels", "150", "--tolerance", "1e-3", "--json",
          "--max-time", BOUND], True),
        (["levels", "--criterion", "velocity_ratio", "--levels", "1.5", "--tolerance", "1e-3", "--json",
          "--max-time", BOUND], True),
        (["explain", "0", "0", "--json"], True),
        (["plot", "--out", out], False),
    ]


def test_corpus_is_there():
    names = {p.name for p in CORPUS}
    for expected in ["nested_arrays_100000.json", "duplicate_key_nested.json", "three_rpr_collinear_base.json",
                     "three_rpr_zero_load.json", "three_rpr_negative_zero_window.json",
                     "three_rpr_singular_everywhere.json", "moma_huge_numbers.json"]:
        assert expected in names


@pytest.mark.parametrize("path", CORPUS, ids=lambda p: p.stem)
def test_every_command_on_a_corpus_file(path, tmp_path):
    for args, prints_json in commands(tmp_path):
        argv = [CLI, args[0], path, *args[1:]]
        r = subprocess.run(list(map(str, argv)), capture_output=True, text=True, timeout=TIMEOUT)
        what = f"pkmws {' '.join(map(str, args))} {path.name}"
        assert r.returncode in (0, 2), f"{what}: exit {r.returncode}: {r.stderr[-3000:]}"
        if r.returncode == 2:
            lines = r.stderr.strip("\n").split("\n")
            assert len(lines) == 1 and lines[0].startswith("pkmws: error: "), f"{what}: {r.stderr[-1000:]}"
            continue
        if prints_json:
            j = json.loads(r.stdout, parse_constant=no_constant)  # NaN / Infinity are not JSON
            assert bare_nulls(j) == [], f"{what}: {bare_nulls(j)}"
    leftovers = [p.name for p in tmp_path.rglob("*") if "partial" in p.name or ".tmp-" in p.name]
    assert leftovers == []


def test_singular_everywhere_is_answered_at_once():
    # The answer is known: no position holds a load, the limited area is 0.
    r = subprocess.run([CLI, "area", "--json", str(SOURCE_DIR / "tests/fuzz/corpus/three_rpr_singular_everywhere.json")],
                       capture_output=True, text=True, timeout=20)
    assert r.returncode == 0, r.stderr
    j = json.loads(r.stdout)
    assert j["area_lower"] == 0.0 and j["area_upper"] == 0.0
    assert "singular at every position" in j["note"]
    assert "stopped" not in j
