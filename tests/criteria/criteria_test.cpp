// Criterion fields ([Briot]): the worked reactions on real PAMINSA poses, the
// type-2 singular circle, reactions against a direct linear solve of the
// statics, jets against finite differences, interval enclosures against samples.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include <Eigen/Dense>

#include "pkmws/core/error.hpp"
#include "pkmws/criteria/fields.hpp"
#include "mechanisms/five_bar/criteria.hpp"
#include "mechanisms/three_rpr/criteria.hpp"
#include "support/field_checks.hpp"
#include "support/mechanisms/five_bar.hpp"

namespace {

using namespace pkmws;
using geometry::Box;
using geometry::Point;
using mechanisms::Load;
using mechanisms::Pose;
using mechanisms::ThreeRpr;
using mechanisms::ThreeRprActuation;

constexpr double pi = std::numbers::pi;
constexpr double deg = pi / 180.0;

ThreeRpr paminsa(double phi, std::optional<Box> window = std::nullopt) {
  // [Briot]: R_b = 0.35 m, R_p = 0.1 m, actuated base revolutes.
  const ThreeRpr s = ThreeRpr::symmetric(0.35, 0.1, ThreeRprActuation::revolute, phi);
  return ThreeRpr(s.base(), s.platform(), ThreeRprActuation::revolute, phi, std::nullopt, window);
}

using pkmws::test::five_bar::dextar;

// [Briot], first example: P = (0, 0.2), φ = 0 puts the instantaneous centre
// I_1 of leg 1's twist (the meeting point of the force lines of legs 2 and 3)
// at O: |B_1 I_1| = d_1 = b_1 = 0.1 m, |P I_1| = 2 b_1 (γ_1 = 2), leg 1 vertical
// so r_1 ∥ v_1 (α_1 = 0): R_1 = 2 f + |m| / b_1 = 300 N for f = 100 N, m = 10 N·m.
TEST(CriteriaPaperReactions, ThreeHundredNewtonsOnARealPaminsaPose) {
  const ThreeRpr m = paminsa(0.0);
  const Pose pose{0.0, 0.2, 0.0};
  const auto t = m.transmission(pose);
  EXPECT_NEAR(t.pressure_angle[0], 0.0, 1e-12);
  EXPECT_NEAR(t.lever[0], 0.1, 1e-12);
  EXPECT_NEAR(t.lever_ratio[0], 2.0, 1e-12);
  EXPECT_NEAR(m.reaction_max(pose, Load{100.0, 10.0})[0], 300.0, 1e-9);
  const auto field = criteria::three_rpr_reaction(m, Load{100.0, 10.0}, 0);
  EXPECT_NEAR(field.value({0.0, 0.2}), 300.0, 1e-9);
}

// Second example: P at the base centre (φ = 0): I_1 = (0, 0.2), d_1 = 3 b_1,
// γ = 2/3, α_1 = 0: R_1 = 2f/3 + |m| / (3 b_1) = 180 N for f = 240 N, m = 6 N·m.
TEST(CriteriaPaperReactions, HundredEightyNewtonsAtTheCentre) {
  const ThreeRpr m = paminsa(0.0);
  const Pose pose{0.0, 0.0, 0.0};
  const auto t = m.transmission(pose);
  EXPECT_NEAR(t.pressure_angle[0], 0.0, 1e-12);
  EXPECT_NEAR(t.lever[0], 0.3, 1e-12);
  EXPECT_NEAR(t.lever_ratio[0], 2.0 / 3.0, 1e-12);
  EXPECT_NEAR(m.reaction_max(pose, Load{240.0, 6.0})[0], 180.0, 1e-9);
  const auto field = criteria::three_rpr_reaction(m, Load{240.0, 6.0}, 0);
  EXPECT_NEAR(field.value({0.0, 0.0}), 180.0, 1e-9);
  // The pressure-angle field: α_1 = 0 there.
  EXPECT_NEAR(criteria::three_rpr_pressure_angle(m, 0).value({0.0, 0.0}), 0.0, 1e-6);
}

// [Briot] / docs/theory/three_dof.md: for fixed φ the type-2 singularity is the circle about
// O of radius sqrt(R_b² + R_p² - 2 R_b R_p cos φ); for cos φ = R_p / R_b every
// position is singular. The field's determinant (through its reaction, which
// blows up) and the mechanism's det A agree.
TEST(CriteriaPaminsa, TypeTwoSingularCircleAndTheAllSingularOrientation) {
  const double rb = 0.35, rp = 0.1;
  for (double phi_deg : {0.0, 25.0, 50.0}) {
    const double phi = phi_deg * deg;
    const ThreeRpr m = paminsa(phi);
    const double radius = std::sqrt(rb * rb + rp * rp - 2.0 * rb * rp * std::cos(phi));
    const auto field = criteria::three_rpr_reaction(m, Load{100.0, 5.0}, 0);
    for (int k = 0; k < 36; ++k) {
      const double a = 2.0 * pi * k / 36.0 + 0.013;
      const Point on{radius * std::cos(a), radius * std::sin(a)};
      EXPECT_LT(std::abs(m.transmission({on.x, on.y, phi}).determinant), 1e-12) << phi_deg << " " << k;
      const Point off{0.8 * on.x, 0.8 * on.y}, out{1.1 * on.x, 1.1 * on.y};
      EXPECT_GT(std::abs(m.transmission({off.x, off.y, phi}).determinant), 1e-4);
      EXPECT_GT(std::abs(m.transmission({out.x, out.y, phi}).determinant), 1e-4);
      // Near the circle the reaction grows without bound.
      const Point near{(1.0 - 1e-7) * on.x, (1.0 - 1e-7) * on.y};
      EXPECT_GT(field.value(near), 1e3);
    }
  }
  const ThreeRpr all = paminsa(std::acos(rp / rb));
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  for (int k = 0; k < 200; ++k) {
    const Pose p{u(rng), u(rng), std::acos(rp / rb)};
    EXPECT_LT(std::abs(all.transmission(p).determinant), 1e-12);
  }
}

// R_i,max = f |v_P,i| + |m| |ω_i| against the statics solved directly: for
// random poses and load directions, A^T R = -w ([Briot]: w = -A^T R) by LU,
// and the largest |R_i| over 720 force directions and both moment signs.
TEST(CriteriaReactions, MaximumMatchesADirectLinearSolveOfTheStatics) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.2, 0.2), ang(-0.9, 0.9);
  for (int trial = 0; trial < 30; ++trial) {
    const double phi = ang(rng);
    const ThreeRpr m = paminsa(phi);
    const Pose pose{u(rng), u(rng), phi};
    const auto t = m.transmission(pose);
    if (t.singular || std::abs(t.determinant) < 1e-3) continue;
    const Load load{50.0 + 100.0 * std::abs(u(rng)), 20.0 * std::abs(u(rng))};
    const Point p{pose.x, pose.y};
    const Eigen::Matrix3d a = m.wrench_matrix(pose, p);
    std::array<double, 3> best{};
    for (int k = 0; k < 720; ++k) {
      const double th = 2.0 * pi * k / 720.0;
      for (int sign : {-1, 1}) {
        const Eigen::Vector3d w(load.force_N * std::cos(th), load.force_N * std::sin(th), sign * load.moment_Nm);
        const Eigen::Vector3d r = a.transpose().partialPivLu().solve(-w);
        for (int i = 0; i < 3; ++i) best[static_cast<std::size_t>(i)] = std::max(best[static_cast<std::size_t>(i)], std::abs(r(i)));
      }
    }
    const auto rmax = m.reaction_max(pose, load);
    for (int i = 0; i < 3; ++i) {
      const auto k = static_cast<std::size_t>(i);
      // 720 directions: the sampled maximum is within cos(π/720) of the true one.
      EXPECT_LE(best[k], rmax[k] * (1.0 + 1e-9));
      EXPECT_GE(best[k], rmax[k] * std::cos(pi / 720.0) * (1.0 - 1e-9));
      const auto field = criteria::three_rpr_reaction(m, load, i);
      EXPECT_NEAR(field.value(p), rmax[k], 1e-9 * rmax[k]);
    }
  }
}

