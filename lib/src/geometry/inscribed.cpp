#include "pkmws/geometry/inscribed.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <queue>
#include <stdexcept>
#include <vector>

namespace pkmws::geometry {

namespace {

// A boundary curve, with what the many point queries of a search need of an
// arc computed once: its end directions from the centre, ordered
// counter-clockwise (a cw arc from S to T is the ccw arc from T to S), and
// whether it spans more than a half turn. Unused for segments.
struct Piece {
  const Curve* curve;
  Point from, to;  // ccw: the arc covers the directions from `from` to `to`
  bool major = false;
};

Piece piece(const Curve& c) {
  if (c.kind != Curve::Kind::arc) return Piece{&c, {}, {}, false};
  const Point s = c.source - c.center, t = c.target - c.center;
  const double sweep = c.sweep();
  return sweep >= 0 ? Piece{&c, s, t, sweep > std::numbers::pi} : Piece{&c, t, s, -sweep > std::numbers::pi};
}

// Is the direction v (from the arc's centre) within the arc's span? Within
// a half turn or less: v is ccw of `from` and cw of `to`; beyond a half turn:
// v is not strictly inside the complementary span (from `to` to `from`),
// which is less than a half turn. Cross products instead of polar angles
// (atan2 and a remainder were 14 % of a sweep of inscribed circles).
bool within_span(const Piece& k, Point v) {
  if (!k.major) return cross(k.from, v) >= 0.0 && cross(v, k.to) >= 0.0;
  return !(cross(k.to, v) > 0.0 && cross(v, k.from) > 0.0);
}

// Crossings of the ray {(x, p.y + delta) : x > p.x}, delta an infinitesimal
// upward shift (the half-open rule), with one curve.
int crossings(const Piece& k, Point p) {
  const Curve& c = *k.curve;
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
    // The crossing moved up along the circle by a turn of 1e-9: ccw on the
    // right half (tangent (-dy, h)), cw on the left (tangent (dy, h)).
    const Point v{side * h, dy};
    const Point up{-side * dy, h};
    if (within_span(k, v + 1e-9 * up)) ++n;
  }
  return n;
}

// |v| without std::hypot's guard against overflow (coordinates are lengths of
// a machine, far from it): hypot was 4 % of an area + circle sweep.
double length(Point v) { return std::sqrt(v.x * v.x + v.y * v.y); }

double distance(const Piece& k, Point p) {
  const Curve& c = *k.curve;
  if (c.kind == Curve::Kind::segment) {
    const Point d = c.target - c.source;
    const double len2 = dot(d, d);
    double t = len2 > 0 ? dot(p - c.source, d) / len2 : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    return length(p - (c.source + t * d));
  }
  if (within_span(k, p - c.center)) return std::abs(length(p - c.center) - c.radius);
  return std::min(length(p - c.source), length(p - c.target));
}

std::vector<Piece> pieces(const Component& component) {
  std::vector<Piece> out;
  for (const Curve& c : component.outer.curves) out.push_back(piece(c));
  for (const Loop& h : component.holes) {
    for (const Curve& c : h.curves) out.push_back(piece(c));
  }
  return out;
}

double distance_to_boundary(const std::vector<Piece>& boundary, Point p) {
  double d = std::numeric_limits<double>::infinity();
  for (const Piece& k : boundary) {
    const Curve& c = *k.curve;
    if (c.kind == Curve::Kind::arc) {
      // An arc is no closer than its circle: skip it when the circle is
      // farther than d (|p - centre| outside [r - d, r + d], compared
      // squared). The slack covers the rounding of the arc's end points,
      // which lie on the circle, and of these products, so d is the same as
      // without the test.
      const double dx = p.x - c.center.x, dy = p.y - c.center.y;
      const double rho2 = dx * dx + dy * dy;
      const double slack = 1e-12 * (c.radius + std::abs(dx) + std::abs(dy));
      const double outer = c.radius + d + slack, inner = c.radius - d - slack;
      if (rho2 > outer * outer || (inner > 0.0 && rho2 < inner * inner)) continue;
    }
    d = std::min(d, distance(k, p));
  }
  return d;
}

bool inside(const std::vector<Piece>& boundary, Point p) {
  int n = 0;
  for (const Piece& k : boundary) n += crossings(k, p);
  return n % 2 == 1;
}

}  // namespace

double distance(const Curve& c, Point p) { return distance(piece(c), p); }

double distance_to_boundary(const Component& component, Point p) { return distance_to_boundary(pieces(component), p); }

bool inside(const Component& component, Point p) { return inside(pieces(component), p); }

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
  const std::vector<Piece> boundary = pieces(component);
  auto make = [&](Point c, double h) {
    const double d = (inside(boundary, c) ? 1.0 : -1.0) * distance_to_boundary(boundary, c);
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
