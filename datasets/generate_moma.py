#!/usr/bin/env python3
"""Writes the MOMA datasets: every configuration of the program of building
(seed 000 §2, SPEC §1.1) for every rod length l in {180, 195, 250} mm, with
stroke [0, 200] mm. Run from the repository root: python3 datasets/generate_moma.py"""
import json
import os

PAPER = ("Vasilić G., Živanović S.: Analiza radnog prostora rekonfigurabilnog dvoosnog "
         "paralelnog mehanizma MOMA (Workspace analysis of reconfigurable 2-DOF parallel "
         "mechanism MOMA), seed 000")
H_MAX = 200.0


def gamma_tag(g):
    return "0" if g == 0 else ("p%d" % g if g > 0 else "m%d" % -g)


def leg(ref, angle, l, branch=-1):
    return {"reference": ref, "guide_angle_deg": angle, "stroke": [0, H_MAX],
            "rod_length": l, "branch": branch}


def configs():
    for l in (180, 195, 250):
        # M1: parallel guides, alpha = 3pi/2 + gamma.
        for g in (0, -5, 5):
            fig = None
            if g == 0 and l == 250:
                fig = "Fig. 5 (§4.1, DK sweep)"
            if g == -5 and l == 195:
                fig = "Fig. 9 (§4.2, IK grid in polar coordinates)"
            note = "M1: parallel guides, gamma1 = gamma2 = %d deg" % g
            if g == -5:
                note += ("; the paper's §4.2 prints alpha1 = alpha2 = 3pi/2 - 5 deg for M1, "
                         "i.e. gamma = -5 deg")
            yield ("moma_m1_g%s_l%d" % (gamma_tag(g), l),
                   "MOMA M1 (gamma = %d°), l = %d mm" % (g, l),
                   [leg([-100, 0], 270 + g, l), leg([100, 0], 270 + g, l)], fig or "Fig. 2a/2b (program of building)", note)
        # M2: guides parallel to the axes, platform in quadrant I.
        yield ("moma_m2_l%d" % l, "MOMA M2 (quadrant I), l = %d mm" % l,
               [leg([50, 0], 90, l), leg([0, 50], 0, l)],
               "Fig. 6 (§4.1, DK sweep)" if l == 250 else "Fig. 2c (program of building)",
               "M2: alpha1 = pi/2, alpha2 = 0, R1 = (50, 0), R2 = (0, 50) as printed in §4.1")
        # M3: the printed alpha1 = 0, alpha2 = pi/2, R1 = (50, 0), R2 = (0, 50) put the platform
        # in quadrant I with eq. 5; we keep the printed guides and take the other root of eq. 4
        # (branch +1, platform behind the sliders), which puts it in quadrant III.
        yield ("moma_m3_l%d" % l, "MOMA M3 (quadrant III), l = %d mm" % l,
               [leg([50, 0], 0, l, +1), leg([0, 50], 90, l, +1)],
               "Fig. 7 (§4.1, DK sweep)" if l == 250 else "Fig. 2d (program of building)",
               "M3: the paper prints alpha1 = 0, alpha2 = pi/2, R1 = (50, 0), R2 = (0, 50), which "
               "with eq. 5 (minus root) cannot put the platform in quadrant III. Choice made here: "
               "keep the printed guides and use the other root of eq. 4 (branch +1 on both legs: "
               "the platform lies behind each slider), which puts the workspace in quadrant III "
               "(checked by tests/mechanisms/moma_test.cpp).")
        # M4 diverging, M5 converging guides.
        for name, pairs, kind in (("m4", ((-5, 5), (0, 5), (-5, 0)), "diverging"),
                                  ("m5", ((5, -5), (0, -5), (5, 0)), "converging")):
            for g1, g2 in pairs:
                fig = None
                if l == 195 and name == "m4" and (g1, g2) == (-5, 5):
                    fig = "Fig. 10 (§4.2, IK grid in polar coordinates)"
                if l == 195 and name == "m5" and (g1, g2) == (5, -5):
                    fig = "Fig. 11 (§4.2, IK grid: a) polar, b) Cartesian)"
                yield ("moma_%s_g%s_g%s_l%d" % (name, gamma_tag(g1), gamma_tag(g2), l),
                       "MOMA %s (%s, gamma = %d°/%d°), l = %d mm" % (name.upper(), kind, g1, g2, l),
                       [leg([-100, 0], 270 + g1, l), leg([100, 0], 270 + g2, l)],
                       fig or ("Fig. 2e (program of building)" if name == "m4" else "Fig. 2f (program of building)"),
                       "%s: %s guides, gamma1 = %d deg, gamma2 = %d deg" % (name.upper(), kind, g1, g2))


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    for stem, name, legs, figure, note in configs():
        doc = {
            "name": name,
            "mechanism": "moma",
            "units": "mm",
            "description": "MOMA desktop parallel mechanism, stroke h_max = 200 mm, "
                           "alpha_i = 3pi/2 + gamma_i where applicable",
            "legs": legs,
            "source": {"paper": PAPER, "figure": figure, "note": note},
        }
        with open(os.path.join(here, stem + ".json"), "w", encoding="utf-8") as f:
            json.dump(doc, f, indent=2, ensure_ascii=False)
            f.write("\n")


if __name__ == "__main__":
    main()
