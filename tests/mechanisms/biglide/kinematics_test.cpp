// Biglide ([Strutynskyi]): the paper's closed forms (eq. 1-8) against the robust
// geometric kinematics, IK/DK round trips, the zero-position rule (eq. 9),
// simplified == real when the tool sits on the joint, velocity ratio V/V_y
// against finite differences, statics.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "pkmws/io/mechanism_file.hpp"
#include "mechanisms/biglide/biglide.hpp"
#include "support/fixtures.hpp"

using namespace pkmws;
using geometry::Point;
using mechanisms::Biglide;
using mechanisms::BiglideParams;
using pkmws::test::dataset;

namespace {

constexpr double pi = std::numbers::pi;

BiglideParams simplified(double b = 500, double l1 = 940, double l2 = 940, double s = 1600) {
  BiglideParams p;
  p.half_width = b;
  p.rods = {l1, l2};
  p.strokes = {{{0, s}, {0, s}}};
  return p;
}

BiglideParams real(double l4 = 150, double l3 = 900) {
  BiglideParams p = simplified();
  p.tool = mechanisms::BiglideTool{l3, l4};
  p.rods[1] = Biglide::zero_position_rod_length(500, 940, l3, l4);
  return p;
}

// Random tool points where the paper's branches reach with margin.
Point random_pose(const Biglide& m, std::mt19937& rng) {
  std::uniform_real_distribution<double> ux(200, 2000), uy(-420, 420);
  for (;;) {
    const Point t{ux(rng), uy(rng)};
    const auto q = m.inverse_joints(t);
    if (!q) continue;
    const Point j = m.joint_of(t, (*q)[0]);
    const double l3 = m.tool_distance(), l2 = m.params().rods[1], b = m.params().half_width;
    if (std::abs(t.y + b) > 0.97 * l3 || std::abs(b - j.y) > 0.97 * l2) continue;
    return t;
  }
}

}  // namespace

TEST(BiglideKinematics, PaperClosedFormsAgreeWithTheGeometry) {
  std::mt19937 rng(1);
  for (const Biglide& m : {Biglide(simplified()), Biglide(real())}) {
    for (int n = 0; n < 200; ++n) {
      const Point t = random_pose(m, rng);
      const auto q = *m.inverse_joints(t);
      const auto closed = m.inverse_closed_form(t);  // eq. 5-6 / eq. 7-8 (corrected sign)
      ASSERT_TRUE(closed);
      EXPECT_NEAR((*closed)[0], q[0], 1e-9);
      EXPECT_NEAR((*closed)[1], q[1], 1e-9);
      // DK: eq. 1-2 / 3-4 is the first (paper's) assembly mode of the robust DK.
      const auto assemblies = m.direct_all(q[0], q[1]);
      ASSERT_EQ(assemblies.size(), 2u);
      EXPECT_EQ(assemblies[0].sign, -1);
      EXPECT_LT(norm(assemblies[0].tool - t), 1e-9);
      const auto dk = m.direct_closed_form(q[0], q[1]);
      ASSERT_TRUE(dk);
      EXPECT_LT(norm(*dk - t), 1e-9);
      // Through the Mechanism interface: the paper's mode is valid and DK finds the pose.
      const auto ik = m.inverse({t.x, t.y, 0});
      EXPECT_EQ(ik[0].mode, "--");
      const bool in_stroke = q[0] >= 0 && q[0] <= 1600 && q[1] >= 0 && q[1] <= 1600;
      EXPECT_EQ(ik[0].valid, in_stroke) << ik[0].reason;
      if (in_stroke) {
        const auto sol = m.direct(ik[0].joints);
        EXPECT_TRUE(sol[0].valid) << sol[0].reason;
        EXPECT_LT(norm(Point{sol[0].pose.x, sol[0].pose.y} - t), 1e-9);
      }
    }
  }
}

TEST(BiglideKinematics, PrintedEquationEightDoesNotCloseTheLoop) {
  // [Strutynskyi] eq. 8 is printed with acos(B+y / l3) - acos(...) in its last term;
  // with that sign the joint J computed from T is not at distance l1 from S1.
  const Biglide m(real());
  const Point t{900, 120};
  const auto good = *m.inverse_closed_form(t, false);
  const auto printed = *m.inverse_closed_form(t, true);
  EXPECT_NEAR(good[0], printed[0], 1e-12);
  EXPECT_GT(std::abs(good[1] - printed[1]), 1.0);  // more than 1 mm off
  const auto dk = m.direct_closed_form(printed[0], printed[1]);
  ASSERT_TRUE(dk);
  EXPECT_GT(norm(*dk - t), 1.0);
}

