#include "pkmws/geometry/inscribed_rectangle.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <queue>
#include <stdexcept>

#include "geometry/boundary_pieces.hpp"
#include "pkmws/geometry/inscribed.hpp"
#include "pkmws/geometry/primitives.hpp"

namespace pkmws::geometry {

namespace {

struct YRange {
  double lo;
  double hi;
};

// An x-monotone piece of a boundary curve, p0.x <= p1.x: a segment, or a
// part of one half circle (sigma = +1 upper, -1 lower).
struct Piece {
  const Curve* curve;
  Point p0, p1;
  double sigma;
};

// y on the half circle (sigma = +1 upper, -1 lower) above/below x; the
// product (r - d)(r + d) keeps the relative error of the root small near the
// circle's leftmost and rightmost points.
double circle_y(const Curve& c, double sigma, double x) {
  const double d = x - c.center.x;
  return c.center.y + sigma * std::sqrt(std::max(0.0, (c.radius - d) * (c.radius + d)));
}

// y-range of the part of an x-monotone piece with a <= x <= b.
std::optional<YRange> clip_piece(const Piece& piece, double a, double b) {
  const Curve& c = *piece.curve;
  const Point p0 = piece.p0, p1 = piece.p1;
  const double sigma = piece.sigma;
  const double u = std::max(p0.x, a), v = std::min(p1.x, b);
  if (u > v) return std::nullopt;
  const auto y_at = [&](double x) {
    if (x == p0.x) return p0.y;
    if (x == p1.x) return p1.y;
    if (c.kind == Curve::Kind::segment) return p0.y + (x - p0.x) * (p1.y - p0.y) / (p1.x - p0.x);
    return circle_y(c, sigma, x);
  };
  const double yu = y_at(u), yv = y_at(v);
  YRange r{std::min(yu, yv), std::max(yu, yv)};
  if (c.kind == Curve::Kind::arc && u <= c.center.x && c.center.x <= v) {
    if (sigma > 0) r.hi = std::max(r.hi, c.center.y + c.radius);
    else r.lo = std::min(r.lo, c.center.y - c.radius);
  }
  return r;
}

// Splits `c` into x-monotone pieces (once per search, not per strip).
void split_curve(const Curve& c, std::vector<Piece>& out) {
  const auto add = [&](Point p0, Point p1, double sigma) {
    if (p0.x > p1.x) std::swap(p0, p1);
    out.push_back({&c, p0, p1, sigma});
  };
  if (c.kind == Curve::Kind::segment) {
    add(c.source, c.target, 0.0);
    return;
  }
  // Counter-clockwise from `start` over the sweep, split where the circle
  // turns in x (multiples of pi): each piece lies on one half circle.
  const double s = c.sweep();
  const Point from = s >= 0 ? c.source : c.target;
  const Point to = s >= 0 ? c.target : c.source;
  const double start = std::atan2(from.y - c.center.y, from.x - c.center.x);
  const double end = start + std::abs(s);
  const double pi = std::numbers::pi;
  double t0 = start;
  Point p0 = from;
  for (double m = std::floor(start / pi) + 1.0;; m += 1.0) {
    const bool last = m * pi >= end;
    const double t1 = last ? end : m * pi;
    const Point p1 = last ? to : Point{c.center.x + (std::fmod(m, 2.0) == 0.0 ? c.radius : -c.radius), c.center.y};
    // The piece [t0, t1] lies in [(m - 1) pi, m pi]: upper half when m - 1 is even.
    const double sigma = std::fmod(std::abs(m - 1.0), 2.0) == 0.0 ? 1.0 : -1.0;
    if (t1 > t0) add(p0, p1, sigma);
    if (last) break;
    t0 = t1;
    p0 = p1;
  }
}

// A component ready for many free-height queries.
struct Prepared {
  std::vector<Piece> pieces;
  detail::BoundaryIndex boundary;  // for the membership tests (built once: 73 % of a search had gone to them)
  Box bbox;
  explicit Prepared(const Component& c) : boundary(c), bbox(c.outer.bbox()) {
    for (const Curve& k : c.outer.curves) split_curve(k, pieces);
    for (const Loop& h : c.holes) {
      for (const Curve& k : h.curves) split_curve(k, pieces);
    }
  }
};

FreeInterval free_interval(const Prepared& prepared, double x0, double x1, double slack);

double scale_of(const Box& b) {
  return std::max({std::abs(b.min.x), std::abs(b.min.y), std::abs(b.max.x), std::abs(b.max.y), b.width(),
                   b.height()});
}

// ---- branch and bound over the rectangle's x-range ----------------------

struct Candidate {
  Box box;
  double area = 0.0;
};

class Search {
 public:
  Search(const Prepared& prepared, RectangleShape shape)
      : prepared_(prepared), shape_(shape), bbox_(prepared.bbox), slack_(1e-12 * scale_of(bbox_)) {}

