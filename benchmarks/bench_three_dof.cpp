// 3-DOF direct kinematics (the [Mitsi] elimination against the closed form,
// the 3-RPR sextic) and the certified real-scheme biglide workspace per depth.
#include <benchmark/benchmark.h>

#include <array>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "bench_common.hpp"
#include "pkmws/io/mechanism_file.hpp"
#include "pkmws/mechanisms/three_rpr.hpp"
#include "pkmws/mechanisms/three_rrp.hpp"

namespace {

using namespace pkmws;

const mechanisms::ThreeRrp& mitsi() {
  static const io::MechanismFile f = io::load_mechanism(bench::dataset("three_rrp_mitsi"));
  const auto* m = dynamic_cast<const mechanisms::ThreeRrp*>(f.model.get());
  if (!m) throw std::runtime_error("three_rrp_mitsi is not a 3-RRP");
  return *m;
}

const std::vector<double>& mitsi_joints() {
  constexpr double deg = std::numbers::pi / 180.0;
  static const std::vector<double> q{60 * deg, 10 * deg, 10 * deg};
  return q;
}

void assur_closed_form(benchmark::State& state) {
  const auto& m = mitsi();
  for (auto _ : state) benchmark::DoNotOptimize(m.direct_closed_form(mitsi_joints()));
}
BENCHMARK(assur_closed_form)->Name("dk/three_rrp_mitsi/closed_form")->Unit(benchmark::kMicrosecond);

void assur_elimination(benchmark::State& state) {
  const auto& m = mitsi();
  for (auto _ : state) benchmark::DoNotOptimize(m.direct_elimination(mitsi_joints()));
}
BENCHMARK(assur_elimination)->Name("dk/three_rrp_mitsi/elimination")->Unit(benchmark::kMicrosecond);

void rpr_sextic(benchmark::State& state) {
  static const io::MechanismFile f = io::load_mechanism(bench::dataset("three_rpr_prismatic"));
  const auto& m = dynamic_cast<const mechanisms::ThreeRpr&>(*f.model);
  const std::array<double, 3> rho{1.809, 1.142, 0.694};
  for (auto _ : state) benchmark::DoNotOptimize(m.direct_from_lengths(rho));
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
