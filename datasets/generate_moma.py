#!/usr/bin/env python3
"""Writes the MOMA datasets: every configuration of the program of building
([Vasilic] §2, docs/theory/moma.md) for every rod length l in {180, 195, 250} mm, with
stroke [0, h_max], h_max = 200 mm ([Vasilic] §4.1). 11 configurations x 3 rod
lengths = 33 files. Python 3 standard library only.

Run from anywhere: python3 datasets/generate_moma.py (writes beside this file).
"""
import json
import os

PAPER = ("Vasilić, Živanović: Workspace analysis of reconfigurable 2-DOF parallel "
         "mechanism MOMA ([Vasilic])")
H_MAX = 200  # mm, [Vasilic] §4.1
ROD_LENGTHS = (180, 195, 250)  # mm, [Vasilic] §2
# [Vasilic] §4.1/§4.2: R1 = (-100, 0), R2 = (100, 0) for M1, M4, M5.
R_LEFT, R_RIGHT = [-100, 0], [100, 0]


def gamma_tag(g):
    return "0" if g == 0 else ("p%d" % g if g > 0 else "m%d" % -g)


def leg(ref, angle_deg, l, branch=-1):
    return {"reference": ref, "guide_angle_deg": angle_deg, "stroke": [0, H_MAX],
            "rod_length": l, "branch": branch}


def m1(l):
    # M1: parallel guides, alpha1 = alpha2 = 3pi/2 + gamma ([Vasilic] §2, Fig. 2a, 2b).
    for g in (0, -5, 5):
        figure = {0: "Fig. 2a (program of building)",
                  -5: "Fig. 2b (program of building)",
                  5: "§2 (program of building; mirror image of Fig. 2b, no figure of its own)"}[g]
        note = "M1: parallel guides, gamma1 = gamma2 = %d deg, alpha_i = 270 + gamma_i deg" % g
        if g == 0 and l == 250:
            figure = "Fig. 5 (§4.1, workspace from the direct kinematics)"
            note += "; §4.1 reference: h_max = 200, l1 = l2 = 250, R = (-100, 0), (100, 0)"
        if g == -5 and l == 195:
            figure = "Fig. 9 (§4.2, workspace from the inverse kinematics, polar grid)"
            note += "; §4.2 reference: alpha1 = alpha2 = 3pi/2 - 5 deg, l1 = l2 = 195 (h_max = 200 assumed)"
        yield ("moma_m1_g%s_l%d" % (gamma_tag(g), l),
               "MOMA M1 (gamma = %d°), l = %d mm" % (g, l),
               "MOMA M1, parallel guides at gamma = %d deg, rods %d mm, stroke 0..%d mm" % (g, l, H_MAX),
               [leg(R_LEFT, 270 + g, l), leg(R_RIGHT, 270 + g, l)], figure, note)


def m2(l):
    # M2: guides parallel to the axes, platform in quadrant I ([Vasilic] §4.1, Fig. 2c).
    figure = "Fig. 6 (§4.1, workspace from the direct kinematics)" if l == 250 else \
        "Fig. 2c (program of building)"
    yield ("moma_m2_l%d" % l, "MOMA M2 (quadrant I), l = %d mm" % l,
           "MOMA M2, guides along the axes, platform in quadrant I, rods %d mm, stroke 0..%d mm" % (l, H_MAX),
           [leg([50, 0], 90, l), leg([0, 50], 0, l)], figure,
           "M2: alpha1 = pi/2, alpha2 = 0, R1 = (50, 0), R2 = (0, 50) as printed in §4.1; "
           "branch -1 (eq. 5) on both legs. The paper's closed form (eq. 9-12) divides by zero "
           "at p2 = 50 (both sliders on x = 50).")


# Measured shares of the M3 workspace area per quadrant (exact regions, pkmws).
M3_SHARES = {
    250: "The workspace then lies mostly in quadrant III: 74.8 % of its area, 12.6 % each in "
         "quadrants II and IV, none in I",
    195: "With these shorter rods (not in the paper's §4) quadrant III holds the largest share, "
         "43.0 % (II and IV 24.2 % each, I 8.6 %), and the main component's centroid; a second "
         "component of 92 mm^2 lies near (190, 190)",
    180: "With these shorter rods (not in the paper's §4) quadrant III holds the largest share, "
         "34.8 % (II and IV 24.8 % each, I 15.7 %), and the main component's centroid; a second "
         "component of 399 mm^2 lies near (168, 168)",
}