  // Upper bound of the area over x0 in [a0, b0], x1 in [a1, b1].
  double upper(double a0, double b0, double a1, double b1) const {
    if (a0 >= b1) return 0.0;
    const double w = std::min(b1 - a0, bbox_.width());
    const double h = b0 < a1 ? free_interval(prepared_, b0, a1, slack_).length() : bbox_.height();
    return area_of(w, h);
  }

  // A rectangle of the shape inside for x0, x1 (lower bound).
  Candidate candidate(double x0, double x1) const {
    if (!(x1 > x0)) return {};
    const FreeInterval f = free_interval(prepared_, x0, x1, -slack_);
    double w = x1 - x0, h = f.length();
    if (h <= 0.0) return {};
    if (shape_.kind == RectangleShape::Kind::aspect) {
      if (h >= shape_.value * w) h = shape_.value * w;
      else w = h / shape_.value;
    }
    const double xm = 0.5 * (x0 + x1), ym = 0.5 * (f.y0 + f.y1);
    Candidate c;
    c.box.min = {xm - 0.5 * w, ym - 0.5 * h};
    c.box.max = {xm + 0.5 * w, ym + 0.5 * h};
    c.area = w * h;
    return c;
  }

  double area_of(double w, double h) const {
    if (shape_.kind == RectangleShape::Kind::aspect) {
      const double k = shape_.value;
      const double side = std::min(w, h / k);
      return k * side * side;
    }
    return w * h;
  }

  const Box& bbox() const { return bbox_; }

