// The grid report (pkmws/report/grid.hpp) against closed forms (the toy
// annulus, 40π; a Cartesian grid's error is bounded by the boundary's cells),
// the exact area of a MOMA file inside its certified grid bounds, its JSON
// text parsed back, its text form and its errors.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "pkmws/core/error.hpp"
#include "pkmws/pkmws.hpp"
#include "pkmws/report/grid.hpp"
#include "support/fixtures.hpp"
#include "support/report_fixtures.hpp"

namespace pkmws {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kAnnulus = 40 * kPi;  // 3 <= |P - (1, 2)| <= 7

report::GridOptions cells(std::size_t n) {
  report::GridOptions o;
  o.cells = n;
  o.threads = 1;
  return o;
}

TEST(ReportGrid, CartesianEstimateOfTheAnnulusIsWithinItsBoundaryCells) {
  const report::GridReport r = report::grid(test::toy_annulus_file(), cells(200));
  EXPECT_EQ(r.result.method, "cartesian");
  EXPECT_EQ(r.result.cells, 200u * 200u);
  // The box is 14 x 14 mm: only cells on the boundary (perimeter 20π) can be miscounted.
  const double h = 14.0 / 200;
  EXPECT_NEAR(r.result.area, kAnnulus, 20 * kPi * h * std::sqrt(2.0));
  EXPECT_NEAR(r.result.area, h * h * static_cast<double>(r.result.inside), 1e-9);
  EXPECT_EQ(r.area_units, "mm²");
  EXPECT_FALSE(r.polar || r.adaptive || r.sweep);
}

TEST(ReportGrid, PolarGridIsCentredOnTheBox) {
  report::GridOptions o = cells(60);
  o.polar = true;
  const report::GridReport r = report::grid(test::toy_annulus_file(), o);
  ASSERT_TRUE(r.polar);
  EXPECT_EQ(r.polar->rings, 60u);
  EXPECT_EQ(r.polar->sectors, 4 * static_cast<std::size_t>(std::llround(kPi * 60 / 4)));
  EXPECT_NEAR(r.polar->centre.x, 1.0, 1e-12);
  EXPECT_NEAR(r.polar->centre.y, 2.0, 1e-12);
  EXPECT_NEAR(r.polar->radius, 7 * std::sqrt(2.0), 1e-9);  // to the box's corner
  EXPECT_NEAR(r.result.area, kAnnulus, 0.05 * kAnnulus);
}

TEST(ReportGrid, CertifiedBoundsOfAMomaGridHoldTheExactArea) {
  const io::MechanismFile f = io::load_mechanism(test::dataset("moma_m1_g0_l180"));
  const report::GridReport r = report::grid(f, cells(64));
  ASSERT_TRUE(r.certified()) << r.bounds;
  const Area exact = pkmws::area(f);
  EXPECT_LE(*r.result.area_lower, exact.lower);
  EXPECT_GE(*r.result.area_upper, exact.upper);
  const auto j = test::parsed(report::to_json_text(r));
  EXPECT_EQ(j["area_lower"].get<double>(), *r.result.area_lower);
  EXPECT_EQ(j["area_upper"].get<double>(), *r.result.area_upper);
  EXPECT_FALSE(j.contains("area_lower_if_resolved"));
  EXPECT_EQ(j["bounds"], r.bounds);
}

TEST(ReportGrid, JsonTextAndTextStateTheEstimate) {
  report::GridOptions o = cells(16);
  o.adaptive = 2;
  const report::GridReport r = report::grid(test::toy_annulus_file(), o);
  ASSERT_TRUE(r.adaptive);
  EXPECT_EQ(r.adaptive->depth, 2u);
  EXPECT_EQ(r.adaptive->effective_cells, 64u);
  const auto j = test::parsed(report::to_json_text(r));
  EXPECT_EQ(j["method"], "grid");
  EXPECT_EQ(j["sampler"], "adaptive");
  EXPECT_EQ(j["name"], "toy annulus");
  EXPECT_EQ(j["units"], "mm");
  EXPECT_EQ(j["area"].get<double>(), r.result.area);
  EXPECT_EQ(j["root_cells"], 16);
  EXPECT_EQ(j["cells_per_level"].size(), 3u);
  EXPECT_EQ(j["points_tested"].get<std::uint64_t>(), r.result.points_tested);
  const std::string text = report::to_text(r);
  EXPECT_EQ(text.rfind("toy annulus (toy_rp)\narea       ", 0), 0u);
  char area[64];
  std::snprintf(area, sizeof area, "%.10g mm²", r.result.area);
  EXPECT_NE(text.find(area), std::string::npos);
  EXPECT_NE(text.find("adaptive quadtree, 16^2 root cells, depth 2 (64 cells per side)"), std::string::npos);
}

TEST(ReportGrid, RefusesTwoSamplersTooMuchWorkAndAnUnknownIsa) {
  const io::MechanismFile f = test::toy_annulus_file();
  const auto message = [&](const report::GridOptions& o) {
    try {
      report::grid(f, o);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  report::GridOptions o = cells(8);
  o.polar = o.sweep = true;
  EXPECT_EQ(message(o), "grid: give at most one of --polar, --adaptive, --sweep");
  o = cells(1024);
  o.adaptive = 15;
  EXPECT_EQ(message(o).rfind("--adaptive: --cells x 2^DEPTH must not exceed 2^24", 0), 0u);
  o = cells(8);
  o.isa = "sse9";
  EXPECT_EQ(message(o).rfind("--isa: expected scalar, baseline, avx2, avx512 or best, got \"sse9\"", 0), 0u);
}

}  // namespace
}  // namespace pkmws
