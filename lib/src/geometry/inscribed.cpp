#include "pkmws/geometry/inscribed.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <queue>
#include <stdexcept>

namespace pkmws::geometry {

namespace {

// Is the polar angle `a` (about the arc's centre) within the arc's sweep?
bool within_sweep_angle(const Curve& c, double a) {
  const double a0 = std::atan2(c.source.y - c.center.y, c.source.x - c.center.x);
  const double s = c.sweep();
  double rel = std::remainder(a - a0, 2.0 * std::numbers::pi);  // [-pi, pi]
  if (s > 0 && rel < 0) rel += 2.0 * std::numbers::pi;
  if (s < 0 && rel > 0) rel -= 2.0 * std::numbers::pi;
  return std::abs(rel) <= std::abs(s);
}

bool within_sweep(const Curve& c, Point q) {
  return within_sweep_angle(c, std::atan2(q.y - c.center.y, q.x - c.center.x));
}

// Crossings of the ray {(x, p.y + delta) : x > p.x}, delta an infinitesimal
// upward shift (the half-open rule), with one curve.
int crossings(const Curve& c, Point p) {
  if (c.kind == Curve::Kind::segment) {
    const Point a = c.source, b = c.target;
    if ((a.y > p.y) == (b.y > p.y)) return 0;
    const double x = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
    return x > p.x ? 1 : 0;
  }
  const double dy = p.y - c.center.y;
  if (std::abs(dy) >= c.radius) return 0;
  const double h = std::sqrt(c.radius * c.radius - dy * dy);
  int n = 0;
  for (int side : {-1, 1}) {
    const double x = c.center.x + side * h;
    if (x <= p.x) continue;
    // Moving up along the circle turns the angle ccw on the right half, cw on the left.
    const double a = std::atan2(dy, side * h) + side * 1e-9;
    if (within_sweep_angle(c, a)) ++n;
  }
  return n;
}

}  // namespace

double distance(const Curve& c, Point p) {
  if (c.kind == Curve::Kind::segment) {
    const Point d = c.target - c.source;
    const double len2 = dot(d, d);
    double t = len2 > 0 ? dot(p - c.source, d) / len2 : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    return norm(p - (c.source + t * d));
  }
  if (within_sweep(c, p)) return std::abs(norm(p - c.center) - c.radius);
  return std::min(norm(p - c.source), norm(p - c.target));
}

double distance_to_boundary(const Component& component, Point p) {
  double d = std::numeric_limits<double>::infinity();
  for (const Curve& c : component.outer.curves) d = std::min(d, distance(c, p));
  for (const Loop& h : component.holes) {
    for (const Curve& c : h.curves) d = std::min(d, distance(c, p));
  }
  return d;
}

bool inside(const Component& component, Point p) {
  int n = 0;
  for (const Curve& c : component.outer.curves) n += crossings(c, p);
  for (const Loop& h : component.holes) {
    for (const Curve& c : h.curves) n += crossings(c, p);
  }
  return n % 2 == 1;
}

InscribedCircle largest_inscribed_circle(const Component& component, double precision) {
  if (!(precision > 0.0)) throw std::invalid_argument("inscribed circle: precision must be positive");
  const Box b = component.outer.bbox();
  if (b.empty()) return {};
  struct Cell {
    Point c;
    double h;      // half size
    double d;      // signed distance at the centre (negative outside)
    double bound;  // no point of the cell is farther than this from the boundary
  };
  auto make = [&](Point c, double h) {
    const double d = (inside(component, c) ? 1.0 : -1.0) * distance_to_boundary(component, c);
    return Cell{c, h, d, d + h * std::numbers::sqrt2};
  };
  auto worse = [](const Cell& a, const Cell& x) { return a.bound < x.bound; };
  std::priority_queue<Cell, std::vector<Cell>, decltype(worse)> queue(worse);
  const double size = std::max(b.width(), b.height());
  const double h0 = size / 2.0;
  queue.push(make({b.min.x + b.width() / 2, b.min.y + b.height() / 2}, h0));
  Cell best = make(component.centroid, 0.0);
  if (best.d < 0) best = queue.top();
  std::size_t evaluations = 0;
  while (!queue.empty()) {
    const Cell cell = queue.top();
    queue.pop();
    if (cell.d > best.d) best = cell;
    if (cell.bound - best.d <= precision) {
      // The best cell bound left in the queue is the certified upper bound.
      return {best.c, std::max(best.d, 0.0), std::max(cell.bound, best.d)};
    }
    if (++evaluations > 2'000'000) break;
    const double h = cell.h / 2.0;
    for (int i = -1; i <= 1; i += 2) {
      for (int j = -1; j <= 1; j += 2) queue.push(make({cell.c.x + i * h, cell.c.y + j * h}, h));
    }
  }
  return {best.c, std::max(best.d, 0.0), queue.empty() ? best.d : queue.top().bound};
}

}  // namespace pkmws::geometry