 private:
  const Prepared& prepared_;
  RectangleShape shape_;
  Box bbox_;
  double slack_;
};

// Best-first branch and bound shared by the searches: `upper(c)` bounds every
// rectangle of cell c, `candidate(c)` is one that fits (the lower bound),
// `split(c)` halves c. Stops when the best bound left is within `precision`
// of the best candidate, or after `max_evaluations` candidates, or as soon as
// the best bound left is at most `stop_below` (a caller that only needs to
// know the area does not exceed it; `area_upper` is then still valid).
template <class C, class Upper, class Make, class Split>
InscribedRectangle best_first(C root, Upper&& upper, Make&& candidate, Split&& split, double precision,
                              std::size_t max_evaluations, double stop_below = 0.0) {
  auto lower_ub = [](const C& a, const C& b) { return a.upper < b.upper; };
  std::priority_queue<C, std::vector<C>, decltype(lower_ub)> queue(lower_ub);
  InscribedRectangle out;
  Candidate best;
  auto consider = [&](const C& c) {
    ++out.evaluations;
    const Candidate k = candidate(c);
    if (k.area > best.area) best = k;
  };
  root.upper = upper(root);
  consider(root);
  queue.push(root);
  while (!queue.empty()) {
    const C top = queue.top();
    if (top.upper <= best.area || (top.upper - best.area) <= precision * top.upper) break;
    if (top.upper <= stop_below) break;
    if (out.evaluations >= max_evaluations) break;
    queue.pop();
    for (C h : split(top)) {
      h.upper = upper(h);
      if (h.upper <= best.area) continue;
      consider(h);
      queue.push(h);
    }
  }
  out.box = best.box;
  out.area = best.area;
  out.area_upper = queue.empty() ? best.area : std::max(best.area, queue.top().upper);
  return out;
}

struct Cell {
  double a0, b0, a1, b1;  // x0 in [a0, b0], x1 in [a1, b1]
  double upper;
};

InscribedRectangle search_free_or_aspect(const Search& s, double precision, std::size_t max_evaluations,
                                         double stop_below = 0.0) {
  const Box& bb = s.bbox();
  return best_first(
      Cell{bb.min.x, bb.max.x, bb.min.x, bb.max.x, 0.0},
      [&](const Cell& c) { return s.upper(c.a0, c.b0, c.a1, c.b1); },
      [&](const Cell& c) { return s.candidate(0.5 * (c.a0 + c.b0), 0.5 * (c.a1 + c.b1)); },
      [](const Cell& c) {
        std::array<Cell, 2> halves = {c, c};
        if (c.b0 - c.a0 >= c.b1 - c.a1) {
          halves[0].b0 = halves[1].a0 = 0.5 * (c.a0 + c.b0);
        } else {
          halves[0].b1 = halves[1].a1 = 0.5 * (c.a1 + c.b1);
        }
        return halves;
      },
      precision, max_evaluations, stop_below);
}

InscribedRectangle search_width(const Prepared& prepared, double w, double precision,
                                std::size_t max_evaluations) {
  const Box bb = prepared.bbox;
  if (w > bb.width()) return {};  // nothing of that width fits
  const double slack = 1e-12 * scale_of(bb);
  struct Interval {
    double a, b, upper;  // x0 in [a, b]
  };
  return best_first(
      Interval{bb.min.x, bb.max.x - w, 0.0},
      [&](const Interval& i) {
        return w * (i.b < i.a + w ? free_interval(prepared, i.b, i.a + w, slack).length() : bb.height());
      },
      [&](const Interval& i) {
        const double x0 = 0.5 * (i.a + i.b);
        const FreeInterval f = free_interval(prepared, x0, x0 + w, -slack);
        Candidate k;
        if (f.length() > 0.0) {
          k.area = w * f.length();
          k.box.min = {x0, f.y0};
          k.box.max = {x0 + w, f.y1};
        }
        return k;
      },
      [](const Interval& i) {
        const double m = 0.5 * (i.a + i.b);
        return std::array<Interval, 2>{Interval{i.a, m, 0.0}, Interval{m, i.b, 0.0}};
      },
      precision, max_evaluations);
}

// ---- distances between boundaries ------------------------------------------

Curve segment_curve(Point a, Point b) {
  Curve c;
  c.kind = Curve::Kind::segment;
  c.source = a;
  c.target = b;
  return c;
}

double orient(Point a, Point b, Point c) { return cross(b - a, c - a); }

bool segments_cross(Point p, Point q, Point r, Point s) {
  const double d1 = orient(p, q, r), d2 = orient(p, q, s), d3 = orient(r, s, p), d4 = orient(r, s, q);
  return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

// Distance between the segment pq and a boundary curve.
double segment_distance(Point p, Point q, const Curve& c) {
  const Curve seg = segment_curve(p, q);
  double d = std::min({distance(c, p), distance(c, q), distance(seg, c.source), distance(seg, c.target)});
  if (c.kind == Curve::Kind::segment) {
    if (segments_cross(p, q, c.source, c.target)) return 0.0;
    return d;
  }
  // The common normal through the centre, and the crossings with the circle.
  const Point dir = q - p;
  const double len2 = dot(dir, dir);
  if (len2 > 0.0) {
    const double t = std::clamp(dot(c.center - p, dir) / len2, 0.0, 1.0);
    d = std::min(d, distance(c, p + t * dir));
    const Point f = p - c.center;
    const double B = dot(f, dir), C = dot(f, f) - c.radius * c.radius;
    const double disc = B * B - len2 * C;
    if (disc >= 0.0) {
      for (double sgn : {-1.0, 1.0}) {
        const double u = (-B + sgn * std::sqrt(disc)) / len2;
        if (u >= 0.0 && u <= 1.0) d = std::min(d, distance(c, p + u * dir));
      }
    }
  }
  return d;
}

// Largest distance from a point of the polygon to the region (0 inside it),
// by branch and bound on the 1-Lipschitz distance; returns {value, error}.
// The farthest point lies in polygon − region, so the search covers only
// `domains`, the bounding boxes of that set's components (a sliver outside a
// corner: a tiny box, not the whole polygon at the tolerance's resolution),
// with rectangular cells split across their longer side.
std::pair<double, double> farthest_outside(const Region& region, const std::vector<Loop>& loops,
                                           const std::vector<Point>& polygon, const std::vector<Box>& domains,
                                           double tolerance) {
  const auto dist_to_region = [&](Point x) {
    if (region.contains(x)) return 0.0;
    double d = std::numeric_limits<double>::infinity();
    for (const Loop& l : loops) {
      for (const Curve& c : l.curves) d = std::min(d, distance(c, x));
    }
    return d;
  };
  const auto in_polygon = [&](Point x) {
    bool in = false;
    for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
      const Point a = polygon[i], b = polygon[j];
      if ((a.y > x.y) != (b.y > x.y) && x.x < a.x + (x.y - a.y) * (b.x - a.x) / (b.y - a.y)) in = !in;
    }
    return in;
  };
  const auto polygon_distance = [&](Point x) {
    if (in_polygon(x)) return 0.0;
    double d = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
      d = std::min(d, distance(segment_curve(polygon[j], polygon[i]), x));
    }
    return d;
  };
  struct Window {
    Point c;
    double hx, hy, bound;
  };
  double best = 0.0;
  for (const Point& v : polygon) best = std::max(best, dist_to_region(v));
  auto lower = [](const Window& a, const Window& b) { return a.bound < b.bound; };
  std::priority_queue<Window, std::vector<Window>, decltype(lower)> queue(lower);
  auto push = [&](Point c, double hx, double hy) {
    const double reach = std::hypot(hx, hy);
    if (polygon_distance(c) > reach) return;  // the cell misses the polygon
    if (in_polygon(c)) best = std::max(best, dist_to_region(c));
    queue.push({c, hx, hy, dist_to_region(c) + reach});
  };
  for (const Box& d : domains) {
    push({0.5 * (d.min.x + d.max.x), 0.5 * (d.min.y + d.max.y)}, 0.5 * d.width(), 0.5 * d.height());
  }
  std::size_t evaluations = 0;
  while (!queue.empty() && queue.top().bound - best > tolerance && ++evaluations < 2'000'000) {
    const Window cell = queue.top();
    queue.pop();
    const bool split_x = cell.hx >= 0.5 * cell.hy, split_y = cell.hy >= 0.5 * cell.hx;
    const double hx = split_x ? 0.5 * cell.hx : cell.hx, hy = split_y ? 0.5 * cell.hy : cell.hy;
    for (int i = split_x ? -1 : 0; i <= (split_x ? 1 : 0); i += 2) {
      for (int j = split_y ? -1 : 0; j <= (split_y ? 1 : 0); j += 2) push({cell.c.x + i * hx, cell.c.y + j * hy}, hx, hy);
    }
  }
  const double upper = queue.empty() ? best : std::max(best, queue.top().bound);
  return {best, upper - best};
}

}  // namespace

