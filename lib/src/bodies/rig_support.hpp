// Enclosures of part shapes over a box of platform positions: what the body
// rigs of the mechanism modules share (private; docs/theory/interference.md).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "pkmws/bodies/bodies.hpp"

namespace pkmws::bodies::detail {

inline std::array<Point, 4> corners(const Box& b) {
  return {Point{b.min.x, b.min.y}, Point{b.max.x, b.min.y}, Point{b.max.x, b.max.y}, Point{b.min.x, b.max.y}};
}
inline Point centre(const Box& b) { return {0.5 * (b.min.x + b.max.x), 0.5 * (b.min.y + b.max.y)}; }
inline double half_diagonal(const Box& b) { return 0.5 * std::hypot(b.width(), b.height()); }

// Rectangle along unit direction a: guide coordinates [s0, s1] from `origin`, half-width w across.
inline std::vector<Point> guide_rectangle(Point origin, Point a, double s0, double s1, double w) {
  const Point n{-a.y, a.x};
  return {origin + s0 * a - w * n, origin + s1 * a - w * n, origin + s1 * a + w * n, origin + s0 * a + w * n};
}

// An inner witness: shape with radius r if positive, else none.
inline std::optional<Shape> witness(std::vector<Point> core, double r) {
  if (!(r > 0.0)) return std::nullopt;
  return Shape{std::move(core), r};
}

inline Shape hull_of(std::vector<Point> pts, double r) { return Shape{convex_hull(std::move(pts)), r}; }

// Range [lo, hi] of the linear function f over the box (attained at corners).
template <class F>
inline std::array<double, 2> linear_range(const Box& b, F&& f) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (Point c : corners(b)) {
    const double v = f(c);
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  return {lo, hi};
}


}  // namespace pkmws::bodies::detail
