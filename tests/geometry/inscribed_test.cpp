#include <gtest/gtest.h>

#include <cmath>

#include "pkmws/geometry/inscribed.hpp"
#include "pkmws/geometry/primitives.hpp"

using namespace pkmws::geometry;

TEST(Inscribed, DiskRectangleAnnulusBand) {
  const double eps = 1e-4;
  {
    const auto c = disk({2, -1}, 3).components().at(0);
    const auto ic = largest_inscribed_circle(c, eps);
    EXPECT_NEAR(ic.radius, 3.0, 2 * eps);
    EXPECT_LE(ic.radius, ic.radius_upper);
    EXPECT_NEAR(ic.center.x, 2.0, 1e-3);
  }
  {
    const auto c = rectangle({{0, 0}, {4, 2}}).components().at(0);
    const auto ic = largest_inscribed_circle(c, eps);
    EXPECT_NEAR(ic.radius, 1.0, 2 * eps);
    EXPECT_GE(ic.radius_upper, 1.0 - 1e-12);
  }
  {
    const auto c = annulus({0, 0}, 1, 3).components().at(0);
    const auto ic = largest_inscribed_circle(c, eps);
    EXPECT_NEAR(ic.radius, 1.0, 2 * eps);
    EXPECT_NEAR(std::hypot(ic.center.x, ic.center.y), 2.0, 1e-3);
    EXPECT_FALSE(inside(c, {0, 0}));
    EXPECT_TRUE(inside(c, {2, 0.1}));
  }
  {
    // A band of half-width 5 swept along 20: the widest disk has radius 5.
    const auto c = band({0, 0}, 0.0, 20, 5, 1).components().at(0);
    const auto ic = largest_inscribed_circle(c, eps);
    EXPECT_NEAR(ic.radius, 5.0, 2 * eps);
  }
}

TEST(Inscribed, DistanceToArcsAndSegments) {
  const auto c = disk({0, 0}, 2).components().at(0);
  EXPECT_NEAR(distance_to_boundary(c, {0.5, 0}), 1.5, 1e-15);
  EXPECT_NEAR(distance_to_boundary(c, {0, 5}), 3.0, 1e-15);
  Curve seg;
  seg.source = {0, 0};
  seg.target = {4, 0};
  EXPECT_NEAR(distance(seg, {2, 3}), 3.0, 1e-15);
  EXPECT_NEAR(distance(seg, {7, 4}), 5.0, 1e-15);
}
