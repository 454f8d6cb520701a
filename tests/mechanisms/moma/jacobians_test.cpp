// MOMA ([Vasilic], docs/theory/moma.md): Jacobians against finite differences,
// singularities at constructed poses, pressure angle and reactions against
// their definitions, impossible legs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <Eigen/LU>
#include <Eigen/QR>

#include "pkmws/geometry/primitives.hpp"
#include "pkmws/io/mechanism_file.hpp"
#include "mechanisms/moma/moma.hpp"
#include "support/fixtures.hpp"
#include "support/mechanisms/moma.hpp"

using namespace pkmws;
using namespace pkmws::test::moma;
using geometry::Point;
using mechanisms::Moma;
using mechanisms::MomaLeg;
using pkmws::test::dataset;

namespace {

constexpr double pi = std::numbers::pi;
constexpr double deg = pi / 180.0;

}  // namespace

TEST(MomaKinematics, JacobiansMatchFiniteDifferences) {
  std::mt19937 rng(3);
  for (const char* stem : {"moma_m1_gm5_l195", "moma_m2_l250", "moma_m3_l195", "moma_m4_gm5_gp5_l180"}) {
    const auto mech = io::load_mechanism(dataset(stem));
    const Moma& m = as_moma(mech);
    const auto box = m.bounds();
    std::uniform_real_distribution<double> x(box.min.x, box.max.x), y(box.min.y, box.max.y);
    int checked = 0;
    for (int k = 0; k < 400 && checked < 60; ++k) {
      const Point p{x(rng), y(rng)};
      for (const auto& s : m.inverse({p.x, p.y, 0})) {
        if (s.joints.size() != 2) continue;
        const auto j = m.jacobians(p, s.joints[0], s.joints[1]);
        // Keep away from singular poses, where finite differences break down.
        if (std::abs(j.B(0, 0)) < 20 || std::abs(j.B(1, 1)) < 20 || std::abs(j.A.determinant()) < 2000) continue;
        const int b1 = s.mode[0] == '-' ? -1 : 1;  // one sign per leg
        const int b2 = s.mode[1] == '-' ? -1 : 1;
        const double h = 1e-4;
        auto q = [&](Point at, int i) { return *m.inverse_leg(i, at, i == 0 ? b1 : b2); };
        Eigen::Matrix2d fd;
        for (int i = 0; i < 2; ++i) {
          fd(i, 0) = (q({p.x + h, p.y}, i) - q({p.x - h, p.y}, i)) / (2 * h);
          fd(i, 1) = (q({p.x, p.y + h}, i) - q({p.x, p.y - h}, i)) / (2 * h);
        }
        // IK Jacobian dq/dx = B^-1 A.
        const Eigen::Matrix2d jq = j.B.inverse() * j.A;
        EXPECT_LT((jq - fd).norm(), 1e-6 * (1 + jq.norm())) << stem << " " << s.mode;
        // DK Jacobian dx/dq = A^-1 B against the circle intersection, same assembly mode.
        const double side = cross(m.slider(1, s.joints[1]) - m.slider(0, s.joints[0]), p - m.slider(0, s.joints[0]));
        auto x_of = [&](double q1, double q2) {
          for (const auto& a : m.direct_all(q1, q2)) {
            if (a.sign == (side > 0 ? 1 : -1)) return a.platform;
          }
          ADD_FAILURE() << "assembly mode lost";
          return Point{};
        };
        Eigen::Matrix2d fdx;
        for (int i = 0; i < 2; ++i) {
          const double d1 = i == 0 ? h : 0, d2 = i == 1 ? h : 0;
          const Point plus = x_of(s.joints[0] + d1, s.joints[1] + d2);
          const Point minus = x_of(s.joints[0] - d1, s.joints[1] - d2);
          fdx(0, i) = (plus.x - minus.x) / (2 * h);
          fdx(1, i) = (plus.y - minus.y) / (2 * h);
        }
        const Eigen::Matrix2d jx = j.A.inverse() * j.B;
        EXPECT_LT((jx - fdx).norm(), 1e-6 * (1 + jx.norm())) << stem << " " << s.mode;
        // evaluate() reports det(dq/dx) and its conditioning for this mode.
        for (const auto& e : m.evaluate({p.x, p.y, 0}, {})) {
          if (e.mode != s.mode) continue;
          EXPECT_NEAR(e.jacobian_det, jq.determinant(), 1e-12 * (1 + std::abs(jq.determinant())));
          // 2x2 singular values in closed form: s1 s2 = |det|, s1^2 + s2^2 = |J|_F^2.
          const double fro2 = jq.squaredNorm(), det = std::abs(jq.determinant());
          const double s_max = std::sqrt((fro2 + std::sqrt(fro2 * fro2 - 4 * det * det)) / 2);
          const double s_min = det / s_max;
          EXPECT_NEAR(e.condition_number, s_max / s_min, 1e-9 * (s_max / s_min));
          ASSERT_TRUE(e.velocity_ratio.has_value());
          EXPECT_NEAR(*e.velocity_ratio, s_max, 1e-9 * s_max);
        }
        ++checked;
      }
    }
    EXPECT_GE(checked, 30) << stem;
  }
}

