#!/usr/bin/env python3
"""Writes the five-bar (DexTAR), biglide and active Pi-joint datasets (issue 4):
[Briot] (DexTAR five-bar), [Strutynskyi] (biglide), [Milutinovic] (active Pi-joint).
Run from the repository root: python3 datasets/generate_five_bar_biglide_pi_joint.py"""
import json
import math
import os

MILUTINOVIC = ("Milutinović D., Kokotović B., Slavković N., Živanović S.: Mehanizam aktivnog "
            "P-zgloba kao ekvivalenta kombinacije obrtnog zgloba i segmenta konstantne dužine "
            "(technical solution, Belgrade 2014), [Milutinovic]")
STRUTYNSKYI = ("Strutynskyi V. B., Kyrychenko A. M.: Kinematic relations of a machine tool with the "
            "'biglide' parallel mechanism, [Strutynskyi]")
BRIOT = ("Pressure angles and joint reactions in the workspace of planar parallel manipulators "
            "(five-bar DexTAR and 3-RPR PAMINSA), [Briot]")

# DexTAR ([Briot]): l_AB = l_DE = l_BC = l_CD = 0.23 m, a = 0.1375 m.
DEXTAR_L = 0.23
DEXTAR_A = 0.1375

# Biglide ([Strutynskyi] gives no dimensions). Chosen: table half width B = 500 mm and
# rods l = 940 mm, so that V/V_y = 1.5 and 2 fall at 782 mm and 841 mm from the
# guide of slider 1, where fig. 8a reads 780 mm and 850 mm; strokes 1600 mm.
BIGLIDE_B = 500.0
BIGLIDE_L = 940.0
BIGLIDE_STROKE = [0.0, 1600.0]
# Real scheme: the same l1 = |S1 J|, tool at l3 = 900 mm from S1 and l4 = 150 mm from J;
# l2 from the zero-position rule ([Strutynskyi] eq. 9 in the form consistent with eq. 3-4).
BIGLIDE_L3 = 900.0
BIGLIDE_L4 = 150.0


def zero_position_l2(b, l1, l3, l4):
    gamma = math.acos((l1 * l1 + l3 * l3 - l4 * l4) / (2 * l1 * l3))
    phi0 = math.acos(b / l3) - gamma
    return math.sqrt(4 * b * b + l1 * l1 - 4 * b * l1 * math.cos(phi0))


def sign_tag(s):
    return "p" if s > 0 else "m"


