"""MOMA M1: workspace area and usable table (largest inscribed rectangle)
against the rod length, both rods tied -- a sweep table (pandas-ready rows)
and its matplotlib plot (moma_rod_sweep.png in the working directory)."""
import pathlib

import pkmws

ROOT = pathlib.Path(__file__).resolve().parents[2]
base = ROOT / "datasets" / "moma_m1_g0_l250.json"

rows = pkmws.sweep(
    base,
    [{"name": "rod_length", "path": ["legs[0].rod_length", "legs[1].rod_length"], "from": 150, "to": 300,
      "steps": 7}],
    metrics=["area", "inscribed_rectangle"],
)
print(f"{'rod (mm)':>9} {'area (mm²)':>12} {'table (mm)':>17} {'status':>7}")
for r in rows:
    table = f"{r['rectangle_width']:.1f} x {r['rectangle_height']:.1f}" if r["status"] == "ok" else "-"
    area = f"{r['area']:.2f}" if r["area"] is not None else "-"
    print(f"{r['rod_length']:9.1f} {area:>12} {table:>17} {r['status']:>7}")

# The sweep's area is the exact one of the design itself.
m = pkmws.load(base)
m.parameters.update({"legs[0].rod_length": 250, "legs[1].rod_length": 250})
r250 = next(r for r in rows if r["rod_length"] == 250)
assert abs(r250["area"] - m.workspace().area) < 1e-9 * r250["area"]
areas = [r["area"] for r in rows if r["status"] == "ok"]
assert areas == sorted(areas), "longer rods reach more"

# The sweep as a plot: area and the usable table's area against the rod length.
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ok = [r for r in rows if r["status"] == "ok"]
rod = [r["rod_length"] for r in ok]
fig, ax = plt.subplots(figsize=(6, 4))
ax.plot(rod, [r["area"] / 1e3 for r in ok], "o-", label="workspace area")
ax.plot(rod, [r["rectangle_width"] * r["rectangle_height"] / 1e3 for r in ok], "s--",
        label="largest inscribed rectangle")
ax.set_xlabel("rod length l (mm)")
ax.set_ylabel("area (10³ mm²)")
ax.set_title("MOMA M1 (γ = 0°): both rods of length l")
ax.grid(True, alpha=0.3)
ax.legend()
fig.tight_layout()
fig.savefig("moma_rod_sweep.png", dpi=120)
assert all(r["rectangle_width"] * r["rectangle_height"] <= r["area"] for r in ok), "a rectangle inside fits"
print("wrote moma_rod_sweep.png")
