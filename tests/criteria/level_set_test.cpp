// Certified sub-level sets: closed forms (disk, Cassini ovals with two
// components, the lemniscate's saddle), dense sampling, point membership of
// inner/outer, width against tolerance, DexTAR mirror symmetries, [Briot]
// figure 10's splitting, PAMINSA reaction-limited regions.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "pkmws/certified/template_field.hpp"
#include "pkmws/criteria/fields.hpp"
#include "pkmws/geometry/primitives.hpp"
#include "mechanisms/five_bar/criteria.hpp"
#include "mechanisms/three_rpr/criteria.hpp"
#include "support/mechanisms/five_bar.hpp"

namespace {

using namespace pkmws;
using certified::CellState;
using certified::Interval;
using geometry::Box;
using geometry::Point;

constexpr double pi = std::numbers::pi;

Box box(double x0, double y0, double x1, double y1) {
  Box b;
  b.min = {x0, y0};
  b.max = {x1, y1};
  return b;
}

// Cassini ovals: F = |p - f1|² |p - f2|², foci (±a, 0); F <= b⁴ is one oval for
// b > a, two for b < a; b = a is the lemniscate (saddle of F at the origin).
struct Cassini {
  double a = 1.0;
  template <class T> T eval(const T& x, const T& y) const {
    using certified::sqr;
    return (sqr(x - a) + sqr(y)) * (sqr(x + a) + sqr(y));
  }
  CellState domain(const Box&) const { return CellState::inside; }
};

// Area of { |p - f1| |p - f2| <= b² } in polar form r² = a² cos 2θ ± sqrt(b⁴ - a⁴ sin² 2θ):
// b > a: ½ ∫ sqrt(b⁴ - a⁴ sin² 2θ) dθ over [0, 2π] ... plus the a² cos 2θ term
// that integrates to 0; b < a: ∫ sqrt(b⁴ - a⁴ sin² 2θ) dθ where it is real.
double cassini_area(double a, double b) {
  const double b4 = b * b * b * b, a4 = a * a * a * a;
  if (b > a) {
    const int n = 200000;  // periodic smooth integrand: midpoint rule converges fast
    double s = 0.0;
    for (int k = 0; k < n; ++k) {
      const double t = 2.0 * pi * (k + 0.5) / n;
      s += std::sqrt(b4 - a4 * std::sin(2 * t) * std::sin(2 * t));
    }
    return 0.5 * s * 2.0 * pi / n;
  }
  // sin 2θ = (b²/a²) sin t, t ∈ [-π/2, π/2] over each of the 4 θ-intervals: the
  // integrand becomes smooth: sqrt(b⁴ - a⁴ sin²2θ) dθ = b⁴ cos² t / (2 a² sqrt(1 - k² sin² t)) dt, k = b²/a².
  const double k = b * b / (a * a);
  const int n = 200000;
  double s = 0.0;
  for (int i = 0; i < n; ++i) {
    const double t = -pi / 2 + pi * (i + 0.5) / n;
    s += b4 * std::cos(t) * std::cos(t) / (2.0 * a * a * std::sqrt(1.0 - k * k * std::sin(t) * std::sin(t)));
  }
  return 2.0 * s * pi / n;  // two lobes (θ near 0 and near π), each ∫ over t
}

certified::WithinTest always_inside(const Box& w) {
  return [w](const Box& b) {
    if (b.min.x >= w.min.x && b.max.x <= w.max.x && b.min.y >= w.min.y && b.max.y <= w.max.y) return CellState::inside;
    return CellState::undecided;
  };
}

TEST(LevelSets, CassiniOvalsOneAndTwoComponentsAndTheLemniscate) {
  const certified::TemplateField<Cassini> f(Cassini{1.0});
  const Box w = box(-2.0, -1.5, 2.0, 1.5);
  const geometry::Region window = geometry::rectangle(w);
  for (double b : {0.7, 0.95, 1.0, 1.05, 1.3}) {
    certified::LevelSetOptions o;
    o.relative_tolerance = 1e-7;
    o.build_regions = false;
    const double level = b * b * b * b;
    const auto r = certified::sublevel_set(f, level, window, always_inside(w), o);
    for (const auto& piece : r.curves) {
      for (const Point& p : piece) EXPECT_NEAR(f.value(p), level, 1e-13 * level);
    }
    if (b != 0.7 && b != 1.3) continue;
    o.relative_tolerance = 1e-3;
    o.build_regions = true;
    const auto coarse = certified::sublevel_set(f, level, window, always_inside(w), o);
    const double exact = cassini_area(1.0, b);
    EXPECT_LE(r.region.area_lower, exact) << b;
    EXPECT_GE(r.region.area_upper, exact) << b;
    // The saddle (b = 1) leaves undecided cells around the origin only.
    EXPECT_LT(r.region.width(), (b == 1.0 ? 1e-5 : 1e-6) * exact) << b;
    EXPECT_GT(r.traced_cells, 0u);
    // Regions: the inner region's area is the lower bound up to region rounding,
    // and components: two ovals for b < 1.
    // area(inner) <= area_lower <= exact <= area_upper <= area(outer), and the
    // regions follow the traced envelopes: within the target width of the
    // bounds (cell boxes alone, a staircase, would miss by ~1e-2).
    EXPECT_LE(coarse.region.inner.area(), coarse.region.area_lower * (1 + 1e-12)) << b;
    EXPECT_GE(coarse.region.outer.area(), coarse.region.area_upper * (1 - 1e-12)) << b;
    EXPECT_GT(coarse.region.inner.area(), coarse.region.area_lower - 1e-3 * exact) << b;
    EXPECT_LT(coarse.region.outer.area(), coarse.region.area_upper + 1e-3 * exact) << b;
    // Right at the curve (the fine run's points on F = level, moved 1e-9
    // along the normal): the side F > level is never in inner, the side
    // F < level always in outer.
    int probed = 0;
    for (const auto& piece : r.curves) {
      for (std::size_t k = 0; k < piece.size(); k += 7) {
        const Point p = piece[k];
        const auto g = f.grad(p);
        const double n = std::hypot(g.dx, g.dy), e = 1e-9;
        const Point out{p.x + e * g.dx / n, p.y + e * g.dy / n}, in{p.x - e * g.dx / n, p.y - e * g.dy / n};
        ASSERT_GT(f.value(out), level);
        ASSERT_LT(f.value(in), level);
        EXPECT_FALSE(coarse.region.inner.contains(out)) << b << " at " << p.x << ", " << p.y;
        EXPECT_TRUE(coarse.region.outer.contains(in)) << b << " at " << p.x << ", " << p.y;
        ++probed;
      }
    }
    EXPECT_GT(probed, 100) << b;
    // Points: inner satisfies F <= level, outside outer does not.
    std::mt19937 rng(2);
    std::uniform_real_distribution<double> ux(w.min.x, w.max.x), uy(w.min.y, w.max.y);
    for (int k = 0; k < 2000; ++k) {
      const Point p{ux(rng), uy(rng)};
      if (coarse.region.inner.contains(p)) {
        EXPECT_LE(f.value(p), level * (1 + 1e-12));
      }
      if (!coarse.region.outer.contains(p)) {
        EXPECT_GT(f.value(p), level * (1 - 1e-12));
      }
    }
    if (b < 0.99) {
      EXPECT_EQ(coarse.region.outer.components(1e-9).size(), 2u) << b;
    }
    if (b > 1.01) {
      EXPECT_EQ(coarse.region.inner.components(1e-9).size(), 1u) << b;
    }
  }
}

TEST(LevelSets, WidthShrinksWithTheToleranceAndBoundsNest) {
  const certified::TemplateField<Cassini> f(Cassini{1.0});
  const Box w = box(-2.0, -1.5, 2.0, 1.5);
  const geometry::Region window = geometry::rectangle(w);
  double previous = std::numeric_limits<double>::infinity();
  const double exact = cassini_area(1.0, 1.2);
  for (double tol : {1e-3, 1e-5, 1e-7}) {
    certified::LevelSetOptions o;
    o.relative_tolerance = tol;
    o.build_regions = false;
    const auto r = certified::sublevel_set(f, std::pow(1.2, 4), window, always_inside(w), o);
    EXPECT_LT(r.region.width(), previous);
    EXPECT_LE(r.region.width(), tol * exact);
    EXPECT_LE(r.region.area_lower, exact);
    EXPECT_GE(r.region.area_upper, exact);
    previous = r.region.width();
  }
  // Layer (a) alone, deeper quadtree: narrower, always valid.
  double cell_prev = std::numeric_limits<double>::infinity();
  for (int depth : {4, 6, 8}) {
    const auto c = certified::certify_cells(f, std::pow(1.2, 4), window, 16, depth, 1);
    EXPECT_LE(c.area_lower, exact);
    EXPECT_GE(c.area_upper, exact);
    EXPECT_LT(c.width(), cell_prev);
    cell_prev = c.width();
  }
}

// The cover's depth chosen from the target (0) or given: every depth gives
// bounds that hold the closed form and meet the target; depths outside
// [0, 24] and refinements outside [0, 40] are refused.
TEST(LevelSets, EveryCoverDepthMeetsTheTargetAndBadDepthsAreRefused) {
  const certified::TemplateField<Cassini> f(Cassini{1.0});
  const Box w = box(-2.0, -1.5, 2.0, 1.5);
  const geometry::Region window = geometry::rectangle(w);
  const double exact = cassini_area(1.0, 1.2), level = std::pow(1.2, 4);
  for (double tol : {1e-6, 1e-9}) {
    for (int depth : {0, 3, 4, 5, 6}) {
      certified::LevelSetOptions o;
      o.relative_tolerance = tol;
      o.cover_depth = depth;
      const auto r = certified::sublevel_set(f, level, window, always_inside(w), o);
      EXPECT_LE(r.region.area_lower, exact) << tol << " " << depth;
      EXPECT_GE(r.region.area_upper, exact) << tol << " " << depth;
      EXPECT_LE(r.region.width(), tol * exact) << tol << " " << depth;
      EXPECT_GT(r.traced_cells, 0u);
    }
  }
  for (int depth : {-1, 25}) {
    certified::LevelSetOptions o;
    o.cover_depth = depth;
    EXPECT_THROW(certified::sublevel_set(f, level, window, always_inside(w), o), std::invalid_argument) << depth;
  }
  certified::LevelSetOptions o;
  o.refine_depth = 41;
  EXPECT_THROW(certified::sublevel_set(f, level, window, always_inside(w), o), std::invalid_argument);
}

// An absolute target (a chart's share of a whole's width): the width meets
// it, not the far tighter relative one, and the bounds hold the closed form.
// A relative target alone of the same size gives the same work; the
// absolute one only ever loosens: a larger relative target wins.
TEST(LevelSets, AnAbsoluteToleranceIsMetAndOnlyLoosens) {
  const certified::TemplateField<Cassini> f(Cassini{1.0});
  const Box w = box(-2.0, -1.5, 2.0, 1.5);
  const geometry::Region window = geometry::rectangle(w);
  const double exact = cassini_area(1.0, 1.2), level = std::pow(1.2, 4);
  certified::LevelSetOptions o;
  o.relative_tolerance = 1e-15;
  o.absolute_tolerance = 1e-5 * exact;
  const auto a = certified::sublevel_set(f, level, window, always_inside(w), o);
  EXPECT_LE(a.region.width(), 1e-5 * exact);
  EXPECT_GT(a.region.width(), 1e-9 * exact);  // not traced to the relative 1e-15
  EXPECT_LE(a.region.area_lower, exact);
  EXPECT_GE(a.region.area_upper, exact);
  certified::LevelSetOptions rel;
  rel.relative_tolerance = 1e-5;
  const auto b = certified::sublevel_set(f, level, window, always_inside(w), rel);
  EXPECT_LT(std::abs(static_cast<double>(a.curve_points) - static_cast<double>(b.curve_points)),
            0.1 * static_cast<double>(b.curve_points));
  rel.absolute_tolerance = 1e-9 * exact;  // below the relative one: no effect
  const auto c = certified::sublevel_set(f, level, window, always_inside(w), rel);
  EXPECT_EQ(c.region.area_lower, b.region.area_lower);
  EXPECT_EQ(c.region.area_upper, b.region.area_upper);
  rel.absolute_tolerance = -1.0;
  EXPECT_THROW(certified::sublevel_set(f, level, window, always_inside(w), rel), std::invalid_argument);
}

// A star r = f(θ) = 1 + e cos 3θ in a polar chart: the field r - f(θ) with θ
// on one axis and r on the other, and the area element ρ = r (the chart's
// weight). ∫∫_{r <= f} r dr dθ = ½ ∫ f² dθ = π (1 + e²/2) in closed form.
struct PolarStar {
  double e = 0.3;
  bool r_on_x = false;  // (x, y) = (r, θ) instead of (θ, r)
  int side = 1;         // +1: r - f(θ) <= 0 (inside the star); -1: f(θ) - r <= 0
  template <class T> T eval(const T& x, const T& y) const {
    using certified::cos;
    using std::cos;
    const T& r = r_on_x ? x : y;
    const T& t = r_on_x ? y : x;
    const T v = r - (1.0 + e * cos(3.0 * t));
    return side > 0 ? v : -v;
  }
  CellState domain(const Box&) const { return CellState::inside; }
};

TEST(LevelSets, WeightedChartAreasAgainstClosedForms) {
  // The chart's θ-window [-π_d, π_d] misses 2.4e-16 of the turn: far below the tolerance.
  const double e = 0.3, r_max = 1.5;
  const double star = pi * (1.0 + 0.5 * e * e), annulus = pi * r_max * r_max - star;
  for (bool r_on_x : {false, true}) {
    for (int side : {1, -1}) {
      const certified::TemplateField<PolarStar> f(PolarStar{e, r_on_x, side});
      const Box w = r_on_x ? box(0.0, -pi, r_max, pi) : box(-pi, 0.0, pi, r_max);
      certified::LevelSetOptions o;
      o.relative_tolerance = 1e-9;
      o.threads = 1;
      o.weight = r_on_x ? certified::AreaWeight{0.0, 1.0, 0.0} : certified::AreaWeight{0.0, 0.0, 1.0};
      const auto r = certified::sublevel_set(f, 0.0, geometry::rectangle(w), always_inside(w), o);
      const double exact = side > 0 ? star : annulus;
      EXPECT_LE(r.region.area_lower, exact + 1e-13) << r_on_x << side;
      EXPECT_GE(r.region.area_upper, exact - 1e-13) << r_on_x << side;
      EXPECT_LE(r.region.width(), 1e-9 * exact) << r_on_x << side;
      EXPECT_GT(r.traced_cells, 0u);
      // The unweighted area of the same set in (θ, r): ∫ f dθ = 2π (and its complement).
      o.weight = {};
      o.relative_tolerance = 1e-7;
      const auto plain = certified::sublevel_set(f, 0.0, geometry::rectangle(w), always_inside(w), o);
      const double flat = side > 0 ? 2.0 * pi : 2.0 * pi * (r_max - 1.0);
      EXPECT_LE(plain.region.area_lower, flat + 1e-13);
      EXPECT_GE(plain.region.area_upper, flat - 1e-13);
    }
  }
}

// Random polar curves r = f(θ) that dip below r = 0 (the chart's edge, where
// its weight ρ = r changes sign beyond the window): the weighted bounds must
// hold ½ ∫ max(f, 0)² dθ; pieces next to that edge have envelopes reaching
// below it, where the clamped part's monotonicity fails.
struct PolarWave {
  std::array<double, 6> a{}, phase{};
  double a0 = 0.0;
  template <class T> T f(const T& t) const {
    using certified::cos;
    using std::cos;
    T v = T(a0);
    for (std::size_t k = 0; k < a.size(); ++k) v = v + a[k] * cos(static_cast<double>(2 * k + 3) * t + phase[k]);
    return v;
  }
  // y - f(x), plus a term that is 0 but which interval arithmetic cannot
  // cancel: the derivatives' enclosures are wide, so the envelopes reach far
  // beyond the cell (the case where they cross the window's edge).
  double blur = 0.0;
  template <class T> T eval(const T& x, const T& y) const {
    using certified::cos;
    using certified::sin;
    using certified::sqr;
    using std::cos;
    using std::sin;
    return y - f(x) + blur * (sqr(cos(3.0 * x)) + sqr(sin(3.0 * x)) - 1.0);
  }
  CellState domain(const Box&) const { return CellState::inside; }
};

TEST(LevelSets, WeightedChartAreasNextToTheWindowsEdge) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> amp(0.05, 0.3), ph(0.0, 2.0 * pi), base(-0.05, 0.1);
  for (int k = 0; k < 8; ++k) {
    PolarWave w;
    w.blur = k % 2 == 0 ? 0.0 : 0.05;
    w.a0 = base(rng);
    for (std::size_t j = 0; j < w.a.size(); ++j) {
      w.a[j] = amp(rng) / static_cast<double>(j + 1);
      w.phase[j] = ph(rng);
    }
    const int n = 200000;  // midpoint rule of a C¹ periodic integrand
    double exact = 0.0;
    for (int i = 0; i < n; ++i) {
      const double v = w.f(-pi + 2.0 * pi * (i + 0.5) / n);
      exact += v > 0.0 ? v * v : 0.0;
    }
    exact *= 0.5 * 2.0 * pi / n;
    const certified::TemplateField<PolarWave> field(w);
    const Box win = box(-pi, 0.0, pi, 0.8);
    certified::LevelSetOptions o;
    o.relative_tolerance = 1e-7;
    o.threads = 1;
    o.weight = {0.0, 0.0, 1.0};
    const auto r = certified::sublevel_set(field, 0.0, geometry::rectangle(win), always_inside(win), o);
    EXPECT_LE(r.region.area_lower, exact * (1.0 + 1e-9)) << k;
    EXPECT_GE(r.region.area_upper, exact * (1.0 - 1e-9)) << k;
    EXPECT_LE(r.region.area_lower, r.region.area_upper) << k;
  }
}