def files():
    for s1 in (1, -1):
        for s2 in (1, -1):
            stem = "five_bar_dextar_%s%s" % (sign_tag(s1), sign_tag(s2))
            yield stem, {
                "name": "DexTAR five-bar, working mode (%+d, %+d)" % (s1, s2),
                "mechanism": "five_bar",
                "units": "m",
                "description": "Planar 5R five-bar DexTAR: base joints A = (-a, 0), E = (a, 0), "
                               "l_AB = l_DE = l_BC = l_CD = 0.23 m, a = 0.1375 m; working mode "
                               "s_i = sign((C - A_i) x (B_i - A_i)); cranks rotate freely",
                "base": [[-DEXTAR_A, 0.0], [DEXTAR_A, 0.0]],
                "proximal": [DEXTAR_L, DEXTAR_L],
                "distal": [DEXTAR_L, DEXTAR_L],
                "working_mode": [s1, s2],
                "source": {"paper": BRIOT,
                           "figure": "Fig. 7 (the five-bar), Fig. 9 (reactions for f = 100 N; outer "
                                     "contour = type-1 singularity), Fig. 10 (workspace vs alpha_max)",
                           "note": "The reachable workspace is the same in every working mode (the "
                                   "lens of two disks of radius 0.46 m); the working mode selects the "
                                   "branch of the inverse kinematics and the singular curves."},
            }
    # Five-bar with Pi-joint drives ([Milutinovic] fig. 5): the prototype joint
    # (a = 170 mm, k = 0.4) drives each crank; d in [117, 232] mm (the paper's
    # rounded d_min, d_max) limits theta_Pi to [-59.08, 61.40] deg.
    yield "five_bar_pi_joint", {
        "name": "Five-bar driven by two active Pi-joints",
        "mechanism": "five_bar",
        "units": "mm",
        "description": "Five-bar 5R whose actuated revolute joints and proximal links are replaced by the "
                       "active Pi-joint prototype (a = 170 mm, k = 0.4); base joints at (-100, 0) and "
                       "(100, 0) mm (DexTAR's a/l ratio), distal links 170 mm; each crank angle is "
                       "base_angle + sense * theta_Pi, theta_Pi from d by [Milutinovic] eq. 3-5",
        "base": [[-100.0, 0.0], [100.0, 0.0]],
        "proximal": [170.0, 170.0],
        "distal": [170.0, 170.0],
        "working_mode": [1, -1],
        "pi_joints": [
            {"k": 0.4, "stroke": [117.0, 232.0], "base_angle_deg": 90.0, "sense": 1},
            {"k": 0.4, "stroke": [117.0, 232.0], "base_angle_deg": 90.0, "sense": -1},
        ],
        "source": {"paper": MILUTINOVIC,
                   "figure": "Fig. 5 (planar 5R mechanisms with active Pi-joints); prototype of §4.2",
                   "note": "Dimensions other than the Pi-joint's are our choice. Leg 2 is the mirror "
                           "image of leg 1 (sense -1), so the workspace is symmetric about x = 0."},
    }
    biglide_source = {"paper": STRUTYNSKYI,
                      "figure": "Fig. 3 (simplified scheme), Fig. 8a (velocity ratio)",
                      "note": "The paper gives no dimensions: B = 500 mm and l1 = l2 = 940 mm are "
                              "chosen so that V/V_y = 1.5 and 2 fall 782 mm and 841 mm from guide 1 "
                              "(fig. 8a reads 780 and 850 mm)."}
    yield "biglide_simplified", {
        "name": "Biglide, simplified scheme",
        "mechanism": "biglide",
        "units": "mm",
        "description": "Sliders at (q1, -B) and (q2, +B), rods l1, l2 meeting at the tool ([Strutynskyi] fig. 3)",
        "half_width": BIGLIDE_B,
        "rods": [BIGLIDE_L, BIGLIDE_L],
        "stroke": [BIGLIDE_STROKE, BIGLIDE_STROKE],
        "source": biglide_source,
    }
    l2 = round(zero_position_l2(BIGLIDE_B, BIGLIDE_L, BIGLIDE_L3, BIGLIDE_L4), 6)
    yield "biglide_real", {
        "name": "Biglide, real scheme (tool on the first link)",
        "mechanism": "biglide",
        "units": "mm",
        "description": "Rigid triangle S1 J T (|S1 J| = l1, |S1 T| = l3, |J T| = l4) on slider 1, rod l2 "
                       "from slider 2 to J; l2 from the zero-position rule (tool on y = 0 at q1 = q2)",
        "half_width": BIGLIDE_B,
        "rods": [BIGLIDE_L, l2],
        "stroke": [BIGLIDE_STROKE, BIGLIDE_STROKE],
        "tool": {"l3": BIGLIDE_L3, "l4": BIGLIDE_L4},
        "source": {"paper": STRUTYNSKYI,
                   "figure": "Fig. 4 (real scheme), Fig. 5 (zero position), Fig. 8b (velocity ratio)",
                   "note": "l1 = 940, l3 = 900, l4 = 150 mm chosen; l2 = %.6f mm from eq. 9 in the form "
                           "consistent with eq. 3-4 (the printed eq. 9 has the sign of asin(B/l3) "
                           "flipped, docs/theory/biglide.md). The exact workspace is not available: "
                           "its boundary contains slider-crank coupler curves." % l2},
    }
    yield "pi_joint_prototype", {
        "name": "Active Pi-joint prototype",
        "mechanism": "pi_joint",
        "units": "mm",
        "description": "Parallelogram with telescopic diagonal: a = 170 mm, k = 0.4 (b = 68 mm), "
                       "theta = +-60 deg; stepper-motor linear actuator of Table 1",
        "crank_length": 170.0,
        "k": 0.4,
        "theta_limits_deg": [-60.0, 60.0],
        "actuator": {"lead": 2.54, "resolution_per_step": 0.0127, "max_speed": 50.0, "max_force_N": 130.0},
        "source": {"paper": MILUTINOVIC,
                   "figure": "§4.2, Table 1, Fig. 15-17 (resolution, angular velocity, torque)",
                   "note": "d(+-60 deg) = 231.40 / 116.20 mm; the paper prints d_max = 232, d_min = 117 "
                           "(rounded up) and d_max - d_min = 115 mm."},
    }


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    for stem, doc in files():
        with open(os.path.join(here, stem + ".json"), "w", encoding="utf-8") as f:
            json.dump(doc, f, indent=2, ensure_ascii=False)
            f.write("\n")


if __name__ == "__main__":
    main()
