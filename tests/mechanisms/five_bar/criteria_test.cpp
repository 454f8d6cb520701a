// Five-bar criterion fields with crank limits and Π-joint drives: the box test
// against the limited workspace is conservative, and the certified limited
// areas contain dense-grid estimates through the mechanism's own evaluation.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "mechanisms/five_bar/criteria.hpp"
#include "pkmws/criteria/fields.hpp"
#include "pkmws/io/mechanism_file.hpp"
#include "support/field_checks.hpp"
#include "support/fixtures.hpp"

namespace {

using namespace pkmws;
using geometry::Box;
using geometry::Point;
constexpr double kDeg = std::numbers::pi / 180.0;

// DexTAR (+1, +1) with cranks limited to [-30, 150] and [30, 210] degrees.
mechanisms::FiveBar limited_dextar() {
  const double l = 0.23, a = 0.1375;
  std::array<mechanisms::FiveBarLeg, 2> legs;
  legs[0] = {{-a, 0.0}, l, l, 1, std::array<double, 2>{-30 * kDeg, 150 * kDeg}, std::nullopt};
  legs[1] = {{a, 0.0}, l, l, 1, std::array<double, 2>{30 * kDeg, 210 * kDeg}, std::nullopt};
  return mechanisms::FiveBar(legs);
}

// Area of {reachable, alpha <= t} (the file's working mode) by cell centres on an n x n grid.
double grid_area(const mechanisms::Mechanism& m, double alpha, int n) {
  return test::grid_area(m.bounds(), n, [&](Point p) {
    const auto e = m.evaluate({p.x, p.y, 0.0}, {});
    return e.front().reachable && e.front().pressure_angle_deg.at(0) <= alpha;
  });
}

TEST(FiveBarCriteria, BoxTestRespectsCrankLimits) {
  const auto m = limited_dextar();
  const auto c = criteria::five_bar_pressure_angle(m);
  const Box bb = m.bounds();
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> ux(bb.min.x, bb.max.x), uy(bb.min.y, bb.max.y), us(1e-4, 2e-2);
  int inside = 0, outside = 0;
  for (int k = 0; k < 20000; ++k) {
    const Point p{ux(rng), uy(rng)};
    const double h = us(rng);
    const Box b{{p.x - h, p.y - h}, {p.x + h, p.y + h}};
    const auto state = c.within_test(b);
    for (int a = 0; a <= 4; ++a) {
      for (int d = 0; d <= 4; ++d) {
        const Point q{b.min.x + b.width() * a / 4.0, b.min.y + b.height() * d / 4.0};
        const bool r = m.reachable({q.x, q.y, 0.0});
        if (state == certified::CellState::inside) {
          EXPECT_TRUE(r) << q.x << " " << q.y;
        }
        if (state == certified::CellState::outside) {
          EXPECT_FALSE(r) << q.x << " " << q.y;
        }
      }
    }
    inside += state == certified::CellState::inside;
    outside += state == certified::CellState::outside;
  }
  EXPECT_GT(inside, 1000);  // the test decides most boxes
  EXPECT_GT(outside, 1000);
}

TEST(FiveBarCriteria, CrankLimitedAreaAgainstAGridAndTheFreeCranks) {
  const double alpha = 40.0;
  mechanisms::Design d;
  d.path = "limited DexTAR";
  d.model = std::make_shared<mechanisms::FiveBar>(limited_dextar());
  certified::LevelSetOptions o;
  o.relative_tolerance = 1e-6;
  const auto r = criteria::limited_workspace(d, {{"pressure_angle", alpha}}, o);
  EXPECT_LE(r.region.width(), 1e-6 * r.region.area_upper);
  const double grid = grid_area(*d.model, alpha, 700);
  EXPECT_NEAR(grid, 0.5 * (r.region.area_lower + r.region.area_upper), 4e-3 * grid);
  // Limiting the cranks can only remove area: inside the free DexTAR's bounds.
  const auto free = io::load_mechanism(test::dataset("five_bar_dextar_pp_alpha40"));
  const auto rf = criteria::limited_workspace(free, {{"pressure_angle", alpha}}, o);
  EXPECT_LT(r.region.area_upper, rf.region.area_lower);
  EXPECT_GT(r.region.area_lower, 0.1 * rf.region.area_upper);
}

TEST(FiveBarCriteria, VelocityRatioAndConditionNumberAgreeWithTheEvaluation) {
  const auto f = io::load_mechanism(test::dataset("five_bar_dextar_pm"));
  const auto& m = *f.model;
  const auto vr = criteria::fields_for(f, "velocity_ratio").at(0);
  const auto kc = criteria::fields_for(f, "condition_number").at(0);
  const Box bb = m.bounds();
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> ux(bb.min.x, bb.max.x), uy(bb.min.y, bb.max.y);
  int checked = 0;
  for (int n = 0; n < 5000 && checked < 300; ++n) {
    const Point p{ux(rng), uy(rng)};
    const auto e = m.evaluate({p.x, p.y, 0.0}, {});
    if (!e.front().reachable) {
      EXPECT_TRUE(std::isnan(kc.value(p)));  // outside the working mode's workspace
    }
    if (!e.front().reachable || e.front().singular) continue;
    const double ratio = *e.front().velocity_ratio, kappa = e.front().condition_number;
    if (!(ratio < 1e3 && kappa < 1e3)) continue;  // near a singularity
    EXPECT_NEAR(vr.surrogate->value(p), ratio * ratio, 1e-9 * ratio * ratio);
    test::expect_same_sublevel(kc, p, kappa, {1.5, 3.0, 10.0});
    EXPECT_NEAR(kc.value(p), kappa, 1e-9 * kappa);  // κ from the surrogate (the GCI's) against the SVD's
    const Box box{{p.x - 2e-4, p.y - 1e-4}, {p.x + 1e-4, p.y + 2e-4}};
    if (vr.surrogate->domain(box) == certified::CellState::inside) test::check_field(*vr.surrogate, p, 1e-6, box);
    if (kc.surrogate->domain(box) == certified::CellState::inside) test::check_field(*kc.surrogate, p, 1e-6, box);
    ++checked;
  }
  EXPECT_EQ(checked, 300);
  // The certified κ <= 3 area against a grid through the evaluation (at the
  // base joints, where every level curve ends, the bounds narrow slowly: 1e-3).
  certified::LevelSetOptions o;
  o.relative_tolerance = 1e-3;
  const auto r = criteria::limited_workspace(f, {{"condition_number", 3.0}}, o);
  EXPECT_LE(r.region.width(), 1e-3 * r.region.area_upper);
  const double grid = test::grid_area(bb, 500, [&](Point p) {
    const auto e = m.evaluate({p.x, p.y, 0.0}, {});
    return e.front().reachable && e.front().condition_number <= 3.0;
  });
  EXPECT_NEAR(grid, 0.5 * (r.region.area_lower + r.region.area_upper), 5e-3 * grid);
}

TEST(FiveBarCriteria, PiJointDrivenFiveBarAgainstAGrid) {
  const auto f = io::load_mechanism(test::dataset("five_bar_pi_joint"));
  certified::LevelSetOptions o;
  o.relative_tolerance = 1e-5;
  const double alpha = 45.0;
  const auto r = criteria::limited_workspace(f, {{"pressure_angle", alpha}}, o);
  EXPECT_LE(r.region.width(), 1e-5 * r.region.area_upper);
  EXPECT_LT(r.region.area_upper, f.model->workspace().area());
  const double grid = grid_area(*f.model, alpha, 700);
  EXPECT_NEAR(grid, 0.5 * (r.region.area_lower + r.region.area_upper), 4e-3 * grid);
}

}  // namespace