TEST(BiglideKinematics, IkDkRoundTripInEveryBranchAndAssemblyMode) {
  std::mt19937 rng(2);
  for (const Biglide& m : {Biglide(simplified()), Biglide(real())}) {
    for (int n = 0; n < 100; ++n) {
      const Point t = random_pose(m, rng);
      for (int b1 : {-1, 1}) {
        for (int b2 : {-1, 1}) {
          const auto q = m.inverse_joints(t, b1, b2);
          if (!q) continue;
          double best = 1e9;
          for (const auto& a : m.direct_all((*q)[0], (*q)[1])) {
            best = std::min(best, norm(a.tool - t));
            // Each assembly maps back to the same sliders in its own branches.
            const int c1 = a.tool.x - (*q)[0] >= 0 ? -1 : 1;
            const int c2 = a.joint.x - (*q)[1] >= 0 ? -1 : 1;
            const auto back = m.inverse_joints(a.tool, c1, c2);
            ASSERT_TRUE(back);
            EXPECT_NEAR((*back)[0], (*q)[0], 1e-8);
            EXPECT_NEAR((*back)[1], (*q)[1], 1e-8);
          }
          EXPECT_LT(best, 1e-9);
        }
      }
    }
  }
}

TEST(BiglideKinematics, ZeroPositionRuleEquationNine) {
  // Consistent with eq. 3-4: at q1 = q2 = 0 the tool is on y = 0.
  for (const auto& [l3, l4] : {std::pair{900.0, 150.0}, {850.0, 200.0}, {940.0, 60.0}}) {
    const Biglide m(real(l4, l3));
    const auto a = m.direct_all(0, 0);
    ASSERT_FALSE(a.empty());
    EXPECT_NEAR(a[0].tool.y, 0.0, 1e-9) << l3 << " " << l4;
    EXPECT_NEAR(a[0].tool.x, std::sqrt(l3 * l3 - 500.0 * 500.0), 1e-9);
    // The printed eq. 9 (sign of asin(B/l3) flipped) misses the axis.
    BiglideParams p = real(l4, l3);
    p.rods[1] = Biglide::zero_position_rod_length_as_printed(500, 940, l3, l4);
    const auto b = Biglide(p).direct_all(0, 0);
    if (!b.empty()) {
      EXPECT_GT(std::abs(b[0].tool.y), 10.0);
    }
  }
  // Degenerate triangle (tool on the joint): consistent rule gives l2 = l1, the
  // printed one sqrt(l1² + 8B²).
  EXPECT_NEAR(Biglide::zero_position_rod_length(500, 940, 940, 0), 940.0, 1e-9);
  EXPECT_NEAR(Biglide::zero_position_rod_length_as_printed(500, 940, 940, 0),
              std::sqrt(940.0 * 940.0 + 8 * 500.0 * 500.0), 1e-9);
  // The dataset follows the rule.
  const auto f = io::load_mechanism(dataset("biglide_real"));
  const auto& m = dynamic_cast<const Biglide&>(*f.model);
  ASSERT_TRUE(m.real_scheme());
  EXPECT_NEAR(m.direct_all(0, 0)[0].tool.y, 0.0, 1e-5);
}

TEST(BiglideKinematics, SimplifiedEqualsRealWhenTheToolSitsOnTheJoint) {
  const Biglide s(simplified());
  BiglideParams p = simplified();
  p.tool = mechanisms::BiglideTool{940, 0};
  const Biglide r(p);
  EXPECT_EQ(r.gamma(), 0.0);
  std::mt19937 rng(3);
  for (int n = 0; n < 100; ++n) {
    const Point t = random_pose(s, rng);
    const auto qs = *s.inverse_joints(t), qr = *r.inverse_joints(t);
    EXPECT_NEAR(qs[0], qr[0], 1e-12);
    EXPECT_NEAR(qs[1], qr[1], 1e-12);
    const auto ds = s.direct_all(qs[0], qs[1]), dr = r.direct_all(qs[0], qs[1]);
    ASSERT_EQ(ds.size(), dr.size());
    for (std::size_t k = 0; k < ds.size(); ++k) EXPECT_LT(norm(ds[k].tool - dr[k].tool), 1e-12);
    EXPECT_LT(norm(*s.direct_closed_form(qs[0], qs[1]) - *r.direct_closed_form(qs[0], qs[1])), 1e-12);
    const auto es = s.evaluate({t.x, t.y, 0}, {}), er = r.evaluate({t.x, t.y, 0}, {});
    EXPECT_NEAR(*es[0].velocity_ratio, *er[0].velocity_ratio, 1e-12 * *es[0].velocity_ratio);
    EXPECT_NEAR(es[0].jacobian_det, er[0].jacobian_det, 1e-12 * std::abs(es[0].jacobian_det));
    EXPECT_NEAR(es[0].pressure_angle_deg[0], er[0].pressure_angle_deg[0], 1e-9);
    EXPECT_EQ(s.reachable({t.x, t.y, 0}), r.reachable({t.x, t.y, 0}));
  }
}