namespace {

void check_arguments(double precision, RectangleShape shape) {
  if (!(precision > 0.0) || !std::isfinite(precision)) {
    throw std::invalid_argument("inscribed rectangle: precision must be positive");
  }
  if (shape.kind != RectangleShape::Kind::free && !(shape.value > 0.0 && std::isfinite(shape.value))) {
    throw std::invalid_argument(shape.kind == RectangleShape::Kind::aspect
                                    ? "inscribed rectangle: aspect ratio must be positive"
                                    : "inscribed rectangle: width must be positive");
  }
}

// Checks the rectangle against the exact region (its corners as an exact
// polygon); shrinks it about its centre by growing relative amounts if
// rounding put a corner outside.
void verify(InscribedRectangle& out, const Region& region) {
  if (out.box.empty() || out.area <= 0.0) return;
  const Point c{0.5 * (out.box.min.x + out.box.max.x), 0.5 * (out.box.min.y + out.box.max.y)};
  const double w = out.box.width(), h = out.box.height();
  for (double shrink = 0.0; shrink <= 1e-6; shrink = shrink == 0.0 ? 1e-13 : shrink * 10.0) {
    InscribedRectangle t = out;
    const double hw = 0.5 * w * (1.0 - shrink), hh = 0.5 * h * (1.0 - shrink);
    t.box.min = {c.x - hw, c.y - hh};
    t.box.max = {c.x + hw, c.y + hh};
    const auto k = t.corners();
    const Region r = t.angle == 0.0 ? rectangle(t.box) : polygon({k.begin(), k.end()});
    if (r.subtract(region).empty()) {
      out.box = t.box;
      out.area = t.box.width() * t.box.height();
      out.verified = true;
      return;
    }
  }
}

// An upper bound of the squared diameter of a loop: the farthest pair of a
// polyline within `tolerance` of the curves, plus twice the tolerance.
double squared_diameter_bound(const Loop& loop) {
  const Box b = loop.bbox();
  const double tolerance = 1e-6 * std::max(b.width(), b.height());
  std::vector<Point> p = loop.polyline(tolerance);
  // The farthest pair is a pair of convex-hull vertices (Andrew's monotone chain).
  std::sort(p.begin(), p.end(), [](Point u, Point v) { return u.x < v.x || (u.x == v.x && u.y < v.y); });
  std::vector<Point> hull;
  for (int pass = 0; pass < 2; ++pass) {
    const std::size_t base = hull.size();
    for (const Point& q : p) {
      while (hull.size() >= base + 2 && cross(hull.back() - hull[hull.size() - 2], q - hull[hull.size() - 2]) <= 0.0) {
        hull.pop_back();
      }
      hull.push_back(q);
    }
    hull.pop_back();
    std::reverse(p.begin(), p.end());
  }
  double far = 0.0;
  for (std::size_t i = 0; i < hull.size(); ++i) {
    for (std::size_t j = i + 1; j < hull.size(); ++j) far = std::max(far, norm(hull[i] - hull[j]));
  }
  far = far * (1.0 + 1e-12) + 2.0 * tolerance;
  return far * far;
}

// The component turned by `angle` (radians, counter-clockwise) about the origin.
Component turned(const Component& c, double angle) {
  const double cs = std::cos(angle), sn = std::sin(angle);
  const auto turn = [&](Point p) { return Point{cs * p.x - sn * p.y, sn * p.x + cs * p.y}; };
  const auto turn_loop = [&](const Loop& l) {
    Loop out = l;
    for (Curve& k : out.curves) {
      k.source = turn(k.source);
      k.target = turn(k.target);
      k.center = turn(k.center);
    }
    return out;
  };
  Component out;
  out.outer = turn_loop(c.outer);
  for (const Loop& h : c.holes) out.holes.push_back(turn_loop(h));
  out.area = c.area;
  out.perimeter = c.perimeter;
  out.centroid = turn(c.centroid);
  out.bbox = out.outer.bbox();
  return out;
}

// Branch and bound over the angle. An interval of angles [m - d, m + d] is
// bounded by one axis-aligned search of the component turned by -m: a
// rectangle inside at an angle within d of m, with half sides a >= b,
// contains the rectangle at angle m with the same centre and aspect scaled by
// 1 / (cos d + (a / b) sin d), so its area is at most that search's upper
// bound times (cos d + rho sin d)^2, rho >= a / b. For a given aspect k,
// rho = max(k, 1 / k); for a free aspect only rectangles larger than the best
// found matter, and a^2 + b^2 <= D^2 / 4 (D the diameter) with 4ab > best
// gives a / b <= D^2 / best.
InscribedRectangle search_any_angle(const Component& component, double precision, RectangleShape shape,
                                    std::size_t max_evaluations) {
  const double pi = std::numbers::pi;
  const bool free_aspect = shape.kind == RectangleShape::Kind::free;
  // A free rectangle turned by pi/2 is one of the same set; one of aspect k
  // turned by pi/2 has aspect 1/k.
  const double period = free_aspect ? 0.5 * pi : pi;
  const double diameter2 = squared_diameter_bound(component.outer);
  InscribedRectangle best;
  std::size_t evaluations = 0, orientations = 0;
  const auto rho = [&]() {
    if (!free_aspect) return std::max(shape.value, 1.0 / shape.value);
    // a / b + b / a = (a^2 + b^2) / (ab) <= q = D^2 / best: a / b is at most
    // the larger root of r^2 - q r + 1.
    const double q = best.area > 0.0 ? diameter2 / best.area : std::numeric_limits<double>::infinity();
    return q >= 2.0 ? 0.5 * (q + std::sqrt((q - 2.0) * (q + 2.0))) : 1.0;
  };
  const auto factor = [&](double d) {
    if (d == 0.0) return 1.0;
    const double f = std::cos(d) + rho() * std::sin(d);
    return std::isfinite(f) ? f * f : std::numeric_limits<double>::infinity();
  };
  // The axis-aligned search at angle m; its precision need not beat the
  // interval's own bound factor, and it may stop once its bound shows the
  // interval cannot beat the best so far.
  const auto search_at = [&](double m, double d) {
    const Component t = turned(component, -m);
    const Prepared prepared(t);
    const double f = factor(d);
    const double local = std::clamp(0.25 * (f - 1.0), 0.25 * precision, 1e-2);
    const double stop_below = std::isfinite(f) ? best.area / f : 0.0;
    const std::size_t budget = max_evaluations > evaluations ? max_evaluations - evaluations : 1;
    InscribedRectangle r = search_free_or_aspect(Search(prepared, shape), local, budget, stop_below);
    evaluations += r.evaluations;
    ++orientations;
    r.angle = m;
    if (r.area > best.area) best = r;
    return r.area_upper;
  };
  struct Turn {
    double m, d, upper_mid, upper;
  };
  auto lower_ub = [](const Turn& a, const Turn& b) { return a.upper < b.upper; };
  std::priority_queue<Turn, std::vector<Turn>, decltype(lower_ub)> queue(lower_ub);
  // Intervals centred on k period / 16 (half-widths pi / 64 or pi / 32), cut
  // in three so that every centre, angle 0 among them, is searched again
  // with each refinement.
  constexpr int kStart = 16;
  std::vector<Turn> start;
  for (int i = 0; i < kStart; ++i) {
    const double d = 0.5 * period / kStart;
    start.push_back({2 * i * d, d, 0.0, 0.0});
  }
  for (Turn& t : start) t.upper_mid = search_at(t.m, t.d);
  for (Turn& t : start) {  // bounds once the best of the first searches is known
    t.upper = t.upper_mid * factor(t.d);
    if (t.upper > best.area) queue.push(t);
  }
  while (!queue.empty()) {
    const Turn top = queue.top();
    if (top.upper <= best.area || (top.upper - best.area) <= precision * top.upper) break;
    if (evaluations >= max_evaluations) break;
    queue.pop();
    for (double side : {-2.0, 0.0, 2.0}) {
      Turn h{top.m + side * top.d / 3.0, top.d / 3.0, 0.0, 0.0};
      h.upper_mid = search_at(h.m, h.d);
      // The parent's bound covers the half too (and is the better one when
      // the budget ran out inside this search).
      h.upper = std::min(top.upper, h.upper_mid * factor(h.d));
      if (h.upper > best.area) queue.push(h);
    }
  }
  best.area_upper = queue.empty() ? best.area : std::max(best.area, queue.top().upper);
  best.evaluations = evaluations;
  best.orientations = orientations;
  // The angle in [0, period): turning the rectangle's frame by the period
  // keeps the set (a free rectangle's sides swap).
  if (best.angle < 0.0 || best.angle >= period) {
    const double k = std::floor(best.angle / period);
    const double a = best.angle - k * period;
    // Rotate the box in the frame so that the same rectangle is described at angle a.
    const double turn = best.angle - a;  // a multiple of the period
    const int quarter = static_cast<int>(std::lround(turn / (0.5 * pi))) & 3;
    Box b = best.box;
    for (int q = 0; q < quarter; ++q) b = Box{{-b.max.y, b.min.x}, {-b.min.y, b.max.x}};  // R(pi/2) b
    best.box = b;
    best.angle = a < period ? a : 0.0;  // a == period: -angle was a rounding of 0
  }
  return best;
}

}  // namespace

