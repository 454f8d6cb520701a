// pkmws_bench: Google Benchmark cases for the exact workspaces and the grid
// baseline. Every case checks its result once (against an independent
// computation) before it is timed, and reports an error instead of a time
// when the check fails.
#include <benchmark/benchmark.h>

#include <cmath>
#include <map>
#include <memory>
#include <string>

#include "bench_common.hpp"
#include "pkmws/geometry/region.hpp"
#include "pkmws/grid/sampler.hpp"
#include "pkmws/io/mechanism_file.hpp"

using namespace pkmws;

namespace {

const io::MechanismFile& load(const std::string& stem) {
  static std::map<std::string, std::unique_ptr<io::MechanismFile>> cache;
  auto& slot = cache[stem];
  if (!slot) slot = std::make_unique<io::MechanismFile>(io::load_mechanism(bench::dataset(stem)));
  return *slot;
}

double exact_area(const io::MechanismFile& m) { return m.model->workspace().area(); }

// Exact workspace (build + area). Check: the area lies in the certified
// bracket of a 1000^2 grid (MOMA), or within 0.5% of a 400^2 grid (others:
// no certified cell test).
void exact_workspace(benchmark::State& state, const std::string& stem) {
  const auto& m = load(stem);
  const double area = exact_area(m);
  grid::CartesianOptions check;
  const bool certified = grid::MembershipKernel(*m.model).certified();
  check.cells_x = check.cells_y = certified ? 1000 : 400;
  check.certified_bounds = certified;
  const auto g = grid::cartesian(*m.model, check);
  const bool ok = certified ? (*g.area_lower <= area && area <= *g.area_upper)
                            : std::abs(g.area - area) <= 5e-3 * area;
  if (!ok) {
    state.SkipWithError(("exact area " + std::to_string(area) + " disagrees with the grid check").c_str());
    return;
  }
  for (auto _ : state) {
    const geometry::Region region = m.model->workspace();
    benchmark::DoNotOptimize(region.area());
  }
  state.counters["area"] = area;
}

bool within(const grid::SampleResult& r, double exact, double rel) {
  if (r.area_lower && r.area_upper && r.bounds_certified && !(*r.area_lower <= exact && exact <= *r.area_upper)) {
    return false;
  }
  return std::abs(r.area - exact) <= rel * exact;
}

// Uniform grid: N x N cell-centre tests per iteration.
void cartesian_grid(benchmark::State& state, const std::string& stem, grid::Isa isa, int threads, std::size_t n) {
  const auto& m = load(stem);
  const double exact = exact_area(m);
  grid::Execution e;
  e.isa = isa;
  e.threads = threads;
  grid::CartesianOptions o;
  o.cells_x = o.cells_y = n;
  o.certified_bounds = true;
  if (!within(grid::cartesian(*m.model, o, e), exact, 2e-4)) {
    state.SkipWithError("grid area outside its certified bracket or off the exact area");
    return;
  }
  o.certified_bounds = false;
  for (auto _ : state) benchmark::DoNotOptimize(grid::cartesian(*m.model, o, e).area);
  state.counters["points_per_second"] =
      benchmark::Counter(double(n) * double(n), benchmark::Counter::kIsIterationInvariantRate);
}

void polar_grid(benchmark::State& state, const std::string& stem, int threads) {
  const auto& m = load(stem);
  const double exact = exact_area(m);
  grid::Execution e;
  e.threads = threads;
  grid::PolarOptions o;
  o.rings = 2000;
  o.sectors = 6284;
  o.certified_bounds = true;
  if (!within(grid::polar(*m.model, o, e), exact, 2e-4)) {
    state.SkipWithError("polar area outside its certified bracket");
    return;
  }
  o.certified_bounds = false;
  for (auto _ : state) benchmark::DoNotOptimize(grid::polar(*m.model, o, e).area);
  state.counters["points_per_second"] =
      benchmark::Counter(double(o.rings) * double(o.sectors), benchmark::Counter::kIsIterationInvariantRate);
}

void quadtree(benchmark::State& state, const std::string& stem, int depth, int threads) {
  const auto& m = load(stem);
  const double exact = exact_area(m);
  grid::Execution e;
  e.threads = threads;
  grid::AdaptiveOptions o;
  o.depth = depth;
  const auto first = grid::adaptive(*m.model, o, e);
  if (!within(first, exact, 1e-2)) {
    state.SkipWithError("quadtree bracket does not contain the exact area");
    return;
  }
  for (auto _ : state) benchmark::DoNotOptimize(grid::adaptive(*m.model, o, e).area);
  state.counters["points_per_second"] =
      benchmark::Counter(double(first.points_tested), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["guaranteed_rel_error"] = 0.5 * (*first.area_upper - *first.area_lower) / exact;
  state.counters["observed_rel_error"] = std::abs(first.area - exact) / exact;
}

void joint_sweep(benchmark::State& state, const std::string& stem, int threads) {
  const auto& m = load(stem);
  const double exact = exact_area(m);
  grid::Execution e;
  e.threads = threads;
  grid::JointSweepOptions o;
  o.samples = 500;
  o.raster_cells = 100;
  const auto first = grid::joint_sweep(*m.model, o, e);
  if (!(*first.area_lower <= exact && exact <= *first.area_upper)) {
    state.SkipWithError("DK sweep raster bracket does not contain the exact area");
    return;
  }
  for (auto _ : state) benchmark::DoNotOptimize(grid::joint_sweep(*m.model, o, e).area);
  state.counters["dk_per_second"] = benchmark::Counter(250000.0, benchmark::Counter::kIsIterationInvariantRate);
}

}  // namespace

int main(int argc, char** argv) {
  for (const auto& stem : bench::dataset_stems()) {
    bool has_workspace = true;
    try {
      (void)load(stem).model->workspace();
    } catch (const std::exception&) {
      has_workspace = false;  // e.g. a lone Pi-joint
    }
    if (!has_workspace) continue;
    benchmark::RegisterBenchmark(("exact/" + stem).c_str(), exact_workspace, stem)->Unit(benchmark::kMicrosecond);
  }
  const std::string m1 = "moma_m1_g0_l250";
  for (const grid::Isa isa : grid::available_isas()) {
    for (const int threads : {1, 2}) {
      benchmark::RegisterBenchmark(
          ("cartesian_4000/" + m1 + "/" + std::string(grid::to_string(isa)) + "/threads:" + std::to_string(threads))
              .c_str(),
          cartesian_grid, m1, isa, threads, std::size_t{4000})
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime();
    }
  }
  for (const auto& c : bench::report_cases()) {
    benchmark::RegisterBenchmark(("cartesian_4000/" + std::string(c.stem) + "/best/threads:2").c_str(),
                                 cartesian_grid, std::string(c.stem), grid::Isa::best, 2, std::size_t{4000})
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
  }
  for (const int threads : {1, 2}) {
    benchmark::RegisterBenchmark(("polar_2000x6284/" + m1 + "/threads:" + std::to_string(threads)).c_str(),
                                 polar_grid, m1, threads)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
    for (const int depth : {8, 12, 16}) {
      benchmark::RegisterBenchmark(
          ("quadtree/" + m1 + "/depth:" + std::to_string(depth) + "/threads:" + std::to_string(threads)).c_str(),
          quadtree, m1, depth, threads)
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime();
    }
    benchmark::RegisterBenchmark(("dk_sweep_500x500/" + m1 + "/threads:" + std::to_string(threads)).c_str(),
                                 joint_sweep, m1, threads)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
  }
  bench::register_level_set_benchmarks();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
