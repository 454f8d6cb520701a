// Exact primitive regions (disk, annulus, half-plane, strip, polygon, stadium,
// band, annulus sector). Every input double is an exact rational; directions
// are rational unit vectors, so every arc endpoint lies exactly on its circle.
#include "pkmws/geometry/primitives.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

// GCC 12 at -O2 reports a false -Wmaybe-uninitialized inside CGAL's
// is_simple_2 (Polygon_2_algorithms_impl.h); the warning is not ours.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <CGAL/Polygon_2.h>
#pragma GCC diagnostic pop

#include "detail/cgal_kernel.hpp"

namespace pkmws::geometry {

using detail::Circle;
using detail::CoordNT;
using detail::Curve;
using detail::ExactDirection;
using detail::FT;
using detail::KPoint;
using detail::OnePoint;

namespace {

void require(bool ok, const char* what) {
  if (!ok) throw std::invalid_argument(what);
}

bool finite(double v) { return std::isfinite(v); }
bool finite(Point p) { return std::isfinite(p.x) && std::isfinite(p.y); }

ExactDirection exact(const RationalDirection& d) {
  // u = ((1 - t^2) / (1 + t^2), 2t / (1 + t^2)), then a quarter-turn rotation.
  const FT t(d.t);
  const FT den = FT(1) + t * t;
  const FT x = (FT(1) - t * t) / den;
  const FT y = FT(2) * t / den;
  switch (d.quadrant) {
    case 1: return {-y, x};
    case 2: return {-x, -y};
    case 3: return {y, -x};
    default: return {x, y};
  }
}

ExactDirection exact_direction(double angle) { return exact(rational_direction(angle)); }

KPoint kpoint(Point p) { return KPoint(FT(p.x), FT(p.y)); }
OnePoint one_point(const FT& x, const FT& y) { return OnePoint(CoordNT(x), CoordNT(y)); }
OnePoint one_point(const KPoint& p) { return one_point(p.x(), p.y()); }
KPoint offset(const KPoint& p, const ExactDirection& u, const FT& s) {
  return KPoint(p.x() + s * u.x, p.y() + s * u.y);
}

Curve segment(const KPoint& a, const KPoint& b) { return Curve(a, b); }
Curve arc(const KPoint& center, const FT& squared_radius, const KPoint& from, const KPoint& to,
          bool ccw) {
  return Curve(Circle(center, squared_radius, ccw ? CGAL::COUNTERCLOCKWISE : CGAL::CLOCKWISE),
               one_point(from), one_point(to));
}

// Convex polygon (ccw) clipped by { p : a x + b y + c >= 0 }, exactly.
std::vector<KPoint> clip(const std::vector<KPoint>& poly, const FT& a, const FT& b, const FT& c) {
  std::vector<KPoint> out;
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    const KPoint& p = poly[i];
    const KPoint& q = poly[(i + 1) % n];
    const FT fp = a * p.x() + b * p.y() + c;
    const FT fq = a * q.x() + b * q.y() + c;
    if (!CGAL::is_negative(fp)) out.push_back(p);
    if ((CGAL::is_positive(fp) && CGAL::is_negative(fq)) ||
        (CGAL::is_negative(fp) && CGAL::is_positive(fq))) {
      const FT s = fp / (fp - fq);
      out.emplace_back(p.x() + s * (q.x() - p.x()), p.y() + s * (q.y() - p.y()));
    }
  }
  return out;
}

// Twice the signed area, summed with the exact value forced at every step.
// Polygon_2::area() sums lazily, so a polygon of n vertices builds a
// construction DAG n deep whose exact evaluation recurses n deep: a cell
// region of a few thousand vertices overflowed the stack.
FT twice_signed_area(const std::vector<KPoint>& vertices) {
  FT sum(0);
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const KPoint& p = vertices[i];
    const KPoint& q = vertices[(i + 1) % vertices.size()];
    sum = FT(CGAL::exact(sum + (p.x() * q.y() - q.x() * p.y())));
  }
  return sum;
}

Region polygon_region(const std::vector<KPoint>& vertices) {
  if (vertices.size() < 3) return Region();
  CGAL::Polygon_2<detail::Kernel> pg(vertices.begin(), vertices.end());
  if (!pg.is_simple()) throw std::invalid_argument("polygon is not simple (it self-intersects)");
  if (pg.orientation() == CGAL::COLLINEAR || CGAL::is_zero(twice_signed_area(vertices))) return Region();
  if (pg.orientation() == CGAL::CLOCKWISE) pg.reverse_orientation();
  std::vector<Curve> loop;
  for (auto e = pg.edges_begin(); e != pg.edges_end(); ++e) loop.push_back(segment(e->source(), e->target()));
  return detail::region_from_loop(loop);
}

