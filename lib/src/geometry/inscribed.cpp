#include "pkmws/geometry/inscribed.hpp"

#include "geometry/boundary_pieces.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <queue>
#include <stdexcept>
#include <vector>

namespace pkmws::geometry {

namespace {

using Piece = detail::BoundaryPiece;

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

}  // namespace

std::vector<detail::BoundaryPiece> detail::boundary_pieces(const Component& component) {
  std::vector<Piece> out;
  for (const Curve& c : component.outer.curves) out.push_back(piece(c));
  for (const Loop& h : component.holes) {
    for (const Curve& c : h.curves) out.push_back(piece(c));
  }
  return out;
}

bool detail::inside(const std::vector<detail::BoundaryPiece>& boundary, Point p) {
  int n = 0;
  for (const Piece& k : boundary) n += crossings(k, p);
  return n % 2 == 1;
}

detail::BoundaryIndex::BoundaryIndex(const Component& component) : pieces_(boundary_pieces(component)) {
  if (pieces_.size() < 32) return;  // no bins: `inside` counts over all pieces
  // Each piece's y-extent: a segment's ends; an arc's ends and the circle's
  // top and bottom where the arc's span (as `crossings` tests it) holds
  // them, widened for the span test's tilt and rounding.
  double lo_all = std::numeric_limits<double>::infinity(), hi_all = -lo_all;
  std::vector<std::pair<double, double>> extent;
  extent.reserve(pieces_.size());
  for (const Piece& k : pieces_) {
    const Curve& c = *k.curve;
    double lo = std::min(c.source.y, c.target.y), hi = std::max(c.source.y, c.target.y);
    if (c.kind == Curve::Kind::arc) {
      if (within_span(k, {0.0, 1.0})) hi = c.center.y + c.radius;
      if (within_span(k, {0.0, -1.0})) lo = c.center.y - c.radius;
      const double margin = 1e-6 * (c.radius + std::abs(c.center.y));
      lo -= margin;
      hi += margin;
    }
    extent.emplace_back(lo, hi);
    lo_all = std::min(lo_all, lo);
    hi_all = std::max(hi_all, hi);
  }
  // About √n bins.
  const auto n = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(pieces_.size())))) + 1;
  y0_ = lo_all;
  bin_height_ = hi_all > lo_all ? (hi_all - lo_all) / static_cast<double>(n) : 1.0;
  bins_.resize(n);
  const auto bin_of = [&](double y) {
    return static_cast<std::size_t>(std::clamp(std::floor((y - y0_) / bin_height_), 0.0, static_cast<double>(n - 1)));
  };
  for (std::size_t i = 0; i < pieces_.size(); ++i) {
    for (std::size_t b = bin_of(extent[i].first); b <= bin_of(extent[i].second); ++b) bins_[b].push_back(i);
  }
}

bool detail::BoundaryIndex::inside(Point p) const {
  if (bins_.size() <= 1) return detail::inside(pieces_, p);  // a few dozen pieces: all of them
  const double f = std::floor((p.y - y0_) / bin_height_);
  if (!(f >= 0.0) || f >= static_cast<double>(bins_.size())) return false;  // above or below every piece: no crossing
  int n = 0;
  for (const std::size_t i : bins_[static_cast<std::size_t>(f)]) n += crossings(pieces_[i], p);
  return n % 2 == 1;
}

double distance(const Curve& c, Point p) { return distance(piece(c), p); }

double distance_to_boundary(const Component& component, Point p) {
  return distance_to_boundary(detail::boundary_pieces(component), p);
}

bool inside(const Component& component, Point p) { return detail::inside(detail::boundary_pieces(component), p); }

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
  const detail::BoundaryIndex index(component);
  const std::vector<Piece>& boundary = index.pieces();
  auto make = [&](Point c, double h) {
    const double d = (index.inside(c) ? 1.0 : -1.0) * distance_to_boundary(boundary, c);
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
