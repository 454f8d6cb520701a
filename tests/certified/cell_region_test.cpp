#include "pkmws/certified/cell_region.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

#include "pkmws/geometry/primitives.hpp"

namespace {

using pkmws::certified::CellOptions;
using pkmws::certified::CellState;
using pkmws::geometry::Box;
using pkmws::geometry::Point;

// Conservative test of the closed disk |p - c| <= r: the nearest and farthest
// points of a box from c decide it.
pkmws::certified::CellTest disk_test(Point c, double r) {
  return [c, r](const Box& b) {
    const double nx = std::clamp(c.x, b.min.x, b.max.x) - c.x;
    const double ny = std::clamp(c.y, b.min.y, b.max.y) - c.y;
    const double fx = std::max(std::abs(b.min.x - c.x), std::abs(b.max.x - c.x));
    const double fy = std::max(std::abs(b.min.y - c.y), std::abs(b.max.y - c.y));
    const double margin = 1e-12 * r;
    if (std::hypot(fx, fy) < r - margin) return CellState::inside;
    if (std::hypot(nx, ny) > r + margin) return CellState::outside;
    return CellState::undecided;
  };
}

Box box(double x0, double y0, double x1, double y1) {
  Box b;
  b.min = {x0, y0};
  b.max = {x1, y1};
  return b;
}

TEST(CertifiedCover, DiskBoundsContainTheAreaAndShrinkWithDepth) {
  const double r = 1.3;
  const double exact = std::numbers::pi * r * r;
  double previous_width = 1e300;
  for (int depth = 2; depth <= 8; depth += 2) {
    CellOptions o;
    o.window = box(-2.0, -1.5, 2.5, 2.0);  // not square, disk off-centre
    o.base = 8;
    o.max_depth = depth;
    const auto c = pkmws::certified::cover(disk_test({0.2, 0.1}, r), o);
    const double lower = c.area_inside, upper = c.area_inside + c.area_undecided;
    EXPECT_LE(lower, exact);
    EXPECT_GE(upper, exact);
    EXPECT_LT(upper - lower, previous_width);
    // A boundary of length 2 pi r covered by cells of side h: width ~ 2 pi r h * const.
    const double h = 4.5 / (8.0 * std::ldexp(1.0, depth));
    EXPECT_LT(upper - lower, 4.0 * 2.0 * std::numbers::pi * r * h);
    previous_width = upper - lower;
  }
}

// A window 10 times wider than high: with rows of their own the cells are
// square. The bounds still hold the disk's area, every cell has the height
// the rows give, and the cover tests fewer cells than with as many rows as
// columns (cells 10 times flatter).
TEST(CertifiedCover, RowsOfTheirOwnGiveSquareCellsAndValidBounds) {
  const double r = 0.4;
  CellOptions o;
  o.window = box(-5.0, -0.5, 5.0, 0.5);
  o.base = 20;
  o.max_depth = 4;
  o.base_rows = 2;
  const auto c = pkmws::certified::cover(disk_test({0.3, 0.05}, r), o);
  const double exact = std::numbers::pi * r * r;  // the disk lies inside the window
  EXPECT_LE(c.area_inside, exact);
  EXPECT_GE(c.area_inside + c.area_undecided, exact);
  const double h = 1.0 / (2.0 * 16.0), w = 10.0 / (20.0 * 16.0);
  ASSERT_FALSE(c.undecided.empty());
  for (const Box& b : c.undecided) {
    EXPECT_NEAR(b.height(), h, 1e-12);
    EXPECT_NEAR(std::fmod(b.width() + 0.5 * w, w), 0.5 * w, 1e-9);  // runs of whole cells
  }
  CellOptions flat = o;
  flat.base_rows = 0;  // 20 rows: cells 20 times wider than high
  const auto f = pkmws::certified::cover(disk_test({0.3, 0.05}, r), flat);
  EXPECT_LE(f.area_inside, exact);
  EXPECT_GE(f.area_inside + f.area_undecided, exact);
  EXPECT_LT(c.tests, f.tests);
  o.base_rows = -1;
  EXPECT_THROW(pkmws::certified::cover(disk_test({0, 0}, 1), o), std::invalid_argument);
}

TEST(CertifiedCover, ThreadCountDoesNotChangeTheResult) {
  CellOptions o;
  o.window = box(-2, -2, 2, 2);
  o.base = 4;
  o.max_depth = 7;
  o.threads = 1;
  const auto a = pkmws::certified::cover(disk_test({0.3, -0.2}, 1.1), o);
  o.threads = 2;
  const auto b = pkmws::certified::cover(disk_test({0.3, -0.2}, 1.1), o);
  EXPECT_EQ(a.area_inside, b.area_inside);
  EXPECT_EQ(a.area_undecided, b.area_undecided);
  EXPECT_EQ(a.tests, b.tests);
  EXPECT_EQ(a.inside.size(), b.inside.size());
}

TEST(CertifiedCover, RejectsBadOptions) {
  CellOptions o;
  EXPECT_THROW(pkmws::certified::cover(disk_test({0, 0}, 1), o), std::invalid_argument);  // empty window
  o.window = box(0, 0, 1, 1);
  o.base = 0;
  EXPECT_THROW(pkmws::certified::cover(disk_test({0, 0}, 1), o), std::invalid_argument);
  o.base = 2;
  o.max_depth = 30;
  EXPECT_THROW(pkmws::certified::cover(disk_test({0, 0}, 1), o), std::invalid_argument);
}

TEST(CertifiedRegion, CertifyWithinAnExactRegionEnclosesTheTrueSet) {
  namespace g = pkmws::geometry;
  // The true set: disk(c, r) ∩ square; its exact area comes from the exact engine.
  const Point c{0.4, 0.1};
  const double r = 1.0;
  const g::Region square = g::rectangle(box(-0.5, -0.5, 1.5, 0.8));
  const double truth = square.intersect(g::disk(c, r)).area();
  CellOptions o;
  o.base = 8;
  o.max_depth = 6;
  const auto cr = pkmws::certified::certify(disk_test(c, r), square, o);
  EXPECT_FALSE(cr.exact);
  EXPECT_EQ(cr.method(), "certified");
  EXPECT_LE(cr.area_lower, truth);
  EXPECT_GE(cr.area_upper, truth);
  EXPECT_NEAR(cr.area_lower, cr.inner.area(), 1e-12);
  // inner ⊆ outer ⊆ square.
  EXPECT_LT(cr.inner.subtract(cr.outer).area(), 1e-12);
  EXPECT_LT(cr.outer.subtract(square).area(), 1e-12);
  EXPECT_LE(std::abs(cr.area_estimate() - truth), 0.5 * cr.width() + 1e-12);
}

TEST(CertifiedRegion, DecidedEverywhereIsExact) {
  namespace g = pkmws::geometry;
  const g::Region ring = g::annulus({0, 0}, 0.5, 1.0);
  CellOptions o;
  o.base = 4;
  o.max_depth = 3;
  const auto cr = pkmws::certified::certify([](const Box&) { return CellState::inside; }, ring, o);
  EXPECT_TRUE(cr.exact);
  EXPECT_EQ(cr.method(), "exact");
  EXPECT_NEAR(cr.area_lower, 0.75 * std::numbers::pi, 1e-13);
  EXPECT_EQ(cr.area_lower, cr.area_upper);
}

TEST(CertifiedRegion, SetAlgebraKeepsTheEnclosure) {
  namespace g = pkmws::geometry;
  const g::Region square = g::rectangle(box(-2, -2, 2, 2));
  CellOptions o;
  o.window = box(-2, -2, 2, 2);
  o.base = 8;
  o.max_depth = 5;
  const auto d1 = pkmws::certified::certify(disk_test({-0.5, 0}, 1.0), square, o);
  const auto d2 = pkmws::certified::certify(disk_test({0.5, 0}, 1.0), square, o);
  const double lens = g::disk({-0.5, 0}, 1.0).intersect(g::disk({0.5, 0}, 1.0)).area();
  const double both = 2.0 * std::numbers::pi - lens;
  const auto i = pkmws::certified::intersect(d1, d2);
  const auto u = pkmws::certified::unite(d1, d2);
  const auto s = pkmws::certified::subtract(pkmws::certified::from_exact(square), u);
  EXPECT_LE(i.area_lower, lens);
  EXPECT_GE(i.area_upper, lens);
  EXPECT_LE(u.area_lower, both);
  EXPECT_GE(u.area_upper, both);
  EXPECT_LE(s.area_lower, 16.0 - both);
  EXPECT_GE(s.area_upper, 16.0 - both);
  // Inclusion-exclusion holds for the bounds' midpoints to within the widths.
  EXPECT_NEAR(u.area_estimate() + i.area_estimate(), d1.area_estimate() + d2.area_estimate(),
              0.5 * (u.width() + i.width() + d1.width() + d2.width()));
}

TEST(CertifiedRegion, BoxesRegionMergesRuns) {
  std::vector<Box> boxes{box(0, 0, 1, 1), box(1, 0, 2, 1), box(2, 0, 3, 1), box(0, 1, 1, 2)};
  const auto r = pkmws::certified::boxes_region(boxes);
  EXPECT_NEAR(r.area(), 4.0, 1e-14);
  EXPECT_EQ(r.components().size(), 1u);
  EXPECT_TRUE(pkmws::certified::boxes_region({}).empty());
}

TEST(CertifiedRegion, BoxesRegionHandlesPinchesHolesAndIslands) {
  // Two squares touching at a corner (CGAL may keep them as one polygon
  // pinched at the vertex; the point set is what matters).
  const auto pinch = pkmws::certified::boxes_region({box(0, 0, 1, 1), box(1, 1, 2, 2)});
  EXPECT_NEAR(pinch.area(), 2.0, 1e-14);
  EXPECT_TRUE(pinch.contains({0.5, 0.5}));
  EXPECT_TRUE(pinch.contains({1.5, 1.5}));
  EXPECT_FALSE(pinch.contains({0.5, 1.5}));
  // A ring of 8 unit cells around a hole (3x3 minus the centre).
  std::vector<Box> ring;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i)
      if (i != 1 || j != 1) ring.push_back(box(i, j, i + 1, j + 1));
  const auto r = pkmws::certified::boxes_region(ring);
  EXPECT_NEAR(r.area(), 8.0, 1e-14);
  EXPECT_FALSE(r.contains({1.5, 1.5}));
  EXPECT_TRUE(r.contains({0.5, 1.5}));
  // 5x5 frame with a 1x1 island in its 3x3 hole: area 16 + 1.
  std::vector<Box> framed;
  for (int j = 0; j < 5; ++j)
    for (int i = 0; i < 5; ++i)
      if (i == 0 || j == 0 || i == 4 || j == 4 || (i == 2 && j == 2)) framed.push_back(box(i, j, i + 1, j + 1));
  const auto f = pkmws::certified::boxes_region(framed);
  EXPECT_NEAR(f.area(), 17.0, 1e-14);
  EXPECT_TRUE(f.contains({2.5, 2.5}));
  EXPECT_FALSE(f.contains({1.5, 2.5}));
  // C-shape whose ends, cells (0,1) and (1,2), touch at the corner (1,2): the
  // boundary traced turning left revisits that vertex and is split there.
  std::vector<Box> c{box(0, 0, 1, 1), box(1, 0, 2, 1), box(2, 0, 3, 1), box(2, 1, 3, 2), box(2, 2, 3, 3),
                     box(1, 2, 2, 3), box(0, 1, 1, 2)};
  const auto cs = pkmws::certified::boxes_region(c);
  EXPECT_NEAR(cs.area(), 7.0, 1e-14);
  EXPECT_FALSE(cs.contains({1.5, 1.5}));
}

