"""MOMA M1: workspace area and usable table (largest inscribed rectangle)
against the rod length, both rods tied -- a sweep table (pandas-ready rows)."""
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
