// The largest inscribed axis-aligned rectangle against closed forms (disk,
// half annulus), against an independent raster search on random regions and
// the MOMA M1 workspace, and the task-polygon fit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "pkmws/geometry/inscribed.hpp"
#include "pkmws/geometry/inscribed_rectangle.hpp"
#include "pkmws/geometry/primitives.hpp"
#include "pkmws/io/mechanism_file.hpp"
#include "support/fixtures.hpp"
#include "support/raster_rectangle.hpp"

using namespace pkmws::geometry;

namespace {

constexpr double kPrecision = 1e-9;

void expect_certified(const InscribedRectangle& r, double exact, double rel) {
  EXPECT_TRUE(r.verified);
  EXPECT_LE(r.area, r.area_upper);
  EXPECT_LE(r.area_upper - r.area, kPrecision * r.area_upper);
  EXPECT_LE(r.area, exact * (1 + 1e-12));
  EXPECT_GE(r.area_upper, exact * (1 - 1e-12));
  EXPECT_NEAR(r.area, exact, rel * exact);
  EXPECT_NEAR(r.box.width() * r.box.height(), r.area, 1e-12 * exact);
}

}  // namespace

TEST(InscribedRectangle, DiskGivesTheSquareOfSideRRoot2) {
  const double r = 3.0;
  const Region d = disk({2.5, -1.25}, r);
  const Component c = d.components().at(0);
  const auto rect = largest_inscribed_rectangle(c, kPrecision, {}, &d);
  expect_certified(rect, 2 * r * r, 1e-9);
  EXPECT_NEAR(rect.box.width(), r * std::sqrt(2.0), 1e-4);
  EXPECT_NEAR(rect.box.height(), r * std::sqrt(2.0), 1e-4);
}

TEST(InscribedRectangle, DiskWithAspectAndWidth) {
  const double r = 2.0;
  const Region d = disk({0, 0}, r);
  const Component c = d.components().at(0);
  // height = 2 width: w^2 + (2w)^2 = (2r)^2.
  const double w = 2 * r / std::sqrt(5.0);
  expect_certified(largest_inscribed_rectangle(c, kPrecision, {RectangleShape::Kind::aspect, 2.0}, &d), 2 * w * w,
                   1e-9);
  // Given width 1: height 2 sqrt(r^2 - 1/4).
  expect_certified(largest_inscribed_rectangle(c, kPrecision, {RectangleShape::Kind::width, 1.0}, &d),
                   2 * std::sqrt(r * r - 0.25), 1e-9);
  // Wider than the disk: nothing fits.
  const auto none = largest_inscribed_rectangle(c, kPrecision, {RectangleShape::Kind::width, 4.5}, &d);
  EXPECT_EQ(none.area, 0.0);
  EXPECT_EQ(none.area_upper, 0.0);
}

TEST(InscribedRectangle, HalfAnnulusAgainstItsClosedFormHeight) {
  // Upper half annulus r1 <= |p| <= r2, y >= 0. For an x-range [x0, x1] the
  // free height is sqrt(r2^2 - max x^2) minus the inner circle's top over the
  // range (r1 if the range holds 0, else sqrt(r1^2 - min x^2) or 0).
  const double r1 = 1.0, r2 = 2.5;
  const Region ring = annulus_sector({0, 0}, r1, r2, 0.0, std::numbers::pi);
  const Component c = ring.components().at(0);
  const auto height = [&](double x0, double x1) {
    const double m = std::max(x0 * x0, x1 * x1);
    if (m >= r2 * r2) return 0.0;
    const double top = std::sqrt(r2 * r2 - m);
    const double near = (x0 <= 0 && x1 >= 0) ? 0.0 : std::min(std::abs(x0), std::abs(x1));
    const double bottom = near < r1 ? std::sqrt(r1 * r1 - near * near) : 0.0;
    return std::max(0.0, top - bottom);
  };
  double reference = 0.0;
  const int n = 3000;
  for (int i = 0; i <= n; ++i) {
    for (int j = i + 1; j <= n; ++j) {
      const double x0 = -r2 + 2 * r2 * i / n, x1 = -r2 + 2 * r2 * j / n;
      reference = std::max(reference, (x1 - x0) * height(x0, x1));
    }
  }
  const auto rect = largest_inscribed_rectangle(c, kPrecision, {}, &ring);
  EXPECT_TRUE(rect.verified);
  EXPECT_GE(rect.area_upper, reference * (1 - 1e-12));
  EXPECT_NEAR(rect.area, reference, 2e-5 * reference);  // the grid is 1/3000 of the width
  EXPECT_LE(rect.area_upper - rect.area, 1e-9 * rect.area_upper);
}

