#!/usr/bin/env bash
# make demo: exact workspaces of every bundled mechanism, their figures and a
# summary table in out/ (summary.md, summary.json, one SVG per dataset).
set -euo pipefail
pkmws=${1:-build/bin/pkmws}
out=${2:-out}
cd "$(dirname "$0")/.."
"$pkmws" batch datasets/*.json --out "$out"
echo
echo "Reference case (seed 000 §4.1, M1: h = 200, l = 250, R = (-100, 0), (100, 0)):"
"$pkmws" area datasets/moma_m1_g0_l250.json
echo
echo "Figures and the summary table are in $out/ (open $out/summary.md)."
