"""The README's Python example as a figure: MOMA M1's exact workspace drawn by
pkmws.plot (the mechanism at the largest inscribed circle's centre), the two
points the example tests with contains, and the workspace after
m.parameters["legs[1].rod_length"] = 260.

    PYTHONPATH=build/python python3 examples/python/readme_figure.py docs/figures/python_workspace.png

(docs/figures/generate.sh does this); without an argument it writes
python_workspace.png in the working directory (the test).
"""
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import PathPatch  # noqa: E402

import pkmws  # noqa: E402
import pkmws.plot  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[2]
out = sys.argv[1] if len(sys.argv) > 1 else "python_workspace.png"

m = pkmws.load(ROOT / "datasets" / "moma_m1_g0_l250.json")
ws = m.workspace()
points = [[0, -300], [0, 0]]
inside = ws.contains(points)
longer = m.with_parameters({"legs[1].rod_length": 260}).workspace()

fig, ax = plt.subplots(figsize=(6.4, 5.6))
ax.add_patch(PathPatch(pkmws.plot.region_path(longer), facecolor="none", edgecolor="#2e7d32", lw=1.2, ls="--",
                       label=f"legs[1].rod_length = 260: area {longer.area:.6g} mm²"))
pkmws.plot.workspace(m, ax=ax, title="pkmws.plot.workspace(m): " + m.name)
for (x, y), flag in zip(points, inside):
    ax.plot([x], [y], "P" if flag else "X", ms=9, color="#2e7d32" if flag else "k", ls="",
            label=f"contains(({x}, {y})) = {bool(flag)}")
(x0, y0), (x1, y1) = longer.bbox
lo, hi = ax.get_ylim()
ax.set_ylim(min(lo, y0 - 10), max(hi, y1 + 10))
ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.13), ncol=2, fontsize="small")
ax.title.set_fontsize("medium")
fig.tight_layout()
fig.savefig(out, dpi=100)
print(f"wrote {out}")

assert list(inside) == [True, False]
assert longer.area > ws.area
assert pathlib.Path(out).stat().st_size > 10_000
