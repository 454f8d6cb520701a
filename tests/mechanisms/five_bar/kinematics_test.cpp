// Five-bar 5R ([Briot], DexTAR): IK/DK round trips in every working and
// assembly mode, Jacobians against finite differences, the mirror symmetries of
// the four working modes, pressure angle and reactions against statics, the
// type-2 curves, actuator torques.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include <Eigen/LU>

#include "pkmws/geometry/primitives.hpp"
#include "pkmws/io/mechanism_file.hpp"
#include "mechanisms/five_bar/five_bar.hpp"
#include "support/fixtures.hpp"
#include "support/mechanisms/five_bar.hpp"

using namespace pkmws;
using namespace pkmws::test::five_bar;
using geometry::Point;
using mechanisms::FiveBar;
using pkmws::test::dataset;

namespace {

constexpr double pi = std::numbers::pi;
constexpr double deg = pi / 180.0;

Point random_in_lens(std::mt19937& rng) {
  std::uniform_real_distribution<double> ux(-0.32, 0.32), uy(-0.42, 0.42);
  for (;;) {
    const Point c{ux(rng), uy(rng)};
    if (norm(c - Point{-A, 0}) < 2 * L - 1e-3 && norm(c - Point{A, 0}) < 2 * L - 1e-3 &&
        norm(c - Point{-A, 0}) > 1e-3 && norm(c - Point{A, 0}) > 1e-3) {
      return c;
    }
  }
}

double angle_diff(double a, double b) { return std::abs(std::remainder(a - b, 2 * pi)); }

}  // namespace

TEST(FiveBarKinematics, DexTARDatasetsCarryTheirWorkingModes) {
  for (const auto& [tag, s1, s2] : {std::tuple{"pp", 1, 1}, {"pm", 1, -1}, {"mp", -1, 1}, {"mm", -1, -1}}) {
    const auto f = io::load_mechanism(dataset(std::string("five_bar_dextar_") + tag));
    const auto& m = dynamic_cast<const FiveBar&>(*f.model);
    EXPECT_EQ(m.legs()[0].working_mode, s1);
    EXPECT_EQ(m.legs()[1].working_mode, s2);
    EXPECT_EQ(m.legs()[0].proximal, L);
    EXPECT_EQ(m.legs()[1].base.x, A);
    EXPECT_NE(f.source.find("[Briot]"), std::string::npos);
    // The file's working mode comes first and is the valid one.
    const auto sol = m.inverse({0.05, 0.2, 0.0});
    ASSERT_EQ(sol.size(), 4u);
    EXPECT_TRUE(sol[0].valid);
    EXPECT_EQ(sol[0].mode, std::string(1, s1 > 0 ? '+' : '-') + (s2 > 0 ? '+' : '-'));
    for (std::size_t k = 1; k < 4; ++k) EXPECT_FALSE(sol[k].valid) << sol[k].reason;
  }
}

TEST(FiveBarKinematics, InverseThenDirectRoundTripInEveryWorkingAndAssemblyMode) {
  std::mt19937 rng(4);
  for (int s1 : {1, -1}) {
    for (int s2 : {1, -1}) {
      const FiveBar m = dextar(s1, s2);
      for (int n = 0; n < 200; ++n) {
        const Point c = random_in_lens(rng);
        const auto q1 = m.inverse_leg(0, c, s1), q2 = m.inverse_leg(1, c, s2);
        ASSERT_TRUE(q1 && q2);
        // The elbows are where the working mode says.
        EXPECT_EQ(FiveBar::working_mode_sign({-A, 0}, m.elbow(0, *q1), c), s1);
        EXPECT_EQ(FiveBar::working_mode_sign({A, 0}, m.elbow(1, *q2), c), s2);
        EXPECT_NEAR(norm(c - m.elbow(0, *q1)), L, 1e-14);
        EXPECT_NEAR(norm(c - m.elbow(1, *q2)), L, 1e-14);
        // DK gives both assembly modes; one is C, and every assembly maps back
        // to the same joints through IK in its own working mode.
        const auto assemblies = m.direct_all(*q1, *q2);
        double best = 1.0;
        for (const auto& a : assemblies) {
          best = std::min(best, norm(a.tool - c));
          const int t1 = FiveBar::working_mode_sign({-A, 0}, a.elbows[0], a.tool);
          const int t2 = FiveBar::working_mode_sign({A, 0}, a.elbows[1], a.tool);
          const auto r1 = m.inverse_leg(0, a.tool, t1), r2 = m.inverse_leg(1, a.tool, t2);
          ASSERT_TRUE(r1 && r2);
          EXPECT_LT(angle_diff(*r1, *q1), 1e-9);
          EXPECT_LT(angle_diff(*r2, *q2), 1e-9);
        }
        EXPECT_LT(best, 1e-12);
        // Through the Mechanism interface: the file's mode is valid and DK finds C.
        const auto ik = m.inverse({c.x, c.y, 0.0});
        ASSERT_TRUE(ik[0].valid) << ik[0].reason;
        const auto dk = m.direct(ik[0].joints);
        int valid_at_c = 0;
        for (const auto& s : dk) valid_at_c += s.valid && norm(Point{s.pose.x, s.pose.y} - c) < 1e-12;
        EXPECT_EQ(valid_at_c, 1);
      }
    }
  }
}

