"""DexTAR five-bar ([Briot]): a pressure-angle map over a grid of poses.

The largest pressure angle of the two chains, evaluated by the vectorised
Mechanism.evaluate_many over an n x n grid of cell centres covering the
workspace (file's working mode (+1, +1)), drawn with matplotlib's pcolormesh
under the exact workspace outline (pkmws.plot) and the level curve of the
file's limit; saved as five_bar_pressure_angle.png in the working directory.

Checked against the certified criteria-limited area: the cells with
alpha <= alpha_max, times the cell area, lie within the certified interval
limited_area() widened by the grid's resolution (the cells the boundary of
the limited workspace may cross: those with a neighbour on the other side).
"""
import math
import pathlib
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import pkmws  # noqa: E402
import pkmws.plot  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[2]
start = time.perf_counter()
m = pkmws.load(ROOT / "datasets" / "five_bar_dextar_pp_alpha40.json")
limit = math.radians(m.parameters["criteria.max_pressure_angle_deg"])  # the file's degrees -> radians
ws = m.workspace()  # exact reachable workspace (m), the lens of two disks

n = 500
(x0, y0), (x1, y1) = ws.bbox
xs, ys = np.linspace(x0, x1, n + 1), np.linspace(y0, y1, n + 1)  # cell edges
cx, cy = 0.5 * (xs[1:] + xs[:-1]), 0.5 * (ys[1:] + ys[:-1])  # cell centres
X, Y = np.meshgrid(cx, cy)
ev = m.evaluate_many(np.column_stack([X.ravel(), Y.ravel()]))
pa = ev["pressure_angle"]  # (n*n, 2) radians, NaN where unreachable
alpha = np.full(len(pa), np.nan)
ok = ev["reachable"]
alpha[ok] = np.abs(pa[ok]).max(axis=1)
A = alpha.reshape(n, n)

# The certified criteria-limited area and the grid's estimate.
lower, upper = m.limited_area()
cell = (xs[1] - xs[0]) * (ys[1] - ys[0])
grid_area = np.count_nonzero(A <= limit) * cell
# Grid resolution: the cells on the boundary of the {alpha <= limit} mask (a
# 4-neighbour on the other side), where the level curve or the workspace
# boundary may cross; each may be misclassified by at most its area.
mask = np.pad(A <= limit, 1)
edge = np.zeros_like(mask)
for axis in (0, 1):
    for shift in (1, -1):
        edge |= mask != np.roll(mask, shift, axis=axis)
boundary_cells = np.count_nonzero(edge[1:-1, 1:-1])
tolerance = boundary_cells * cell
print(f"reachable area {ws.area:.6f} m², limited area (alpha <= {math.degrees(limit):g} deg) "
      f"in [{lower:.6f}, {upper:.6f}] m²")
print(f"grid {n} x {n}: {grid_area:.6f} m² (tolerance {tolerance:.6f} m²: {boundary_cells} boundary cells)")
assert lower - tolerance <= grid_area <= upper + tolerance, (grid_area, lower, upper, tolerance)
assert np.all(np.isnan(A[~ok.reshape(n, n)]))
# Poses the exact workspace contains are the ones evaluate_many finds reachable (but for cells on the boundary).
inside = ws.contains(np.column_stack([X.ravel(), Y.ravel()]))
assert np.count_nonzero(inside != ok) <= 4 * n, np.count_nonzero(inside != ok)

fig, ax = plt.subplots(figsize=(7, 6))
mesh = ax.pcolormesh(xs, ys, np.degrees(A), cmap="viridis", vmin=0, vmax=90, shading="flat")
fig.colorbar(mesh, ax=ax, label="largest pressure angle (deg)")
ax.contour(X, Y, np.degrees(A), levels=[math.degrees(limit)], colors="w", linewidths=1.2)
ax.plot([], [], color="w", lw=1.2, label=f"α = {math.degrees(limit):g}° (limit)")
pkmws.plot.workspace(ws, ax=ax, facecolor="none", edgecolor="k",
                     title=f"{m.name}\nlimited area {lower:.4f}…{upper:.4f} m², grid {grid_area:.4f} m²")
ax.title.set_fontsize("small")
ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.12), ncol=2, fontsize="small", facecolor="0.85")
fig.tight_layout()
fig.savefig("five_bar_pressure_angle.png", dpi=100)
elapsed = time.perf_counter() - start
print(f"wrote five_bar_pressure_angle.png ({elapsed:.1f} s)")
assert elapsed < 120, elapsed  # about 5 s on an idle core