TEST(LevelSets, CosineAndSineEnclosures) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> centre(-10.0, 10.0), width(0.0, 3.0), t(0.0, 1.0);
  for (int k = 0; k < 2000; ++k) {
    const double lo = centre(rng), hi = lo + (k % 10 == 0 ? 0.0 : width(rng));
    const Interval c = certified::cos(Interval(lo, hi)), s = certified::sin(Interval(lo, hi));
    for (int j = 0; j <= 20; ++j) {
      const double x = j == 20 ? hi : lo + (hi - lo) * t(rng);
      EXPECT_TRUE(c.contains(std::cos(x))) << lo << " " << hi;
      EXPECT_TRUE(s.contains(std::sin(x))) << lo << " " << hi;
    }
    // Tight: extremes reached only where an extremum lies within the interval (± slack).
    if (hi - lo < 1e-3) {
      EXPECT_LT(c.width(), 2e-3);
      EXPECT_LT(s.width(), 2e-3);
    }
  }
  // Jets: the chain rule against the closed forms.
  const auto j = certified::sin(certified::Jet<double>::variable_x(0.7) * 2.0);
  EXPECT_NEAR(j.dx, 2.0 * std::cos(1.4), 1e-15);
  EXPECT_NEAR(j.dxx, -4.0 * std::sin(1.4), 1e-15);
}

