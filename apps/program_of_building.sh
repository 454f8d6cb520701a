#!/usr/bin/env bash
# The MOMA program of building ([Vasilic] §4): every configuration M1-M5 (with
# its gamma variants) against rod length 150-300 mm, one sweep per
# configuration (examples/sweeps/program_*.json, 17 rod lengths each: every
# 10 mm plus the bundled 195 mm), then the figure (area and largest inscribed
# rectangle vs rod length) and the Markdown tables (area, rectangle, and the
# real area of the three configurations whose machine files have bodies).
# Called by apps/demo.sh; about half a minute on two cores.
set -euo pipefail
pkmws=${1:-build/bin/pkmws}
out=${2:-out}
cd "$(dirname "$0")/.."
mkdir -p "$out"
configs=(m1_g0 m1_gm5 m1_gp5 m2 m3 m4_g0_gp5 m4_gm5_g0 m4_gm5_gp5 m5_g0_gm5 m5_gp5_g0 m5_gp5_gm5)
labels=("M1 γ = 0°" "M1 γ = −5°" "M1 γ = +5°" "M2" "M3" "M4 γ = 0°/+5°" "M4 γ = −5°/0°" "M4 γ = −5°/+5°"
        "M5 γ = 0°/−5°" "M5 γ = +5°/0°" "M5 γ = +5°/−5°")
echo "MOMA program of building: ${#configs[@]} configurations x 17 rod lengths (150-300 mm):"
csvs=()
for k in "${!configs[@]}"; do
  csv="$out/program_${configs[$k]}.csv"
  "$pkmws" sweep "examples/sweeps/program_${configs[$k]}.json" -o "$csv" --no-timing
  csvs+=("$csv=${labels[$k]}")
done
common=(--x rod_length --x-label "rod length l (mm)" --mark 180,195,250)
"$pkmws" chart "${csvs[@]}" "${common[@]}" --y area --y rectangle_area \
  --y-label "workspace area (mm²)" --y-label "largest inscribed rectangle (mm²)" \
  --mark-label "bundled rod lengths (180, 195, 250 mm)" \
  --title "MOMA program of building: configurations M1–M5 against rod length" \
  --caption "Exact workspace area and certified largest axis-aligned inscribed rectangle (relative width 1e-4) per configuration; guides at x = ∓100 mm, stroke 0–200 mm; one design per dot. Mirror-image configurations coincide (M1 ∓5°; M4 0°/+5° and −5°/0°; M5 0°/−5° and +5°/0°)." \
  -o "$out/program_of_building.svg"
"$pkmws" chart "${csvs[@]}" "${common[@]}" --y area --y rectangle_area --y real_area \
  --y-label "workspace area (mm²)" --y-label "largest inscribed rectangle (mm²)" \
  --y-label "real area (mm²), machine files with bodies" --markdown "$out/program_of_building.md"