FreeInterval free_interval(const Component& component, double x0, double x1, double slack) {
  return free_interval(Prepared(component), x0, x1, slack);
}

namespace {

FreeInterval free_interval(const Prepared& prepared, double x0, double x1, double slack) {
  const double a = x0 + slack, b = x1 - slack;
  const Box& bb = prepared.bbox;
  if (a > b) return {bb.min.y, bb.max.y};  // thinner than the rounding: no constraint in x
  thread_local std::vector<YRange> blocked;  // reused: this runs ~1e5 times per search
  blocked.clear();
  for (const Piece& p : prepared.pieces) {
    if (p.p1.x < a || p.p0.x > b) continue;
    if (p.p0.x == p.p1.x) {  // vertical segment
      blocked.push_back({std::min(p.p0.y, p.p1.y), std::max(p.p0.y, p.p1.y)});
    } else if (auto r = clip_piece(p, a, b)) {
      blocked.push_back(*r);
    }
  }
  for (YRange& r : blocked) {
    // Shorter by the slack at both ends, but never gone: even a point (a
    // horizontal edge) separates the free gaps above and below it.
    if (r.hi - r.lo > 2 * slack) {
      r.lo += slack;
      r.hi -= slack;
    } else {
      r.lo = r.hi = 0.5 * (r.lo + r.hi);
    }
  }
  std::sort(blocked.begin(), blocked.end(), [](const YRange& p, const YRange& q) { return p.lo < q.lo; });
  FreeInterval best;
  double reach = -std::numeric_limits<double>::infinity();
  const double xm = 0.5 * (x0 + x1);
  for (const YRange& r : blocked) {
    // The open gap (reach, r.lo) meets no boundary: the strip over it lies
    // wholly inside or wholly outside the component.
    if (r.lo > reach && std::isfinite(reach) && r.lo - reach > best.length() &&
        prepared.boundary.inside({xm, 0.5 * (reach + r.lo)})) {
      best = {reach, r.lo};
    }
    reach = std::max(reach, r.hi);
  }
  return best;
}

}  // namespace

