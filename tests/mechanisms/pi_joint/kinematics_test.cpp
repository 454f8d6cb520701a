// Active Π-joint ([Milutinovic]): the prototype's d range as the paper rounds it,
// eq. 2-5 round trips, eq. 7 against the derivative of eq. 2 and against
// eq. 9-11, statics eq. 12-15 by virtual work, accelerations eq. 17-20 against
// finite differences, singularities.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "pkmws/io/mechanism_file.hpp"
#include "pkmws/io/plot.hpp"
#include "mechanisms/pi_joint/charts.hpp"
#include "support/fixtures.hpp"
#include "support/mechanisms/pi_joint.hpp"

using namespace pkmws;
using namespace pkmws::test::pi_joint;
using mechanisms::PiJoint;
using mechanisms::PiJointKinematics;

namespace {

constexpr double pi = std::numbers::pi;
constexpr double deg = pi / 180.0;

}  // namespace

TEST(PiJointKinematics, PrototypeReproducesThePapersDRange) {
  const PiJoint& m = prototype();
  EXPECT_EQ(m.dof(), 1);
  const PiJointKinematics& k = m.kinematics();
  EXPECT_EQ(k.a, 170.0);
  EXPECT_NEAR(k.b(), 68.0, 1e-12);  // b = k a = 68 mm
  const double d_max = k.length(60 * deg), d_min = k.length(-60 * deg);
  EXPECT_NEAR(d_max, 231.4012, 1e-4);
  EXPECT_NEAR(d_min, 116.1959, 1e-4);
  // The paper prints d_max = 232, d_min = 117 (rounded up) and d_max - d_min = 115.
  EXPECT_EQ(std::ceil(d_max), 232.0);
  EXPECT_EQ(std::ceil(d_min), 117.0);
  EXPECT_EQ(std::round(d_max - d_min), 115.0);
  EXPECT_DOUBLE_EQ(m.d_min(), d_min);
  EXPECT_DOUBLE_EQ(m.d_max(), d_max);
  // Through the Mechanism interface (Pose.phi = θ, the one joint is d).
  const auto ik = m.inverse({0, 0, 60 * deg});
  ASSERT_EQ(ik.size(), 1u);
  EXPECT_TRUE(ik[0].valid) << ik[0].reason;
  EXPECT_NEAR(ik[0].joints[0], d_max, 1e-12);
  EXPECT_FALSE(m.inverse({0, 0, 61 * deg})[0].valid);
  EXPECT_FALSE(m.inverse({0, 0, 95 * deg})[0].valid);
}

TEST(PiJointKinematics, InverseThenDirectRoundTrip) {
  for (double k : {0.3, 0.4, 0.5, 1.0, 1.5}) {
    const PiJointKinematics kin{170.0, k};
    for (double t = -89.0; t <= 89.0; t += 0.5) {
      const double d = kin.length(t * deg);  // eq. 2
      const auto back = kin.angle(d);        // eq. 3-5
      ASSERT_TRUE(back);
      EXPECT_NEAR(*back, t * deg, 1e-9) << k << " " << t;
    }
    EXPECT_NEAR(kin.length(-pi / 2), kin.length_min(), 1e-12);
    EXPECT_NEAR(kin.length(pi / 2), kin.length_max(), 1e-12);
    EXPECT_FALSE(kin.angle(kin.length_max() * 1.01));
  }
  // Through the interface: two DK roots, the eq. 4 one valid.
  const PiJoint& m = prototype();
  const auto dk = m.direct(std::vector<double>{200.0});
  ASSERT_EQ(dk.size(), 2u);
  EXPECT_TRUE(dk[0].valid);
  EXPECT_FALSE(dk[1].valid);
  EXPECT_NEAR(m.kinematics().length(dk[0].pose.phi), 200.0, 1e-12);
  EXPECT_NEAR(m.kinematics().length(dk[1].pose.phi), 200.0, 1e-12);
  EXPECT_LT(std::cos(dk[1].pose.phi), 0.0);
  // The drawn parallelogram has |O A| = d and a translating coupler.
  const auto p = m.points(dk[0].pose.phi);
  EXPECT_NEAR(norm(p.a - p.o), 200.0, 1e-12);
  EXPECT_NEAR(norm(p.a - p.q), m.kinematics().b(), 1e-12);
}

