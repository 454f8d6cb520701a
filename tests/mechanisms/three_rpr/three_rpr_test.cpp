// 3-RPR: direct kinematics of random instances, six real assembly modes, base
// angle round trips, the velocity relation against finite differences, the
// annulus workspace, PAMINSA's traced singularity, actuator efforts.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "mechanisms/three_rpr/three_rpr.hpp"

#include "support/fixtures.hpp"
#include "support/mechanisms/three_dof.hpp"

namespace {

using namespace pkmws::mechanisms;
using namespace pkmws::test::three_dof;
using pkmws::geometry::Point;
using pkmws::test::grid_area;
constexpr double pi = std::numbers::pi;

// 3-RPR

struct RandomRpr {
  std::array<Point, 3> base, platform;
};

RandomRpr random_rpr(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  RandomRpr r;
  for (auto& p : r.base) p = {u(rng), u(rng)};
  for (auto& p : r.platform) p = {0.4 * u(rng), 0.4 * u(rng)};
  return r;
}

// Poses with legs 1 and 2 at the given lengths, at orientation phi: the circle
// intersection, returned with the leg-3 residual |B3 - A3|^2 - rho3^2.
std::vector<std::pair<Pose, double>> legs12_poses(const ThreeRpr& m, const std::array<double, 3>& rho, double phi) {
  std::vector<std::pair<Pose, double>> out;
  const Point c1 = m.base()[0] - rot(phi, m.platform()[0]);
  const Point c2 = m.base()[1] - rot(phi, m.platform()[1]);
  const Point d = c2 - c1;
  const double dist = std::hypot(d.x, d.y);
  if (dist == 0.0) return out;
  const double a = (rho[0] * rho[0] - rho[1] * rho[1] + dist * dist) / (2 * dist);
  const double h2 = rho[0] * rho[0] - a * a;
  if (h2 < 0.0) return out;
  const double h = std::sqrt(h2);
  for (int s : {1, -1}) {
    const Point p{c1.x + a * d.x / dist - s * h * d.y / dist, c1.y + a * d.y / dist + s * h * d.x / dist};
    const Point b3 = p + rot(phi, m.platform()[2]);
    const double r3 = std::hypot(b3.x - m.base()[2].x, b3.y - m.base()[2].y);
    out.push_back({Pose{p.x, p.y, phi}, r3 * r3 - rho[2] * rho[2]});
  }
  return out;
}

TEST(ThreeRpr, DirectKinematicsFindsEveryPoseOfRandomInstances) {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int instances = 0, poses_total = 0, missed = 0;
  std::array<int, 7> histogram{};
  for (int trial = 0; trial < 300; ++trial) {
    const RandomRpr r = random_rpr(rng);
    const ThreeRpr m(r.base, r.platform, ThreeRprActuation::prismatic);
    const Pose truth{0.5 * u(rng), 0.5 * u(rng), pi * u(rng)};
    const auto rho = m.leg_lengths(truth);
    const auto d = m.direct_from_lengths(rho);
    if (d.continuum) continue;
    ++instances;
    ASSERT_LE(d.poses.size(), 6u);
    ++histogram[d.poses.size()];
    poses_total += static_cast<int>(d.poses.size());
    bool found = false;
    for (const Pose& p : d.poses) {
      const auto l = m.leg_lengths(p);
      for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(l[i], rho[i], 1e-10 * std::max(1.0, rho[i]));
      found = found || (std::hypot(p.x - truth.x, p.y - truth.y) < 1e-8 && std::abs(angle_diff(p.phi, truth.phi)) < 1e-8);
    }
    EXPECT_TRUE(found) << "trial " << trial;
    // Dense scan of the orientation: every sign change of leg 3's residual
    // on a branch of legs 1-2 must be a returned pose.
    const int steps = 20000;
    std::vector<std::pair<Pose, double>> prev = legs12_poses(m, rho, -pi);
    for (int k = 1; k <= steps; ++k) {
      const double phi = -pi + 2 * pi * k / steps;
      const auto cur = legs12_poses(m, rho, phi);
      if (cur.size() == 2 && prev.size() == 2) {
        for (std::size_t b = 0; b < 2; ++b) {
          if ((prev[b].second < 0) != (cur[b].second < 0)) {
            bool near = false;
            for (const Pose& p : d.poses) near = near || std::abs(angle_diff(p.phi, phi)) < 4 * pi / steps;
            if (!near) ++missed;
          }
        }
      }
      prev = cur;
    }
  }
  EXPECT_EQ(missed, 0);
  EXPECT_GT(instances, 280);
  EXPECT_GT(poses_total, instances);  // more than one pose on average
}

TEST(ThreeRpr, SixRealAssemblyModes) {
  // The design of datasets/three_rpr_prismatic.json: the sextic has six real
  // roots for leg lengths (1.809, 1.142, 0.694), each a pose with those legs.
  const ThreeRpr m({Point{-0.94, -0.84}, Point{-0.15, -0.47}, Point{0.55, 0.61}},
                   {Point{-0.09, 0.14}, Point{-0.29, -0.06}, Point{0.09, -0.21}}, ThreeRprActuation::prismatic);
  const std::array<double, 3> rho{1.809, 1.142, 0.694};
  const auto d = m.direct_from_lengths(rho);
  ASSERT_EQ(d.poses.size(), 6u);
  EXPECT_EQ(d.roots.degree, 6);
  EXPECT_EQ(d.roots.real.size(), 6u);
  for (const Pose& p : d.poses) {
    const auto l = m.leg_lengths(p);
    for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(l[i], rho[i], 1e-12);
  }
  // Assembly modes alternate in the sign of det A along phi.
  int sign_changes = 0;
  for (std::size_t k = 1; k < d.poses.size(); ++k)
    sign_changes += (m.transmission(d.poses[k]).determinant > 0) != (m.transmission(d.poses[k - 1]).determinant > 0);
  EXPECT_GE(sign_changes, 1);
}

TEST(ThreeRpr, BaseAngleDirectKinematicsRoundTrips) {
  const ThreeRpr m = ThreeRpr::symmetric(0.35, 0.1, ThreeRprActuation::revolute);
  std::mt19937_64 rng(19);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int checked = 0;
  for (int trial = 0; trial < 500; ++trial) {
    const Pose truth{0.15 * u(rng), 0.15 * u(rng), 0.8 * u(rng)};
    const auto q = m.leg_angles(truth);
    const auto d = m.direct_from_angles(q);
    bool found = false;
    for (const Pose& p : d.poses) {
      const auto back = m.leg_angles(p);
      for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(std::remainder(back[i] - q[i], pi), 0.0, 1e-9);
      found = found || (std::hypot(p.x - truth.x, p.y - truth.y) < 1e-9 && std::abs(angle_diff(p.phi, truth.phi)) < 1e-9);
    }
    EXPECT_TRUE(found) << "trial " << trial;
    ++checked;
  }
  EXPECT_EQ(checked, 500);
}

TEST(ThreeRpr, VelocityRelationMatchesFiniteDifferences) {
  for (auto act : {ThreeRprActuation::prismatic, ThreeRprActuation::revolute}) {
    const ThreeRpr m = ThreeRpr::symmetric(0.35, 0.1, act);
    std::mt19937_64 rng(23);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int trial = 0; trial < 100; ++trial) {
      const Pose pose{0.1 * u(rng), 0.1 * u(rng), 0.5 * u(rng)};
      const Eigen::Vector3d dir(u(rng), u(rng), u(rng));
      const double h = 1e-6;
      const Pose pp{pose.x + h * dir[0], pose.y + h * dir[1], pose.phi + h * dir[2]};
      const Pose pm{pose.x - h * dir[0], pose.y - h * dir[1], pose.phi - h * dir[2]};
      const auto qp = act == ThreeRprActuation::prismatic ? m.leg_lengths(pp) : m.leg_angles(pp);
      const auto qm = act == ThreeRprActuation::prismatic ? m.leg_lengths(pm) : m.leg_angles(pm);
      Eigen::Vector3d qdot;
      for (int i = 0; i < 3; ++i) qdot[i] = std::remainder(qp[static_cast<std::size_t>(i)] - qm[static_cast<std::size_t>(i)], 2 * pi) / (2 * h);
      const auto j = m.jacobians(pose);
      const Eigen::Vector3d lhs = j.A * dir, rhs = j.B * qdot;
      EXPECT_LT((lhs - rhs).norm(), 1e-6 * (1.0 + lhs.norm()));
    }
  }
}

