// Certified sub-level sets of the biglide velocity ratio V_i/V_y = |∂q_i/∂y|
// ([Strutynskyi] fig. 8), condition number, pressure angle and reaction over
// the exact simplified-scheme workspace, and the real scheme's workspace and
// criteria, whose boundary is traced too.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "pkmws/criteria/fields.hpp"
#include "pkmws/io/mechanism_file.hpp"
#include "mechanisms/biglide/criteria.hpp"
#include "support/field_checks.hpp"
#include "support/fixtures.hpp"

namespace {

using namespace pkmws;
using geometry::Point;
using pkmws::test::dataset;

io::MechanismFile simplified() {
  return io::load_mechanism(dataset("biglide_simplified"));
}

TEST(BiglideVelocityRatio, SurrogateIsTheSquaredRatioWithItsDerivatives) {
  const auto f = simplified();
  const auto& m = dynamic_cast<const mechanisms::Biglide&>(*f.model);
  const auto box = m.bounds();
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> ux(box.min.x, box.max.x), uy(box.min.y, box.max.y);
  int checked = 0;
  for (int n = 0; n < 2000 && checked < 300; ++n) {
    const Point p{ux(rng), uy(rng)};
    if (!m.reachable({p.x, p.y, 0})) continue;
    const auto ratio = m.velocity_ratio_y(p);
    for (int leg = 0; leg < 2; ++leg) {
      const auto c = criteria::biglide_velocity_ratio(m, leg);
      const double r = ratio[static_cast<std::size_t>(leg)];
      if (!(r < 50.0)) continue;  // near a type-1 singularity
      EXPECT_NEAR(c.surrogate->value(p), r * r, 1e-9 * (1 + r * r));
      EXPECT_NEAR(c.value(p), r, 1e-12 * (1 + r));
      // Jet against central differences of the surrogate.
      const double h = 1e-4;
      const auto j = c.surrogate->jet(p);
      const double fx = (c.surrogate->value({p.x + h, p.y}) - c.surrogate->value({p.x - h, p.y})) / (2 * h);
      const double fy = (c.surrogate->value({p.x, p.y + h}) - c.surrogate->value({p.x, p.y - h})) / (2 * h);
      EXPECT_NEAR(j.dx, fx, 1e-5 * (1 + std::abs(fx)));
      EXPECT_NEAR(j.dy, fy, 1e-5 * (1 + std::abs(fy)));
      // The interval enclosure of a small box holds the point value.
      const geometry::Box b{{p.x - 0.5, p.y - 0.5}, {p.x + 0.5, p.y + 0.5}};
      if (c.surrogate->domain(b) == certified::CellState::inside) {
        const auto e = c.surrogate->enclose(b);
        EXPECT_LE(e.lo, r * r);
        EXPECT_GE(e.hi, r * r);
      }
    }
    ++checked;
  }
  EXPECT_GE(checked, 300);
}

TEST(BiglideVelocityRatio, CertifiedBoundsContainADenseGridEstimate) {
  const auto f = simplified();
  const auto& m = dynamic_cast<const mechanisms::Biglide&>(*f.model);
  certified::LevelSetOptions o;
  o.relative_tolerance = 1e-4;
  const double limit = 2.0;
  const auto r = criteria::limited_workspace(f, {{"velocity_ratio", limit}}, o);
  ASSERT_LT(r.region.area_lower, r.region.area_upper);
  EXPECT_LT(r.region.width(), 1e-3 * r.region.area_upper);
  EXPECT_LT(r.region.area_upper, m.workspace().area());  // the limit removes a part
  // Dense grid: reachable and both ratios <= limit at cell centres; its error is
  // at most about (boundary length) x (cell diagonal).
  const auto box = m.bounds();
  const int n = 1500;
  const double dx = box.width() / n, dy = box.height() / n;
  long count = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Point p{box.min.x + (i + 0.5) * dx, box.min.y + (j + 0.5) * dy};
      if (!m.reachable({p.x, p.y, 0})) continue;
      const auto v = m.velocity_ratio_y(p);
      count += (v[0] <= limit && v[1] <= limit) ? 1 : 0;
    }
  const double grid = static_cast<double>(count) * dx * dy;
  const double slack = 2.0 * (box.width() + box.height()) * 2.0 * std::hypot(dx, dy);
  EXPECT_GE(grid, r.region.area_lower - slack);
  EXPECT_LE(grid, r.region.area_upper + slack);
  EXPECT_NEAR(grid, r.region.area_estimate(), 2e-3 * grid);
}

