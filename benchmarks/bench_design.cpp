// Design-space cases: the inscribed rectangle at two precisions, and a MOMA
// rod-length sweep (exact area + inscribed circle + rectangle per design) on
// one and on two threads, reported as designs per second. Each case checks
// its result once before timing it.
#include <benchmark/benchmark.h>

#include <cmath>
#include <numeric>
#include <string>

#include "bench_common.hpp"
#include "pkmws/design/sweep.hpp"
#include "pkmws/geometry/inscribed_rectangle.hpp"
#include "pkmws/geometry/primitives.hpp"
#include "pkmws/io/mechanism_file.hpp"

using namespace pkmws;

namespace {

// Rectangle in a disk of radius 1: the square of area 2 (closed form).
void rectangle_disk(benchmark::State& state, double precision) {
  const geometry::Region d = geometry::disk({0.25, -0.5}, 1.0);
  const geometry::Component c = d.components().at(0);
  const auto r = geometry::largest_inscribed_rectangle(c, precision, {}, &d);
  if (!(r.verified && r.area <= 2.0 + 1e-12 && r.area_upper >= 2.0 - 1e-12)) {
    state.SkipWithError("the certified interval misses the closed form 2 r^2");
    return;
  }
  for (auto _ : state) benchmark::DoNotOptimize(geometry::largest_inscribed_rectangle(c, precision, {}, &d));
  state.counters["evaluations"] = static_cast<double>(r.evaluations);
}
BENCHMARK_CAPTURE(rectangle_disk, 1e-6, 1e-6)->Name("design/rectangle/disk/1e-6")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(rectangle_disk, 1e-9, 1e-9)->Name("design/rectangle/disk/1e-9")->Unit(benchmark::kMillisecond);

// 31 rod lengths x 3 guide angles of MOMA M1 (examples/sweeps/moma_m1_rods.json).
void sweep_moma(benchmark::State& state) {
  const int threads = static_cast<int>(state.range(0));
  const design::SweepSpec spec =
      design::load_sweep(std::string(PKMWS_SOURCE_DIR) + "/examples/sweeps/moma_m1_rods.json");
  std::vector<std::size_t> all(design::design_count(spec));
  std::iota(all.begin(), all.end(), std::size_t{0});
  // Check: the design with l = 250 mm and both guides at 270 deg is the bundled M1 file.
  const double m1 = io::load_mechanism(bench::dataset("moma_m1_g0_l250")).model->workspace().area();
  bool found = false;
  for (std::size_t i = 0; i < all.size(); ++i) {
    const auto v = design::design_values(spec, i);
    if (v[0] == 250.0 && v[1] == 270.0) {
      const auto row = design::evaluate_design(spec, i);
      found = row.status == "ok" && std::abs(*row.metrics[0] - m1) <= 1e-12 * m1;
    }
  }
  if (!found) {
    state.SkipWithError("the sweep's l = 250 mm design disagrees with the bundled M1 file");
    return;
  }
  for (auto _ : state) benchmark::DoNotOptimize(design::run_sweep(spec, all, threads));
  state.counters["designs_per_second"] =
      benchmark::Counter(static_cast<double>(all.size()), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(sweep_moma)->Name("design/sweep/moma_m1_rods/threads")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
