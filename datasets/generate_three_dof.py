#!/usr/bin/env python3
"""Writes the 3-DOF datasets (issue 7): the 3-RRP of [Mitsi] (Tables 1-2,
reconstructed), a 3-PRP example, the planar PAMINSA 3-RPR of [Briot] and a
prismatic 3-RPR with six real assembly modes.
Run from the repository root: python3 datasets/generate_three_dof.py"""
import json
import math
import os

MITSI = ("Mitsi S., Bouzakis K.-D., Mansour G., Popescu I.: A method for solving the direct "
            "kinematics of the planar parallel robots 3-RRP and 3-PRP (in Greek), [Mitsi]")
BRIOT = ("Briot S., Arakelian V., Glazunov V. A.: Pressure angles and joint reactions in planar "
            "parallel manipulators (in Russian), [Briot]")

S3 = math.sqrt(3.0)

# [Mitsi] Table 1 lost every digit 0 and 2 in text extraction. What is legible:
# "x_A2 = 14", "x_A3 = 7", "y_A3 = 11,44" (the fixed revolutes, i.e. O_i), equal
# cranks "l_OA = 1", equal sides "l = 4", "alpha = 6" degrees, crank angles
# "phi1 = 6", "phi2 = 1", "phi3 = 1".
BASE_SIDE = 140.0        # "14" and "7" = 140 and 70; y = 140 sin 60 = 121.2436 prints "121,244" -> "11,44"
CRANK = 10.0             # "1"; 100 and 120 are rejected below
PLATFORM_SIDE = 40.0     # "4"; the printed B1B2 of Table 2 row 1 is about 40 long
ALPHA_DEG = 60.0         # "6", the equilateral platform of the text
CRANK_ANGLES_DEG = [60.0, 10.0, 10.0]   # "6", "1", "1"


def equilateral_platform(side):
    """B1, B2, B3 counter-clockwise about the centroid (the platform frame's origin), B1B2 along x."""
    r = side / S3
    return [[r * math.cos(math.radians(a)), r * math.sin(math.radians(a))] for a in (210.0, 330.0, 90.0)]


def base_triangle(side):
    return [[0.0, 0.0], [side, 0.0], [side / 2.0, side * S3 / 2.0]]


def three_rrp_mitsi():
    return {
        "name": "3-RRP of [Mitsi] (Tables 1-2), reconstructed",
        "mechanism": "three_rrp",
        "units": "mm",
        "description": "Symmetric 3-RRP: equilateral base O1O2O3 (side 140 mm, O1 at the origin, O2 on the "
                       "x-axis), equal cranks O_iA_i = 10 mm, equilateral platform B1B2B3 (side 40 mm, "
                       "alpha_i = 60 deg); chain i's slider runs on side B_iB_{i+1}. Platform frame at the "
                       "platform's centroid. The paper's joint values are phi = (60, 10, 10) deg.",
        "base": base_triangle(BASE_SIDE),
        "platform": equilateral_platform(PLATFORM_SIDE),
        "crank_lengths": [CRANK, CRANK, CRANK],
        "orientation_deg": 20.0,
        "source": {
            "paper": MITSI,
            "table": "Table 1 (data), Table 2 (platform points), Fig. 4 (the two assembly modes)",
            "joints_deg": CRANK_ANGLES_DEG,
            "note": ("Table 1 lost its digits 0 and 2 in text extraction; values inferred, nothing was fitted "
                     "to the damaged solutions of Tables 1-2. Legible: an equilateral base with O1 at the "
                     "origin and O2 on the x-axis, equal cranks, l1 = l2 = l3, alpha = 60 deg. Base: '14', "
                     "'7', '11,44' read as 140, 70 and 121.244 = 140 sin 60 deg (its two 2s are the lost "
                     "digits, which confirms the side 140 mm). Every other damaged number is restored with "
                     "one trailing zero, the commonest loss: platform side '4' -> 40 mm, cranks '1' -> "
                     "10 mm, crank angles '6', '1', '1' -> 60, 10, 10 deg, alpha '6' -> 60 deg. The "
                     "reading is checked against the legible sentence 'two real and two imaginary "
                     "solutions' of the eliminant: with cranks of 10 mm the true triangle A1A2A3 admits "
                     "two placements and its mirror image none (two real, two complex roots), whereas "
                     "cranks of 100 or 120 mm give four real roots. orientation_deg (20 deg, near the "
                     "second assembly mode's 19.83 deg) is not from the paper: the constant-orientation "
                     "workspace with full-turn cranks is empty at 0 deg."),
        },
    }


