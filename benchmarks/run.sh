#!/usr/bin/env bash
# make bench: the Google Benchmark suite (short, bounded runs), then the report
# generator, which measures exact against grid and writes docs/benchmarks.md
# and docs/figures/bench_error_vs_time.svg, then benchmarks/level_sets.py its
# section "Certified level sets". About a quarter of an hour on 2 cores. When the
# Python module is built (build/python), benchmarks/python_overhead.py then
# replaces the report's section "Python module overhead" (Python against C++
# per call and per point, measured side by side) and
# benchmarks/design_space.py its section "Design-space sweeps" (designs per
# second of pkmws and of shapely/GEOS on the same MOMA designs, threads and
# MPI ranks, the cost against the number of parameters).
#   PKMWS_BUILD_DIR  build directory (default: build, what `make build` uses)
#   BENCH_MIN_TIME   --benchmark_min_time per case in seconds (default 0.05)
#   BENCH_FILTER     --benchmark_filter regex (default: all)
#   BENCH_LEVEL_REPEATS  more runs of the levels/ two-thread cases (default 4)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${PKMWS_BUILD_DIR:-$root/build}"
for exe in pkmws_bench pkmws_bench_report; do
  if [ ! -x "$build/bin/$exe" ]; then
    echo "run.sh: $build/bin/$exe not found; build first (make build, PKMWS_BUILD_BENCHMARKS=ON)" >&2
    exit 2
  fi
done
mkdir -p "$root/docs/figures"
"$build/bin/pkmws_bench" \
  --benchmark_min_time="${BENCH_MIN_TIME:-0.05}" \
  --benchmark_filter="${BENCH_FILTER:-.}" \
  --benchmark_out="$build/bench.json" --benchmark_out_format=json
"$build/bin/pkmws_bench_report" \
  --out "$root/docs/benchmarks.md" \
  --figure "$root/docs/figures/bench_error_vs_time.svg" \
  --gbench "$build/bench.json"
# Certified level sets against grids of the same criteria (the levels/ cases),
# with BENCH_LEVEL_REPEATS (default 4) more runs of the two-thread cases: the
# report takes the median of their paired speed-ups (a busy spell of this
# machine's shared second core moves all the pairs of one case).
repeats=()
if "$build/bin/pkmws_bench" --benchmark_list_tests --benchmark_filter="${BENCH_FILTER:-.}" | grep '^levels/1e-6/.*/threads:2' >/dev/null; then
  for k in $(seq 1 "${BENCH_LEVEL_REPEATS:-4}"); do
    "$build/bin/pkmws_bench" --benchmark_filter='^levels/1e-6/.*/threads:2' \
      --benchmark_out="$build/bench_levels_threads_$k.json" --benchmark_out_format=json >/dev/null
    repeats+=(--repeat "$build/bench_levels_threads_$k.json")
  done
fi
python3 "$root/benchmarks/level_sets.py" --gbench "$build/bench.json" "${repeats[@]}" --report "$root/docs/benchmarks.md"
if compgen -G "$build/python/pkmws/_pkmws*.so" >/dev/null; then
  # The interpreter the module was built for (CMake cache), else python3.
  py="$(sed -n 's/^PKMWS_PYTHON3:[A-Z]*=//p' "$build/CMakeCache.txt" 2>/dev/null | head -n 1)"
  PYTHONPATH="$build/python" "${py:-python3}" "$root/benchmarks/python_overhead.py" --report "$root/docs/benchmarks.md"
  # Design-space sweeps: pkmws (in-process, threads, MPI ranks) against
  # shapely/GEOS on the same designs, about two minutes.
  PYTHONPATH="$build/python" PKMWS_BUILD_DIR="$build" "${py:-python3}" "$root/benchmarks/design_space.py" \
    --report "$root/docs/benchmarks.md"
else
  echo "run.sh: the Python module is not built ($build/python); no Python overhead and design-space sections" >&2
fi
echo "wrote docs/benchmarks.md and docs/figures/bench_error_vs_time.svg"
