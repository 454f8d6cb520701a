"""pkmws sweep under mpirun: the same file as a serial run, byte for byte;
resume and bad input behave as without MPI."""
import json
import os
import pathlib
import subprocess
import sys

import pytest

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1]))
from conftest import CLI, SOURCE_DIR, run  # noqa: E402

MPIEXEC = os.environ.get("PKMWS_MPIEXEC") or "mpirun"
BASE = SOURCE_DIR / "datasets" / "moma_m1_g0_l250.json"


def mpirun(n, *args):
    return subprocess.run([MPIEXEC, "-np", str(n), "--oversubscribe", CLI, *map(str, args)],
                          capture_output=True, text=True, timeout=600)


def spec_file(tmp_path, metrics=("area", "components", "inscribed_rectangle")):
    spec = {
        "base": str(BASE),
        "parameters": [
            {"name": "rod_length", "path": ["legs[0].rod_length", "legs[1].rod_length"],
             "values": [-5, 40, 150, 180, 195, 220, 250, 300]},
            {"path": "legs[1].guide_angle_deg", "values": [265, 270]},
        ],
        "metrics": list(metrics),
    }
    p = tmp_path / "spec.json"
    p.write_text(json.dumps(spec))
    return p


@pytest.mark.parametrize("rank0", ["auto", "evaluate", "collect"])
def test_three_ranks_write_the_serial_file(tmp_path, rank0):
    spec = spec_file(tmp_path)
    serial, distributed = tmp_path / "serial.csv", tmp_path / "mpi.csv"
    run("sweep", spec, "-o", serial, "--threads", "1", "--no-timing")
    r = mpirun(3, "sweep", spec, "-o", distributed, "--no-timing", "--json", tmp_path / "mpi.json",
               "--mpi-rank0", rank0)
    assert r.returncode == 0, r.stderr
    assert distributed.read_bytes() == serial.read_bytes()
    assert r.stdout.count("designs (") == 1  # only rank 0 reports
    statuses = [row["status"] for row in json.loads((tmp_path / "mpi.json").read_text())["rows"]]
    assert statuses[:4] == ["invalid", "invalid", "empty", "empty"] and statuses[4:] == ["ok"] * 12


def test_resume_under_mpi(tmp_path):
    spec = spec_file(tmp_path, metrics=("area",))
    full = tmp_path / "full.csv"
    run("sweep", spec, "-o", full, "--no-timing")
    timed = tmp_path / "timed.csv"
    run("sweep", spec, "-o", timed)
    lines = timed.read_text().splitlines()
    out = tmp_path / "out.csv"
    (tmp_path / "out.csv.partial").write_text("\n".join(lines[:6]) + "\n")
    r = mpirun(2, "sweep", spec, "-o", out, "--resume", "--no-timing")
    assert r.returncode == 0, r.stderr
    assert "11 evaluated" in r.stdout
    assert out.read_bytes() == full.read_bytes()


def test_bad_sweep_file_is_one_line_and_status_2(tmp_path):
    spec = tmp_path / "bad.json"
    spec.write_text(json.dumps({"base": str(BASE), "parameters": [{"path": "legs[9].rod_length", "values": [1]}]}))
    out = tmp_path / "out.csv"
    r = mpirun(3, "sweep", spec, "-o", out)
    assert r.returncode == 2
    errors = [line for line in r.stderr.splitlines() if line.startswith("pkmws: error:")]
    assert len(errors) == 1 and "parameters[0].path" in errors[0]
    assert not out.exists()