def three_prp_example():
    return {
        "name": "3-PRP example (equilateral base, radial guides)",
        "mechanism": "three_prp",
        "units": "mm",
        "description": "3-PRP with the base and platform of the [Mitsi] 3-RRP: actuated sliders at O_i "
                       "moving towards the base centroid (directions 30, 150, 270 deg), strokes 0-80 mm; "
                       "equilateral platform of side 40 mm, frame at its centroid.",
        "base": base_triangle(BASE_SIDE),
        "platform": equilateral_platform(PLATFORM_SIDE),
        "directions_deg": [30.0, 150.0, 270.0],
        "strokes": [[0.0, 80.0], [0.0, 80.0], [0.0, 80.0]],
        "orientation_deg": 0.0,
        "source": {
            "paper": MITSI,
            "note": ("The paper gives no 3-PRP example; this one reuses its base and platform with guides along "
                     "the base's medians ([Mitsi] eq. 2: A_i = O_i + s_i (cos delta_i, sin delta_i)). "
                     "Joint values s = (40, 40, 40) mm put the platform centroid on the base centroid."),
            "joints": [40.0, 40.0, 40.0],
        },
    }


def three_rpr_paminsa():
    rb, rp = 0.35, 0.1
    theta = (-90.0, 30.0, 150.0)
    return {
        "name": "Planar PAMINSA (3-RPR with actuated base revolutes)",
        "mechanism": "three_rpr",
        "units": "m",
        "description": "Equilateral base and platform, circumradii R_b = 0.35 m and R_p = 0.1 m, "
                       "A_i = R_b u(theta_i), B_i = P + R_p u(theta_i + phi), theta_i = -90, 30, 150 deg. "
                       "The base revolutes are actuated: leg i pushes on the platform through B_i "
                       "perpendicular to the leg. No leg limits are given by the paper.",
        "base": [[rb * math.cos(math.radians(t)), rb * math.sin(math.radians(t))] for t in theta],
        "platform": [[rp * math.cos(math.radians(t)), rp * math.sin(math.radians(t))] for t in theta],
        "actuation": "revolute",
        "orientation_deg": 0.0,
        "criteria": {"load": {"force_N": 100.0, "moment_Nm": 5.0}, "max_reaction_N": 200.0},
        "source": {
            "paper": BRIOT,
            "figure": "Fig. 11b (the planar model), Fig. 12 (reactions at B1 for f = 100 N, m = 5 N m, "
                      "phi = 0, 25, 50 deg), Fig. 13a (workspace for phi = 0, R_max = 200 N)",
            "note": ("Type-2 singular for fixed phi on the circle about O of radius "
                     "sqrt(R_b^2 + R_p^2 - 2 R_b R_p cos phi), and everywhere when cos phi = R_p / R_b."),
        },
    }


def three_rpr_prismatic():
    return {
        "name": "3-RPR with actuated legs: six real assembly modes",
        "mechanism": "three_rpr",
        "units": "m",
        "description": "General 3-RPR (leg lengths actuated, 0.3-2.0 m) whose direct kinematics has six "
                       "real solutions for leg lengths (1.809, 1.142, 0.694) m.",
        "base": [[-0.94, -0.84], [-0.15, -0.47], [0.55, 0.61]],
        "platform": [[-0.09, 0.14], [-0.29, -0.06], [0.09, -0.21]],
        "actuation": "prismatic",
        "orientation_deg": 0.0,
        "leg_limits": [[0.3, 2.0], [0.3, 2.0], [0.3, 2.0]],
        "source": {
            "note": ("Not from a paper: a design found by a random search for an example of the sextic "
                     "(docs/theory/three_dof.md) with all six roots real. Leg lengths (1.809, 1.142, "
                     "0.694) m give six poses (phi about -162.2, -66.9, -51.4, 53.6, 93.6, 104.7 deg)."),
            "joints": [1.809, 1.142, 0.694],
        },
    }


def main():
    out = {
        "three_rrp_mitsi": three_rrp_mitsi(),
        "three_prp_example": three_prp_example(),
        "three_rpr_paminsa": three_rpr_paminsa(),
        "three_rpr_prismatic": three_rpr_prismatic(),
    }
    here = os.path.dirname(os.path.abspath(__file__))
    for stem, doc in out.items():
        with open(os.path.join(here, stem + ".json"), "w", encoding="utf-8") as f:
            json.dump(doc, f, indent=2, ensure_ascii=False)
            f.write("\n")


if __name__ == "__main__":
    main()