using pkmws::test::five_bar::dextar;

// Dense sampling: the fraction of a fine grid of cell centres of W's bbox that
// satisfy the criterion; its error is at most (cells met by the boundary) x h²,
// bounded generously by 4 x perimeter / h cells.
double grid_estimate(const criteria::CriterionField& c, double threshold, const Box& w, int n, double& error) {
  const double hx = w.width() / n, hy = w.height() / n;
  long count = 0;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const Point p{w.min.x + (i + 0.5) * hx, w.min.y + (j + 0.5) * hy};
      const double v = c.value(p);
      if (std::isfinite(v) && v <= threshold) ++count;
    }
  }
  error = 0.0;
  return static_cast<double>(count) * hx * hy;
}

bool in_polygon(const std::vector<Point>& poly, Point p) {
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    if ((poly[i].y > p.y) != (poly[j].y > p.y) &&
        p.x < (poly[j].x - poly[i].x) * (p.y - poly[i].y) / (poly[j].y - poly[i].y) + poly[i].x) {
      in = !in;
    }
  }
  return in;
}

TEST(LevelSets, DexTARBoundsContainDenseSamplingAndThePiecesClassifyPoints) {
  const auto m = dextar(1, 1);
  const auto c = criteria::five_bar_pressure_angle(m);
  const geometry::Region ws = m.workspace();
  const Box w = ws.bbox();
  for (double alpha : {20.0, 60.0}) {
    certified::LevelSetOptions o;
    o.relative_tolerance = 1e-5;
    const auto r = certified::sublevel_set(*c.surrogate, c.level(alpha), ws, c.within_test, o);
    double err = 0.0;
    const int n = 500;
    const double est = grid_estimate(c, alpha, w, n, err);
    // Boundary cells of an 800² grid: the curves are a few metres long.
    const double h = w.width() / n;
    const double slack = 8.0 * h * std::max(w.width(), w.height());
    EXPECT_LE(r.region.area_lower, est + slack) << alpha;
    EXPECT_GE(r.region.area_upper, est - slack) << alpha;
    EXPECT_LT(std::abs(est - r.region.area_estimate()), 0.02 * est) << alpha;
    EXPECT_LE(r.region.width(), 1e-5 * r.region.area_upper) << alpha;
    // Points certified in S (inside cells ∩ W, traced cells' inner polygons,
    // which lie inside W) satisfy the criterion.
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> ux(w.min.x, w.max.x), uy(w.min.y, w.max.y);
    int in = 0;
    for (int k = 0; k < 2000; ++k) {
      const Point p{ux(rng), uy(rng)};
      bool certain = false;
      for (const Box& b : r.inside_boxes) certain = certain || (b.contains(p) && ws.contains(p));
      for (const auto& poly : r.inner_polygons) certain = certain || in_polygon(poly, p);
      if (certain) {
        ++in;
        EXPECT_LE(c.value(p), alpha + 1e-9) << p.x << " " << p.y;
      }
    }
    EXPECT_GT(in, 100);
    EXPECT_FALSE(r.inner_polygons.empty());
  }
}