TEST(FiveBarKinematics, JacobiansMatchFiniteDifferences) {
  std::mt19937 rng(7);
  const double h = 1e-6;
  for (int s1 : {1, -1}) {
    for (int s2 : {1, -1}) {
      const FiveBar m = dextar(s1, s2);
      int tested = 0;
      for (int n = 0; n < 50; ++n) {
        const Point c = random_in_lens(rng);
        const double q1 = *m.inverse_leg(0, c, s1), q2 = *m.inverse_leg(1, c, s2);
        const auto j = m.jacobians(c, q1, q2);
        // Away from singularities (|sin| of the link angles above ~0.2).
        if (std::abs(j.B(0, 0)) < 0.01 || std::abs(j.B(1, 1)) < 0.01 || std::abs(j.A.determinant()) < 0.01) continue;
        const Eigen::Matrix2d jq = j.B.inverse() * j.A;
        Eigen::Matrix2d fd;
        for (int col = 0; col < 2; ++col) {
          const Point e = col == 0 ? Point{h, 0} : Point{0, h};
          for (int leg = 0; leg < 2; ++leg) {
            const int s = leg == 0 ? s1 : s2;
            const double qp = *m.inverse_leg(leg, c + e, s), qm = *m.inverse_leg(leg, c - e, s);
            fd(leg, col) = std::remainder(qp - qm, 2 * pi) / (2 * h);
          }
        }
        EXPECT_LT((jq - fd).norm(), 1e-6 * std::max(1.0, jq.norm())) << jq << "\n" << fd;
        // The A matrix alone: A (dC/dq) = B for the DK (columns: moving one crank).
        Eigen::Matrix2d dc;
        for (int col = 0; col < 2; ++col) {
          const double dq1 = col == 0 ? h : 0.0, dq2 = col == 1 ? h : 0.0;
          Point cp, cm;
          for (const auto& a : m.direct_all(q1 + dq1, q2 + dq2)) if (norm(a.tool - c) < 1e-4) cp = a.tool;
          for (const auto& a : m.direct_all(q1 - dq1, q2 - dq2)) if (norm(a.tool - c) < 1e-4) cm = a.tool;
          dc(0, col) = (cp.x - cm.x) / (2 * h);
          dc(1, col) = (cp.y - cm.y) / (2 * h);
        }
        EXPECT_LT((j.A * dc - j.B).norm(), 1e-7 * j.B.norm());
        // evaluate() reports the same determinant.
        const auto ev = m.evaluate({c.x, c.y, 0.0}, {});
        EXPECT_NEAR(ev[0].jacobian_det, fd.determinant(), 1e-5 * std::abs(fd.determinant()) + 1e-9);
        ++tested;
      }
      EXPECT_GE(tested, 20);
    }
  }
}

