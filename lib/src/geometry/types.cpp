// Double-precision geometry of boundary curves: sweep, length, Green's-theorem
// area, polylines at a max deviation, bounding boxes. No CGAL here.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "pkmws/geometry/polyline.hpp"
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

bool tangent_polyline(const Curve& curve, Approximation approximation) {
  return curve.kind == Curve::Kind::arc && approximation != Approximation::chords &&
         curve.ccw == (approximation == Approximation::outside);
}

double polyline_pieces(const Curve& curve, double tolerance, Approximation approximation) {
  if (!(tolerance > 0.0)) throw std::invalid_argument("polyline tolerance must be positive");
  if (curve.kind != Curve::Kind::arc) return 1.0;
  constexpr double saturated = 9007199254740992.0;  // 2^53
  const double s = std::abs(curve.sweep());
  const double rho = tolerance / curve.radius;
  double h = 0.0;
  if (tangent_polyline(curve, approximation)) {
    // Tangents at the ends of a piece of angle h meet r / cos(h/2) from the
    // centre: deviation r (sec(h/2) - 1) <= tolerance iff
    // 1 - cos(h/2) = 2 sin^2(h/4) <= rho / (1 + rho); pieces of at most pi/2.
    h = std::min(4.0 * std::asin(std::sqrt(0.5 * rho / (1.0 + rho))), std::numbers::pi / 2.0);
  } else {
    // A chord of angle h deviates r (1 - cos(h/2)) = 2 r sin^2(h/4) from its
    // arc (written with the sine: 1 - rho rounds to 1 for rho < 1e-16).
    h = 4.0 * std::asin(std::sqrt(0.5 * std::min(rho, 1.0)));
  }
  double n = h > 0.0 ? std::ceil(s / h) : saturated;
  if (!(n < saturated)) n = saturated;
  if (!tangent_polyline(curve, approximation) && s > std::numbers::pi) n = std::max(n, 3.0);  // keep a full circle a polygon
  return std::max(n, 1.0);
}

void append_polyline(const Curve& curve, double tolerance, Approximation approximation,
                     std::vector<Point>& out) {
  out.push_back(curve.source);
  if (curve.kind != Curve::Kind::arc) return;
  const double n = polyline_pieces(curve, tolerance, approximation);
  const double s = curve.sweep();
  if (tangent_polyline(curve, approximation)) {
    // An arc whose whole chord deviates less than the rounding of its
    // coordinates gets no tangent vertex (it would duplicate its source).
    const Point c = curve.center;
    const double r = curve.radius;
    const double sagitta = 2.0 * r * std::pow(std::sin(0.25 * s), 2);
    const double rounding = 8.0 * std::numeric_limits<double>::epsilon() *
                            (std::max(std::abs(c.x), std::abs(c.y)) + r);
    if (sagitta <= rounding) return;
    const double h = s / n;
    const double a0 = angle_of(curve.source, c);
    const double rt = r / std::cos(0.5 * h);
    const auto count = static_cast<std::size_t>(n);
    for (std::size_t k = 0; k < count; ++k) {
      const double a = a0 + (static_cast<double>(k) + 0.5) * h;
      out.push_back({c.x + rt * std::cos(a), c.y + rt * std::sin(a)});
    }
    return;
  }
  const auto count = static_cast<std::size_t>(n);
  for (std::size_t k = 1; k < count; ++k) out.push_back(curve.at(static_cast<double>(k) / n));
}

std::vector<Point> polyline(const Loop& loop, double tolerance, Approximation approximation) {
  if (!(tolerance > 0.0)) throw std::invalid_argument("polyline tolerance must be positive");
  std::vector<Point> out;
  for (const Curve& c : loop.curves) append_polyline(c, tolerance, approximation, out);
  return out;
}

std::vector<Point> Loop::polyline(double tolerance) const {
  return geometry::polyline(*this, tolerance, Approximation::chords);
}

}  // namespace pkmws::geometry