// DexTAR is symmetric about both axes: y -> -y maps working mode (s1, s2) to
// (-s1, -s2); x -> -x swaps the legs: (s1, s2) -> (-s2, -s1). So
// area(+,+) = area(-,-), area(+,-) = area(-,+), and each is its own x-mirror.
TEST(LevelSets, FourWorkingModesObeyTheMirrorSymmetries) {
  for (double alpha : {40.0}) {
    std::map<std::pair<int, int>, certified::CertifiedRegion> r;
    for (int s1 : {-1, 1}) {
      for (int s2 : {-1, 1}) {
        const auto m = dextar(s1, s2);
        const auto c = criteria::five_bar_pressure_angle(m);
        certified::LevelSetOptions o;
        o.relative_tolerance = 1e-5;
        r[{s1, s2}] = certified::sublevel_set(*c.surrogate, c.level(alpha), m.workspace(), c.within_test, o).region;
      }
    }
    auto overlap = [](const certified::CertifiedRegion& a, const certified::CertifiedRegion& b) {
      return a.area_lower <= b.area_upper && b.area_lower <= a.area_upper;
    };
    EXPECT_TRUE(overlap(r[{1, 1}], r[{-1, -1}])) << alpha;
    EXPECT_TRUE(overlap(r[{1, -1}], r[{-1, 1}])) << alpha;
    // The (+,+) and (+,-) modes differ (the criterion depends on the mode).
    EXPECT_FALSE(overlap(r[{1, 1}], r[{1, -1}])) << alpha;
  }
}

