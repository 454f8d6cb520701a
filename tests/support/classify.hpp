// Test helper: fast point classification against a region's exact boundary.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "pkmws/geometry/region.hpp"

namespace pkmws::testing_bodies {

using geometry::Point;
// Fast point classification against a region's exact boundary loops (segments
// and arcs): even-odd crossings of the ray to +x; points within `tol` of the
// boundary are "near" (Region::contains builds a CGAL set per call: too slow
// for thousands of samples).
enum class Side { inside, outside, near };
struct Classifier {
  std::vector<geometry::Curve> curves;
  double tol = 1e-7;
  explicit Classifier(const geometry::Region& r, double tolerance) : tol(tolerance) {
    for (const auto& loop : r.loops()) curves.insert(curves.end(), loop.curves.begin(), loop.curves.end());
  }
  static bool on_arc(const geometry::Curve& c, double theta) {
    const double ts = std::atan2(c.source.y - c.center.y, c.source.x - c.center.x);
    double d = (theta - ts) * (c.ccw ? 1.0 : -1.0);
    d = std::fmod(d, 2 * std::numbers::pi);
    if (d < 0) d += 2 * std::numbers::pi;
    return d <= std::abs(c.sweep()) + 1e-12;
  }
  Side operator()(Point p) const {
    int crossings = 0;
    for (const auto& c : curves) {
      if (c.kind == geometry::Curve::Kind::segment) {
        const Point a = c.source, b = c.target, ab = b - a;
        const double len2 = dot(ab, ab);
        const double t = len2 > 0 ? std::clamp(dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
        if (norm(p - (a + t * ab)) < tol) return Side::near;
        if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) / (b.y - a.y) * ab.x) ++crossings;
      } else {
        const Point w = p - c.center;
        const double theta = std::atan2(w.y, w.x);
        double dist = std::min(norm(p - c.source), norm(p - c.target));
        if (on_arc(c, theta)) dist = std::min(dist, std::abs(norm(w) - c.radius));
        if (dist < tol) return Side::near;
        const double dy = p.y - c.center.y;
        if (std::abs(dy) >= c.radius) continue;
        const double dx = std::sqrt(c.radius * c.radius - dy * dy);
        for (double x : {c.center.x - dx, c.center.x + dx}) {
          if (x > p.x && on_arc(c, std::atan2(dy, x - c.center.x))) ++crossings;
        }
      }
    }
    return crossings % 2 ? Side::inside : Side::outside;
  }
};


}  // namespace pkmws::testing_bodies