// Shoelace area of a simple polygon (either orientation).
double shoelace(const std::vector<Point>& p) {
  double s = 0.0;
  for (std::size_t k = 0; k < p.size(); ++k) {
    const Point& a = p[k];
    const Point& b = p[(k + 1) % p.size()];
    s += a.x * b.y - a.y * b.x;
  }
  return 0.5 * std::abs(s);
}

std::vector<Point> corners(const Box& b) { return {b.min, {b.max.x, b.min.y}, b.max, {b.min.x, b.max.y}}; }

TEST(CertifiedRegion, PolygonsRegionUnitesPiecesOfCells) {
  using pkmws::certified::polygons_region;
  using pkmws::geometry::Region;
  // Pinches, holes and islands as in boxes_region, the pieces as polygons.
  EXPECT_TRUE(polygons_region({}).empty());
  const auto pinch = polygons_region({corners(box(0, 0, 1, 1)), corners(box(1, 1, 2, 2))});
  EXPECT_NEAR(pinch.area(), 2.0, 1e-14);
  EXPECT_FALSE(pinch.contains({0.5, 1.5}));
  std::vector<std::vector<Point>> framed;
  for (int j = 0; j < 5; ++j)
    for (int i = 0; i < 5; ++i)
      if (i == 0 || j == 0 || i == 4 || j == 4 || (i == 2 && j == 2)) framed.push_back(corners(box(i, j, i + 1, j + 1)));
  const auto fr = polygons_region(framed);
  EXPECT_NEAR(fr.area(), 17.0, 1e-14);
  EXPECT_TRUE(fr.contains({2.5, 2.5}));
  EXPECT_FALSE(fr.contains({1.5, 2.5}));
  // A triangle in a cell whose apex touches the cell above at one point of
  // its edge, and a T-junction: a big cell beside two small ones.
  const std::vector<std::vector<Point>> touch{{{0, 0}, {2, 0}, {1, 1}}, corners(box(0, 1, 2, 2)), corners(box(2, 0, 4, 2)),
                                              corners(box(4, 0, 5, 1)), corners(box(4, 1, 5, 2))};
  const auto t = polygons_region(touch);
  EXPECT_NEAR(t.area(), 1.0 + 2.0 + 4.0 + 2.0, 1e-14);
  EXPECT_FALSE(t.contains({0.2, 0.8}));
  EXPECT_TRUE(t.contains({1.0, 0.5}));
}

