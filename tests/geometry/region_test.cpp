// Exact regions against closed forms, inclusion-exclusion and both argument orders.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "pkmws/geometry/primitives.hpp"
#include "pkmws/geometry/region.hpp"

using namespace pkmws::geometry;
constexpr double pi = std::numbers::pi;

namespace {

void expect_rel(double actual, double expected, double tol = 1e-13) {
  EXPECT_LE(std::abs(actual - expected), tol * std::abs(expected))
      << "actual " << actual << " expected " << expected;
}

// Area of the lens of two disks of radii r1, r2 at centre distance d.
double lens_area(double r1, double r2, double d) {
  if (d >= r1 + r2) return 0.0;
  if (d <= std::abs(r1 - r2)) return pi * std::min(r1, r2) * std::min(r1, r2);
  const double a1 = std::acos((d * d + r1 * r1 - r2 * r2) / (2 * d * r1));
  const double a2 = std::acos((d * d + r2 * r2 - r1 * r1) / (2 * d * r2));
  return r1 * r1 * (a1 - std::sin(2 * a1) / 2) + r2 * r2 * (a2 - std::sin(2 * a2) / 2);
}

const Box big{{-1000, -1000}, {1000, 1000}};

}  // namespace

TEST(RegionPrimitives, DiskAreaPerimeterCentroid) {
  const Region d = disk({3.25, -1.5}, 2.75);
  expect_rel(d.area(), pi * 2.75 * 2.75);
  const auto comps = d.components();
  ASSERT_EQ(comps.size(), 1u);
  expect_rel(comps[0].perimeter, 2 * pi * 2.75);
  EXPECT_NEAR(comps[0].centroid.x, 3.25, 1e-13);
  EXPECT_NEAR(comps[0].centroid.y, -1.5, 1e-13);
  // Consecutive arcs on one circle are merged into one full-turn arc.
  ASSERT_EQ(comps[0].outer.curves.size(), 1u);
  EXPECT_NEAR(comps[0].outer.curves[0].sweep(), 2 * pi, 1e-15);
  const Box b = d.bbox();
  EXPECT_NEAR(b.min.x, 0.5, 1e-14);
  EXPECT_NEAR(b.max.y, 1.25, 1e-14);
}

TEST(RegionPrimitives, AnnulusHasOneHole) {
  const Region a = annulus({0, 0}, 1.0, 3.0);
  expect_rel(a.area(), pi * (9.0 - 1.0));
  const auto comps = a.components();
  ASSERT_EQ(comps.size(), 1u);
  ASSERT_EQ(comps[0].holes.size(), 1u);
  EXPECT_LT(comps[0].holes[0].signed_area(), 0.0);
  EXPECT_GT(comps[0].outer.signed_area(), 0.0);
  EXPECT_TRUE(a.contains({2.0, 0.0}));
  EXPECT_FALSE(a.contains({0.5, 0.0}));
  EXPECT_TRUE(a.contains({1.0, 0.0}));  // boundary counts as inside
}

TEST(RegionPrimitives, LensMatchesClosedForm) {
  for (double d : {0.3, 1.0, 1.7, 2.9}) {
    const Region lens = disk({0, 0}, 2.0).intersect(disk({d, 0.1}, 1.5));
    expect_rel(lens.area(), lens_area(2.0, 1.5, std::hypot(d, 0.1)), 1e-12);
  }
}

TEST(RegionPrimitives, StadiumAndBand) {
  const Point a{1, 2}, b{7.5, -3};
  const double len = std::hypot(b.x - a.x, b.y - a.y);
  expect_rel(stadium(a, b, 0.8).area(), pi * 0.64 + 2 * 0.8 * len);
  // Band: half circle of radius l swept along h: area 2 l h (Cavalieri).
  for (int side : {-1, 1}) {
    for (double angle : {0.0, 1.5 * pi, 1.5 * pi - 5 * pi / 180, 0.3}) {
      const Region band_region = band({-100, 0}, angle, 200, 250, side);
      expect_rel(band_region.area(), 2 * 250 * 200);
    }
  }
}