TEST(ThreeRpr, AnnulusWorkspaceMatchesAGridCount) {
  const std::array<std::array<double, 2>, 3> limits{{{0.2, 0.5}, {0.25, 0.55}, {0.2, 0.45}}};
  const ThreeRpr m = ThreeRpr::symmetric(0.35, 0.1, ThreeRprActuation::prismatic, 0.3, limits);
  const auto ws = m.workspace();
  const double exact = ws.area();
  ASSERT_GT(exact, 0.0);
  int disagreements = 0;
  const double grid = grid_area(m.bounds(), 500, [&](Point q) {
    const Pose p{q.x, q.y, 0.3};
    const auto l = m.leg_lengths(p);
    bool in = true;
    for (std::size_t k = 0; k < 3; ++k) in = in && l[k] >= limits[k][0] && l[k] <= limits[k][1];
    disagreements += in != m.reachable(p) ? 1 : 0;
    return in;
  });
  EXPECT_EQ(disagreements, 0);
  EXPECT_NEAR(grid, exact, 0.01 * exact);
}

}  // namespace

namespace {

TEST(ThreeRpr, TracedSingularityOfPaminsaIsThePapersCircle) {
  // [Briot]: for fixed phi the type-2 singularity of the planar PAMINSA
  // (actuated base revolutes) is the circle about O of radius
  // sqrt(R_b^2 + R_p^2 - 2 R_b R_p cos phi). The drawing traces det A = 0.
  const double rb = 0.35, rp = 0.1;
  const ThreeRpr m = ThreeRpr::symmetric(rb, rp, ThreeRprActuation::revolute);
  for (double phi_deg : {0.0, 25.0, 50.0}) {
    const double phi = phi_deg * pi / 180.0;
    const double radius = std::sqrt(rb * rb + rp * rp - 2 * rb * rp * std::cos(phi));
    const auto d = m.draw({0.0, 0.0, phi});
    ASSERT_FALSE(d.singular_curves.empty());
    std::size_t points = 0;
    double turning = 0.0;
    for (const auto& curve : d.singular_curves) {
      for (std::size_t k = 0; k < curve.size(); ++k) {
        EXPECT_NEAR(std::hypot(curve[k].x, curve[k].y), radius, 1e-9) << "phi " << phi_deg;
        if (k > 0) turning += std::remainder(std::atan2(curve[k].y, curve[k].x) - std::atan2(curve[k - 1].y, curve[k - 1].x), 2 * pi);
      }
      points += curve.size();
    }
    EXPECT_GT(points, 100u);
    EXPECT_NEAR(std::abs(turning), 2 * pi, 0.1);  // the whole circle
  }
}

}  // namespace