TEST(BiglideKinematics, VelocityRatioMatchesFiniteDifferences) {
  std::mt19937 rng(4);
  const double h = 1e-4;  // mm
  for (const Biglide& m : {Biglide(simplified()), Biglide(real())}) {
    for (int n = 0; n < 100; ++n) {
      const Point t = random_pose(m, rng);
      for (int b1 : {-1, 1}) {
        for (int b2 : {-1, 1}) {
          const auto q = m.inverse_joints(t, b1, b2);
          if (!q) continue;
          const auto jq = m.inverse_jacobian(t, b1, b2);
          for (int col = 0; col < 2; ++col) {
            const Point e = col == 0 ? Point{h, 0} : Point{0, h};
            const auto p = m.inverse_joints(t + e, b1, b2), mi = m.inverse_joints(t - e, b1, b2);
            ASSERT_TRUE(p && mi);
            for (int row = 0; row < 2; ++row) {
              const double fd = ((*p)[row] - (*mi)[row]) / (2 * h);
              EXPECT_NEAR(jq(row, col), fd, 1e-6 * std::max(1.0, std::abs(fd)));
            }
          }
        }
      }
      // V/V_y of the paper: |dq_i/dy| at constant x.
      const auto v = m.velocity_ratio_y(t);
      const auto up = *m.inverse_joints({t.x, t.y + h}), down = *m.inverse_joints({t.x, t.y - h});
      EXPECT_NEAR(v[0], std::abs(up[0] - down[0]) / (2 * h), 1e-6 * std::max(1.0, v[0]));
      EXPECT_NEAR(v[1], std::abs(up[1] - down[1]) / (2 * h), 1e-6 * std::max(1.0, v[1]));
      const auto e = m.evaluate({t.x, t.y, 0}, {});
      EXPECT_DOUBLE_EQ(*e[0].velocity_ratio, std::max(v[0], v[1]));
    }
  }
}

TEST(BiglideKinematics, VelocityRatioOfTheSimplifiedDatasetAgainstFigureEight) {
  // Simplified scheme: V1/V_y = h / sqrt(l² - h²) at distance h = y + B from
  // guide 1, so V/V_y = r at h = l r / sqrt(1 + r²): 782 mm for r = 1.5 and
  // 841 mm for r = 2 with l = 940 mm (fig. 8a reads 780 and 850 mm).
  const auto f = io::load_mechanism(dataset("biglide_simplified"));
  const auto& m = dynamic_cast<const Biglide&>(*f.model);
  const double l = m.params().rods[0], b = m.params().half_width;
  for (const auto& [r, paper] : {std::pair{1.5, 780.0}, {2.0, 850.0}}) {
    const double h = l * r / std::sqrt(1 + r * r);
    EXPECT_NEAR(m.velocity_ratio_y({800, h - b})[0], r, 1e-12);
    EXPECT_NEAR(h, paper, 0.015 * paper);
  }
}

TEST(BiglideKinematics, ReactionsAgreeWithStatics) {
  mechanisms::Criteria crit;
  crit.load = mechanisms::Load{100.0, 5.0};
  std::mt19937 rng(6);
  // Simplified: two-force rods at a point: R = f / |sin ε|.
  {
    const Biglide m(simplified());
    for (int n = 0; n < 50; ++n) {
      const Point t = random_pose(m, rng);
      const auto q = *m.inverse_joints(t);
      const Point u1 = t - m.slider(0, q[0]), u2 = t - m.slider(1, q[1]);
      const double sin_eps = std::abs(cross(u1, u2)) / (norm(u1) * norm(u2));
      const auto e = m.evaluate({t.x, t.y, 0}, crit).front();
      EXPECT_NEAR(e.reactions_N[0], 100.0 / sin_eps, 1e-9 * e.reactions_N[0]);
    }
  }
  // Real: equilibrium of the triangle S1 J T under w at T and the moment m.
  const Biglide m(real());
  int tested = 0;
  for (int n = 0; n < 30; ++n) {
    const Point t = random_pose(m, rng);
    const auto q = *m.inverse_joints(t);
    const Point s1 = m.slider(0, q[0]), s2 = m.slider(1, q[1]), j = m.joint_of(t, q[0]);
    const Point r2 = (1 / norm(j - s2)) * (j - s2);
    const double den = cross(j - s1, r2);
    if (std::abs(den) < 50) continue;
    double rod = 0, joint = 0;
    for (int sgn : {-1, 1}) {
      for (int k = 0; k < 20000; ++k) {
        const double a = 2 * pi * k / 20000;
        const Point w{100 * std::cos(a), 100 * std::sin(a)};
        const double lambda = -(cross(t - s1, w) + sgn * 5.0 * 1000.0) / den;  // m in N·mm
        rod = std::max(rod, std::abs(lambda));
        joint = std::max(joint, norm(w + lambda * r2));  // force on the triangle at S1 is -(w + λ r2)
      }
    }
    const auto e = m.evaluate({t.x, t.y, 0}, crit).front();
    ASSERT_EQ(e.reactions_N.size(), 2u);
    EXPECT_NEAR(e.reactions_N[1], rod, 1e-6 * rod);
    EXPECT_GE(e.reactions_N[0], joint * (1 - 1e-12));
    EXPECT_NEAR(e.reactions_N[0], joint, 1e-6 * joint);
    ++tested;
  }
  EXPECT_GE(tested, 15);
}