TEST(RegionPrimitives, BandSideConvention) {
  // Guide along +x from the origin, stroke 10, radius 3: side +1 lies ahead.
  const Region ahead = band({0, 0}, 0.0, 10, 3, 1);
  EXPECT_TRUE(ahead.contains({12.5, 0}));
  EXPECT_FALSE(ahead.contains({-2.5, 0}));
  EXPECT_FALSE(ahead.contains({1.0, 0}));  // inside the start half disk: not reached
  const Region behind = band({0, 0}, 0.0, 10, 3, -1);
  EXPECT_TRUE(behind.contains({-2.5, 0}));
  EXPECT_FALSE(behind.contains({12.5, 0}));
}

TEST(RegionPrimitives, HalfPlaneStripPolygonSector) {
  const Region half_disk = disk({0, 0}, 2).intersect(half_plane({0, 0}, pi / 2, big));
  expect_rel(half_disk.area(), 2 * pi);
  const Region s = strip({0, -1}, pi / 2, 2, {{-5, -5}, {5, 5}});
  expect_rel(s.area(), 10 * 2);
  const Region tilted = strip({0, 0}, 0.7, 1.5, big).intersect(disk({0.5, 0.5}, 100));
  EXPECT_GT(tilted.area(), 0);
  expect_rel(polygon({{0, 0}, {4, 0}, {4, 3}}).area(), 6);
  expect_rel(polygon({{0, 0}, {4, 3}, {4, 0}}).area(), 6);  // clockwise input
  EXPECT_THROW(polygon({{0, 0}, {1, 1}, {1, 0}, {0, 1}}), std::invalid_argument);
  expect_rel(annulus_sector({1, 1}, 1, 2, 0.2, pi / 3).area(), (4 - 1) * (pi / 3) / 2);
  expect_rel(annulus_sector({1, 1}, 0, 2, -0.4, 1.5 * pi).area(), 4 * 1.5 * pi / 2);
  expect_rel(oriented_rectangle({1, 1}, 0.3, 5, 0.5).area(), 5.0);
}

TEST(RegionPrimitives, RationalDirectionIsCloseToTheAngle) {
  for (double a : {0.0, 0.1, 1.0, 1.5 * pi - 5 * pi / 180, -2.0, 3.0, 7.0}) {
    const RationalDirection d = rational_direction(a);
    EXPECT_NEAR(std::remainder(d.angle() - a, 2 * pi), 0.0, 4e-16);
    EXPECT_NEAR(d.unit().x, std::cos(a), 4e-16);
    EXPECT_NEAR(d.unit().y, std::sin(a), 4e-16);
  }
}

TEST(RegionPrimitives, BadParametersThrow) {
  EXPECT_THROW(disk({0, 0}, 0.0), std::invalid_argument);
  EXPECT_THROW(disk({0, 0}, NAN), std::invalid_argument);
  EXPECT_THROW(annulus({0, 0}, 2, 1), std::invalid_argument);
  EXPECT_THROW(band({0, 0}, 0, -1, 1, 1), std::invalid_argument);
  EXPECT_THROW(band({0, 0}, 0, 1, 1, 0), std::invalid_argument);
}

TEST(RegionBooleans, InclusionExclusionBothOrders) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-3, 3), r(0.5, 2.5);
  for (int k = 0; k < 20; ++k) {
    const Region a = disk({u(rng), u(rng)}, r(rng)).subtract(disk({u(rng), u(rng)}, r(rng) / 2));
    const Region b = stadium({u(rng), u(rng)}, {u(rng), u(rng)}, r(rng) / 2);
    const double ab = a.intersect(b).area();
    expect_rel(ab, b.intersect(a).area(), 1e-12);
    const double uni = a.unite(b).area();
    expect_rel(uni, b.unite(a).area(), 1e-12);
    EXPECT_NEAR(uni, a.area() + b.area() - ab, 1e-12 * uni);
    EXPECT_NEAR(a.subtract(b).area(), a.area() - ab, 1e-12 * a.area());
    EXPECT_NEAR(a.symmetric_difference(b).area(), uni - ab, 1e-12 * uni);
  }
}