std::vector<KPoint> box_corners(const Box& b) {
  return {kpoint(b.min), kpoint({b.max.x, b.min.y}), kpoint(b.max), kpoint({b.min.x, b.max.y})};
}

// { p : (p - point) . u >= 0 } as a x + b y + c >= 0.
void half_plane_coefficients(const KPoint& point, const ExactDirection& u, FT& a, FT& b, FT& c) {
  a = u.x;
  b = u.y;
  c = -(u.x * point.x() + u.y * point.y());
}

// The band with its half circles ahead (along +u) of the moving centre, which
// runs from s0 to s1 = s0 + length u.
Region band_ahead(const KPoint& s0, const ExactDirection& u, const FT& length, double r) {
  const ExactDirection n{-u.y, u.x};
  const FT fr(r);
  const FT r2 = fr * fr;
  const KPoint s1 = offset(s0, u, length);
  const KPoint a0 = offset(s0, n, -fr), a1 = offset(s1, n, -fr);
  const KPoint b0 = offset(s0, n, fr), b1 = offset(s1, n, fr);
  return detail::region_from_loop({segment(a0, a1), arc(s1, r2, a1, b1, true), segment(b1, b0),
                                   arc(s0, r2, b0, a0, false)});
}

}  // namespace

RationalDirection rational_direction(double angle) {
  if (!finite(angle)) throw std::invalid_argument("direction angle must be finite");
  const double quarter = std::numbers::pi / 2.0;
  const double k = std::nearbyint(angle / quarter);
  const double rest = angle - k * quarter;  // in [-pi/4, pi/4]
  RationalDirection d;
  d.t = std::tan(rest / 2.0);
  long q = static_cast<long>(k) % 4;
  if (q < 0) q += 4;
  d.quadrant = static_cast<int>(q);
  return d;
}

Point RationalDirection::unit() const {
  const double den = 1.0 + t * t;
  const Point u{(1.0 - t * t) / den, 2.0 * t / den};
  switch (quadrant) {
    case 1: return {-u.y, u.x};
    case 2: return {-u.x, -u.y};
    case 3: return {u.y, -u.x};
    default: return u;
  }
}

double RationalDirection::angle() const {
  return 2.0 * std::atan(t) + quadrant * std::numbers::pi / 2.0;
}

Region disk(Point c, double r) {
  require(finite(c) && finite(r), "disk: non-finite parameter");
  require(r > 0.0, "disk: radius must be positive");
  const FT fr(r);
  return detail::region_from_loop({Curve(Circle(kpoint(c), fr * fr, CGAL::COUNTERCLOCKWISE))});
}

Region annulus(Point c, double r_inner, double r_outer) {
  require(finite(c) && finite(r_inner) && finite(r_outer), "annulus: non-finite parameter");
  require(r_inner >= 0.0 && r_outer > r_inner, "annulus: need 0 <= r_inner < r_outer");
  Region outer = disk(c, r_outer);
  if (r_inner == 0.0) return outer;
  return outer.subtract(disk(c, r_inner));
}

Region half_plane(Point point, double normal_angle, const Box& box) {
  require(finite(point) && !box.empty(), "half_plane: bad point or empty clip box");
  FT a, b, c;
  half_plane_coefficients(kpoint(point), exact_direction(normal_angle), a, b, c);
  return polygon_region(clip(box_corners(box), a, b, c));
}

Region strip(Point point, double normal_angle, double width, const Box& box) {
  require(finite(point) && finite(width) && !box.empty(), "strip: bad parameter");
  require(width > 0.0, "strip: width must be positive");
  const ExactDirection u = exact_direction(normal_angle);
  const KPoint p0 = kpoint(point);
  const KPoint p1 = offset(p0, u, FT(width));
  FT a, b, c;
  half_plane_coefficients(p0, u, a, b, c);
  std::vector<KPoint> poly = clip(box_corners(box), a, b, c);
  half_plane_coefficients(p1, ExactDirection{-u.x, -u.y}, a, b, c);
  return polygon_region(clip(poly, a, b, c));
}

