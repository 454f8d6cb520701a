// 3-RRP / 3-PRP ([Mitsi]): IK/DK round trips in every working mode, sliders on
// their side lines, the velocity relation against finite differences, strip
// workspaces against an inverse-kinematics grid count.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "mechanisms/three_rrp/three_rrp.hpp"

#include "support/fixtures.hpp"
#include "support/mechanisms/three_dof.hpp"

namespace {

using namespace pkmws::mechanisms;
using namespace pkmws::test::three_dof;
using pkmws::geometry::Point;
using pkmws::test::grid_area;
constexpr double pi = std::numbers::pi;

ThreeRrp mitsi_rrp() {
  const double side = 140.0, h = side * std::sqrt(3.0) / 2.0;
  std::array<ThreeRrpChain, 3> c;
  c[0].base = {0, 0};
  c[1].base = {side, 0};
  c[2].base = {side / 2, h};
  for (auto& ch : c) ch.crank_length = 10.0;
  const double r = 40.0 / std::sqrt(3.0);
  std::array<Point, 3> plat{rot(-pi / 2 - pi / 3, {r, 0}), rot(-pi / 2 + pi / 3, {r, 0}), rot(pi / 2, {r, 0})};
  return ThreeRrp(ThreeRrpDrive::crank, c, plat);
}

ThreeRrp example_prp() {
  const double side = 140.0, h = side * std::sqrt(3.0) / 2.0;
  std::array<ThreeRrpChain, 3> c;
  c[0].base = {0, 0};
  c[1].base = {side, 0};
  c[2].base = {side / 2, h};
  c[0].direction = pi / 6;
  c[1].direction = 5 * pi / 6;
  c[2].direction = -pi / 2;
  for (auto& ch : c) ch.limits = std::array<double, 2>{0.0, 80.0};
  const double r = 40.0 / std::sqrt(3.0);
  std::array<Point, 3> plat{rot(-pi / 2 - pi / 3, {r, 0}), rot(-pi / 2 + pi / 3, {r, 0}), rot(pi / 2, {r, 0})};
  return ThreeRrp(ThreeRrpDrive::slider, c, plat);
}

TEST(ThreeRrp, InverseThenDirectRoundTripsInEveryWorkingMode) {
  // Poses come from the DK of random crank angles (so they are reachable);
  // each of the 8 working modes' IK joints goes back through the DK.
  const ThreeRrp m = mitsi_rrp();
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> uq(-pi, pi);
  int round_trips = 0;
  std::array<int, 8> per_mode{};
  for (int trial = 0; trial < 300; ++trial) {
    const std::array<double, 3> q0{uq(rng), uq(rng), uq(rng)};
    for (const auto& start : m.direct(q0)) {
      const Pose pose = start.pose;
      const auto sols = m.inverse(pose);
      ASSERT_EQ(sols.size(), 8u);
      for (std::size_t k = 0; k < sols.size(); ++k) {
        const auto& s = sols[k];
        if (s.joints.size() != 3) continue;
        const auto poses = m.direct(s.joints);
        ASSERT_LE(poses.size(), 2u);
        bool found = false;
        for (const auto& p : poses)
          found = found || (std::hypot(p.pose.x - pose.x, p.pose.y - pose.y) < 1e-8 &&
                            std::abs(angle_diff(p.pose.phi, pose.phi)) < 1e-10);
        EXPECT_TRUE(found) << "mode " << s.mode;
        ++round_trips;
        ++per_mode[k];
      }
    }
  }
  EXPECT_GT(round_trips, 1000);
  for (int c : per_mode) EXPECT_GT(c, 50);  // every working mode exercised
}

TEST(ThreeRrp, SlidersRoundTripAndStayOnTheirSideLines) {
  const ThreeRrp m = example_prp();
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> uq(0.0, 80.0);
  int solved = 0;
  for (int trial = 0; trial < 500; ++trial) {
    const std::array<double, 3> q{uq(rng), uq(rng), uq(rng)};
    const auto poses = m.direct(q);
    ASSERT_LE(poses.size(), 2u);
    for (const auto& p : poses) {
      ++solved;
      const auto back = m.inverse(p.pose);
      ASSERT_EQ(back.size(), 1u);
      for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(back[0].joints[i], q[i], 1e-9);
      // The closed form and the elimination give the same poses.
      const auto elim = m.direct_elimination(q);
      EXPECT_TRUE(has_assembly(elim.assemblies, {p.pose.x, p.pose.y}, p.pose.phi, 1e-9));
    }
  }
  EXPECT_GT(solved, 400);
}

TEST(ThreeRrp, VelocityRelationMatchesFiniteDifferences) {
  // A [v_P; ω] = B q̇ for the IK joint rates along a random direction.
  for (const ThreeRrp& m : {mitsi_rrp(), example_prp()}) {
    std::mt19937_64 rng(13);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int checked = 0;
    for (int trial = 0; trial < 100; ++trial) {
      const Pose pose{70 + 10 * u(rng), 40 + 8 * u(rng), 0.5 * u(rng)};
      const Eigen::Vector3d dir(u(rng), u(rng), 0.02 * u(rng));
      const auto sols = m.inverse(pose);
      for (std::size_t k = 0; k < sols.size(); ++k) {
        if (sols[k].joints.size() != 3) continue;
        const double h = 1e-6;
        const auto plus = m.inverse({pose.x + h * dir[0], pose.y + h * dir[1], pose.phi + h * dir[2]});
        const auto minus = m.inverse({pose.x - h * dir[0], pose.y - h * dir[1], pose.phi - h * dir[2]});
        if (plus.size() != sols.size() || minus.size() != sols.size()) continue;
        if (plus[k].mode != sols[k].mode || minus[k].mode != sols[k].mode) continue;
        if (plus[k].joints.size() != 3 || minus[k].joints.size() != 3) continue;
        Eigen::Vector3d qdot;
        for (int i = 0; i < 3; ++i) qdot[i] = std::remainder(plus[k].joints[static_cast<std::size_t>(i)] - minus[k].joints[static_cast<std::size_t>(i)], 2 * pi) / (2 * h);
        if (m.drive() == ThreeRrpDrive::slider)
          for (int i = 0; i < 3; ++i) qdot[i] = (plus[k].joints[static_cast<std::size_t>(i)] - minus[k].joints[static_cast<std::size_t>(i)]) / (2 * h);
        const auto j = m.jacobians(pose, sols[k].joints);
        const Eigen::Vector3d lhs = j.A * dir, rhs = j.B * qdot;
        EXPECT_LT((lhs - rhs).norm(), 1e-6 * (1.0 + lhs.norm())) << "mode " << sols[k].mode;
        ++checked;
      }
    }
    EXPECT_GT(checked, 80);
  }
}

TEST(ThreeRrp, StripWorkspaceMatchesAnInverseKinematicsGridCount) {
  // The exact area against counting grid points whose IK is valid in some
  // working mode (an independent membership test).
  const ThreeRrp m = example_prp();
  const auto ws = m.workspace();
  const double exact = ws.area();
  const double grid = grid_area(ws.bbox(), 400, [&](Point q) {
    const auto sols = m.inverse({q.x, q.y, m.orientation()});
    return std::any_of(sols.begin(), sols.end(), [](const JointSolution& s) { return s.valid; });
  });
  EXPECT_NEAR(grid, exact, 0.01 * exact);
  EXPECT_GT(exact, 0.0);
}

TEST(ThreeRrp, CrankLimitedStripWorkspaceMatchesAnInverseKinematicsGridCount) {
  // Cranks limited to a quarter turn each: the strips narrow to the range of
  // r n_i . u(phi_i) over the allowed angles; still exact.
  const double side = 140.0, h = side * std::sqrt(3.0) / 2.0;
  std::array<ThreeRrpChain, 3> c;
  c[0].base = {0, 0};
  c[1].base = {side, 0};
  c[2].base = {side / 2, h};
  const std::array<double, 3> centre{pi / 4, 3 * pi / 4, -pi / 2};
  for (std::size_t i = 0; i < 3; ++i) {
    c[i].crank_length = 25.0;
    c[i].limits = std::array<double, 2>{centre[i] - pi / 4, centre[i] + pi / 4};
  }
  const double r = 40.0 / std::sqrt(3.0);
  std::array<Point, 3> plat{rot(-pi / 2 - pi / 3, {r, 0}), rot(-pi / 2 + pi / 3, {r, 0}), rot(pi / 2, {r, 0})};
  const ThreeRrp m(ThreeRrpDrive::crank, c, plat, 0.35);
  const auto ws = m.workspace();
  const double exact = ws.area();
  ASSERT_GT(exact, 0.0);
  const ThreeRrp unlimited = [&] {
    auto free = c;
    for (auto& ch : free) ch.limits.reset();
    return ThreeRrp(ThreeRrpDrive::crank, free, plat, 0.35);
  }();
  EXPECT_LT(exact, unlimited.workspace().area());
  // In the workspace iff every chain has some crank angle within its limits
  // (any working mode per chain).
  const double grid = grid_area(ws.bbox(), 400, [&](Point q) {
    for (int k = 0; k < 3; ++k) {
      bool any = false;
      for (const auto& s : m.inverse_chain(k, {q.x, q.y, 0.35})) any = any || m.limit_problem(k, s.joint).empty();
      if (!any) return false;
    }
    return true;
  });
  EXPECT_NEAR(grid, exact, 0.01 * exact);
}

}  // namespace
