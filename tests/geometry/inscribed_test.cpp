#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "geometry/boundary_pieces.hpp"
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

// The searches' binned membership test (a horizontal ray meets only the
// pieces of its height's bin) against the even-odd count over every piece
// and the exact Region::contains: regions of arcs, segments and holes with
// many curves (many bins), at random points and at the heights where a
// piece starts or ends (arc tops and bottoms, vertices: the bins' edges).
TEST(Inscribed, BinnedMembershipMatchesTheFullCount) {
  namespace gd = pkmws::geometry::detail;
  std::mt19937 rng(20261205);
  std::uniform_real_distribution<double> u(-10.0, 10.0), radius(0.3, 2.5);
  std::vector<Region> parts;
  for (int k = 0; k < 30; ++k) parts.push_back(disk({u(rng), u(rng)}, radius(rng)));
  for (int k = 0; k < 10; ++k) {
    const double x = u(rng), y = u(rng);
    parts.push_back(rectangle({{x, y}, {x + radius(rng), y + radius(rng)}}));
  }
  const Region holes = Region::unite_all({disk({0, 0}, 1.5), annulus({4, 4}, 0.5, 0.9)});
  const Region region = Region::unite_all(parts).subtract(holes);
  const std::vector<Component> components = region.components();
  std::vector<gd::BoundaryIndex> indexes;
  std::vector<std::vector<gd::BoundaryPiece>> all;
  std::vector<Point> queries;
  std::size_t curves = 0;
  for (const Component& c : components) {
    indexes.emplace_back(c);
    all.push_back(gd::boundary_pieces(c));
    curves += all.back().size();
    for (const Loop* loop : {&c.outer}) {
      for (const Curve& k : loop->curves) {
        for (double y : {k.source.y, k.center.y + k.radius, k.center.y - k.radius}) queries.push_back({u(rng), y});
      }
    }
    for (const Loop& h : c.holes) {
      for (const Curve& k : h.curves) queries.push_back({u(rng), k.source.y});
    }
  }
  for (int k = 0; k < 4000; ++k) queries.push_back({u(rng), u(rng)});
  std::size_t in = 0, compared = 0;
  for (const Point& p : queries) {
    int count = 0;
    double clearance = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < components.size(); ++i) {
      const bool binned = indexes[i].inside(p);
      ASSERT_EQ(binned, gd::inside(all[i], p)) << p.x << " " << p.y;
      count += binned;
      clearance = std::min(clearance, distance_to_boundary(components[i], p));
    }
    if (clearance > 1e-9) {  // off the boundary: the exact test agrees (in exactly one component)
      ASSERT_EQ(count == 1, region.contains(p)) << p.x << " " << p.y;
      ASSERT_LE(count, 1);
      ++compared;
    }
    in += count;
  }
  EXPECT_GT(curves, 60u);  // many pieces, many bins
  EXPECT_GT(in, 500u);
  EXPECT_GT(compared - in, 500u);
}