std::array<Point, 4> InscribedRectangle::corners() const {
  const double c = std::cos(angle), s = std::sin(angle);
  const auto turn = [&](double x, double y) { return Point{c * x - s * y, s * x + c * y}; };
  return {turn(box.min.x, box.min.y), turn(box.max.x, box.min.y), turn(box.max.x, box.max.y),
          turn(box.min.x, box.max.y)};
}

InscribedRectangle largest_inscribed_rectangle(const Component& component, double precision, RectangleShape shape,
                                               const Region* region, std::size_t max_evaluations) {
  check_arguments(precision, shape);
  if (component.outer.curves.empty()) return {};
  const Prepared prepared(component);
  InscribedRectangle out = shape.kind == RectangleShape::Kind::width
                               ? search_width(prepared, shape.value, precision, max_evaluations)
                               : search_free_or_aspect(Search(prepared, shape), precision, max_evaluations);
  if (region != nullptr) verify(out, *region);
  return out;
}

InscribedRectangle largest_inscribed_rectangle_any_angle(const Component& component, double precision,
                                                         RectangleShape shape, const Region* region,
                                                         std::size_t max_evaluations) {
  check_arguments(precision, shape);
  if (shape.kind == RectangleShape::Kind::width) {
    throw std::invalid_argument("inscribed rectangle: a given width needs a fixed orientation");
  }
  if (component.outer.curves.empty()) return {};
  InscribedRectangle out = search_any_angle(component, precision, shape, max_evaluations);
  if (region != nullptr) verify(out, *region);
  return out;
}