TEST(BiglideConditionNumber, SurrogateAgreesWithTheEvaluationAndBoundsAGrid) {
  const auto f = simplified();
  const auto& m = dynamic_cast<const mechanisms::Biglide&>(*f.model);
  const auto c = criteria::biglide_condition_number(m);
  const auto box = m.bounds();
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> ux(box.min.x, box.max.x), uy(box.min.y, box.max.y);
  int checked = 0;
  for (int n = 0; n < 4000 && checked < 300; ++n) {
    const Point p{ux(rng), uy(rng)};
    const auto e = m.evaluate({p.x, p.y, 0.0}, {});
    // The evaluation of the paper's branches (the fields' mode).
    const auto own = std::find_if(e.begin(), e.end(), [](const auto& v) { return v.mode == "--"; });
    if (own == e.end() || !own->reachable || own->singular) continue;
    const double kappa = own->condition_number;
    if (!(kappa < 1e3)) continue;
    EXPECT_NEAR(c.value(p), kappa, 1e-9 * kappa);
    test::expect_same_sublevel(c, p, kappa, {1.5, 3.0, 10.0});
    ++checked;
  }
  EXPECT_EQ(checked, 300);
  // κ depends on y only (both rows start with 1): the certified area of κ <= 3
  // against a grid of the evaluation.
  certified::LevelSetOptions o;
  o.relative_tolerance = 1e-6;
  const auto r = criteria::limited_workspace(f, {{"condition_number", 3.0}}, o);
  EXPECT_LE(r.region.width(), 1e-6 * r.region.area_upper);
  const double grid =
      test::grid_area(box, 600, [&](Point p) { return m.reachable({p.x, p.y, 0.0}) && c.value(p) <= 3.0; });
  EXPECT_NEAR(grid, 0.5 * (r.region.area_lower + r.region.area_upper), 3e-3 * grid);
}

TEST(BiglideVelocityRatio, TheRealSchemesRodAnglesAndAReactionWithoutLoadAreRefusedClearly) {
  const auto real = io::load_mechanism(dataset("biglide_real"));
  for (const char* name : {"pressure_angle", "reaction"}) {
    EXPECT_THROW(criteria::fields_for(real, name), io::InputError) << name;
  }
  EXPECT_EQ(criteria::fields_for(real, "velocity_ratio").size(), 2u);
  EXPECT_EQ(criteria::fields_for(real, "condition_number").size(), 1u);
  EXPECT_THROW(criteria::fields_for(simplified(), "reaction"), io::InputError);  // no criteria.load
  // The 3-RPR without leg limits or an analysis window has no bounded region.
  const auto paminsa = io::load_mechanism(dataset("three_rpr_paminsa"));
  EXPECT_THROW(criteria::fields_for(paminsa, "velocity_ratio"), io::InputError);
}

// The rods of the paper's branches from the inverse kinematics: sin ε, independently of the fields.
double sin_eps(const mechanisms::Biglide& m, Point p) {
  const auto q = m.inverse_joints(p);
  const Point s1 = m.slider(0, (*q)[0]), s2 = m.slider(1, (*q)[1]);
  const Point u1 = p - s1, u2 = p - s2;
  return (u1.x * u2.y - u1.y * u2.x) / (std::hypot(u1.x, u1.y) * std::hypot(u2.x, u2.y));
}