// [Briot] fig. 10: at small α_max the usable workspace splits into several
// parts: the certified inner region has several components (they meet only at
// the base joints A and E, where ε is undefined and every level curve ends).
TEST(LevelSets, SmallPressureAngleSplitsTheDexTARWorkspace) {
  const auto m = dextar(1, -1);
  const auto c = criteria::five_bar_pressure_angle(m);
  const geometry::Region ws = m.workspace();
  const auto small = certified::certify_cells(*c.surrogate, c.level(20.0), ws, 16, 4, 1);
  EXPECT_GE(small.inner.components(1e-9).size(), 2u);
  // The traced bounds: inside the cell baseline's, and the 20° region is much
  // smaller than the 80° one.
  certified::LevelSetOptions o;
  o.relative_tolerance = 1e-5;
  const auto s20 = certified::sublevel_set(*c.surrogate, c.level(20.0), ws, c.within_test, o);
  const auto s80 = certified::sublevel_set(*c.surrogate, c.level(80.0), ws, c.within_test, o);
  EXPECT_LT(s20.region.area_upper, s80.region.area_lower);
  EXPECT_LE(s80.region.area_upper, ws.area() * (1 + 1e-12));
  EXPECT_LE(s20.region.area_upper, small.area_upper);
  EXPECT_GE(s20.region.area_lower, small.area_lower);
}