TEST(FiveBarKinematics, WorkingModesObeyTheMirrorSymmetries) {
  // DexTAR is symmetric about x = 0 (the mirror swaps the legs and flips the
  // working modes: (s1, s2) -> (-s2, -s1), q1' = π - q2) and about y = 0
  // ((s1, s2) -> (-s1, -s2), q' = -q).
  std::mt19937 rng(11);
  for (int s1 : {1, -1}) {
    for (int s2 : {1, -1}) {
      const FiveBar m = dextar(s1, s2);
      const FiveBar mx = dextar(-s2, -s1), my = dextar(-s1, -s2);
      for (int n = 0; n < 100; ++n) {
        const Point c = random_in_lens(rng);
        const Point cx{-c.x, c.y}, cy{c.x, -c.y};
        const double q1 = *m.inverse_leg(0, c, s1), q2 = *m.inverse_leg(1, c, s2);
        EXPECT_LT(angle_diff(*mx.inverse_leg(0, cx, -s2), pi - q2), 1e-12);
        EXPECT_LT(angle_diff(*mx.inverse_leg(1, cx, -s1), pi - q1), 1e-12);
        EXPECT_LT(angle_diff(*my.inverse_leg(0, cy, -s1), -q1), 1e-12);
        EXPECT_LT(angle_diff(*my.inverse_leg(1, cy, -s2), -q2), 1e-12);
        const auto e = m.evaluate({c.x, c.y, 0}, {}).front();
        const auto ex = mx.evaluate({cx.x, cx.y, 0}, {}).front();
        const auto ey = my.evaluate({cy.x, cy.y, 0}, {}).front();
        EXPECT_NEAR(e.pressure_angle_deg[0], ex.pressure_angle_deg[0], 1e-9);
        EXPECT_NEAR(e.pressure_angle_deg[0], ey.pressure_angle_deg[0], 1e-9);
        if (std::isfinite(e.condition_number) && e.condition_number < 1e6) {
          EXPECT_NEAR(e.condition_number, ex.condition_number, 1e-7 * e.condition_number);
          EXPECT_NEAR(e.condition_number, ey.condition_number, 1e-7 * e.condition_number);
        }
      }
    }
  }
}

TEST(FiveBarKinematics, PressureAngleAndReactionsAgreeWithStatics) {
  // [Briot]: A^T = [R1 R2] (unit distal directions), cos α = |sin(ψ2 - ψ1)|;
  // R = A^-T w for a load w at C; R_i,max = f / |sin ε| (docs/theory/three_dof.md).
  std::mt19937 rng(3);
  const FiveBar m = dextar(1, -1);
  mechanisms::Criteria crit;
  crit.load = mechanisms::Load{100.0, 5.0};
  for (int n = 0; n < 100; ++n) {
    const Point c = random_in_lens(rng);
    const double q1 = *m.inverse_leg(0, c, 1), q2 = *m.inverse_leg(1, c, -1);
    const Point r1 = (1 / L) * (c - m.elbow(0, q1)), r2 = (1 / L) * (c - m.elbow(1, q2));
    const double psi1 = std::atan2(r1.y, r1.x), psi2 = std::atan2(r2.y, r2.x);
    const auto e = m.evaluate({c.x, c.y, 0}, crit).front();
    const double alpha = std::acos(std::abs(std::sin(psi2 - psi1))) / deg;
    EXPECT_NEAR(e.pressure_angle_deg[0], alpha, 1e-9);
    EXPECT_NEAR(e.pressure_angle_deg[1], alpha, 1e-9);
    Eigen::Matrix2d at;
    at << r1.x, r2.x, r1.y, r2.y;
    if (std::abs(at.determinant()) < 1e-3) continue;
    double worst = 0.0;
    for (int k = 0; k < 3600; ++k) {
      const Eigen::Vector2d w(100.0 * std::cos(2 * pi * k / 3600), 100.0 * std::sin(2 * pi * k / 3600));
      worst = std::max(worst, std::abs((at.inverse() * w)(0)));
    }
    EXPECT_NEAR(e.reactions_N[0], worst, 1e-4 * worst);  // the moment does not reach C
    EXPECT_GE(e.reactions_N[0], worst * (1 - 1e-12));
  }
}