TEST(InscribedRectangle, RandomRegionsAgainstARaster) {
  std::mt19937 rng(20261201);
  std::uniform_real_distribution<double> u(-1.0, 1.0), rad(0.3, 1.0);
  for (int trial = 0; trial < 12; ++trial) {
    Region r = disk({u(rng), u(rng)}, rad(rng)).unite(rectangle({{u(rng) - 1, u(rng) - 1}, {u(rng) + 1, u(rng) + 1}}));
    r = r.subtract(disk({u(rng), u(rng)}, 0.5 * rad(rng)));
    for (const Component& c : r.components(1e-9)) {
      if (c.area < 0.05) continue;
      const auto rect = largest_inscribed_rectangle(c, kPrecision, {}, &r);
      const double raster = pkmws::test::raster_rectangle(c, 300);
      SCOPED_TRACE("trial " + std::to_string(trial));
      EXPECT_TRUE(rect.verified);
      EXPECT_LE(rect.area_upper - rect.area, 1e-9 * rect.area_upper);
      // The raster's rectangle lies inside up to one cell; ours is the best.
      const Box b = c.outer.bbox();
      const double cell = (b.width() + b.height()) / 300.0 * std::max(b.width(), b.height());
      EXPECT_GE(rect.area_upper + 2 * cell, raster);
      EXPECT_LE(rect.area, raster + 4 * cell);
    }
  }
}

TEST(InscribedRectangle, MomaM1Workspace) {
  const auto f = pkmws::io::load_mechanism(pkmws::test::dataset("moma_m1_g0_l250"));
  const Region w = f.model->workspace();
  const Component c = w.components().at(0);
  const auto rect = largest_inscribed_rectangle(c, kPrecision, {}, &w);
  EXPECT_TRUE(rect.verified);
  EXPECT_LE(rect.area_upper - rect.area, 1e-9 * rect.area_upper);
  const double raster = pkmws::test::raster_rectangle(c, 600);
  const Box b = c.outer.bbox();
  const double cell = (b.width() + b.height()) / 600.0 * std::max(b.width(), b.height());
  EXPECT_NEAR(rect.area, raster, 4 * cell);
  // M1 is symmetric about x = 0 (guides at x = -100 and 100): so is its rectangle.
  EXPECT_NEAR(rect.box.min.x + rect.box.max.x, 0.0, 1e-3);
  // A fixed width no wider than the optimum's gives a smaller or equal area.
  const auto narrow =
      largest_inscribed_rectangle(c, kPrecision, {RectangleShape::Kind::width, 0.5 * rect.box.width()}, &w);
  EXPECT_LE(narrow.area, rect.area_upper);
  EXPECT_NEAR(narrow.box.width(), 0.5 * rect.box.width(), 1e-9 * rect.box.width());
}

TEST(InscribedRectangle, FreeIntervalIsAnUpperAndLowerBound) {
  const Region d = disk({0, 0}, 1.0);
  const Component c = d.components().at(0);
  const double x = 0.6;  // [0, 0.6]: height 2 sqrt(1 - 0.36) = 1.6
  EXPECT_NEAR(free_interval(c, 0.0, x, 0.0).length(), 1.6, 1e-14);
  EXPECT_GE(free_interval(c, 0.0, x, 1e-12).length(), 1.6);
  EXPECT_LE(free_interval(c, 0.0, x, -1e-12).length(), 1.6);
  EXPECT_EQ(free_interval(c, 1.5, 2.0, 0.0).length(), 0.0);  // outside
}

TEST(TaskFit, InsideOutsideAndMargins) {
  const Region d = disk({0, 0}, 2.0);
  // A unit square at the centre: clearance 2 - sqrt(0.5) to the circle.
  const auto in = fit(d, {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}}, 1e-9);
  EXPECT_TRUE(in.inside);
  EXPECT_EQ(in.area_outside, 0.0);
  EXPECT_NEAR(in.margin, 2.0 - std::sqrt(0.5), 1e-12);
  // Sticking out to x = 3: farthest point (3, +-0.5) at sqrt(9.25) - 2.
  const auto out = fit(d, {{0, -0.5}, {3, -0.5}, {3, 0.5}, {0, 0.5}}, 1e-9);
  EXPECT_FALSE(out.inside);
  EXPECT_GT(out.area_outside, 0.0);
  EXPECT_NEAR(out.margin, -(std::sqrt(9.25) - 2.0), 1e-8 + out.margin_error);
  // Covering a hole: the hole's centre is the farthest point from the region.
  const Region ring = annulus({0, 0}, 1.0, 3.0);
  const auto hole = fit(ring, {{-1.5, -1.5}, {1.5, -1.5}, {1.5, 1.5}, {-1.5, 1.5}}, 1e-9);
  EXPECT_FALSE(hole.inside);
  EXPECT_NEAR(hole.area_outside, std::numbers::pi, 1e-9);
  EXPECT_NEAR(hole.margin, -1.0, 1e-8 + hole.margin_error);
}

TEST(InscribedRectangle, RectangleIsItsOwnLargestRectangle) {
  // Horizontal edges block a strip at single points: they must still count.
  const Region r = rectangle({{-2, -1}, {3, 2}});
  const auto rect = largest_inscribed_rectangle(r.components().at(0), kPrecision, {}, &r);
  expect_certified(rect, 15.0, 1e-9);
}