TEST(LevelSets, PaminsaReactionLimitedRegionAgainstSampling) {
  const auto s = mechanisms::ThreeRpr::symmetric(0.35, 0.1, mechanisms::ThreeRprActuation::revolute, 25.0 * pi / 180);
  const Box w = box(-0.3, -0.3, 0.3, 0.3);
  const mechanisms::ThreeRpr m(s.base(), s.platform(), s.actuation(), s.orientation(), std::nullopt, w);
  const auto c = criteria::three_rpr_reaction(m, mechanisms::Load{100.0, 5.0}, 0);
  certified::LevelSetOptions o;
  o.relative_tolerance = 1e-3;  // fast; `pkmws area` on the PAMINSA datasets aims at 1e-6
  o.build_regions = false;
  const auto r = certified::sublevel_set(*c.surrogate, c.level(200.0), m.workspace(), c.within_test, o);
  double err = 0.0;
  const int n = 600;
  const double est = grid_estimate(c, 200.0, w, n, err);
  const double slack = 8.0 * (w.width() / n) * w.width();
  EXPECT_GT(est, 0.01);
  EXPECT_LE(r.region.area_lower, est + slack);
  EXPECT_GE(r.region.area_upper, est - slack);
  // Undecided cells remain along an arc of the singular circle where R_1 stays
  // bounded (0/0): the width is limited by the depth there.
  EXPECT_LE(r.region.width(), 2e-3 * r.region.area_upper);
  // R_max = 110 N gives a smaller region inside ([Briot] fig. 13).
  const auto r110 = certified::sublevel_set(*c.surrogate, c.level(110.0), m.workspace(), c.within_test, o);
  EXPECT_LT(r110.region.area_upper, r.region.area_lower);
  EXPECT_GT(r110.region.area_lower, 0.0);
}

}  // namespace

