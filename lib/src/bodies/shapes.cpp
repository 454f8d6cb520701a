// Distances between points, capsules and polygons in double arithmetic (the
// pose-level collision test and the box tests of the interference regions).
#include <algorithm>
#include <cmath>
#include <limits>

#include "pkmws/bodies/bodies.hpp"

namespace pkmws::bodies {

namespace {

double point_segment(Point p, Point a, Point b) {
  const Point ab = b - a;
  const double len2 = dot(ab, ab);
  double t = len2 > 0.0 ? dot(p - a, ab) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return norm(p - (a + t * ab));
}

int orientation(Point a, Point b, Point c) {
  const double v = cross(b - a, c - a);
  return v > 0.0 ? 1 : (v < 0.0 ? -1 : 0);
}

bool on_segment(Point p, Point a, Point b) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

bool segments_intersect(Point a, Point b, Point c, Point d) {
  const int o1 = orientation(a, b, c), o2 = orientation(a, b, d);
  const int o3 = orientation(c, d, a), o4 = orientation(c, d, b);
  if (o1 != o2 && o3 != o4 && o1 * o2 <= 0 && o3 * o4 <= 0) return true;
  if (o1 == 0 && on_segment(c, a, b)) return true;
  if (o2 == 0 && on_segment(d, a, b)) return true;
  if (o3 == 0 && on_segment(a, c, d)) return true;
  if (o4 == 0 && on_segment(b, c, d)) return true;
  return false;
}

double segment_segment(Point a, Point b, Point c, Point d) {
  if (segments_intersect(a, b, c, d)) return 0.0;
  return std::min({point_segment(a, c, d), point_segment(b, c, d), point_segment(c, a, b), point_segment(d, a, b)});
}

// Even-odd rule; points on the boundary may go either way (their distance is 0 anyway).
bool inside_polygon(Point p, const std::vector<Point>& poly) {
  bool in = false;
  const std::size_t n = poly.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Point a = poly[i], b = poly[j];
    if ((a.y > p.y) != (b.y > p.y)) {
      const double x = a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x);
      if (p.x < x) in = !in;
    }
  }
  return in;
}

// Edges of a core: a point is one degenerate edge, a segment one edge, a polygon closed.
template <class F>
void for_edges(const std::vector<Point>& c, F&& f) {
  if (c.size() == 1) { f(c[0], c[0]); return; }
  if (c.size() == 2) { f(c[0], c[1]); return; }
  for (std::size_t i = 0; i < c.size(); ++i) f(c[i], c[(i + 1) % c.size()]);
}

}  // namespace

double core_distance(const std::vector<Point>& a, const std::vector<Point>& b) {
  if (a.empty() || b.empty()) return std::numeric_limits<double>::infinity();
  // Containment of one core in the (filled) other.
  if (b.size() >= 3 && inside_polygon(a[0], b)) return 0.0;
  if (a.size() >= 3 && inside_polygon(b[0], a)) return 0.0;
  // Otherwise two closed sets intersect iff their boundaries do, and the
  // distance of disjoint ones is attained on their boundaries.
  double best = std::numeric_limits<double>::infinity();
  for_edges(a, [&](Point p, Point q) {
    for_edges(b, [&](Point r, Point s) { best = std::min(best, segment_segment(p, q, r, s)); });
  });
  return best;
}

double clearance(const Shape& a, const Shape& b) { return core_distance(a.core, b.core) - a.radius - b.radius; }

bool overlap(const Shape& a, const Shape& b) { return clearance(a, b) <= 0.0; }

std::vector<Point> convex_hull(std::vector<Point> pts) {
  std::sort(pts.begin(), pts.end(), [](Point a, Point b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  if (pts.size() < 3) return pts;
  // Andrew's monotone chain.
  std::vector<Point> h(2 * pts.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    while (k >= 2 && cross(h[k - 1] - h[k - 2], pts[i] - h[k - 2]) <= 0.0) --k;
    h[k++] = pts[i];
  }
  for (std::size_t i = pts.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross(h[k - 1] - h[k - 2], pts[i] - h[k - 2]) <= 0.0) --k;
    h[k++] = pts[i];
  }
  h.resize(k - 1);
  return h;
}

double unsigned_angle(Point u, Point v) { return std::abs(std::atan2(cross(u, v), dot(u, v))); }

bool Part::solid() const {
  switch (kind) {
    case PartKind::platform_joint:
    case PartKind::link: return radius > 0.0;
    case PartKind::slider_block: return length > 0.0 && width > 0.0;
    case PartKind::housing: return to > from && width > 0.0;
    case PartKind::obstacle: return true;  // validated: a simple polygon of positive area
  }
  return false;
}

}  // namespace pkmws::bodies
