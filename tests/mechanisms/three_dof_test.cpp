// 3-RRP / 3-PRP (Assur group RP-RP-RP) and 3-RPR: direct kinematics by two
// methods, round trips, Jacobians against finite differences, workspaces.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <boost/multiprecision/cpp_int.hpp>

#include "mechanisms/three_rrp/assur_rprprp.hpp"
#include "mechanisms/three_rpr/three_rpr.hpp"
#include "mechanisms/three_rrp/three_rrp.hpp"

namespace {

using namespace pkmws::mechanisms;
using pkmws::geometry::Point;
constexpr double pi = std::numbers::pi;

double angle_diff(double a, double b) { return std::remainder(a - b, 2.0 * pi); }

Point rot(double phi, Point p) {
  return {std::cos(phi) * p.x - std::sin(phi) * p.y, std::sin(phi) * p.x + std::cos(phi) * p.y};
}

// A random counter-clockwise triangle, not too flat.
std::array<Point, 3> random_triangle(std::mt19937_64& rng, double scale) {
  std::uniform_real_distribution<double> u(-scale, scale);
  for (;;) {
    std::array<Point, 3> t{Point{u(rng), u(rng)}, Point{u(rng), u(rng)}, Point{u(rng), u(rng)}};
    double area = 0.5 * ((t[1].x - t[0].x) * (t[2].y - t[0].y) - (t[1].y - t[0].y) * (t[2].x - t[0].x));
    if (area < 0) std::swap(t[1], t[2]), area = -area;
    double longest = 0;
    for (int i = 0; i < 3; ++i) longest = std::max(longest, std::hypot(t[(i + 1) % 3].x - t[i].x, t[(i + 1) % 3].y - t[i].y));
    if (area > 0.05 * longest * longest) return t;
  }
}

// External joints on the side lines of the triangle placed at (origin, phi):
// A_i = B_i - s_i u_i ([Mitsi] eq. 14 read backwards).
std::array<Point, 3> joints_on_sides(const AssurTriangle& tri, Point origin, double phi, const std::array<double, 3>& s) {
  std::array<Point, 3> a;
  for (std::size_t i = 0; i < 3; ++i) {
    const Point b = origin + rot(phi, tri.vertices[i]);
    const Point u = rot(phi, tri.direction[i]);
    a[i] = b - s[i] * u;
  }
  return a;
}

bool has_assembly(const std::vector<AssurAssembly>& v, Point origin, double phi, double tol) {
  for (const auto& as : v)
    if (std::hypot(as.origin.x - origin.x, as.origin.y - origin.y) < tol && std::abs(angle_diff(as.phi, phi)) < tol) return true;
  return false;
}

// Area of {p in box : in(p)} counted at the centres of an n x n grid.
template <class Predicate>
double grid_area(const pkmws::geometry::Box& box, int n, Predicate in) {
  const double dx = box.width() / n, dy = box.height() / n;
  long count = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) count += in(Point{box.min.x + (i + 0.5) * dx, box.min.y + (j + 0.5) * dy}) ? 1 : 0;
  return static_cast<double>(count) * dx * dy;
}

// ---------------------------------------------------------------------------
// The Assur group: the paper's elimination against the closed form.

TEST(AssurGroup, EliminationAndClosedFormAgreeOnThousandsOfRandomInstances) {
  std::mt19937_64 rng(20261123);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int two = 0, one_or_none = 0;
  double worst = 0.0;
  for (int trial = 0; trial < 3000; ++trial) {
    const AssurTriangle tri = AssurTriangle::from_vertices(random_triangle(rng, 1.0));
    const Point origin{3.0 * u(rng), 3.0 * u(rng)};
    const double phi = pi * u(rng);
    const std::array<double, 3> s{2.0 * u(rng), 2.0 * u(rng), 2.0 * u(rng)};
    const auto a = joints_on_sides(tri, origin, phi, s);
    const auto closed = assur_closed_form(tri, a);
    const auto elim = assur_elimination(tri, a);
    ASSERT_LE(closed.size(), 2u);
    ASSERT_LE(elim.assemblies.size(), 2u);
    ASSERT_LE(elim.real_roots.size(), 4u);  // true degree 4
    EXPECT_EQ(closed.size(), elim.assemblies.size()) << "trial " << trial;
    // The pose the joints were built from is found by both.
    EXPECT_TRUE(has_assembly(closed, origin, phi, 1e-8)) << "trial " << trial;
    EXPECT_TRUE(has_assembly(elim.assemblies, origin, phi, 1e-8)) << "trial " << trial;
    if (closed.size() == elim.assemblies.size()) {
      for (std::size_t k = 0; k < closed.size(); ++k) {
        for (std::size_t i = 0; i < 3; ++i) {
          const Point d = closed[k].vertices[i] - elim.assemblies[k].vertices[i];
          worst = std::max(worst, std::hypot(d.x, d.y));
          EXPECT_NEAR(closed[k].s[i], elim.assemblies[k].s[i], 1e-8);
        }
      }
    }
    (closed.size() == 2 ? two : one_or_none)++;
    // Every assembly satisfies B_i = A_i + s_i u_i with u_i the rotated side direction.
    for (const auto& as : closed)
      for (std::size_t i = 0; i < 3; ++i) {
        const Point u_i = rot(as.phi, tri.direction[i]);
        const Point r = as.vertices[i] - (a[i] + as.s[i] * u_i);
        EXPECT_LT(std::hypot(r.x, r.y), 1e-10);
      }
  }
  EXPECT_LT(worst, 1e-9);
  EXPECT_GT(two, 2500);  // generic inputs have two assembly modes
}

