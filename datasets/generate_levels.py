#!/usr/bin/env python3
"""Criteria datasets of [Briot] (issue 5): DexTAR with alpha_max in {20, 40, 60, 80} deg
for each working mode (fig. 10, 16 files) and the planar PAMINSA with phi in {0, 25, 50} deg
and R_max in {200, 110} N (fig. 13, 6 files). Derived from the base datasets."""
import json
import os

here = os.path.dirname(os.path.abspath(__file__))


def derived(base, name, criteria, figure):
    """A copy of a base dataset with a name, criteria limits and the figure it reproduces."""
    d = dict(base)
    d["name"] = name
    d["criteria"] = criteria
    d["source"] = dict(base.get("source", {}))
    d["source"]["figure"] = figure
    return d


def write(stem, d):
    with open(os.path.join(here, stem + ".json"), "w") as f:
        json.dump(d, f, indent=2)
        f.write("\n")

modes = {"pp": "(+1, +1)", "pm": "(+1, -1)", "mp": "(-1, +1)", "mm": "(-1, -1)"}
for mode in modes:
    base = json.load(open(os.path.join(here, f"five_bar_dextar_{mode}.json")))
    for alpha in (20, 40, 60, 80):
        write(f"five_bar_dextar_{mode}_alpha{alpha}",
              derived(base, f"DexTAR five-bar, working mode {modes[mode]}, pressure angle <= {alpha} deg",
                      {"max_pressure_angle_deg": float(alpha)},
                      f"Fig. 10 (workspace limited by alpha_max = {alpha} deg), working mode {modes[mode]}"))

base = json.load(open(os.path.join(here, "three_rpr_paminsa.json")))
for phi in (0, 25, 50):
    for rmax in (200, 110):
        d = derived(base, f"Planar PAMINSA, phi = {phi} deg, R_max = {rmax} N at joint B1",
                    {"load": {"force_N": 100.0, "moment_Nm": 5.0}, "max_reaction_N": float(rmax),
                     "reaction_legs": [1]},
                    f"Fig. 13 (constant-orientation workspace, phi = {phi} deg, R_max = {rmax} N)")
        d["orientation_deg"] = float(phi)
        # The type-2 singular circle (radius <= 0.296 m for these phi) lies inside the window,
        # and the region is taken in the assembly mode of the centre, so the window never binds.
        d["analysis_window"] = [[-0.32, -0.32], [0.32, 0.32]]
        write(f"three_rpr_paminsa_phi{phi}_r{rmax}", d)

# PAMINSA at phi = 0 with the condition number of the homogenised Jacobian
# dq/dx', x' = (x, y, L phi), L the platform's circumradius (0.1 m, the default
# of criteria.characteristic_length): the region kappa <= 4 around the centre
# (docs/theory/level_sets.md, 3-RPR conditioning; not a figure of [Briot]).
d = derived(base, "Planar PAMINSA, phi = 0 deg, condition number <= 4",
            {"max_condition_number": 4.0},
            "Fig. 11 mechanism; sub-level set of the condition number of dq/dx' (not in the paper)")
d["orientation_deg"] = 0.0
d["analysis_window"] = [[-0.32, -0.32], [0.32, 0.32]]
write("three_rpr_paminsa_phi0_kappa4", d)

# The 3-PRP example with every chain's pressure angle ([Briot]'s method on
# [Mitsi]'s chains) at most 20 deg, at the file's orientation
# (docs/theory/level_sets.md, 3-RRP / 3-PRP; not a figure of either paper).
base_prp = json.load(open(os.path.join(here, "three_prp_example.json")))
write("three_prp_example_alpha20",
      derived(base_prp, "3-PRP example, pressure angle <= 20 deg",
              {"max_pressure_angle_deg": 20.0},
              "sub-level set of the chains' pressure angles (not in the paper)"))
# ... and where its Jacobian dq/dx' = B^-1 A (x' = (x, y, L phi), L the
# platform's circumradius) is conditioned better than 2.
write("three_prp_example_kappa2",
      derived(base_prp, "3-PRP example, condition number <= 2",
              {"max_condition_number": 2.0},
              "sub-level set of the condition number of dq/dx' (not in the paper)"))

# Biglide, simplified scheme ([Strutynskyi] fig. 8): the workspace where both
# actuators move at most t times faster than the tool along y, V_i / V_y <= t.
base = json.load(open(os.path.join(here, "biglide_simplified.json")))
for ratio in (2,):
    write(f"biglide_simplified_vratio{ratio}",
          derived(base, f"Biglide, simplified scheme, velocity ratio V_i/V_y <= {ratio}",
                  {"max_velocity_ratio": float(ratio)},
                  f"Fig. 8 (velocity ratio V/V_y), sub-level set V_i/V_y <= {ratio} for both sliders"))

# The same biglide with the rods' pressure angle alpha = acos|sin eps| <= 20 deg
# ([Briot]'s criterion on the simplified scheme; docs/theory/level_sets.md).
write("biglide_simplified_alpha20",
      derived(base, "Biglide, simplified scheme, pressure angle <= 20 deg",
              {"max_pressure_angle_deg": 20.0},
              "Fig. 3 (simplified scheme); sub-level set of the rods' pressure angle (not in the paper)"))

# MOMA M1 (gamma = -5 deg, 180 mm rods): the workspace where the rods' pressure
# angle stays below 15 deg, and where dq/dP is conditioned better than 3
# (docs/theory/level_sets.md, MOMA; [Vasilic] gives no criteria figure).
base = json.load(open(os.path.join(here, "moma_m1_gm5_l180.json")))
write("moma_criteria_m1_gm5_l180_alpha15",
      derived(base, "MOMA M1 (gamma = -5 deg), l = 180 mm, pressure angle <= 15 deg",
              {"max_pressure_angle_deg": 15.0},
              "Fig. 2b configuration; sub-level set of the rods' pressure angle (not in the paper)"))
write("moma_criteria_m1_gm5_l180_kappa3",
      derived(base, "MOMA M1 (gamma = -5 deg), l = 180 mm, condition number <= 3",
              {"max_condition_number": 3.0},
              "Fig. 2b configuration; sub-level set of the condition number of dq/dP (not in the paper)"))

# A simplified biglide whose rods align inside the workspace (l1 = 2000 mm,
# l2 = 300 mm, B = 500 mm: u_1 = (w_1, y + B) and u_2 = (w_2, y - B) are
# parallel where w_1 (y - B) = (y + B) w_2, the line y* = 676.5 mm), kept at
# least 20 mm from it: W minus the stadium around W's section of that line
# (docs/theory/level_sets.md, distance to the type-2 singularity; not in the paper).
base = json.load(open(os.path.join(here, "biglide_simplified.json")))
d = derived(base, "Biglide, simplified scheme, rods 2000 and 300 mm, at least 20 mm from the rods' alignment",
            {"min_singularity_distance": 20.0},
            "Fig. 3 (simplified scheme) with unequal rods; distance limit not in the paper")
d["rods"] = [2000.0, 300.0]
d["stroke"] = [[0.0, 2500.0], [0.0, 2500.0]]
d["source"]["note"] = ("Unequal rods so that the type-2 singularity (rods aligned) lies in the workspace: on the line "
                       "w_1 (y - B) = (y + B) w_2, y* = 676.5 mm.")
write("biglide_simplified_dsing20", d)
