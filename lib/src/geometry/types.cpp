// Double-precision geometry of boundary curves: sweep, length, Green's-theorem
// area, polylines at a max deviation, bounding boxes. No CGAL here.
#include <numbers>
#include <stdexcept>

#include "pkmws/geometry/types.hpp"

namespace pkmws::geometry {

namespace {

constexpr double two_pi = 2.0 * std::numbers::pi;

double angle_of(Point p, Point c) { return std::atan2(p.y - c.y, p.x - c.x); }

}  // namespace

double Curve::sweep() const {
  if (kind == Kind::segment) return 0.0;
  if (std::isfinite(swept)) return swept;
  double d = angle_of(target, center) - angle_of(source, center);
  if (ccw) {
    while (d <= 0.0) d += two_pi;   // a closed arc (source == target) is a full turn
  } else {
    while (d >= 0.0) d -= two_pi;
  }
  return d;
}

double Curve::length() const {
  if (kind == Kind::segment) return norm(target - source);
  return radius * std::abs(sweep());
}

Point Curve::at(double t) const {
  if (kind == Kind::segment) return source + t * (target - source);
  if (t <= 0.0) return source;
  if (t >= 1.0) return target;
  const double a = angle_of(source, center) + t * sweep();
  return {center.x + radius * std::cos(a), center.y + radius * std::sin(a)};
}

double Loop::signed_area() const {
  // Green's theorem, relative to a local origin o to avoid cancellation:
  // segment  1/2 (p x q), arc 1/2 [c x (q - p) + r^2 dtheta] (docs/theory/regions.md).
  if (curves.empty()) return 0.0;
  const Point o = curves.front().source;
  double twice = 0.0;
  for (const Curve& c : curves) {
    const Point p = c.source - o;
    const Point q = c.target - o;
    if (c.kind == Curve::Kind::segment) {
      twice += cross(p, q);
    } else {
      const Point m = c.center - o;
      twice += cross(m, q - p) + c.radius * c.radius * c.sweep();
    }
  }
  return 0.5 * twice;
}

double Loop::perimeter() const {
  double s = 0.0;
  for (const Curve& c : curves) s += c.length();
  return s;
}

Box Loop::bbox() const {
  Box b;
  for (const Curve& c : curves) {
    b.expand(c.source);
    b.expand(c.target);
    if (c.kind != Curve::Kind::arc) continue;
    // Axis-extreme points of the circle that lie within the arc's sweep.
    const double a0 = angle_of(c.source, c.center);
    const double s = c.sweep();
    for (int k = 0; k < 4; ++k) {
      const double ak = k * std::numbers::pi / 2.0;
      double rel = ak - a0;  // angle from source to the extreme point, in the sweep's sense
      if (s > 0) { rel = std::fmod(rel, two_pi); if (rel < 0) rel += two_pi; }
      else { rel = std::fmod(rel, two_pi); if (rel > 0) rel -= two_pi; }
      if (std::abs(rel) <= std::abs(s)) {
        b.expand(Point{c.center.x + c.radius * std::cos(ak), c.center.y + c.radius * std::sin(ak)});
      }
    }
  }
  return b;
}

std::vector<Point> Loop::polyline(double tolerance) const {
  if (!(tolerance > 0.0)) throw std::invalid_argument("polyline tolerance must be positive");
  std::vector<Point> out;
  for (const Curve& c : curves) {
    out.push_back(c.source);
    if (c.kind != Curve::Kind::arc) continue;
    // A chord of angle h deviates r (1 - cos(h/2)) from its arc: n pieces
    // with h = sweep / n keep the deviation <= tolerance (docs/theory/regions.md).
    const double ratio = std::min(tolerance / c.radius, 1.0);
    const double max_step = ratio > 0.0 ? 2.0 * std::acos(1.0 - ratio) : 0.0;
    const double s = std::abs(c.sweep());
    std::size_t n = static_cast<std::size_t>(std::ceil(s / max_step));
    n = std::max<std::size_t>(n, s > std::numbers::pi ? 3 : 1);  // keep a full circle a polygon
    for (std::size_t k = 1; k < n; ++k) out.push_back(c.at(static_cast<double>(k) / static_cast<double>(n)));
  }
  return out;
}

}  // namespace pkmws::geometry