TEST(MomaKinematics, SingularitiesAtConstructedPoses) {
  // Type 1 (serial): rod 1 perpendicular to its guide. M1 l = 250, P = (150, 0):
  // |P - R1| = 250 along x, so p1 = 0 on both roots and (P - S1) . a1 = 0.
  const Moma m = m1(250, 0, 1000);
  for (const auto& e : m.evaluate({150, 0, 0}, {})) {
    EXPECT_TRUE(e.singular) << e.mode;
    EXPECT_EQ(e.singularity, "type1") << e.mode;
    EXPECT_TRUE(std::isinf(e.jacobian_det));
    EXPECT_TRUE(std::isinf(e.condition_number));
  }
  // Type 2 (parallel): rods aligned. P = (0, -y0), y0 = sqrt(250^2 - 100^2):
  // mode "-+" (branches -1, 1) puts S1 = (-100, 0) and S2 = (100, -2 y0), P their midpoint.
  const double y0 = std::sqrt(250.0 * 250.0 - 100.0 * 100.0);
  for (const auto& e : m.evaluate({0, -y0, 0}, {})) {
    if (e.mode == "-+" || e.mode == "+-") {
      EXPECT_EQ(e.singularity, "type2") << e.mode;
      EXPECT_TRUE(e.singular);
      EXPECT_NEAR(e.jacobian_det, 0.0, 1e-9);
      EXPECT_TRUE(std::isinf(e.condition_number));
      // Aligned rods cannot resist a load across them: pressure angle 90 degrees.
      EXPECT_NEAR(e.pressure_angle_deg[0], 90.0, 1e-6);
    } else {
      EXPECT_EQ(e.singularity, "") << e.mode;
      EXPECT_FALSE(e.singular);
      EXPECT_TRUE(std::isfinite(e.condition_number));
    }
  }
  // Both: rods of 100 from (-100, 0) and (100, 0) meeting at the origin are
  // aligned and perpendicular to the guides.
  const Moma touching({MomaLeg{{-100, 0}, 1.5 * pi, 0, 200, 100, -1}, MomaLeg{{100, 0}, 1.5 * pi, 0, 200, 100, -1}});
  const auto both = touching.evaluate({0, 0, 0}, {});
  EXPECT_EQ(both[0].singularity, "both");
  EXPECT_TRUE(both[0].singular);
  // 1 mm beside the aligned pose every mode is regular.
  const auto near = m.evaluate({1, -y0, 0}, {});
  for (const auto& e : near) EXPECT_EQ(e.singularity, "") << e.mode;
  // A regular pose of the file's mode.
  const auto regular = m1().evaluate({0, -300, 0}, {});
  EXPECT_FALSE(regular[0].singular);
  EXPECT_TRUE(std::isfinite(regular[0].jacobian_det));
}

