// area_in_disks against CGAL's exact Booleans: boxes and star-shaped
// polygons (both orientations) across one circle of a set of signed disks,
// inside or outside the others; the enclosure must hold the exact area and be
// tight, and the closed form must decide most of them (else the level sets
// fall back to the exact Booleans and gain nothing).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "pkmws/certified/disk_area.hpp"
#include "pkmws/geometry/primitives.hpp"

namespace {

using namespace pkmws;
using certified::SignedDisk;
using geometry::Point;

geometry::Region disks_region(const std::vector<SignedDisk>& disks, const geometry::Box& around) {
  geometry::Region r = geometry::rectangle(around);
  for (const SignedDisk& d : disks) {
    const geometry::Region c = geometry::disk(d.centre, d.radius);
    r = d.inside ? r.intersect(c) : r.subtract(c);
  }
  return r;
}

// A star-shaped polygon about c with n vertices at radii in [0.4, 1] * size.
std::vector<Point> star(Point c, double size, int n, bool clockwise, std::mt19937& rng) {
  std::uniform_real_distribution<double> rad(0.4, 1.0), jitter(-0.3, 0.3);
  std::vector<Point> p;
  for (int k = 0; k < n; ++k) {
    const double t = 2.0 * std::numbers::pi * (k + 0.5 + jitter(rng)) / n;
    const double r = size * rad(rng);
    p.push_back({c.x + r * std::cos(t), c.y + r * std::sin(t)});
  }
  if (clockwise) std::reverse(p.begin(), p.end());
  return p;
}

struct Tally {
  int decided = 0, total = 0;
};

// Polygons near points of the first disk's circle, of sizes from 1e-4 to 0.3
// of its radius.
void check_near_circle(const std::vector<SignedDisk>& disks, bool boxes, std::mt19937& rng, Tally& tally) {
  const geometry::Box around{{-10.0, -10.0}, {10.0, 10.0}};
  const geometry::Region set = disks_region(disks, around);
  const SignedDisk& d = disks.front();
  std::uniform_real_distribution<double> angle(0.0, 2.0 * std::numbers::pi), offset(-1.0, 1.0), lg(-4.0, -0.5);
  for (int k = 0; k < 60; ++k) {
    const double size = d.radius * std::pow(10.0, lg(rng));
    const double t = angle(rng);
    const Point c{d.centre.x + (d.radius + 0.5 * size * offset(rng)) * std::cos(t),
                  d.centre.y + (d.radius + 0.5 * size * offset(rng)) * std::sin(t)};
    std::vector<Point> poly;
    if (boxes) {
      const double h = size * (0.5 + 0.5 * std::abs(offset(rng)));
      poly = {{c.x - size, c.y - h}, {c.x + size, c.y - h}, {c.x + size, c.y + h}, {c.x - size, c.y + h}};
    } else {
      poly = star(c, size, 3 + k % 9, k % 2 == 1, rng);
    }
    const double exact = set.intersect(geometry::polygon(poly)).area();
    const auto a = certified::area_in_disks(poly, disks);
    ++tally.total;
    if (!a) continue;
    ++tally.decided;
    // CGAL's area() sums the exact boundary's curves rounded to doubles (~1e-16
    // of the coordinates' size along the polygon's edges).
    const double scale = d.radius + std::abs(d.centre.x) + std::abs(d.centre.y);
    const double slack = 1e-14 * scale * size + 4.0 * std::numeric_limits<double>::epsilon() * exact;
    EXPECT_LE(a->lo, exact + slack) << "polygon " << k << " of size " << size;
    EXPECT_GE(a->hi, exact - slack) << "polygon " << k << " of size " << size;
    // At the rounding of the circle's scale (the parts are measured from its centre).
    EXPECT_LE(a->hi - a->lo, 1e-12 * d.radius * d.radius) << "polygon " << k << " of size " << size;
  }
}

TEST(DiskArea, EnclosesTheExactAreaOfPolygonsAcrossACircle) {
  std::mt19937 rng(2026);
  Tally tally;
  const std::vector<std::vector<SignedDisk>> sets = {
      {{{0.1, -0.2}, 0.4, true}},
      {{{0.1, -0.2}, 0.4, false}},
      // The crossed circle first; the others contain or avoid the polygons near it.
      {{{0.0, 0.0}, 0.3875, true}, {{0.0, 0.0}, 0.4, true}, {{0.25, 0.0}, 0.4, true}, {{-0.125, 0.0}, 0.0667, false}},
      {{{-0.125, 0.0}, 0.0667, false}, {{0.125, 0.0}, 0.4, true}, {{-0.125, 0.0}, 0.4, true}},
      {{{3.0, 1.0}, 2.5, false}, {{3.0, 1.0}, 6.0, true}},
  };
  for (const auto& disks : sets) {
    check_near_circle(disks, true, rng, tally);
    check_near_circle(disks, false, rng, tally);
  }
  // Most are decided in closed form (the others: a box crossing two
  // circles, a polygon whose edge spans a quarter turn from the centre).
  EXPECT_GE(tally.decided, tally.total * 3 / 4) << tally.decided << " of " << tally.total;
}

TEST(DiskArea, DecidesBoxesInsideOrOutsideEveryCircleWithoutTheClosedForm) {
  const std::vector<SignedDisk> disks{{{0.0, 0.0}, 1.0, true}, {{0.0, 0.0}, 0.25, false}};
  const std::vector<Point> inside{{0.5, 0.0}, {0.6, 0.0}, {0.6, 0.1}, {0.5, 0.1}};
  const std::vector<Point> hole{{0.0, 0.0}, {0.1, 0.0}, {0.1, 0.1}, {0.0, 0.1}};
  const auto a = certified::area_in_disks(inside, disks), b = certified::area_in_disks(hole, disks);
  ASSERT_TRUE(a && b);
  EXPECT_NEAR(a->lo, 0.01, 1e-15);
  EXPECT_NEAR(a->hi, 0.01, 1e-15);
  EXPECT_EQ(b->lo, 0.0);
  EXPECT_EQ(b->hi, 0.0);
  // A box across both circles of an annulus: not decided here.
  const std::vector<Point> across{{0.2, -0.9}, {1.1, -0.9}, {1.1, 0.9}, {0.2, 0.9}};
  EXPECT_FALSE(certified::area_in_disks(across, disks));
}

}  // namespace
