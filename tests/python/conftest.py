"""Shared fixtures for the Python tests: the CLI, the sources, a runner."""
import os
import pathlib
import subprocess

import pytest

CLI = os.environ.get("PKMWS_CLI", str(pathlib.Path(__file__).resolve().parents[2] / "build/bin/pkmws"))
SOURCE_DIR = pathlib.Path(os.environ.get("PKMWS_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
DATASETS = sorted((SOURCE_DIR / "datasets").glob("*.json"))


def run(*args, check=True, timeout=600):
    """Runs `pkmws ARGS...`; returns the CompletedProcess (text mode)."""
    r = subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=timeout)
    if check and r.returncode != 0:
        raise AssertionError(f"pkmws {' '.join(map(str, args))} exited {r.returncode}: {r.stderr.strip()}")
    return r


@pytest.fixture
def pkmws():
    return run