namespace {

TEST(ThreeRpr, ActuatorEffortIsTheWorstVirtualWorkOfTheLoad) {
  // [Briot] Table 2 (chain RPR): the actuator's worst effort over loads of
  // force norm f (any direction) and moment ±m at P is
  // f |∂P/∂q_i| + |m| |∂φ/∂q_i|, here by finite differences of the DK.
  const double f = 100.0, mom = 5.0;
  Criteria criteria;
  criteria.load = Load{f, mom};
  for (auto act : {ThreeRprActuation::revolute, ThreeRprActuation::prismatic}) {
    const ThreeRpr m = ThreeRpr::symmetric(0.35, 0.1, act);
    std::mt19937_64 rng(41);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int checked = 0;
    for (int n = 0; n < 60; ++n) {
      const Pose pose{0.12 * u(rng), 0.12 * u(rng), 0.4 * u(rng)};
      const auto ev = m.evaluate(pose, criteria).front();
      // Away from the type-2 singularity (finite differences lose accuracy there).
      if (ev.singular || ev.reactions_N.size() != 3 || !(ev.condition_number < 50.0)) continue;
      const auto q = act == ThreeRprActuation::revolute ? m.leg_angles(pose) : m.leg_lengths(pose);
      for (std::size_t i = 0; i < 3; ++i) {
        const double h = 1e-7;
        auto solve = [&](double dq) {
          auto qq = q;
          qq[i] += dq;
          const auto d = act == ThreeRprActuation::revolute ? m.direct_from_angles(qq) : m.direct_from_lengths(qq);
          Pose best{1e300, 1e300, 0};
          for (const Pose& p : d.poses)
            if (std::hypot(p.x - pose.x, p.y - pose.y) + std::abs(angle_diff(p.phi, pose.phi)) <
                std::hypot(best.x - pose.x, best.y - pose.y) + std::abs(angle_diff(best.phi, pose.phi)))
              best = p;
          return best;
        };
        const Pose pp = solve(h), pm = solve(-h);
        const double expected = f * std::hypot(pp.x - pm.x, pp.y - pm.y) / (2 * h) +
                                mom * std::abs(angle_diff(pp.phi, pm.phi)) / (2 * h);
        double effort = -1.0;
        for (const auto& [k, v] : ev.extra)
          if (k == "actuator_effort" + std::to_string(i + 1)) effort = v;
        EXPECT_NEAR(effort, expected, 1e-4 * expected);
        ++checked;
      }
    }
    EXPECT_GT(checked, 100);
  }
}

}  // namespace
