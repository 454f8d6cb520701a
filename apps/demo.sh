#!/usr/bin/env bash
# make demo: exact workspaces of every bundled mechanism, their figures and a
# summary table in out/ (summary.md, summary.json, one SVG per dataset), a
# design sweep (CSV/JSON), an atlas figure, the MOMA program of building
# (apps/program_of_building.sh) and two syntheses (pkmws optimize).
set -euo pipefail
pkmws=${1:-build/bin/pkmws}
out=${2:-out}
cd "$(dirname "$0")/.."
"$pkmws" batch datasets/*.json --out "$out"
echo
echo "Reference case ([Vasilic] §4.1, M1: h = 200, l = 250, R = (-100, 0), (100, 0)):"
"$pkmws" area datasets/moma_m1_g0_l250.json
echo
echo "3-RRP of [Mitsi] (reconstructed), crank angles 60, 10, 10 deg: both assembly modes ([Mitsi] fig. 4):"
"$pkmws" dk datasets/three_rrp_mitsi.json 60 10 10 --json --svg "$out/three_rrp_mitsi_assembly" \
  >"$out/three_rrp_mitsi_dk.json"
echo "  $out/three_rrp_mitsi_dk.json (poses, platform points, the eliminant and its roots),"
echo "  $out/three_rrp_mitsi_assembly_1.svg, $out/three_rrp_mitsi_assembly_2.svg"
echo
echo "Design space: MOMA M1 over rod length x guide angle (table) and rod length x stroke (atlas):"
"$pkmws" sweep examples/sweeps/moma_m1_rods.json -o "$out/sweep_moma_m1_rods.csv" --json "$out/sweep_moma_m1_rods.json"
"$pkmws" sweep examples/sweeps/moma_m1_atlas.json -o "$out/sweep_moma_m1_atlas.csv"
"$pkmws" atlas "$out/sweep_moma_m1_atlas.csv" --x rod_length --y stroke --metric rectangle_area \
  --x-label "rod length l (mm)" --y-label "stroke h (mm)" --metric-label "rectangle area (mm²)" \
  --title "MOMA M1: largest inscribed rectangle (guides at x = ∓100 mm)" -o "$out/atlas_moma_m1.svg"
echo
bash apps/program_of_building.sh "$pkmws" "$out"
echo
echo "Synthesis: the shortest MOMA M1 rods that carry an 80 x 40 mm task with 5 mm clearance"
echo "(closed form: sqrt(140^2 + 120^2) + 5 = 189.3909 mm), and the smallest machine (rods + stroke)"
echo "whose inscribed rectangle is at least 20000 mm²:"
"$pkmws" optimize examples/optimize/moma_m1_shortest_rods.json -o "$out/optimize_moma_m1_shortest_rods.json" \
  --design "$out/moma_m1_shortest_rods.json" | sed -n '1,3p'
"$pkmws" optimize examples/optimize/moma_m1_smallest_machine.json --history "$out/optimize_moma_m1_smallest_machine.csv" \
  | sed -n '1,6p'
echo
echo "Figures and the summary table are in $out/ (open $out/summary.md)."