namespace {

// The refinement runs leaves, and the first levels inside a leaf, as parallel
// tasks; every result is merged in a fixed order, so 1 and 2 threads agree bit
// for bit (DexTAR (+1, -1), alpha <= 80 deg: most work near the base joints).
TEST(LevelSets, OneAndTwoThreadsGiveIdenticalResults) {
  const auto m = pkmws::test::five_bar::dextar(1, -1);
  const auto field = criteria::five_bar_pressure_angle(m);
  const geometry::Region w = m.workspace();
  certified::LevelSetResult r[2];
  for (int k = 0; k < 2; ++k) {
    certified::LevelSetOptions o;
    o.relative_tolerance = 1e-6;
    o.threads = k + 1;
    r[k] = certified::sublevel_set(*field.surrogate, field.level(80.0), w, field.within_test, o);
  }
  EXPECT_EQ(r[0].region.area_lower, r[1].region.area_lower);
  EXPECT_EQ(r[0].region.area_upper, r[1].region.area_upper);
  EXPECT_EQ(r[0].traced_cells, r[1].traced_cells);
  EXPECT_EQ(r[0].undecided_cells, r[1].undecided_cells);
  EXPECT_EQ(r[0].cell_tests, r[1].cell_tests);
  ASSERT_EQ(r[0].curves.size(), r[1].curves.size());
  for (std::size_t i = 0; i < r[0].curves.size(); ++i) EXPECT_EQ(r[0].curves[i], r[1].curves[i]);
  EXPECT_GT(r[0].undecided_cells, 1000u);  // the case has the unbalanced work the tasks are for
}

// A transmission limit's fields of the DexTAR (+1, -1) as the front door
// takes them (at `threshold`).
std::vector<criteria::CriterionField> transmission_fields(const std::string& name, double threshold,
                                                          double force = 0.0) {
  mechanisms::Design d;
  d.path = "dextar.json";
  d.model = std::make_shared<mechanisms::FiveBar>(dextar(1, -1));
  if (force > 0.0) d.criteria.load = mechanisms::Load{force, 0.0};
  return criteria::fields_for(d, name, threshold);
}

}  // namespace

