// Areas of polygons clipped to signed disks, enclosed in intervals (see
// disk_area.hpp and docs/theory/level_sets.md, "Charts").
#include "pkmws/certified/disk_area.hpp"

#include <cmath>

namespace pkmws::certified {

namespace {

using geometry::Point;

struct Vec {
  Interval x, y;
};

Interval cross(const Vec& a, const Vec& b) { return a.x * b.y - a.y * b.x; }
Interval dot(const Vec& a, const Vec& b) { return a.x * b.x + a.y * b.y; }

// atan over an interval, widened by four ulps (glibc's atan is within one).
Interval atan(const Interval& q) {
  const auto widen = [](double v, int dir) { return v + dir * (std::abs(v) * 0x1p-50 + 0x1p-1070); };
  return {widen(std::atan(q.lo), -1), widen(std::atan(q.hi), 1)};
}

// The signed area of the circular sector from direction a to direction b
// about the centre: r² θ / 2, θ = atan2(a × b, a · b), for a · b > 0.
std::optional<Interval> sector(const Vec& a, const Vec& b, const Interval& r2) {
  const Interval d = dot(a, b);
  if (!(d.lo > 0.0)) return std::nullopt;
  return Interval(0.5) * r2 * atan(cross(a, b) / d);
}

// The signed area of the triangle (centre, a, b) ∩ the disk of radius² r2
// about the centre (a, b relative to it): along the edge a + t (b - a),
// t in [0, 1], the part inside the circle contributes its triangle, the parts
// outside their sectors.
std::optional<Interval> edge_part(const Vec& a, const Vec& b, const Interval& r2) {
  const Vec d{b.x - a.x, b.y - a.y};
  const Interval len2 = sqr(d.x) + sqr(d.y);
  if (len2.hi == 0.0) return Interval(0.0);  // a repeated vertex
  if (!(len2.lo > 0.0)) return std::nullopt;
  const Interval ca = sqr(a.x) + sqr(a.y) - r2, cb = sqr(b.x) + sqr(b.y) - r2;
  if (ca.hi < 0.0 && cb.hi < 0.0) return Interval(0.5) * cross(a, b);  // both ends inside: the disk is convex
  // |a + t d|² = r²: len2 t² + 2 m t + ca = 0.
  const Interval m = dot(a, d);
  const Interval disc = sqr(m) - len2 * ca;
  const bool ends_outside = ca.lo > 0.0 && cb.lo > 0.0;
  if (disc.hi < 0.0) return ends_outside ? sector(a, b, r2) : std::nullopt;
  if (!(disc.lo > 0.0)) return std::nullopt;  // the edge's line touches the circle
  // The roots t1 <= t2 (inside for t in (t1, t2)): the one without
  // cancellation from -m ∓ root, the other as ca / (len2 t) (their product is
  // ca / len2), so that a near end of the edge is found to a few ulps.
  const Interval root = sqrt(disc);
  Interval t1, t2;
  if (m.lo > 0.0) {
    const Interval q = -(m + root);
    t1 = q / len2;
    t2 = ca / q;
  } else if (m.hi < 0.0) {
    const Interval q = root - m;
    t1 = ca / q;
    t2 = q / len2;
  } else {
    t1 = (-m - root) / len2;
    t2 = (-m + root) / len2;
  }
  const auto straddles = [](const Interval& t, double v) { return t.lo <= v && v <= t.hi; };
  if (straddles(t1, 0.0) || straddles(t1, 1.0) || straddles(t2, 0.0) || straddles(t2, 1.0)) return std::nullopt;
  if (t2.hi < 0.0 || t1.lo > 1.0) return ends_outside ? sector(a, b, r2) : std::nullopt;
  const auto at = [&](const Interval& t) { return Vec{a.x + t * d.x, a.y + t * d.y}; };
  const bool enters = t1.lo > 0.0, leaves = t2.hi < 1.0;
  const Vec p = enters ? at(t1) : a, q = leaves ? at(t2) : b;
  Interval sum = Interval(0.5) * cross(p, q);
  if (enters) {
    const auto s = sector(a, p, r2);
    if (!s) return std::nullopt;
    sum = sum + *s;
  }
  if (leaves) {
    const auto s = sector(q, b, r2);
    if (!s) return std::nullopt;
    sum = sum + *s;
  }
  return sum;
}

}  // namespace

std::optional<Interval> area_in_disks(std::span<const Point> polygon, std::span<const SignedDisk> disks) {
  if (polygon.size() < 3) return Interval(0.0);
  double x0 = polygon[0].x, x1 = x0, y0 = polygon[0].y, y1 = y0;
  for (const Point& p : polygon) {
    x0 = std::min(x0, p.x);
    x1 = std::max(x1, p.x);
    y0 = std::min(y0, p.y);
    y1 = std::max(y1, p.y);
  }
  // The one circle the bounding box crosses, if any.
  const SignedDisk* across = nullptr;
  for (const SignedDisk& d : disks) {
    const Interval d2 = sqr(Interval(x0, x1) - Interval(d.centre.x)) + sqr(Interval(y0, y1) - Interval(d.centre.y));
    const Interval r2 = sqr(Interval(d.radius));
    const bool in = d2.hi < r2.lo, out = d2.lo > r2.hi;
    if (in || out) {
      if (in != d.inside) return Interval(0.0);  // the box misses this part of the set
      continue;
    }
    if (across) return std::nullopt;
    across = &d;
  }
  // The polygon's signed area (shoelace about its first vertex).
  const Point o = polygon[0];
  const auto rel = [](const Point& p, const Point& c) { return Vec{Interval(p.x) - Interval(c.x), Interval(p.y) - Interval(c.y)}; };
  Interval signed_area(0.0);
  for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
    signed_area = signed_area + Interval(0.5) * cross(rel(polygon[k], o), rel(polygon[k + 1], o));
  }
  const double sign = signed_area.lo > 0.0 ? 1.0 : signed_area.hi < 0.0 ? -1.0 : 0.0;
  if (sign == 0.0) return std::nullopt;
  const Interval area = Interval(sign) * signed_area;
  if (!across) return area;
  const Interval r2 = sqr(Interval(across->radius));
  Interval in_disk(0.0);
  for (std::size_t k = 0; k < polygon.size(); ++k) {
    const auto part = edge_part(rel(polygon[k], across->centre), rel(polygon[(k + 1) % polygon.size()], across->centre), r2);
    if (!part) return std::nullopt;
    in_disk = in_disk + *part;
  }
  in_disk = Interval(sign) * in_disk;
  const Interval out = across->inside ? in_disk : area - in_disk;
  // Within [0, area(P)] (the rounding may have left it).
  const Interval clipped(std::max(0.0, out.lo), std::min(area.hi, out.hi));
  if (!(clipped.lo <= clipped.hi)) return std::nullopt;
  return clipped;
}

}  // namespace pkmws::certified