TEST(BiglidePressureAngle, FieldsAgreeWithEvalAndTheAngleBetweenTheRods) {
  const auto f = simplified();
  const auto& m = dynamic_cast<const mechanisms::Biglide&>(*f.model);
  const auto alpha = criteria::biglide_pressure_angle(m);
  const auto reaction = criteria::biglide_reaction(m, 100.0);
  mechanisms::Criteria loaded;
  loaded.load = mechanisms::Load{100.0, 0.0};
  const auto box = m.bounds();
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> ux(box.min.x, box.max.x), uy(box.min.y, box.max.y);
  int checked = 0;
  for (int n = 0; n < 4000 && checked < 300; ++n) {
    const Point p{ux(rng), uy(rng)};
    const auto e = m.evaluate({p.x, p.y, 0.0}, loaded);
    const auto own = std::find_if(e.begin(), e.end(), [](const auto& v) { return v.mode == "--"; });
    if (own == e.end() || !own->reachable || own->singular) continue;
    const double s = sin_eps(m, p);
    const double a = std::acos(std::abs(s)) * 180.0 / std::acos(-1.0);
    EXPECT_NEAR(own->pressure_angle_deg.at(0), a, 1e-9);
    EXPECT_NEAR(own->reactions_N.at(0), 100.0 / std::abs(s), 1e-9 * own->reactions_N.at(0));
    EXPECT_DOUBLE_EQ(alpha.value(p), own->pressure_angle_deg.at(0));
    EXPECT_DOUBLE_EQ(reaction.value(p), own->reactions_N.at(0));
    EXPECT_NEAR(alpha.surrogate->value(p), 1.0 - s * s, 1e-12);  // cos²ε
    test::expect_same_sublevel(alpha, p, a, {10.0, 30.0, 45.0, 70.0});
    test::expect_same_sublevel(reaction, p, 100.0 / std::abs(s), {110.0, 150.0, 400.0});
    ++checked;
  }
  EXPECT_EQ(checked, 300);
  // Jets against finite differences, enclosures over random boxes (mm).
  std::uniform_real_distribution<double> size(0.05, 20.0);
  int boxes = 0;
  for (int n = 0; n < 2000 && boxes < 30; ++n) {
    const Point p{ux(rng), uy(rng)};
    const double h = size(rng);
    const geometry::Box b{{p.x - h, p.y - h}, {p.x + h, p.y + h}};
    if (alpha.surrogate->domain(b) != certified::CellState::inside) continue;
    test::check_field(*alpha.surrogate, p, 1e-2, b);
    ++boxes;
  }
  EXPECT_EQ(boxes, 30);
}

TEST(BiglidePressureAngle, CertifiedBoundsContainAGridAndTheReactionGivesTheSameRegion) {
  const auto f = io::load_mechanism(dataset("biglide_simplified_alpha20"));
  const auto& m = dynamic_cast<const mechanisms::Biglide&>(*f.model);
  certified::LevelSetOptions o;
  o.relative_tolerance = 1e-6;
  const double limit = *f.criteria.max_pressure_angle_deg;
  const auto r = criteria::limited_workspace(f, criteria::file_limits(f), o);
  EXPECT_LT(r.region.width(), 1e-5 * r.region.area_upper);
  EXPECT_LT(r.region.area_upper, 0.9 * m.workspace().area());
  const auto box = m.bounds();
  const int n = 1200;
  const double grid = test::grid_area(box, n, [&](Point p) {
    return m.reachable({p.x, p.y, 0.0}) && std::acos(std::abs(sin_eps(m, p))) * 180.0 / std::acos(-1.0) <= limit;
  });
  EXPECT_NEAR(grid, 0.5 * (r.region.area_lower + r.region.area_upper), 2e-3 * grid);
  // R = f / |sin ε| <= f / cos α_max is the same region.
  auto with_load = f;
  with_load.criteria.load = mechanisms::Load{100.0, 0.0};
  const double r_max = 100.0 / std::cos(limit * std::acos(-1.0) / 180.0);
  const auto rr = criteria::limited_workspace(with_load, {{"reaction", r_max}}, o);
  EXPECT_LE(rr.region.area_lower, r.region.area_upper);
  EXPECT_GE(rr.region.area_upper, r.region.area_lower);
}

}  // namespace

