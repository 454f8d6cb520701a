// MOMA criterion fields: the surrogates against the mechanism's own
// evaluation (pressure angle from the rods' angle, velocity ratio from an SVD
// of dq/dP), jets against finite differences, and certified limited areas
// against closed forms and a dense grid.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "mechanisms/moma/criteria.hpp"
#include "pkmws/criteria/fields.hpp"
#include "pkmws/geometry/primitives.hpp"
#include "pkmws/io/mechanism_file.hpp"
#include "support/field_checks.hpp"
#include "support/fixtures.hpp"

namespace {

using namespace pkmws;
using geometry::Box;
using geometry::Point;
constexpr double kDeg = std::numbers::pi / 180.0;

io::MechanismFile moma(const std::string& stem) { return io::load_mechanism(test::dataset(stem)); }

const mechanisms::Moma& as_moma(const io::MechanismFile& f) { return dynamic_cast<const mechanisms::Moma&>(*f.model); }

TEST(MomaCriteria, SurrogatesAgreeWithTheEvaluationAndTheirDerivatives) {
  for (const char* stem : {"moma_m1_g0_l250", "moma_m1_gm5_l180", "moma_m5_gp5_gm5_l195"}) {
    SCOPED_TRACE(stem);
    const auto f = moma(stem);
    const auto& m = as_moma(f);
    const auto pa = criteria::moma_pressure_angle(m);
    const auto vr = criteria::moma_velocity_ratio(m);
    const auto rr = criteria::moma_reaction(m, 100.0);
    const auto kc = criteria::moma_condition_number(m);
    const Box bb = m.bounds();
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> ux(bb.min.x, bb.max.x), uy(bb.min.y, bb.max.y);
    int checked = 0;
    for (int n = 0; n < 4000 && checked < 200; ++n) {
      const Point p{ux(rng), uy(rng)};
      const auto e = m.evaluate({p.x, p.y, 0.0}, {});
      if (!e.front().reachable || e.front().singular) continue;
      const double alpha = e.front().pressure_angle_deg.at(0), ratio = *e.front().velocity_ratio;
      // cos²ε = sin²α; σ_max² of dq/dP (Eigen's SVD in evaluate).
      EXPECT_NEAR(pa.surrogate->value(p), std::pow(std::sin(alpha * kDeg), 2), 1e-12);
      EXPECT_NEAR(vr.surrogate->value(p), ratio * ratio, 1e-10 * ratio * ratio);
      EXPECT_NEAR(pa.value(p), alpha, 1e-12);
      EXPECT_NEAR(rr.value(p), 100.0 / std::cos(alpha * kDeg), 1e-9 * rr.value(p));
      // κ <= t  <=>  -(det / F)² <= -1 / (t + 1/t)² against the SVD's κ.
      const double kappa = e.front().condition_number;
      test::expect_same_sublevel(kc, p, kappa, {2.3, 2.5, 3.0});
      EXPECT_NEAR(kc.value(p), kappa, 1e-12 * kappa);
      // The sub-level sets agree with the criteria: α <= t  <=>  s <= level(t).
      for (double t : {25.0, 35.0, 45.0}) EXPECT_EQ(alpha <= t, pa.surrogate->value(p) <= pa.level(t));
      const Box box{{p.x - 0.4, p.y - 0.3}, {p.x + 0.2, p.y + 0.5}};
      if (pa.surrogate->domain(box) == certified::CellState::inside) test::check_field(*pa.surrogate, p, 1e-3, box);
      if (vr.surrogate->domain(box) == certified::CellState::inside) test::check_field(*vr.surrogate, p, 1e-3, box);
      if (kc.surrogate->domain(box) == certified::CellState::inside) test::check_field(*kc.surrogate, p, 1e-3, box);
      // The box test against the workspace is conservative.
      if (pa.within_test(box) == certified::CellState::inside) {
        for (const Point q : {box.min, box.max, Point{box.min.x, box.max.y}, Point{box.max.x, box.min.y}}) {
          EXPECT_TRUE(m.reachable({q.x, q.y, 0.0}));
        }
      }
      ++checked;
    }
    EXPECT_EQ(checked, 200);
  }
}

// M1's guides are parallel to y, so dq/dP depends on x only and a sub-level
// set of a criterion growing with |x| is W ∩ {|x| <= x*}: an exact region once
// x* is found by bisection in [lo, hi] on the evaluation at y = -300
// (independent of the field). The certified bounds hold its area to 1e-9.
template <class Value>
certified::LevelSetResult expect_stripe(const std::string& criterion, double t, double lo, double hi, Value value_at) {
  const auto f = moma("moma_m1_g0_l250");
  const auto& m = as_moma(f);
  const auto at = [&](double x) { return value_at(m.evaluate({x, -300.0, 0.0}, {}).front()); };
  EXPECT_LT(at(lo), t);
  EXPECT_GT(at(hi), t);
  const double from = lo;
  for (int k = 0; k < 200 && hi - lo > 1e-13; ++k) (at(0.5 * (lo + hi)) <= t ? lo : hi) = 0.5 * (lo + hi);
  for (double x = 0.0; x < from; x += 1.0) EXPECT_LT(at(x), t);  // below t between 0 and the bracket too
  const geometry::Region w = m.workspace();
  const Box bb = w.bbox();
  const double exact = w.intersect(geometry::rectangle({{-lo, bb.min.y - 1}, {lo, bb.max.y + 1}})).area();
  certified::LevelSetOptions o;
  o.relative_tolerance = 1e-9;
  const auto r = criteria::limited_workspace(f, {{criterion, t}}, o);
  EXPECT_LE(r.region.area_lower, exact + 1e-9);
  EXPECT_GE(r.region.area_upper, exact - 1e-9);
  EXPECT_LE(r.region.width(), 1e-9 * exact);
  return r.detail;
}

TEST(MomaCriteria, ParallelGuidesGiveVerticalVelocityBands) {
  // ratio(0) = sqrt 2 < 1.5 < ratio(100).
  const auto detail = expect_stripe("velocity_ratio", 1.5, 0.0, 100.0,
                                    [](const mechanisms::Evaluation& e) { return *e.velocity_ratio; });
  EXPECT_EQ(detail.undecided_cells, 0u);  // every cell along the lines traced, also across W's boundary
}

TEST(MomaCriteria, ParallelGuidesGiveVerticalConditionBands) {
  // κ stays near its minimum 2.29 for |x| < 60 and grows beyond.
  expect_stripe("condition_number", 2.5, 40.0, 150.0,
                [](const mechanisms::Evaluation& e) { return e.condition_number; });
}

TEST(MomaCriteria, PressureAngleAndReactionAgainstADenseGrid) {
  const auto f = moma("moma_m1_gm5_l180");
  const auto& m = as_moma(f);
  certified::LevelSetOptions o;
  o.relative_tolerance = 1e-7;
  const double alpha = 15.0;  // the workspace spans about 0-25 deg
  const auto r = criteria::limited_workspace(f, {{"pressure_angle", alpha}}, o);
  const double w = m.workspace().area();
  EXPECT_GT(r.region.area_lower, 0.05 * w);  // the limit cuts the workspace
  EXPECT_LT(r.region.area_upper, 0.95 * w);
  EXPECT_LE(r.region.width(), 1e-7 * r.region.area_upper);
  // Cell-centre count on a 600² grid of the bounding box, through the evaluation.
  const double grid = test::grid_area(m.bounds(), 600, [&](Point p) {
    const auto e = m.evaluate({p.x, p.y, 0.0}, {});
    return e.front().reachable && e.front().pressure_angle_deg.at(0) <= alpha;
  });
  EXPECT_NEAR(grid, 0.5 * (r.region.area_lower + r.region.area_upper), 3e-3 * grid);
  // R = f / |sin ε| <= f / cos α is the same set as α <= acos(f / R).
  mechanisms::Criteria with_load;
  with_load.load = mechanisms::Load{100.0, 0.0};
  mechanisms::Design d = f;
  d.criteria = with_load;
  const auto rr = criteria::limited_workspace(d, {{"reaction", 100.0 / std::cos(alpha * kDeg)}}, o);
  EXPECT_LE(rr.region.area_lower, r.region.area_upper * (1 + 1e-12));
  EXPECT_GE(rr.region.area_upper, r.region.area_lower * (1 - 1e-12));
}

}  // namespace