def m3(l):
    # M3: guides parallel to the axes, platform in quadrant III ([Vasilic] §4.1, Fig. 2d).
    # The printed alpha1 = 0, alpha2 = pi/2, R1 = (50, 0), R2 = (0, 50) with eq. 5 (minus
    # root: platform ahead of each slider) put the platform in quadrant I. We keep the
    # printed guides and take the other root of eq. 4 (branch +1: platform behind each
    # slider), which puts the workspace (mostly) in quadrant III.
    figure = "Fig. 7 (§4.1, workspace from the direct kinematics)" if l == 250 else \
        "Fig. 2d (program of building)"
    yield ("moma_m3_l%d" % l, "MOMA M3 (quadrant III), l = %d mm" % l,
           "MOMA M3, guides along the axes, platform in quadrant III, rods %d mm, stroke 0..%d mm" % (l, H_MAX),
           [leg([50, 0], 0, l, +1), leg([0, 50], 90, l, +1)], figure,
           "M3: the paper prints alpha1 = 0, alpha2 = pi/2, R1 = (50, 0), R2 = (0, 50), which "
           "with eq. 5 (minus root, platform ahead of each slider) cannot put the platform in "
           "quadrant III. Choice made here: keep the printed guides and use the other root of "
           "eq. 4 (branch +1 on both legs: the platform lies behind each slider). " + M3_SHARES[l] +
           " (checked by tests/mechanisms/moma/datasets_test.cpp; see docs/theory/moma.md).")


def m4_m5(l):
    # M4 diverging, M5 converging guides ([Vasilic] §2, Fig. 2e, 2f; §4.2 Fig. 10, 11).
    for name, pairs, kind, fig2 in (("m4", ((-5, 5), (0, 5), (-5, 0)), "diverging", "Fig. 2e"),
                                    ("m5", ((5, -5), (0, -5), (5, 0)), "converging", "Fig. 2f")):
        for variant, (g1, g2) in zip(("i", "ii", "iii"), pairs):
            figure = "%s (program of building, variant %s)" % (fig2, variant)
            note = "%s: %s guides, gamma1 = %d deg, gamma2 = %d deg, alpha_i = 270 + gamma_i deg" % (
                name.upper(), kind, g1, g2)
            if l == 195 and variant == "i":
                figure = ("Fig. 10 (§4.2, workspace from the inverse kinematics, polar grid)"
                          if name == "m4" else
                          "Fig. 11 (§4.2, workspace from the inverse kinematics: a) polar, b) Cartesian grid)")
                note += "; §4.2 reference: l1 = l2 = 195, R = (-100, 0), (100, 0) (h_max = 200 assumed)"
            yield ("moma_%s_g%s_g%s_l%d" % (name, gamma_tag(g1), gamma_tag(g2), l),
                   "MOMA %s (%s, gamma = %d°/%d°), l = %d mm" % (name.upper(), kind, g1, g2, l),
                   "MOMA %s, %s guides at gamma = %d/%d deg, rods %d mm, stroke 0..%d mm" % (
                       name.upper(), kind, g1, g2, l, H_MAX),
                   [leg(R_LEFT, 270 + g1, l), leg(R_RIGHT, 270 + g2, l)], figure, note)


def configs():
    for l in ROD_LENGTHS:
        yield from m1(l)
        yield from m2(l)
        yield from m3(l)
        yield from m4_m5(l)


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    count = 0
    for stem, name, description, legs, figure, note in configs():
        doc = {
            "name": name,
            "mechanism": "moma",
            "units": "mm",
            "description": description,
            "legs": legs,
            "source": {"paper": PAPER, "figure": figure, "note": note},
        }
        with open(os.path.join(here, stem + ".json"), "w", encoding="utf-8") as f:
            json.dump(doc, f, indent=2, ensure_ascii=False)
            f.write("\n")
        count += 1
    assert count == 33, count


if __name__ == "__main__":
    main()
