"""The pkmws Python module does not leak: many calls of cheap functions
(10^5) and of loads and workspaces (10^3) leave the resident set size where
it was after a warm-up, to a few MB (allocator slack, Python's free lists).

RSS from /proc/self/statm (Linux); needs the module on PYTHONPATH."""
import gc
import os

import numpy as np
import pytest

import pkmws
from conftest import SOURCE_DIR

DATA = SOURCE_DIR / "datasets"
M1 = DATA / "moma_m1_g0_l250.json"
FIVE_BAR = DATA / "five_bar_dextar_pp_alpha40.json"
BOUND_MB = 4.0

pytestmark = pytest.mark.skipif(not os.path.exists("/proc/self/statm"), reason="needs /proc/self/statm")


def rss_mb():
    with open("/proc/self/statm") as f:
        resident_pages = int(f.read().split()[1])
    return resident_pages * os.sysconf("SC_PAGE_SIZE") / 2**20


def growth_mb(fn, n, warm_up=None):
    """RSS growth (MB) over n calls of fn, measured after warm_up calls (default n // 10)."""
    for _ in range(n // 10 if warm_up is None else warm_up):
        fn()
    gc.collect()
    before = rss_mb()
    for _ in range(n):
        fn()
    gc.collect()
    grown = rss_mb() - before
    print(f"{getattr(fn, '__name__', fn)}: {n} calls, RSS {before:.1f} MB -> {before + grown:.1f} MB")
    return grown


@pytest.fixture(scope="module")
def m1():
    return pkmws.load(M1)


def test_contains_on_a_point(m1):
    ws = m1.workspace()
    assert growth_mb(lambda: ws.contains((0.0, -300.0)), 100_000) < BOUND_MB


def test_contains_on_an_array(m1):
    ws = m1.workspace()
    pts = np.random.default_rng(0).uniform(-300, 300, (100, 2))
    assert growth_mb(lambda: ws.contains(pts), 10_000) < BOUND_MB


def test_inverse(m1):
    assert growth_mb(lambda: m1.inverse(0.0, -300.0), 100_000) < BOUND_MB


def test_vectorised_kinematics():
    m = pkmws.load(FIVE_BAR)
    poses = np.random.default_rng(1).uniform(-0.3, 0.3, (100, 2))

    def calls():
        m.evaluate_many(poses)
        q, _ = m.inverse_many(poses)
        m.direct_many(np.nan_to_num(q))
        m.reachable(poses)

    assert growth_mb(calls, 2_000) < BOUND_MB


def test_load_and_workspace():
    def calls():
        ws = pkmws.load(M1).workspace()
        ws.components()
        ws.loops()

    assert growth_mb(calls, 1_000) < BOUND_MB


def test_load_from_dict_and_parameters(m1):
    doc = m1.document

    def calls():
        m = pkmws.load(doc)
        m.parameters["legs[1].rod_length"] = 260
        m.workspace().area

    assert growth_mb(calls, 1_000) < BOUND_MB


def test_errors():
    bad = {"mechanism": "moma"}

    def calls():
        for source in (bad, DATA / "no_such_file.json"):
            with pytest.raises(ValueError):
                pkmws.load(source)

    assert growth_mb(calls, 10_000) < BOUND_MB


def test_booleans_and_exports(m1):
    a = m1.workspace()
    b = pkmws.load(DATA / "moma_m4_gm5_gp5_l250.json").workspace()

    def calls():
        (a & b).area
        (a - b).polyline()
        a.to_wkt()

    assert growth_mb(calls, 300) < BOUND_MB