TEST(RegionBooleans, UniteAllEqualsFoldedUnion) {
  std::vector<Region> disks;
  Region folded;
  for (int i = 0; i < 12; ++i) {
    disks.push_back(disk({std::cos(i * 0.5) * 3, std::sin(i * 0.7) * 3}, 1.0 + 0.1 * i));
    folded = folded.unite(disks.back());
  }
  const Region all = Region::unite_all(disks);
  expect_rel(all.area(), folded.area(), 1e-12);
  EXPECT_TRUE(all.symmetric_difference(folded).area() < 1e-12 * all.area());
}

TEST(RegionBooleans, SeveralComponentsAndEmpty) {
  const Region two = disk({0, 0}, 1).unite(disk({5, 0}, 1));
  EXPECT_EQ(two.components().size(), 2u);
  expect_rel(two.area(), 2 * pi);
  EXPECT_TRUE(disk({0, 0}, 1).intersect(disk({5, 0}, 1)).empty());
  EXPECT_EQ(Region().area(), 0.0);
  EXPECT_TRUE(Region().bbox().empty());
}

TEST(RegionLoops, PolylineStaysWithinTolerance) {
  const Region a = annulus({1, 2}, 1.0, 3.0);
  for (double tol : {1e-2, 1e-4, 1e-6}) {
    for (const Loop& loop : a.loops()) {
      const auto pts = loop.polyline(tol);
      double shoelace = 0;
      for (std::size_t i = 0; i < pts.size(); ++i) {
        const auto& p = pts[i];
        const auto& q = pts[(i + 1) % pts.size()];
        shoelace += 0.5 * (p.x * q.y - q.x * p.y);
        // Every point lies on its circle; chord midpoints within tol of it.
        const double rp = std::hypot(p.x - 1, p.y - 2);
        EXPECT_TRUE(std::abs(rp - 1.0) < 1e-12 || std::abs(rp - 3.0) < 1e-12);
        const double rm = std::hypot((p.x + q.x) / 2 - 1, (p.y + q.y) / 2 - 2);
        EXPECT_LE(std::min(std::abs(rm - 1.0), std::abs(rm - 3.0)), tol * (1 + 1e-9));
      }
      const double exact = loop.signed_area();
      EXPECT_LE(std::abs(shoelace - exact), loop.perimeter() * tol);
      EXPECT_EQ(shoelace > 0, !loop.hole);
    }
  }
}

TEST(RegionLoops, TinyMergedArcPiecesAreNotFullTurns) {
  // Union of two crank-limited five-bar leg pieces with l1 = l2 (reported by the
  // five-bar work): merged arc pieces ~1e-17 long have endpoints that round to
  // one double and must sweep ~0, not 2 pi.
  const double l = 0.23, deg = pi / 180;
  const Point a{-0.1, 0.05};
  auto half = [&](double t) {
    const RationalDirection d = rational_direction(t);
    const Point b{a.x + l * d.unit().x, a.y + l * d.unit().y};
    return disk(b, l).subtract(annulus_sector(a, 0.0, 4 * l, t, pi));
  };
  const double t0 = -100 * deg, t2 = 130 * deg, t1 = t0 + (t2 - t0) / 2;
  const Region p0 = annulus_sector(a, 0, 2 * l, t0, t1 - t0).unite(half(t0)).subtract(half(t1));
  const Region p1 = annulus_sector(a, 0, 2 * l, t1, t2 - t1).unite(half(t1)).subtract(half(t2));
  const double expected = p0.area() + p1.area() - p0.intersect(p1).area();
  expect_rel(p0.unite(p1).area(), expected, 1e-12);
  expect_rel(Region::unite_all({p0, p1}).area(), expected, 1e-12);
  for (const Loop& loop : p0.unite(p1).loops()) {
    for (const Curve& c : loop.curves) EXPECT_LE(std::abs(c.sweep()), 2 * pi);
  }
}
