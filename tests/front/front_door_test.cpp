// The front door (pkmws/pkmws.hpp) against independent computations: a grid
// count of the mechanism's own membership test, a grid of the pressure angle,
// the 3-DOF orientation default, and an export read back.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>
#include <sstream>

#include "pkmws/pkmws.hpp"

namespace pkmws {
namespace {

const std::filesystem::path kData = std::filesystem::path(PKMWS_SOURCE_DIR) / "datasets";

// Area of {reachable} by the midpoint rule on an n x n grid over the bounds:
// independent of the exact boundary (error ~ perimeter x cell size).
double grid_area(const MechanismFile& f, int n, const std::function<bool(double, double)>& inside) {
  const geometry::Box b = f.model->bounds();
  const double dx = b.width() / n, dy = b.height() / n;
  long count = 0;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      if (inside(b.min.x + (i + 0.5) * dx, b.min.y + (j + 0.5) * dy)) ++count;
    }
  }
  return static_cast<double>(count) * dx * dy;
}

TEST(FrontDoor, ExactAreaAgreesWithAGridOfTheMembershipTest) {
  const MechanismFile f = load(kData / "moma_m1_g0_l250.json");
  const Area a = area(f);
  EXPECT_TRUE(a.exact);
  EXPECT_FALSE(a.limited);
  EXPECT_EQ(a.units, "mm");
  EXPECT_NEAR(a.lower, a.upper, 1e-9 * a.upper);
  const double grid = grid_area(f, 800, [&](double x, double y) { return f.model->reachable({x, y, 0.0}); });
  EXPECT_NEAR(a.lower, grid, 5e-3 * a.lower);
}

TEST(FrontDoor, LimitedAreaBracketsAGridOfThePressureAngle) {
  const MechanismFile f = load(kData / "five_bar_dextar_pm_alpha40.json");
  const Area a = area(f, 1e-6);
  EXPECT_TRUE(a.limited);
  EXPECT_FALSE(a.exact);
  EXPECT_LE(a.lower, a.upper);
  EXPECT_LE(a.upper - a.lower, 1e-5 * a.upper);
  // The grid: reachable in the file's mode with every pressure angle <= 40 deg.
  const double grid = grid_area(f, 700, [&](double x, double y) {
    for (const auto& e : evaluate(f, x, y)) {
      if (!e.reachable) continue;
      bool ok = !e.pressure_angle_deg.empty();
      for (double alpha : e.pressure_angle_deg) ok = ok && alpha <= 40.0;
      if (ok) return true;
    }
    return false;
  });
  EXPECT_NEAR(0.5 * (a.lower + a.upper), grid, 1e-2 * a.upper);
  // The region: inner inside the bounds, outer around them.
  const certified::CertifiedRegion r = region(f);
  EXPECT_LE(r.inner.area(), a.lower * (1 + 1e-12));
  EXPECT_GE(r.outer.area(), a.upper * (1 - 1e-12));
}

TEST(FrontDoor, EvaluateDefaultsToTheFilesOrientation) {
  const MechanismFile f = load(kData / "three_rpr_paminsa_phi25_r200.json");
  ASSERT_NEAR(f.model->orientation(), 25.0 * std::numbers::pi / 180.0, 1e-12);
  const auto by_default = evaluate(f, 0.05, 0.02);
  const auto stated = evaluate(f, 0.05, 0.02, 25.0 * std::numbers::pi / 180.0);
  const auto other = evaluate(f, 0.05, 0.02, 0.0);
  ASSERT_EQ(by_default.size(), stated.size());
  ASSERT_FALSE(by_default.empty());
  EXPECT_EQ(by_default[0].joints, stated[0].joints);
  EXPECT_NE(by_default[0].joints, other[0].joints);
  EXPECT_THROW(evaluate(f, NAN, 0.0), InputError);
}

TEST(FrontDoor, ExportWritesTheBoundaryItMeasures) {
  const MechanismFile f = load(kData / "moma_m1_g0_l250.json");
  const auto out = std::filesystem::temp_directory_path() / "pkmws_front_door.csv";
  export_boundary(f, io::ExportFormat::csv, out);
  std::ifstream in(out);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find("arc"), std::string::npos);  // MOMA's boundary has arcs
  std::filesystem::remove(out);
  const std::string wkt = export_boundary(f, io::ExportFormat::wkt);
  EXPECT_EQ(wkt.rfind("MULTIPOLYGON", 0), 0u);
}

TEST(FrontDoor, BadInputIsAnInputError) {
  EXPECT_THROW(load(kData / "no_such_file.json"), InputError);
  const MechanismFile f = load(kData / "five_bar_dextar_pm_alpha40.json");
  EXPECT_THROW(area(f, 0.0), InputError);
}

}  // namespace
}  // namespace pkmws
