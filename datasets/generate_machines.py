#!/usr/bin/env python3
"""Writes the machine datasets with bodies (docs/format.md (bodies)): the MOMA desktop machine
([Vasilic], CAD model of fig. 1) in configurations M1, M3 and M5 -- the three
whose real workspace the paper shows smaller than the computed one (figs. 5, 7,
11, black outline) -- and a DexTAR-like five-bar ([Briot]) with link thickness.
Python 3 standard library only. Run: python3 datasets/generate_machines.py

The paper gives no part sizes. The sizes below are plausible for a desktop
machine of fig. 1 (stepper-driven ball-screw axes on one base plate, aluminium
rods, a spindle clamp at the platform joint) and are stated in every file.
"""
import json
import os

HERE = os.path.dirname(os.path.abspath(__file__))
MOMA_PAPER = ("Vasilić, Živanović: Workspace analysis of reconfigurable 2-DOF parallel "
              "mechanism MOMA ([Vasilic])")
H_MAX = 200  # mm, [Vasilic] §4.1

# MOMA desktop machine parts (mm), the same in every configuration (the modules are
# re-mounted, not rebuilt: [Vasilic] §2).
MOMA_BODIES = {
    # Revolute joint of the two rods with the spindle clamp under it: 40 mm diameter.
    # The forks of the two rods touch each other below 15 degrees between the rods.
    "platform_joint": {"radius": 20, "min_link_angle_deg": 15},
    # Rods: 18 mm wide aluminium bars (capsules of radius 9 along the rod axis S_i P).
    "rods": [{"radius": 9}, {"radius": 9}],
    # Carriage plate with the rod's joint boss: 60 mm along the guide, 70 mm across.
    "slider_blocks": [{"length": 60, "width": 70}, {"length": 60, "width": 70}],
    # Linear axis body (rails, ball screw, motor and bearing blocks): 50 mm wide,
    # from 50 mm behind the stroke start to 50 mm beyond its end (guide coordinate p).
    "housings": [{"extent": [-50, 250], "width": 50}, {"extent": [-50, 250], "width": 50}],
    # A rod is carried on top of its own carriage and swings over its own axis
    # (its fork straddles the axis cover), but it cannot pass over the other axis.
    "allowed_contacts": [["rod1", "housing1"], ["rod2", "housing2"]],
}

BODIES_NOTE = (
    "Bodies (docs/format.md (bodies); the paper gives no sizes, these are plausible for the desktop machine of "
    "fig. 1): platform joint with spindle clamp, disk of radius 20 mm; rods 18 mm wide (capsules, "
    "radius 9 mm); the rods' forks at the platform joint keep at least 15 degrees between the rods; "
    "carriage plates 60 mm along the guide x 70 mm across; each linear axis body 50 mm wide from "
    "p = -50 to p = 250 mm (motor and bearing blocks beyond the 0..200 mm stroke). A rod swings "
    "over its own axis (allowed contact) but not over the other axis, so the rods cannot carry P "
    "beyond the other guide: that is the difference between the computed (filled) and the real "
    "(black outline) workspace in figs. 5, 7 and 11.")


def leg(ref, angle_deg, l, branch=-1):
    return {"reference": ref, "guide_angle_deg": angle_deg, "stroke": [0, H_MAX],
            "rod_length": l, "branch": branch}