TEST(AssurGroup, NearTangentInstancesAgreeAndCountCorrectly) {
  // Scaling the platform by t divides the sinusoid's amplitude by t: t = K/(1+eta)
  // puts the amplitude at 1 + eta, the two assembly modes eta apart.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (double eta : {1e-3, 1e-6, 1e-9, -1e-9, -1e-6}) {
    int checked = 0;
    for (int trial = 0; trial < 300; ++trial) {
      const auto base_tri = random_triangle(rng, 1.0);
      const std::array<Point, 3> a{Point{3 * u(rng), 3 * u(rng)}, Point{3 * u(rng), 3 * u(rng)}, Point{3 * u(rng), 3 * u(rng)}};
      const auto sc = assur_scale_sinusoid(AssurTriangle::from_vertices(base_tri), a);
      const double k = std::hypot(sc[0], sc[1]);
      if (!(k > 1e-3)) continue;
      const double t = k / (1.0 + eta);
      std::array<Point, 3> scaled;
      for (std::size_t i = 0; i < 3; ++i) scaled[i] = t * base_tri[i];
      const AssurTriangle tri = AssurTriangle::from_vertices(scaled);
      const auto sc2 = assur_scale_sinusoid(tri, a);
      EXPECT_NEAR(std::hypot(sc2[0], sc2[1]), 1.0 + eta, 1e-12);
      const auto closed = assur_closed_form(tri, a);
      const auto elim = assur_elimination(tri, a);
      if (eta >= 1e-6) {
        EXPECT_EQ(closed.size(), 2u);
        EXPECT_EQ(elim.assemblies.size(), 2u);
      } else if (eta <= -1e-6) {
        EXPECT_EQ(closed.size(), 0u);
        EXPECT_EQ(elim.assemblies.size(), 0u);
      }
      // Whatever each finds lies on the side lines and near the other's result:
      // the modes are ~sqrt(eta) apart, so agreement is ~ sqrt(eps) there.
      const double tol = 1e-6 * t;
      for (const auto& as : elim.assemblies) EXPECT_TRUE(has_assembly(closed, as.origin, as.phi, std::max(tol, 1e-6)) || closed.empty());
      ++checked;
    }
    EXPECT_GT(checked, 250);
  }
}

TEST(AssurGroup, EliminantHasTrueDegreeFourInExactArithmetic) {
  // Integer sides give rational cosines (law of cosines), so eq. 9-13 run in
  // exact rationals: the coefficients of s1^8 ... s1^5 vanish identically,
  // s1^4 does not.
  using Q = boost::multiprecision::cpp_rational;
  const std::array<std::array<int, 3>, 4> triangles{{{3, 4, 5}, {7, 8, 9}, {5, 5, 6}, {4, 6, 9}}};
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<int> d(1, 400);
  for (const auto& sides : triangles) {
    // l1 = |B1B2|, l2 = |B2B3|, l3 = |B3B1|; α1 at B1 between sides l1 and l3.
    const Q l1 = sides[0], l2 = sides[1], l3 = sides[2];
    const std::array<Q, 3> side{l1, l2, l3};
    const std::array<Q, 3> cosine{(l1 * l1 + l3 * l3 - l2 * l2) / (2 * l1 * l3),
                                  (l1 * l1 + l2 * l2 - l3 * l3) / (2 * l1 * l2),
                                  (l2 * l2 + l3 * l3 - l1 * l1) / (2 * l2 * l3)};
    for (int k = 0; k < 5; ++k) {
      const std::array<Q, 3> dist{Q(d(rng), 7), Q(d(rng), 3), Q(d(rng), 5)};
      const auto e = assur_eliminant(assur_quadratics(side, cosine, dist));
      for (int p = 5; p <= 8; ++p) EXPECT_EQ(e[static_cast<std::size_t>(p)], 0) << "power " << p;
      EXPECT_NE(e[4], 0);
    }
  }
  // Angles that do not close a triangle keep the nominal degree 8: the
  // cancellation comes from the triangle, not from the elimination.
  const std::array<Q, 3> side{3, 4, 5};
  const std::array<Q, 3> cosine{Q(1, 2), Q(1, 3), Q(1, 5)};
  const auto e = assur_eliminant(assur_quadratics(side, cosine, std::array<Q, 3>{10, 20, 30}));
  EXPECT_NE(e[8], 0);
  // ... and equals 16 G^2, G = cos²α1 + cos²α2 + cos²α3 + 2 cos α1 cos α2 cos α3 - 1
  // (zero exactly for the angles of a triangle).
  const Q g = cosine[0] * cosine[0] + cosine[1] * cosine[1] + cosine[2] * cosine[2] +
              2 * cosine[0] * cosine[1] * cosine[2] - 1;
  EXPECT_EQ(e[8], 16 * g * g);
}

TEST(AssurGroup, EliminantRootsAreTheTrianglesAndTheirMirrorImages) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const AssurTriangle tri = AssurTriangle::from_vertices(random_triangle(rng, 1.0));
    const auto a = joints_on_sides(tri, {u(rng), u(rng)}, pi * u(rng), {u(rng), u(rng), u(rng)});
    const auto elim = assur_elimination(tri, a);
    EXPECT_EQ(elim.roots.degree, 4);
    int assembled = 0;
    for (const auto& r : elim.real_roots) {
      EXPECT_LT(r.residual, 1e-12);
      assembled += r.assembled ? 1 : 0;
    }
    EXPECT_EQ(static_cast<std::size_t>(assembled), elim.assemblies.size());
    EXPECT_EQ(elim.real_s1.size() + elim.complex_s1.size(), 4u);
  }
}

// ---------------------------------------------------------------------------
// 3-RRP / 3-PRP

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

// ---------------------------------------------------------------------------
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
