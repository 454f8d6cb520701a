"""The MOMA program of building ([Vasilic]) as a table: every bundled
configuration (M1..M5, guide angles gamma, rod lengths l = 180, 195, 250 mm)
with its exact workspace area, components, largest inscribed circle and
largest axis-aligned inscribed rectangle.

Checked independently of the module: every area equals the command line's
`pkmws area --json` (a separate process, same library), the area grows with
the rod length for each configuration (as the README's table of the bundled
datasets shows), mirror-image configurations have equal areas (M1 -5/+5 deg,
M4 (0, +5)/(-5, 0), M5 (0, -5)/(+5, 0)), and M1 with parallel guides matches
the closed form of docs/theory/moma.md for every rod length.
"""
import json
import math
import os
import pathlib
import re
import shutil
import subprocess

import pkmws

ROOT = pathlib.Path(__file__).resolve().parents[2]
DATA = ROOT / "datasets"
CLI = os.environ.get("PKMWS_CLI") or shutil.which("pkmws") or str(ROOT / "build" / "bin" / "pkmws")

files = sorted(DATA.glob("moma_m*_l*.json"))
assert len(files) == 33, f"expected the 33 configurations, found {len(files)}"

rows = []
for f in files:
    config, rod = re.fullmatch(r"moma_(.+)_l(\d+)", f.stem).groups()
    m = pkmws.load(f)
    ws = m.workspace()
    circle = ws.inscribed_circle()
    rect = ws.inscribed_rectangle(precision=1e-3)
    guides = "/".join(f"{m.parameters[f'legs[{i}].guide_angle_deg']:g}" for i in (0, 1))  # degrees
    rows.append(dict(file=f.name, config=config, rod=int(rod), guides=guides, ws=ws, area=ws.area,
                     parts=len(ws.components()), radius=circle["radius"], rect=rect))

print(f"{'configuration':<14} {'guides (deg)':>12} {'l (mm)':>6} {'area (mm²)':>12} {'parts':>5} "
      f"{'circle r (mm)':>13} {'rectangle (mm)':>16} {'rect. area (mm²)':>16}")
for r in rows:
    rect = r["rect"]
    print(f"{r['config']:<14} {r['guides']:>12} {r['rod']:>6} {r['area']:12.2f} {r['parts']:>5} {r['radius']:13.2f} "
          f"{rect['width']:7.1f} x {rect['height']:6.1f} {rect['area']:16.1f}")

# 1. The command line agrees, to its certified bounds (exact: +-64 ulp).
for r in rows:
    out = subprocess.run([CLI, "area", str(DATA / r["file"]), "--json"], check=True, capture_output=True,
                         text=True).stdout
    report = json.loads(out)
    assert report["method"] == "exact", r["file"]
    assert report["area_lower"] <= r["area"] <= report["area_upper"], (r["file"], r["area"], report["area"])
    assert len(report["components"]) == r["parts"], r["file"]
    cli_radius = max(c["inscribed_circle"]["radius"] for c in report["components"])
    cli_upper = max(c["inscribed_circle"]["radius_upper"] for c in report["components"])
    assert r["radius"] <= cli_upper + 1e-9 and cli_radius <= r["ws"].inscribed_circle()["radius_upper"] + 1e-9

# 2. Longer rods reach more: per configuration the area grows with l.
by_config = {}
for r in rows:
    by_config.setdefault(r["config"], []).append(r)
for config, group in by_config.items():
    group.sort(key=lambda r: r["rod"])
    assert [r["rod"] for r in group] == [180, 195, 250], config
    assert all(a["area"] < b["area"] for a, b in zip(group, group[1:])), config


# 3. Mirror images have equal areas.
area = {(r["config"], r["rod"]): r["area"] for r in rows}
for a, b in (("m1_gm5", "m1_gp5"), ("m4_g0_gp5", "m4_gm5_g0"), ("m5_g0_gm5", "m5_gp5_g0")):
    for rod in (180, 195, 250):
        assert abs(area[(a, rod)] - area[(b, rod)]) <= 1e-9 * area[(a, rod)], (a, b, rod)
# 4. M1, gamma = 0: the closed form of docs/theory/moma.md (vertical slices of
#    the two bands overlap in h - |s1 - s2|, s_i = sqrt(l^2 - (x -+ 100)^2)).
def m1_area(l, h=200.0, a=100.0):
    F = lambda u: 0.5 * (u * math.sqrt(l * l - u * u) + l * l * math.asin(u / l))
    s = lambda u: math.sqrt(max(l * l - u * u, 0.0))
    lo, hi = 0.0, l - a  # x* where s2 - s1 = h, or the end of band 1
    if s(hi - a) - s(hi + a) < h:
        x = hi
    else:
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if s(mid - a) - s(mid + a) < h else (lo, mid)
        x = 0.5 * (lo + hi)
    return 2 * (h * x + (F(x + a) - F(a)) - (F(x - a) - F(-a)))


for rod in (180, 195, 250):
    assert abs(area[("m1_g0", rod)] - m1_area(rod)) <= 1e-9 * m1_area(rod), (rod, area[("m1_g0", rod)], m1_area(rod))
print(f"{len(rows)} designs: areas equal `pkmws area --json`, grow with the rod length, mirror images agree")