def moma_files():
    yield ("machine_moma_m1",
           "MOMA desktop machine, M1 (gamma = 0°), l = 250 mm, with bodies",
           "MOMA M1 with the part sizes of the desktop machine: computed and real workspace ([Vasilic] fig. 5)",
           [leg([-100, 0], 270, 250), leg([100, 0], 270, 250)],
           "Fig. 5 (§4.1): M1, alpha = 270 deg, l1 = l2 = 250 mm, R = (-100, 0), (100, 0), h_max = 200 mm")
    yield ("machine_moma_m3",
           "MOMA desktop machine, M3 (quadrant III), l = 250 mm, with bodies",
           "MOMA M3 with the part sizes of the desktop machine: computed and real workspace ([Vasilic] fig. 7)",
           [leg([50, 0], 0, 250, 1), leg([0, 50], 90, 250, 1)],
           "Fig. 7 (§4.1): M3 as in moma_m3_l250.json (printed guides alpha1 = 0, alpha2 = 90 deg, "
           "R1 = (50, 0), R2 = (0, 50), other root of eq. 4 on both legs so that the platform lies in "
           "quadrant III; see that file and docs/theory/moma.md)")
    yield ("machine_moma_m5",
           "MOMA desktop machine, M5 (gamma = 5°/-5°), l = 195 mm, with bodies",
           "MOMA M5 with the part sizes of the desktop machine: computed and real workspace ([Vasilic] fig. 11)",
           [leg([-100, 0], 275, 195), leg([100, 0], 265, 195)],
           "Fig. 11 (§4.2): M5, alpha1 = 3pi/2 + 5 deg, alpha2 = 3pi/2 - 5 deg, l1 = l2 = 195 mm, "
           "R = (-100, 0), (100, 0) (h_max = 200 mm assumed)")


def five_bar_file():
    bodies = {
        # Tool joint: 30 mm diameter housing; the distal links' joint housings at C
        # keep at least 20 degrees between the distal links, so they cannot fold onto
        # (and cross) each other near the type-2 singularity (distal links aligned).
        "platform_joint": {"radius": 0.015, "min_link_angle_deg": 20},
        # Carbon tubes: proximal 24 mm, distal 16 mm thick (capsules).
        "proximal": [{"radius": 0.012}, {"radius": 0.012}],
        "distal": [{"radius": 0.008}, {"radius": 0.008}],
        # The motor housings between the base joints (a 0.16 m x 0.08 m block on the
        # base line, centred at the origin) stand in the plane of the distal links.
        "obstacles": [{"name": "motor_block",
                       "polygon": [[-0.08, -0.06], [0.08, -0.06], [0.08, 0.02], [-0.08, 0.02]]}],
        # The cranks work in a plane below the distal links and above the motor block
        # top, and pass each other in two planes.
        "allowed_contacts": [["proximal1", "proximal2"], ["proximal1", "motor_block"],
                             ["proximal2", "motor_block"]],
    }
    return {
        "name": "DexTAR-like five-bar with link thickness, working mode (+,-)",
        "mechanism": "five_bar",
        "units": "m",
        "description": "Five-bar 5R with the DexTAR dimensions and bodies: link thickness, tool joint, "
                       "motor block; the distal links cannot cross each other near the type-2 singularity",
        "base": [[-0.1375, 0.0], [0.1375, 0.0]],
        "proximal": [0.23, 0.23],
        "distal": [0.23, 0.23],
        "working_mode": [1, -1],
        "bodies": bodies,
        "source": {
            "paper": "[Briot] (DexTAR: l_AB = l_DE = l_BC = l_CD = 0.23 m, a = 0.1375 m; docs/theory/five_bar.md)",
            "note": "Part sizes are not in the paper; chosen as plausible for a DexTAR-size robot: "
                    "tool joint radius 15 mm, distal links 16 mm and proximal links 24 mm thick, a "
                    "minimum of 20 degrees between the distal links at the tool joint, a motor block "
                    "0.16 m x 0.08 m between the base joints in the plane of the distal links. The "
                    "cranks pass each other and the motor block in planes of their own.",
        },
    }


def main():
    for stem, name, description, legs, figure in moma_files():
        doc = {"name": name, "mechanism": "moma", "units": "mm", "description": description,
               "legs": legs, "bodies": MOMA_BODIES,
               "source": {"paper": MOMA_PAPER, "figure": figure, "note": BODIES_NOTE}}
        with open(os.path.join(HERE, stem + ".json"), "w", encoding="utf-8") as f:
            json.dump(doc, f, ensure_ascii=False, indent=2)
            f.write("\n")
    with open(os.path.join(HERE, "machine_five_bar_dextar.json"), "w", encoding="utf-8") as f:
        json.dump(five_bar_file(), f, ensure_ascii=False, indent=2)
        f.write("\n")


if __name__ == "__main__":
    main()