Region polygon(const std::vector<Point>& vertices) {
  std::vector<KPoint> ks;
  for (const Point& p : vertices) {
    require(finite(p), "polygon: non-finite vertex");
    if (ks.empty() || ks.back() != kpoint(p)) ks.push_back(kpoint(p));
  }
  if (ks.size() > 1 && ks.front() == ks.back()) ks.pop_back();
  require(ks.size() >= 3, "polygon: needs at least 3 distinct vertices");
  return polygon_region(ks);
}

Region rectangle(const Box& box) {
  require(finite(box.min) && finite(box.max), "rectangle: non-finite box");
  require(box.min.x < box.max.x && box.min.y < box.max.y, "rectangle: empty box");
  return polygon_region(box_corners(box));
}

Region oriented_rectangle(Point start, double angle, double length, double half_width) {
  require(finite(start) && finite(length) && finite(half_width), "oriented_rectangle: non-finite");
  require(length > 0.0 && half_width > 0.0, "oriented_rectangle: sizes must be positive");
  const ExactDirection u = exact_direction(angle);
  const ExactDirection n{-u.y, u.x};
  const KPoint s0 = kpoint(start);
  const KPoint s1 = offset(s0, u, FT(length));
  const FT h(half_width);
  return polygon_region({offset(s0, n, -h), offset(s1, n, -h), offset(s1, n, h), offset(s0, n, h)});
}

Region stadium(Point a, Point b, double r) {
  require(finite(a) && finite(b) && finite(r), "stadium: non-finite parameter");
  require(r > 0.0, "stadium: radius must be positive");
  if (a == b) return disk(a, r);
  const ExactDirection u = exact_direction(std::atan2(b.y - a.y, b.x - a.x));
  const ExactDirection n{-u.y, u.x};
  const FT fr(r);
  const FT r2 = fr * fr;
  const KPoint ka = kpoint(a), kb = kpoint(b);
  // Corners are exactly on the end circles; the long sides are parallel to b - a.
  const KPoint a_minus = offset(ka, n, -fr), b_minus = offset(kb, n, -fr);
  const KPoint a_plus = offset(ka, n, fr), b_plus = offset(kb, n, fr);
  return detail::region_from_loop({segment(a_minus, b_minus), arc(kb, r2, b_minus, b_plus, true),
                                   segment(b_plus, a_plus), arc(ka, r2, a_plus, a_minus, true)});
}

Region band(Point start, double angle, double length, double r, int side) {
  require(finite(start) && finite(angle) && finite(length) && finite(r), "band: non-finite parameter");
  require(length > 0.0 && r > 0.0, "band: length and radius must be positive");
  require(side == 1 || side == -1, "band: side must be +1 or -1");
  const ExactDirection u = exact_direction(angle);
  const KPoint s0 = kpoint(start);
  const FT len(length);
  if (side == 1) return band_ahead(s0, u, len, r);
  // Half circles behind: the same band traversed from the far end backwards.
  return band_ahead(offset(s0, u, len), ExactDirection{-u.x, -u.y}, len, r);
}

Region annulus_sector(Point c, double r_inner, double r_outer, double angle_from, double sweep) {
  require(finite(c) && finite(r_inner) && finite(r_outer) && finite(angle_from) && finite(sweep),
          "annulus_sector: non-finite parameter");
  require(r_inner >= 0.0 && r_outer > r_inner, "annulus_sector: need 0 <= r_inner < r_outer");
  require(sweep > 0.0 && sweep <= 2.0 * std::numbers::pi, "annulus_sector: sweep must lie in (0, 2 pi]");
  if (sweep == 2.0 * std::numbers::pi) return annulus(c, r_inner, r_outer);
  const ExactDirection u0 = exact_direction(angle_from);
  const ExactDirection u1 = exact_direction(angle_from + sweep);
  const KPoint kc = kpoint(c);
  const FT ro(r_outer), ri(r_inner);
  const KPoint o0 = offset(kc, u0, ro), o1 = offset(kc, u1, ro);
  std::vector<Curve> loop{arc(kc, ro * ro, o0, o1, true)};
  if (r_inner == 0.0) {
    loop.push_back(segment(o1, kc));
    loop.push_back(segment(kc, o0));
  } else {
    const KPoint i0 = offset(kc, u0, ri), i1 = offset(kc, u1, ri);
    loop.push_back(segment(o1, i1));
    loop.push_back(arc(kc, ri * ri, i1, i0, false));
    loop.push_back(segment(i0, o0));
  }
  return detail::region_from_loop(loop);
}

}  // namespace pkmws::geometry
