"""Per-call overhead of the pkmws Python module against the same C++ calls.

Run from the repository after `make build`:
    PYTHONPATH=build/python python3 benchmarks/python_overhead.py
Prints one table row per operation: time per call (or per point) from Python
-- a scalar call per point, and one vectorised call over a numpy array --
against the C++ loop the module runs (timed inside the extension, no Python).
"""
import pathlib
import time

import numpy as np

import pkmws
from pkmws import _pkmws

ROOT = pathlib.Path(__file__).resolve().parents[1]
m = pkmws.load(ROOT / "datasets" / "moma_m1_g0_l250.json")
ws = m.workspace()
(x0, y0), (x1, y1) = ws.bbox
rng = np.random.default_rng(0)
N = 20000
pts = np.column_stack([rng.uniform(x0, x1, N), rng.uniform(y0, y1, N)])


def per_call(fn, n, repeat=3):
    best = float("inf")
    for _ in range(repeat):
        t = time.perf_counter()
        fn()
        best = min(best, (time.perf_counter() - t) / n)
    return best


rows = []
listed = [tuple(p) for p in pts]
cpp = min(_pkmws._time_contains(ws, pts) for _ in range(3))
rows.append(("Region.contains, scalar (x, y) per call", per_call(lambda: [ws.contains(p) for p in listed], N), cpp))
rows.append(("Region.contains, (N, 2) array, per point", per_call(lambda: ws.contains(pts), N), cpp))
n_inv = 20000
cpp_inv = min(_pkmws._time_inverse(m, 0.0, -300.0, n_inv) for _ in range(3))
rows.append(("Mechanism.inverse(x, y), scalar -> dicts", per_call(lambda: [m.inverse(0.0, -300.0) for _ in range(n_inv)], n_inv), cpp_inv))
rows.append(("Mechanism.inverse_many, (N, 2), per pose", per_call(lambda: m.inverse_many(pts), N), cpp_inv))
rows.append(("Mechanism.reachable, (N, 2), per pose", per_call(lambda: m.reachable(pts), N), float("nan")))
rows.append(("Mechanism.workspace().area, repeated", per_call(lambda: m.workspace().area, 200), float("nan")))

print(f"{'operation':<44} {'Python (µs)':>12} {'C++ (µs)':>10} {'overhead':>10}")
for name, py, c in rows:
    over = f"{py / c:9.1f}x" if c == c else "-"
    cs = f"{c * 1e6:10.3f}" if c == c else f"{'-':>10}"
    print(f"{name:<44} {py * 1e6:12.3f} {cs} {over:>10}")
