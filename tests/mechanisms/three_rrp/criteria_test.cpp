// 3-RRP / 3-PRP criteria at the file orientation ([Briot]'s planar method on
// [Mitsi]'s chains): the fields against pkmws eval, their jets and
// enclosures, and certified areas against grids.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "pkmws/criteria/fields.hpp"
#include "pkmws/io/mechanism_file.hpp"
#include "mechanisms/three_rrp/criteria.hpp"
#include "support/field_checks.hpp"
#include "support/fixtures.hpp"

namespace {

using namespace pkmws;
using geometry::Box;
using geometry::Point;
using pkmws::test::dataset;

const mechanisms::ThreeRrp& chains(const io::MechanismFile& f) {
  return dynamic_cast<const mechanisms::ThreeRrp&>(*f.model);
}

double extra(const mechanisms::Evaluation& e, const std::string& key) {
  for (const auto& [k, v] : e.extra) {
    if (k == key) return v;
  }
  return std::nan("");
}

TEST(ThreeRrpCriteria, FieldsAgreeWithTheEvaluation) {
  for (const char* name : {"three_prp_example", "three_rrp_mitsi"}) {
    const auto f = io::load_mechanism(dataset(name));
    const auto& m = chains(f);
    const mechanisms::Load load{50.0, 0.0};
    mechanisms::Criteria loaded;
    loaded.load = load;
    const auto vr = criteria::three_rrp_velocity_ratio(m, f.criteria);
    const auto kappa = criteria::three_rrp_condition_number(m, f.criteria);
    const Box box = m.bounds();
    std::mt19937 rng(31);
    std::uniform_real_distribution<double> ux(box.min.x, box.max.x), uy(box.min.y, box.max.y);
    int checked = 0;
    for (int n = 0; n < 5000 && checked < 150; ++n) {
      const Point p{ux(rng), uy(rng)};
      const auto e = m.evaluate({p.x, p.y, m.orientation()}, loaded).front();
      if (!e.reachable || e.singular || !(e.condition_number < 1e4)) continue;
      EXPECT_DOUBLE_EQ(extra(e, "characteristic_length"), m.characteristic_length());
      for (int leg = 0; leg < 3; ++leg) {
        const auto i = static_cast<std::size_t>(leg);
        const auto alpha = criteria::three_rrp_pressure_angle(m, leg);
        const auto reaction = criteria::three_rrp_reaction(m, load, leg);
        const double a = e.pressure_angle_deg.at(i), r = e.reactions_N.at(i);
        const double ca = std::cos(a * std::acos(-1.0) / 180.0);
        EXPECT_NEAR(alpha.surrogate->value(p), 1.0 / (ca * ca), 1e-8 / (ca * ca)) << name << " leg " << leg;
        EXPECT_NEAR(reaction.surrogate->value(p), r, 1e-9 * r) << name << " leg " << leg;
        EXPECT_DOUBLE_EQ(alpha.value(p), a);
        EXPECT_DOUBLE_EQ(reaction.value(p), r);
        test::expect_same_sublevel(alpha, p, a, {10.0, 30.0, 60.0});
      }
      const double s = *e.velocity_ratio, k = e.condition_number;
      EXPECT_NEAR(vr.surrogate->value(p), s * s, 1e-9 * s * s) << name;
      EXPECT_NEAR(kappa.surrogate->value(p), -1.0 / (k * k), 1e-9 / (k * k)) << name;
      test::expect_same_sublevel(kappa, p, k, {1.5, 3.0, 10.0});
      ++checked;
    }
    EXPECT_EQ(checked, 150) << name;
  }
}

TEST(ThreeRrpCriteria, JetsMatchFiniteDifferencesAndIntervalsEncloseOverRandomBoxes) {
  for (const char* name : {"three_prp_example", "three_rrp_mitsi"}) {
    const auto f = io::load_mechanism(dataset(name));
    const auto& m = chains(f);
    const std::vector<criteria::CriterionField> fields = {
        criteria::three_rrp_pressure_angle(m, 1), criteria::three_rrp_reaction(m, {50.0, 2.0}, 2),
        criteria::three_rrp_velocity_ratio(m, f.criteria), criteria::three_rrp_condition_number(m, f.criteria)};
    const Box box = m.bounds();
    std::mt19937 rng(37);
    std::uniform_real_distribution<double> ux(box.min.x, box.max.x), uy(box.min.y, box.max.y);
    std::uniform_real_distribution<double> size(1e-5 * box.width(), 3e-3 * box.width());
    for (const auto& c : fields) {
      int checked = 0;
      for (int n = 0; n < 3000 && checked < 15; ++n) {
        const Point p{ux(rng), uy(rng)};
        const double h = size(rng);
        const Box b{{p.x - h, p.y - h}, {p.x + h, p.y + h}};
        if (c.surrogate->domain(b) != certified::CellState::inside) continue;
        test::check_field(*c.surrogate, p, 1e-5 * box.width(), b);
        ++checked;
      }
      EXPECT_EQ(checked, 15) << name << " " << c.name;
    }
  }
}

// Certified bounds of the file's limit against a grid of eval (the fields'
// working mode, the assembly mode of the box's centre).
void expect_bounds_contain_grid(const char* name, int n, double relative) {
  const auto f = io::load_mechanism(dataset(name));
  const auto& m = chains(f);
  certified::LevelSetOptions o;
  o.relative_tolerance = 1e-6;
  const auto limits = criteria::file_limits(f);
  ASSERT_EQ(limits.size(), 1u);
  const auto r = criteria::limited_workspace(f, limits, o);
  ASSERT_GT(r.region.area_lower, 0.0) << name;
  EXPECT_LT(r.region.width(), 1e-4 * r.region.area_upper) << name;
  EXPECT_LT(r.region.area_upper, 0.99 * m.workspace().area()) << name;
  const Box box = m.bounds();
  const Point centre{0.5 * (box.min.x + box.max.x), 0.5 * (box.min.y + box.max.y)};
  const double centre_det = extra(m.evaluate({centre.x, centre.y, m.orientation()}, f.criteria).front(), "transmission_det");
  const auto& limit = limits.front();
  const double grid = test::grid_area(box, n, [&](Point p) {
    const auto e = m.evaluate({p.x, p.y, m.orientation()}, f.criteria).front();
    if (!e.reachable || !(extra(e, "transmission_det") * centre_det > 0.0)) return false;
    if (limit.name == "condition_number") return e.condition_number <= limit.threshold;
    if (limit.name == "velocity_ratio") return e.velocity_ratio.value_or(1e300) <= limit.threshold;
    for (double a : e.pressure_angle_deg) {
      if (!(a <= limit.threshold)) return false;
    }
    return true;
  });
  EXPECT_NEAR(grid, 0.5 * (r.region.area_lower + r.region.area_upper), relative * grid) << name;
}

TEST(ThreeRrpCriteria, CertifiedAreasContainGridEstimates) {
  expect_bounds_contain_grid("three_prp_example_alpha20", 800, 3e-3);
  expect_bounds_contain_grid("three_prp_example_kappa2", 800, 3e-3);
}

}  // namespace
