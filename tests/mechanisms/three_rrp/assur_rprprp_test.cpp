// The Assur group RP-RP-RP ([Mitsi]): the paper's elimination against the closed
// form on random and near-tangent instances, the eliminant's true degree in
// exact arithmetic, its roots.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <boost/multiprecision/cpp_int.hpp>

#include "mechanisms/three_rrp/assur_rprprp.hpp"

#include "support/fixtures.hpp"
#include "support/mechanisms/three_dof.hpp"

namespace {

using namespace pkmws::mechanisms;
using namespace pkmws::test::three_dof;
using pkmws::geometry::Point;
constexpr double pi = std::numbers::pi;

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

}  // namespace