// Random quadtrees (leaves split while wider than `min_width`, in a window
// 3.4 wide): each leaf empty, whole, or the part of it under (or over) a
// random piecewise-linear function with jumps, clamped to the cell (as a
// traced cell gives). Against CGAL's union of the same polygons and the sum
// of their areas (the pieces' interiors are disjoint).
void check_random_quadtrees(int trials, double min_width) {
  using pkmws::certified::polygons_region;
  using pkmws::geometry::Region;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < trials; ++trial) {
    std::vector<Box> leaves;
    std::vector<Box> todo{box(-1.3, 0.2, 2.1, 3.6)};
    while (!todo.empty()) {
      const Box b = todo.back();
      todo.pop_back();
      if (b.width() > min_width && unit(rng) < 0.7) {
        const double xm = 0.5 * (b.min.x + b.max.x), ym = 0.5 * (b.min.y + b.max.y);
        todo.push_back(box(b.min.x, b.min.y, xm, ym));
        todo.push_back(box(xm, b.min.y, b.max.x, ym));
        todo.push_back(box(b.min.x, ym, xm, b.max.y));
        todo.push_back(box(xm, ym, b.max.x, b.max.y));
      } else {
        leaves.push_back(b);
      }
    }
    std::vector<std::vector<Point>> pieces;
    double sum = 0.0;
    for (const Box& b : leaves) {
      const double kind = unit(rng);
      if (kind < 0.3) continue;
      if (kind < 0.55) {
        pieces.push_back(corners(b));
      } else {
        // Under a function of x (or, swapped, left of a function of y),
        // clamped to the cell; its values at the ends touch the cell's
        // edges now and then.
        const bool swapped = unit(rng) < 0.5, below = unit(rng) < 0.5;
        const double u0 = swapped ? b.min.y : b.min.x, u1 = swapped ? b.max.y : b.max.x;
        const double v0 = swapped ? b.min.x : b.min.y, v1 = swapped ? b.max.x : b.max.y;
        std::vector<std::pair<double, double>> fn;  // (u, v)
        const int n = 1 + static_cast<int>(unit(rng) * 5);
        for (int k = 0; k <= n; ++k) {
          const double u = k == n ? u1 : u0 + (u1 - u0) * k / n;
          const double r = unit(rng);
          const double v = r < 0.15 ? v1 : r < 0.3 ? v0 : v0 + (v1 - v0) * unit(rng);
          fn.push_back({u, v});
          if (k > 0 && k < n && unit(rng) < 0.3) fn.push_back({u, v0 + (v1 - v0) * unit(rng)});  // a jump
        }
        const double base = below ? v0 : v1;
        std::vector<Point> run;
        const auto xy = [&](double u, double v) { return swapped ? Point{v, u} : Point{u, v}; };
        const auto emit = [&](double u) {
          if (run.empty()) return;
          run.push_back(xy(u, base));
          std::vector<Point> clean;
          for (const Point& q : run) if (clean.empty() || !(clean.back() == q)) clean.push_back(q);
          if (clean.size() >= 3 && shoelace(clean) > 0.0) {
            pieces.push_back(clean);
            sum += shoelace(clean);
          }
          run.clear();
        };
        double last = u0;
        for (const auto& [u, v] : fn) {
          if (v == base) {
            if (!run.empty()) run.push_back(xy(u, v));
            emit(u);
            last = u;
            continue;
          }
          if (run.empty()) run.push_back(xy(last, base));
          run.push_back(xy(u, v));
        }
        emit(fn.back().first);
        continue;
      }
      sum += b.width() * b.height();
    }
    const Region mine = polygons_region(pieces);
    std::vector<Region> parts;
    for (const auto& p : pieces) parts.push_back(pkmws::geometry::polygon(p));
    const Region cgal = Region::unite_all(parts);
    EXPECT_NEAR(mine.area(), sum, 1e-12 * (1.0 + sum)) << trial;
    EXPECT_NEAR(mine.symmetric_difference(cgal).area(), 0.0, 1e-12) << trial;
  }
}

// Small trees (a few dozen pieces: also under the sanitizers).
TEST(CertifiedRegion, PolygonsRegionAgainstCgalOnSmallRandomQuadtrees) { check_random_quadtrees(3, 0.8); }

// Trees of hundreds of pieces (heavy: CGAL's reference union takes minutes
// under AddressSanitizer).
TEST(CertifiedRegion, PolygonsRegionAgainstCgalOnRandomQuadtrees) { check_random_quadtrees(12, 0.1); }

}  // namespace
