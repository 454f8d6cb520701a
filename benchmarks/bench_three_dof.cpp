// 3-DOF direct kinematics (the [Mitsi] elimination against the closed form,
// the 3-RPR sextic) and the certified real-scheme biglide workspace per depth.
#include <benchmark/benchmark.h>

#include <array>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "bench_common.hpp"
#include "pkmws/io/mechanism_file.hpp"

namespace {

using namespace pkmws;

// Through the interface: direct() is the closed form (with the limit checks);
// the Elimination capability is the paper's method.
const mechanisms::Mechanism& mitsi() {
  static const io::MechanismFile f = io::load_mechanism(bench::dataset("three_rrp_mitsi"));
  return *f.model;
}

const std::vector<double>& mitsi_joints() {
  constexpr double deg = std::numbers::pi / 180.0;
  static const std::vector<double> q{60 * deg, 10 * deg, 10 * deg};
  return q;
}

void assur_closed_form(benchmark::State& state) {
  const auto& m = mitsi();
  for (auto _ : state) benchmark::DoNotOptimize(m.direct(mitsi_joints()));
}
BENCHMARK(assur_closed_form)->Name("dk/three_rrp_mitsi/closed_form")->Unit(benchmark::kMicrosecond);

void assur_elimination(benchmark::State& state) {
  const auto elimination = mitsi().capability<mechanisms::Elimination>();
  for (auto _ : state) benchmark::DoNotOptimize(elimination->elimination(mitsi_joints()));
}
BENCHMARK(assur_elimination)->Name("dk/three_rrp_mitsi/elimination")->Unit(benchmark::kMicrosecond);

void rpr_sextic(benchmark::State& state) {
  static const io::MechanismFile f = io::load_mechanism(bench::dataset("three_rpr_prismatic"));
  const std::vector<double> rho{1.809, 1.142, 0.694};
  for (auto _ : state) benchmark::DoNotOptimize(f.model->direct(rho));
}
BENCHMARK(rpr_sextic)->Name("dk/three_rpr_prismatic/sextic_6_poses")->Unit(benchmark::kMicrosecond);

void biglide_real_certified(benchmark::State& state) {
  static const io::MechanismFile f = io::load_mechanism(bench::dataset("biglide_real"));
  const int depth = static_cast<int>(state.range(0));
  double width = 0.0;
  for (auto _ : state) {
    const auto e = f.model->workspace_enclosure(depth);
    width = e.width() / e.area_estimate();
  }
  state.counters["relative_width"] = width;
}
BENCHMARK(biglide_real_certified)
    ->Name("certified/biglide_real/depth")
    ->DenseRange(5, 9, 1)
    ->Unit(benchmark::kMillisecond);

}  // namespace