TEST(MomaKinematics, PressureAngleMatchesItsDefinition) {
  // alpha_i = angle between rod i (the force line) and the velocity of P when
  // only actuator i moves (dP = A^-1 B e_i), as an unoriented line angle.
  std::mt19937 rng(23);
  for (const char* stem : {"moma_m1_g0_l250", "moma_m4_g0_gp5_l195", "moma_m3_l250"}) {
    const auto mech = io::load_mechanism(dataset(stem));
    const Moma& m = as_moma(mech);
    for (const Point p : reachable_samples(m, rng, 30)) {
      const auto e = m.evaluate({p.x, p.y, 0}, {})[0];
      if (e.singular) continue;
      const auto j = m.jacobians(p, e.joints[0], e.joints[1]);
      const Eigen::Matrix2d dx = j.A.inverse() * j.B;
      ASSERT_EQ(e.pressure_angle_deg.size(), 2u);
      for (int i = 0; i < 2; ++i) {
        const Eigen::Vector2d v = dx.col(i).normalized();
        const Eigen::Vector2d z = j.A.row(i).transpose().normalized();
        const double alpha = std::acos(std::min(1.0, std::abs(v.dot(z)))) / deg;
        EXPECT_NEAR(e.pressure_angle_deg[i], alpha, 1e-7) << stem;
      }
    }
  }
}

TEST(MomaKinematics, ReactionsMatchTheStatics) {
  const Moma m = m1();
  mechanisms::Criteria c;
  c.load = mechanisms::Load{100.0, 5.0};  // the moment is not transmitted by a point platform
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> ang(0, 2 * pi);
  for (const Point p : {Point{0, -300}, Point{-40, -350}, Point{60, -260}}) {
    const auto e = m.evaluate({p.x, p.y, 0}, c)[0];
    ASSERT_EQ(e.reactions_N.size(), 2u);
    // Rod forces F_i along z_i balance the load w: F1 z1 + F2 z2 = -w.
    const Eigen::Vector2d z1 = Eigen::Vector2d(p.x - m.slider(0, e.joints[0]).x, p.y - m.slider(0, e.joints[0]).y).normalized();
    const Eigen::Vector2d z2 = Eigen::Vector2d(p.x - m.slider(1, e.joints[1]).x, p.y - m.slider(1, e.joints[1]).y).normalized();
    Eigen::Matrix2d Z;
    Z << z1, z2;
    double worst[2] = {0, 0};
    for (int k = 0; k < 4000; ++k) {
      const double t = ang(rng);
      const Eigen::Vector2d f = Z.colPivHouseholderQr().solve(-Eigen::Vector2d(100 * std::cos(t), 100 * std::sin(t)));
      for (int i = 0; i < 2; ++i) worst[i] = std::max(worst[i], std::abs(f(i)));
    }
    for (int i = 0; i < 2; ++i) {
      EXPECT_LE(worst[i], e.reactions_N[i] * (1 + 1e-12));
      EXPECT_GE(worst[i], e.reactions_N[i] * (1 - 1e-5));
      // R_i,max = f / cos(alpha_i).
      EXPECT_NEAR(e.reactions_N[i], 100.0 / std::cos(e.pressure_angle_deg[i] * deg), 1e-9 * e.reactions_N[i]);
    }
  }
  // Without a load: no reactions.
  EXPECT_TRUE(m.evaluate({0, -300, 0}, {})[0].reactions_N.empty());
}

TEST(MomaKinematics, ConstructorRejectsImpossibleLegs) {
  const MomaLeg good{{0, 0}, 0.0, 0, 100, 50, -1};
  auto with = [&](auto change) {
    MomaLeg bad = good;
    change(bad);
    return std::array<MomaLeg, 2>{good, bad};
  };
  EXPECT_NO_THROW(Moma({good, good}));
  EXPECT_THROW(Moma(with([](MomaLeg& l) { l.rod_length = 0; })), std::invalid_argument);
  EXPECT_THROW(Moma(with([](MomaLeg& l) { l.rod_length = std::nan(""); })), std::invalid_argument);
  EXPECT_THROW(Moma(with([](MomaLeg& l) { l.stroke_min = 100; })), std::invalid_argument);
  EXPECT_THROW(Moma(with([](MomaLeg& l) { l.branch = 0; })), std::invalid_argument);
  EXPECT_THROW(Moma(with([](MomaLeg& l) { l.reference.x = std::numeric_limits<double>::infinity(); })),
               std::invalid_argument);
}
