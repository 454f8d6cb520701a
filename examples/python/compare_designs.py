"""Two MOMA designs (M1 parallel guides, M4 diverging guides, rods 250 mm):
what each reaches that the other does not, exactly (pkmws booleans) and
through shapely (GEOS) from __geo_interface__, which agree to the stated tolerance."""
import pathlib

import numpy as np
import shapely.geometry

import pkmws

ROOT = pathlib.Path(__file__).resolve().parents[2]
a = pkmws.load(ROOT / "datasets" / "moma_m1_g0_l250.json").workspace()
b = pkmws.load(ROOT / "datasets" / "moma_m4_gm5_gp5_l250.json").workspace()

ga, gb = shapely.geometry.shape(a), shapely.geometry.shape(b)
print(f"{'region':<14} {'pkmws (exact)':>14} {'shapely':>14}")
for label, exact, geos, bound in [
    ("M1", a, ga, a.area_error_bound()),
    ("M4", b, gb, b.area_error_bound()),
    ("M1 & M4", a & b, ga.intersection(gb), a.area_error_bound() + b.area_error_bound()),
    ("M1 - M4", a - b, ga.difference(gb), a.area_error_bound() + b.area_error_bound()),
    ("M4 - M1", b - a, gb.difference(ga), a.area_error_bound() + b.area_error_bound()),
]:
    print(f"{label:<14} {exact.area:14.3f} {geos.area:14.3f}")
    assert abs(exact.area - geos.area) <= bound

# A task: a 100 x 60 mm table centred at the M1 workspace's largest circle.
cx, cy = a.inscribed_circle()["center"]
corners = np.array([[cx - 50, cy - 30], [cx + 50, cy - 30], [cx + 50, cy + 30], [cx - 50, cy + 30]])
print("table inside M1:", bool(a.contains(corners).all()), " inside M4:", bool(b.contains(corners).all()))