TEST(FiveBarKinematics, SingularitiesAreFlagged) {
  const FiveBar m = dextar(1, -1);
  // Type 1: C on the outer circle of leg 1 (proximal and distal aligned).
  const double phi = 70 * deg;
  const Point c1 = Point{-A, 0} + 2 * L * Point{std::cos(phi), std::sin(phi)};
  const auto e1 = m.evaluate({c1.x, c1.y, 0}, {}).front();
  EXPECT_TRUE(e1.singular);
  EXPECT_TRUE(e1.singularity == "type1" || e1.singularity == "both");
  // Type 2: distal links aligned, C the midpoint of B and D with |B - D| = 2L.
  const double q1 = 120 * deg;
  const Point b = m.elbow(0, q1);
  // D on circle(E, L) at distance 2L from B.
  const Point e{A, 0};
  const double dist = norm(b - e);
  const Point u = (1 / dist) * (e - b);
  const double along = (4 * L * L - L * L + dist * dist) / (2 * dist);
  const Point d = b + along * u + std::sqrt(4 * L * L - along * along) * Point{-u.y, u.x};
  const Point c2 = 0.5 * (b + d);
  int type2 = 0;
  for (const auto& ev : m.evaluate({c2.x, c2.y, 0}, {})) {
    if (ev.joints.size() == 2 && (ev.singularity == "type2" || ev.singularity == "both")) {
      ++type2;
      EXPECT_NEAR(ev.pressure_angle_deg[0], 90.0, 1e-3);
    }
  }
  EXPECT_GE(type2, 1);
}

TEST(FiveBarKinematics, TypeTwoCurvesHaveAlignedDistalLinks) {
  for (int s1 : {1, -1}) {
    for (int s2 : {1, -1}) {
      const FiveBar m = dextar(s1, s2);
      const auto curves = mechanisms::type2_singularity_curves(m, false, 512);
      std::size_t points = 0;
      for (const auto& curve : curves) {
        for (const Point& c : curve) {
          ++points;
          // In the file's working mode the distal links are aligned at C.
          const auto q1 = m.inverse_leg(0, c, s1), q2 = m.inverse_leg(1, c, s2);
          ASSERT_TRUE(q1 && q2);
          const double sin_eps = std::sin(m.transmission_angle(c, *q1, *q2));
          EXPECT_LT(std::abs(sin_eps), 1e-6) << c.x << " " << c.y;
        }
      }
      EXPECT_GT(points, 100u);
      // Every mode's curves together cover the full locus.
      const auto all = mechanisms::type2_singularity_curves(m, true, 512);
      std::size_t all_points = 0;
      for (const auto& curve : all) all_points += curve.size();
      EXPECT_GT(all_points, points);
    }
  }
}
namespace {

TEST(FiveBarStatics, ActuatorTorqueIsTheWorstMomentOfTheLoad) {
  // [Briot] Table 2 (chain R̲RR): the worst actuator torque over force
  // directions of norm f at C is f |∂C/∂q_i| (virtual work), with ∂C/∂q_i
  // taken here by finite differences of the direct kinematics.
  const double f = 100.0;
  pkmws::mechanisms::Criteria criteria;
  criteria.load = pkmws::mechanisms::Load{f, 0.0};
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> ux(-0.25, 0.25), uy(0.05, 0.4);
  int checked = 0;
  for (int s1 : {1, -1})
    for (int s2 : {1, -1}) {
      const FiveBar m = dextar(s1, s2);
      for (int n = 0; n < 40; ++n) {
        const pkmws::mechanisms::Pose pose{ux(rng), uy(rng), 0.0};
        for (const auto& e : m.evaluate(pose, criteria)) {
          if (!e.reachable || e.singular || e.reactions_N.size() != 2) continue;
          for (int i = 0; i < 2; ++i) {
            const double h = 1e-7;
            std::vector<double> qp = e.joints, qm = e.joints;
            qp[static_cast<std::size_t>(i)] += h;
            qm[static_cast<std::size_t>(i)] -= h;
            auto nearest = [&](const std::vector<double>& q) {
              Point best{1e300, 1e300};
              for (const auto& s : m.direct(q))
                if (std::hypot(s.pose.x - pose.x, s.pose.y - pose.y) < std::hypot(best.x - pose.x, best.y - pose.y))
                  best = {s.pose.x, s.pose.y};
              return best;
            };
            const Point cp = nearest(qp), cm = nearest(qm);
            const double expected = f * std::hypot(cp.x - cm.x, cp.y - cm.y) / (2 * h);
            double torque = -1.0;
            for (const auto& [k, v] : e.extra)
              if (k == "actuator_torque" + std::to_string(i + 1)) torque = v;
            EXPECT_NEAR(torque, expected, 1e-5 * expected + 1e-9);
            ++checked;
          }
        }
      }
    }
  EXPECT_GT(checked, 100);
}

}  // namespace