TaskFit fit(const Region& region, const std::vector<Point>& polygon, double precision) {
  if (polygon.size() < 3) throw std::invalid_argument("task polygon: needs at least 3 vertices");
  if (!(precision > 0.0) || !std::isfinite(precision)) {
    throw std::invalid_argument("task polygon: precision must be positive");
  }
  const Region task = geometry::polygon(polygon);
  const Region outside = task.subtract(region);
  TaskFit f;
  f.inside = outside.empty();
  f.area_outside = outside.area();
  const std::vector<Loop> loops = region.loops();
  Box pb;
  for (const Point& p : polygon) pb.expand(p);
  if (f.inside) {
    double d = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
      for (const Loop& l : loops) {
        for (const Curve& c : l.curves) d = std::min(d, segment_distance(polygon[j], polygon[i], c));
      }
    }
    f.margin = d;
    f.margin_error = 1e-12 * scale_of(pb);
    return f;
  }
  std::vector<Box> domains;
  const double slack = 1e-12 * scale_of(pb);  // the boxes' double rounding
  for (const Component& c : outside.components()) {
    domains.push_back({{c.bbox.min.x - slack, c.bbox.min.y - slack}, {c.bbox.max.x + slack, c.bbox.max.y + slack}});
  }
  const auto [far, err] = farthest_outside(region, loops, polygon, domains, precision * scale_of(pb));
  f.margin = -far;
  f.margin_error = err;
  return f;
}

}  // namespace pkmws::geometry