namespace {

// The real scheme's workspace is leg 1's band cut by leg 2's chain, three
// traced level sets (CriterionFields::workspace_sets). Its area with no
// criterion against the quadtree enclosure the mechanism gives (an
// independent cell test of the same conditions) and a grid of reachable().
TEST(BiglideRealScheme, WorkspaceCutByTheChainAgainstTheQuadtreeEnclosureAndAGrid) {
  const auto real = io::load_mechanism(dataset("biglide_real"));
  certified::LevelSetOptions o;
  o.relative_tolerance = 1e-7;
  const auto w = criteria::limited_workspace(real, {}, o);
  const auto enclosure = real.model->workspace_enclosure(9);
  const double lo = w.region.area_lower, hi = w.region.area_upper;
  std::printf("[ real W   ] traced [%.10g, %.10g] (width %.1e), quadtree [%.10g, %.10g] (width %.1e)\n", lo, hi,
              (hi - lo) / hi, enclosure.area_lower, enclosure.area_upper,
              (enclosure.area_upper - enclosure.area_lower) / enclosure.area_upper);
  EXPECT_LE(hi - lo, 1e-6 * hi);
  EXPECT_GE(lo, enclosure.area_lower);  // both enclose the area: the traced interval lies in the wide one
  EXPECT_LE(hi, enclosure.area_upper);
  const auto box = real.model->bounds();
  const double grid = test::grid_area(box, 800, [&](Point p) { return real.model->reachable({p.x, p.y, 0.0}); });
  EXPECT_NEAR(grid, 0.5 * (lo + hi), 2e-3 * grid);
}

// A velocity-ratio and a condition-number limit on the real scheme: inside
// the workspace's bounds above, binding, and against a grid of the fields'
// values (Biglide::velocity_ratio_y and the SVD of the inverse Jacobian).
TEST(BiglideRealScheme, CriteriaLimitsAgainstAGridOfTheEvaluation) {
  const auto real = io::load_mechanism(dataset("biglide_real"));
  const auto& m = *real.model;
  const auto box = m.bounds();
  certified::LevelSetOptions o;
  o.relative_tolerance = 1e-6;
  const double w_upper = criteria::limited_workspace(real, {}, o).region.area_upper;
  const auto vr = criteria::fields_for(real, "velocity_ratio");
  const auto kc = criteria::fields_for(real, "condition_number").at(0);
  struct Case {
    criteria::Limit limit;
    std::function<bool(Point)> holds;
  };
  const std::vector<Case> cases = {
      {{"velocity_ratio", 1.5}, [&](Point p) { return vr[0].value(p) <= 1.5 && vr[1].value(p) <= 1.5; }},
      {{"condition_number", 2.5}, [&](Point p) { return kc.value(p) <= 2.5; }}};
  for (const Case& c : cases) {
    const auto r = criteria::limited_workspace(real, {c.limit}, o);
    const double lo = r.region.area_lower, hi = r.region.area_upper;
    const double grid = test::grid_area(box, 800, [&](Point p) { return m.reachable({p.x, p.y, 0.0}) && c.holds(p); });
    std::printf("[ %s ] [%.10g, %.10g] (width %.1e), grid %.10g, W <= %.10g\n", c.limit.name.c_str(), lo, hi,
                (hi - lo) / hi, grid, w_upper);
    EXPECT_LE(hi - lo, 1e-5 * hi) << c.limit.name;
    EXPECT_LT(hi, 0.95 * w_upper) << c.limit.name;  // the limit binds
    EXPECT_GT(lo, 0.05 * w_upper) << c.limit.name;
    EXPECT_NEAR(grid, 0.5 * (lo + hi), 3e-3 * grid) << c.limit.name;
  }
}

}  // namespace
