#!/usr/bin/env bash
# Regenerates the committed figures of docs/figures (used by README.md) from
# the bundled datasets: docs/figures/generate.sh [path/to/pkmws].
# (bench_error_vs_time.svg comes from benchmarks/run.sh, not from here.)
set -euo pipefail
cd "$(dirname "$0")/../.."
pkmws=${1:-build/bin/pkmws}
d=docs/figures
for f in moma_m1_g0_l250 moma_m3_l250 moma_m5_gp5_gm5_l195 five_bar_dextar_pp machine_moma_m1; do
  "$pkmws" export "datasets/$f.json" -f svg -o "$d/$f.svg"
done
# [Briot] fig. 10: pressure-angle bands of the DexTAR in working mode (+1, -1).
"$pkmws" levels datasets/five_bar_dextar_pm_alpha80.json --criterion pressure_angle --levels 20,40,60,80 \
  --svg "$d/levels/dextar_pm_alpha.svg" >/dev/null
# [Briot] fig. 13: PAMINSA regions of R_1 <= R_max at three orientations (the certified limited region).
for phi in 0 25 50; do
  for r in 200 110; do
    "$pkmws" export "datasets/three_rpr_paminsa_phi${phi}_r${r}.json" -f svg -o "$d/levels/paminsa_phi${phi}_r${r}.svg"
  done
done
# Comparing designs (docs/design_space.md): MOMA M1 at l = 250 mm against gamma = +5 deg at l = 195 mm.
"$pkmws" diff datasets/moma_m1_g0_l250.json datasets/moma_m1_gp5_l195.json -o "$d/diff_moma_m1.svg" >/dev/null
# The MOMA program of building (docs/design_space.md): the sweeps in a scratch directory, the figure here.
tmp=$(mktemp -d)
bash apps/program_of_building.sh "$pkmws" "$tmp" >/dev/null
cp "$tmp/program_of_building.svg" "$d/program_of_building.svg"
rm -rf "$tmp"
# The README's Python example (needs the module: build/python).
PYTHONPATH=build/python "${PYTHON:-/usr/bin/python3}" examples/python/readme_figure.py "$d/python_workspace.png" >/dev/null
echo "figures written to $d"