// The five-bar field reproduces FiveBar::evaluate's pressure angle ([Briot]
// α = acos|sin ε|) in each working mode.
TEST(CriteriaFiveBar, PressureAngleFieldMatchesTheMechanism) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> ux(-0.5, 0.5), uy(-0.45, 0.45);
  for (int s1 : {-1, 1}) {
    for (int s2 : {-1, 1}) {
      const auto m = dextar(s1, s2);
      const auto field = criteria::five_bar_pressure_angle(m);
      int checked = 0;
      for (int k = 0; k < 400; ++k) {
        const Point p{ux(rng), uy(rng)};
        if (!m.reachable({p.x, p.y, 0.0})) {
          EXPECT_TRUE(std::isnan(field.value(p)) || norm(p - Point{-0.1375, 0}) > 0.459 || norm(p - Point{0.1375, 0}) > 0.459);
          continue;
        }
        const auto e = m.evaluate({p.x, p.y, 0.0}, {});
        ASSERT_FALSE(e.empty());
        EXPECT_NEAR(field.value(p), e.front().pressure_angle_deg.at(0), 1e-7) << s1 << s2;
        ++checked;
      }
      EXPECT_GT(checked, 150);
    }
  }
}

TEST(CriteriaFields, JetsMatchFiniteDifferencesAndIntervalsEnclose) {
  const auto fb = criteria::five_bar_pressure_angle(dextar(1, -1));
  const auto rpr = criteria::three_rpr_reaction(paminsa(25 * deg), Load{100.0, 5.0}, 0);
  const auto rpa = criteria::three_rpr_pressure_angle(paminsa(25 * deg), 1);
  // The transmission limits' forms (±cos ε at 20°, -|det A| at 80°).
  mechanisms::Design d;
  d.path = "dextar.json";
  d.model = std::make_shared<mechanisms::FiveBar>(dextar(1, -1));
  std::vector<criteria::CriterionField> forms = criteria::fields_for(d, "pressure_angle", 20.0);
  forms.push_back(criteria::fields_for(d, "pressure_angle", 80.0).front());
  ASSERT_EQ(forms.size(), 3u);
  int checked_forms = 0;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-0.15, 0.15);
  int checked_fb = 0, checked_rpr = 0;
  for (int k = 0; k < 40; ++k) {
    const Point p{u(rng), 0.1 + u(rng)};
    Box box;
    box.min = {p.x - 0.004, p.y - 0.003};
    box.max = {p.x + 0.002, p.y + 0.005};
    if (fb.surrogate->domain(box) == certified::CellState::inside) {
      pkmws::test::check_field(*fb.surrogate, p, 1e-5, box);
      ++checked_fb;
    }
    for (const auto& f : forms) {
      if (f.surrogate->domain(box) != certified::CellState::inside) continue;
      pkmws::test::check_field(*f.surrogate, p, 1e-5, box);
      ++checked_forms;
    }
    Box b2 = box;
    if (rpr.surrogate->domain(b2) == certified::CellState::inside) {
      pkmws::test::check_field(*rpa.surrogate, p, 1e-5, b2);
      ++checked_rpr;
      // R_i has |.| kinks; where the parts do not vanish it is smooth.
      const auto j = rpr.surrogate->jet(b2);
      if (j.dxx.finite()) pkmws::test::check_field(*rpr.surrogate, p, 1e-5, b2);
    }
  }
  EXPECT_GT(checked_fb, 30);
  EXPECT_GT(checked_forms, 80);
  EXPECT_GT(checked_rpr, 30);
}