// The pressure angle α <= t and the reaction f / |sin ε| <= R are |sin ε| >= q
// (q = cos t, f / R), taken as ±cos ε <= √(1 - q²) for q >= 1/√2 and as
// -|det A| <= -q l_1 l_2 below (docs/theory/level_sets.md, "Transmission
// limits"). Both forms are the set of the criterion (point by point against
// the mechanism's own evaluation), and their certified areas meet those of
// the cos²ε form they replace, with the target width.
TEST(LevelSets, TransmissionLimitFormsAreTheCriterionsSetAndMeetTheCosSquaredForm) {
  struct Case {
    std::string name;
    double threshold, force;
    std::size_t fields;
    std::string key;
  };
  const std::vector<Case> cases = {{"pressure_angle", 20.0, 0.0, 2, "five_bar.coseps"},
                                   {"pressure_angle", 44.0, 0.0, 2, "five_bar.coseps"},
                                   {"pressure_angle", 46.0, 0.0, 1, "five_bar.negabssin"},
                                   {"pressure_angle", 80.0, 0.0, 1, "five_bar.negabssin"},
                                   {"reaction", 110.0, 100.0, 2, "five_bar.coseps"},  // q = 0.91
                                   {"reaction", 400.0, 100.0, 1, "five_bar.negabssin"}};
  const auto m = dextar(1, -1);
  const geometry::Region ws = m.workspace();
  const Box w = ws.bbox();
  for (const Case& k : cases) {
    const auto fs = transmission_fields(k.name, k.threshold, k.force);
    ASSERT_EQ(fs.size(), k.fields) << k.name << " " << k.threshold;
    EXPECT_EQ(fs.front().key, k.key) << k.name << " " << k.threshold;
    if (k.fields == 2) {
      EXPECT_EQ(fs.back().key, "five_bar.negcoseps");
    }
    const auto old = k.name == "reaction" ? criteria::five_bar_reaction(m, k.force) : criteria::five_bar_pressure_angle(m);
    // Point by point: inside every new constraint <=> criterion <= threshold
    // (away from the curve, where rounding decides) <=> inside the cos² one.
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> ux(w.min.x, w.max.x), uy(w.min.y, w.max.y);
    int in = 0, out = 0;
    for (int n = 0; n < 4000; ++n) {
      const Point p{ux(rng), uy(rng)};
      const double v = fs.front().value(p);
      if (!std::isfinite(v) || std::abs(v - k.threshold) < 1e-6 * k.threshold) continue;
      bool inside = true;
      for (const auto& f : fs) inside = inside && f.surrogate->value(p) <= f.level(k.threshold);
      EXPECT_EQ(inside, v <= k.threshold) << k.name << " " << k.threshold << " at " << p.x << ", " << p.y;
      EXPECT_EQ(inside, old.surrogate->value(p) <= old.level(k.threshold)) << k.name << " " << k.threshold;
      (inside ? in : out)++;
    }
    EXPECT_GT(in, 100) << k.name << " " << k.threshold;
    EXPECT_GT(out, 100) << k.name << " " << k.threshold;
    // Areas in (x, y) (no charts): both forms' bounds meet.
    if (k.threshold == 44.0 || k.threshold == 46.0) continue;  // the same forms as 20 and 80
    certified::LevelSetOptions o;
    o.relative_tolerance = 1e-6;
    std::vector<certified::Constraint> cs;
    for (const auto& f : fs) cs.push_back({f.surrogate.get(), f.level(k.threshold)});
    const auto now = certified::sublevel_set(cs, ws, fs.front().within_test, o).region;
    const auto before = certified::sublevel_set(*old.surrogate, old.level(k.threshold), ws, old.within_test, o).region;
    EXPECT_LE(now.area_lower, before.area_upper) << k.name << " " << k.threshold;
    EXPECT_GE(now.area_upper, before.area_lower) << k.name << " " << k.threshold;
    EXPECT_LE(now.width(), 1e-6 * now.area_upper) << k.name << " " << k.threshold;
    EXPECT_GT(now.area_lower, 0.05 * ws.area()) << k.name << " " << k.threshold;
  }
}