TEST(PiJointKinematics, JacobianIsTheDerivativeOfEquationTwo) {
  for (double k : {0.3, 0.4, 0.5}) {
    const PiJointKinematics kin{170.0, k};
    for (double t = -85.0; t <= 85.0; t += 5.0) {
      const double th = t * deg, h = 1e-6;
      const double fd = (kin.length(th + h) - kin.length(th - h)) / (2 * h);
      const double j = kin.jacobian(th);
      EXPECT_NEAR(j, fd, 1e-7 * std::max(1.0, std::abs(fd)));
      // eq. 7 second form and eq. 9-11: J = J_d⁻¹ J_θ.
      EXPECT_NEAR(j, kin.a * k * std::cos(th) / std::sqrt(1 + k * k + 2 * k * std::sin(th)), 1e-12);
      EXPECT_NEAR(j, kin.jacobian_theta(th) / kin.jacobian_d(th), 1e-12);
      // J = a sin μ, μ the transmission angle.
      EXPECT_NEAR(j, kin.a * std::sin(kin.transmission_angle(th)), 1e-10);
      const double fd2 = (kin.jacobian(th + h) - kin.jacobian(th - h)) / (2 * h);
      EXPECT_NEAR(kin.jacobian_derivative(th), fd2, 1e-6 * std::max(1.0, std::abs(fd2)));
    }
    // Singularities of eq. 9-11: J_θ = 0 only at ±90°; J is largest at sin θ = -k.
    EXPECT_NEAR(kin.jacobian(pi / 2), 0.0, 1e-12);
    EXPECT_NEAR(kin.jacobian(-pi / 2), 0.0, 1e-12);
    EXPECT_NEAR(kin.jacobian(-std::asin(k)), kin.a * k, 1e-12);
  }
  const PiJoint& m = prototype();
  const auto e = m.evaluate({0, 0, 89.99999999 * deg}, {}).front();
  EXPECT_FALSE(e.reachable);  // outside ±60°
  EXPECT_TRUE(e.singular);    // |cos θ| < 1e-9: the direct-kinematics singularity
  EXPECT_EQ(e.singularity, "type2");
  EXPECT_FALSE(m.evaluate({0, 0, 80 * deg}, {}).front().singular);
  const auto e0 = m.evaluate({0, 0, 0.0}, {}).front();
  EXPECT_TRUE(e0.reachable);
  EXPECT_NEAR(e0.jacobian_det, 170.0 * 0.4 / std::sqrt(1.16), 1e-12);
}

TEST(PiJointKinematics, StaticsByVirtualWork) {
  // eq. 12-14: T = J F, F = T / J; T θ̇ = F ḋ (virtual work).
  const PiJointKinematics kin{0.17, 0.4};  // metres
  for (double t = -60.0; t <= 60.0; t += 10.0) {
    const double th = t * deg;
    const double torque = kin.torque(th, 130.0);
    const double h = 1e-7;
    const double ddot = (kin.length(th + h) - kin.length(th - h)) / (2 * h);  // per unit θ̇
    EXPECT_NEAR(torque * 1.0, 130.0 * ddot, 1e-6);
    EXPECT_NEAR(kin.force(th, torque), 130.0, 1e-9);
  }
  // eq. 15: T_M = F h / (2π η).
  EXPECT_NEAR(PiJointKinematics::motor_torque(130.0, 2.54e-3, 0.5), 130.0 * 2.54e-3 / pi, 1e-15);
  // The prototype's figures 15-17 at θ = 0: J = 63.14 mm/rad.
  const PiJoint& m = prototype();
  mechanisms::Criteria crit;
  crit.load = mechanisms::Load{0.0, 5.0};  // an output torque of 5 N·m
  const auto e = m.evaluate({0, 0, 0.0}, crit).front();
  const double j = 170.0 * 0.4 / std::sqrt(1.16);
  auto extra = [&](const std::string& key) {
    for (const auto& [k, v] : e.extra) if (k == key) return v;
    ADD_FAILURE() << key;
    return 0.0;
  };
  EXPECT_NEAR(extra("output_resolution_deg_per_step"), 0.0127 / j / deg, 1e-12);
  EXPECT_NEAR(extra("angular_velocity_deg_s_at_max_speed"), 50.0 / j / deg, 1e-12);
  EXPECT_NEAR(extra("torque_Nm_at_max_force"), 130.0 * j * 1e-3, 1e-12);
  ASSERT_EQ(e.reactions_N.size(), 1u);
  EXPECT_NEAR(e.reactions_N[0], 5.0 / (j * 1e-3), 1e-9);  // eq. 14
}

TEST(PiJointKinematics, AccelerationEquationsAgainstFiniteDifferences) {
  // θ(t) = θ0 + ω t + α t²/2, d(t) = d(θ(t)) by eq. 2; d̈ by eq. 18 = eq. 19 + eq. 20.
  const PiJointKinematics kin{170.0, 0.4};
  for (double t0 : {-60.0, -20.0, 0.0, 35.0, 60.0}) {
    for (const auto& [w, a] : {std::pair{1.0, 0.0}, {0.0, 2.0}, {-1.5, 0.7}}) {
      const double th = t0 * deg, h = 1e-4;
      auto d_at = [&](double t) { return kin.length(th + w * t + 0.5 * a * t * t); };
      const double fd = (d_at(h) - 2 * d_at(0) + d_at(-h)) / (h * h);
      const double eq18 = kin.acceleration(th, w, a);
      EXPECT_NEAR(eq18, fd, 1e-5 * std::max(1.0, std::abs(fd))) << t0 << " " << w << " " << a;
      EXPECT_NEAR(kin.acceleration_from_angular_acceleration(th, a), kin.jacobian(th) * a, 1e-12);
      // eq. 20 in the paper's closed form (with θ̇², see docs/theory/pi_joint.md).
      const double s = std::sin(th), g = 1 + 0.16 + 0.8 * s;
      const double eq20 = -170.0 * 0.4 * (0.4 + s) * (1 + 0.4 * s) / (std::sqrt(g) * g) * w * w;
      EXPECT_NEAR(kin.acceleration_from_angular_velocity(th, w), eq20, 1e-9 * std::max(1.0, std::abs(eq20)));
    }
  }
}

TEST(PiJointKinematics, LoneJointHasNoPlanarWorkspace) {
  try {
    (void)prototype().workspace();
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no planar"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(prototype().reachable({0, 0, 30 * deg}));
  EXPECT_FALSE(prototype().reachable({0, 0, -61 * deg}));
}