TEST(CriteriaFields, FileCriteriaAndErrors) {
  EXPECT_THROW(criteria::three_rpr_reaction(paminsa(0.0), Load{1, 1}, 3), std::invalid_argument);
  mechanisms::Design f;  // the criteria need no file: a design
  f.path = "x.json";
  f.model = std::make_shared<mechanisms::FiveBar>(dextar(1, 1));
  EXPECT_THROW(criteria::fields_for(f, "velocity"), InputError);
  EXPECT_THROW(criteria::fields_for(f, "reaction"), InputError);  // no load
  EXPECT_EQ(criteria::fields_for(f, "pressure_angle").size(), 1u);
  // Velocity-ratio and condition-number limits are read, in that order.
  f.criteria.max_velocity_ratio = 2.0;
  f.criteria.max_condition_number = 3.0;
  ASSERT_EQ(criteria::file_limits(f).size(), 2u);
  EXPECT_EQ(criteria::file_limits(f).front().name, "velocity_ratio");
  EXPECT_EQ(criteria::file_limits(f).back().name, "condition_number");
  EXPECT_EQ(criteria::fields_for(f, "velocity_ratio").size(), 1u);
  EXPECT_EQ(criteria::fields_for(f, "condition_number").size(), 1u);
}

}  // namespace
