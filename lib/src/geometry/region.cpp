// Region: booleans, membership and the double boundary of exact polygon sets
// over circle-segment curves (CGAL General_polygon_set_2). One of the two
// translation units that include CGAL's Boolean-set headers.
#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>
#include <stdexcept>

#include "detail/cgal_kernel.hpp"
#include "pkmws/geometry/inscribed.hpp"

namespace pkmws::geometry {

namespace detail {

double to_double_exact(const FT& value) {
  // The lazy number's interval encloses the exact value. When it is within
  // 2^-50 of its magnitude (most coordinates: a few interval operations from
  // the input doubles), its midpoint is within 2^-51 of the value (twice the
  // rounding of a correctly rounded conversion) and the exact value, a chain
  // of GMP rationals, is not computed: forcing it was a fifth of a MOMA
  // design's time. Otherwise the exact value, correctly rounded.
  const CGAL::Interval_nt<false> i = value.approx();
  const double lo = i.inf(), hi = i.sup();
  if (lo == hi) return lo;
  if (std::isfinite(lo) && std::isfinite(hi) && hi - lo <= 0x1p-50 * std::max(std::abs(lo), std::abs(hi))) {
    return lo + (hi - lo) / 2;
  }
  return CGAL::to_double(value.exact());
}

double to_double_exact(const CoordNT& value) {
  const double a0 = to_double_exact(value.a0());
  if (CGAL::is_zero(value.a1()) || CGAL::is_zero(value.root())) return a0;
  // a0 + a1 sqrt(root) with every part rounded once: absolute error a few ulp
  // of max(|a0|, |a1 sqrt(root)|), i.e. ~1e-16 of the mechanism's size.
  const long double a1 = static_cast<long double>(to_double_exact(value.a1()));
  const long double root = static_cast<long double>(to_double_exact(value.root()));
  return static_cast<double>(static_cast<long double>(a0) + a1 * std::sqrt(root));
}

void append_x_monotone(const Curve& curve, std::vector<XCurve>& out) {
  Traits traits;
  std::vector<boost::variant<OnePoint, XCurve>> pieces;
  traits.make_x_monotone_2_object()(curve, std::back_inserter(pieces));
  for (const auto& piece : pieces) {
    if (const XCurve* xc = boost::get<XCurve>(&piece)) out.push_back(*xc);
  }
}

Region make_region(std::vector<PolygonWithHoles> pieces) {
  auto impl = std::make_shared<Region::Impl>();
  impl->pieces = std::move(pieces);
  return Region(std::move(impl));
}

Region region_from_loop(const std::vector<Curve>& loop) {
  std::vector<XCurve> xcurves;
  for (const Curve& c : loop) append_x_monotone(c, xcurves);
  Polygon polygon(xcurves.begin(), xcurves.end());
  std::vector<PolygonWithHoles> pieces;
  pieces.emplace_back(polygon);
  return make_region(std::move(pieces));
}

namespace {

PolygonSet to_set(const Region::Impl& impl) {
  PolygonSet set;  // owns its traits: never shared between threads
  for (const auto& p : impl.pieces) set.insert(p);
  return set;
}

Region from_set(const PolygonSet& set) {
  std::vector<PolygonWithHoles> pieces;
  pieces.reserve(set.number_of_polygons_with_holes());
  set.polygons_with_holes(std::back_inserter(pieces));
  return make_region(std::move(pieces));
}

Point to_point(const OnePoint& p) { return {to_double_exact(p.x()), to_double_exact(p.y())}; }

// Exact tests used to merge consecutive pieces of one supporting curve.
bool same_support(const XCurve& a, const XCurve& b) {
  if (a.is_linear() != b.is_linear()) return false;
  if (a.is_linear()) {
    // Lines a x + b y + c = 0 are the same iff their coefficients are proportional.
    const auto la = a.supporting_line();
    const auto lb = b.supporting_line();
    return la.a() * lb.b() == la.b() * lb.a() && la.a() * lb.c() == la.c() * lb.a() &&
           la.b() * lb.c() == la.c() * lb.b();
  }
  const Circle ca = a.supporting_circle();
  const Circle cb = b.supporting_circle();
  return ca.orientation() == cb.orientation() && ca.center() == cb.center() &&
         ca.squared_radius() == cb.squared_radius();
}

geometry::Curve::Kind kind_of(const XCurve& c) {
  return c.is_linear() ? geometry::Curve::Kind::segment : geometry::Curve::Kind::arc;
}

// Sweep of one x-monotone arc piece. A piece spans at most a half turn, so the
// angle between its endpoints is unambiguous even when they round to one
// double (a piece ~1e-17 long sweeps ~0, not a full turn).
double piece_sweep(const XCurve& x, Point center, bool ccw) {
  const Point s = to_point(x.source()), t = to_point(x.target());
  double d = std::atan2(t.y - center.y, t.x - center.x) - std::atan2(s.y - center.y, s.x - center.x);
  if (ccw) {
    while (d < 0.0) d += 2.0 * std::numbers::pi;
    if (d > 1.5 * std::numbers::pi) d = 0.0;  // rounding below zero of a tiny piece
  } else {
    while (d > 0.0) d -= 2.0 * std::numbers::pi;
    if (d < -1.5 * std::numbers::pi) d = 0.0;
  }
  return d;
}

template <typename CurveIt>
Loop make_loop(CurveIt begin, CurveIt end, bool hole, std::size_t& count) {
  std::vector<XCurve> xs(begin, end);
  count += xs.size();
  Loop loop;
  loop.hole = hole;
  if (xs.empty()) return loop;
  // Start at a piece whose predecessor lies on another support, so that runs
  // on one circle or line are merged whole (unless the loop is one support).
  std::size_t start = 0;
  for (std::size_t i = 0; i < xs.size(); ++i) {
    if (!same_support(xs[(i + xs.size() - 1) % xs.size()], xs[i])) { start = i; break; }
  }
  for (std::size_t k = 0; k < xs.size(); ++k) {
    const XCurve& x = xs[(start + k) % xs.size()];
    if (k > 0 && same_support(xs[(start + k - 1) % xs.size()], x)) {
      geometry::Curve& last = loop.curves.back();
      last.target = to_point(x.target());
      if (last.kind == geometry::Curve::Kind::arc) last.swept += piece_sweep(x, last.center, last.ccw);
      continue;
    }
    geometry::Curve c;
    c.kind = kind_of(x);
    c.source = to_point(x.source());
    c.target = to_point(x.target());
    if (c.kind == geometry::Curve::Kind::arc) {
      const Circle circle = x.supporting_circle();
      c.center = {to_double_exact(circle.center().x()), to_double_exact(circle.center().y())};
      c.radius = std::sqrt(to_double_exact(circle.squared_radius()));
      c.ccw = circle.orientation() == CGAL::COUNTERCLOCKWISE;
      c.swept = piece_sweep(x, c.center, c.ccw);
    }
    loop.curves.push_back(c);
  }
  return loop;
}

// Centroid moments by Green's theorem: A cx = oint x^2/2 dy, A cy = -oint y^2/2 dx,
// relative to the local origin o.
void add_moments(const Loop& loop, Point o, double& mx, double& my) {
  for (const geometry::Curve& c : loop.curves) {
    const Point p = c.source - o;
    const Point q = c.target - o;
    if (c.kind == geometry::Curve::Kind::segment) {
      const Point d = q - p;
      mx += 0.5 * d.y * (p.x * p.x + p.x * d.x + d.x * d.x / 3.0);
      my -= 0.5 * d.x * (p.y * p.y + p.y * d.y + d.y * d.y / 3.0);
    } else {
      const Point m = c.center - o;
      const double r = c.radius;
      const double t0 = std::atan2(c.source.y - c.center.y, c.source.x - c.center.x);
      const double t1 = t0 + c.sweep();
      // x = m.x + r cos t, dy = r cos t dt; y = m.y + r sin t, dx = -r sin t dt.
      auto fx = [&](double t) {
        const double s = std::sin(t);
        return r * (m.x * m.x * s + 2.0 * m.x * r * (t / 2.0 + std::sin(2.0 * t) / 4.0) +
                    r * r * (s - s * s * s / 3.0));
      };
      auto fy = [&](double t) {
        const double co = std::cos(t);
        return r * (-m.y * m.y * co + 2.0 * m.y * r * (t / 2.0 - std::sin(2.0 * t) / 4.0) +
                    r * r * (-co + co * co * co / 3.0));
      };
      mx += 0.5 * (fx(t1) - fx(t0));
      my += 0.5 * (fy(t1) - fy(t0));
    }
  }
}

const std::vector<Component>& cached_components(const Region::Impl& impl) {
  std::call_once(impl.loops_once, [&impl] {
    std::size_t count = 0;
    for (const auto& pwh : impl.pieces) {
      Component comp;
      comp.outer = make_loop(pwh.outer_boundary().curves_begin(),
                             pwh.outer_boundary().curves_end(), false, count);
      for (auto h = pwh.holes_begin(); h != pwh.holes_end(); ++h) {
        comp.holes.push_back(make_loop(h->curves_begin(), h->curves_end(), true, count));
      }
      const Point o = comp.outer.curves.empty() ? Point{} : comp.outer.curves.front().source;
      double area = comp.outer.signed_area();
      double perimeter = comp.outer.perimeter();
      double mx = 0.0, my = 0.0;
      add_moments(comp.outer, o, mx, my);
      for (const Loop& h : comp.holes) {
        area += h.signed_area();
        perimeter += h.perimeter();
        add_moments(h, o, mx, my);
      }
      comp.area = area;
      comp.perimeter = perimeter;
      comp.centroid = area > 0.0 ? Point{o.x + mx / area, o.y + my / area} : o;
      comp.bbox = comp.outer.bbox();
      impl.components.push_back(std::move(comp));
    }
    impl.curve_count = count;
  });
  return impl.components;
}

Region boolean(const Region::Impl& a, const Region::Impl& b, int op) {
  PolygonSet sa = to_set(a);
  const PolygonSet sb = to_set(b);
  switch (op) {
    case 0: sa.join(sb); break;
    case 1: sa.intersection(sb); break;
    case 2: sa.difference(sb); break;
    default: sa.symmetric_difference(sb); break;
  }
  return from_set(sa);
}

}  // namespace
}  // namespace detail

Region::Region() : impl_(std::make_shared<Impl>()) {}
Region::Region(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}
Region::~Region() = default;
Region::Region(const Region&) = default;
Region::Region(Region&&) noexcept = default;
Region& Region::operator=(const Region&) = default;
Region& Region::operator=(Region&&) noexcept = default;

bool Region::empty() const { return impl_->pieces.empty(); }

Region Region::unite(const Region& other) const {
  if (other.empty()) return *this;
  if (empty()) return other;
  return detail::boolean(*impl_, *other.impl_, 0);
}
Region Region::intersect(const Region& other) const {
  if (empty() || other.empty()) return Region();
  return detail::boolean(*impl_, *other.impl_, 1);
}
Region Region::subtract(const Region& other) const {
  if (empty() || other.empty()) return *this;
  return detail::boolean(*impl_, *other.impl_, 2);
}
Region Region::symmetric_difference(const Region& other) const {
  if (other.empty()) return *this;
  if (empty()) return other;
  return detail::boolean(*impl_, *other.impl_, 3);
}

Region Region::unite_all(const std::vector<Region>& regions) {
  std::vector<detail::PolygonWithHoles> all;
  for (const Region& r : regions) {
    all.insert(all.end(), r.impl_->pieces.begin(), r.impl_->pieces.end());
  }
  if (all.empty()) return Region();
  detail::PolygonSet set;
  set.join(all.begin(), all.end());
  return detail::from_set(set);
}

Region Region::symmetric_difference_all(const std::vector<Region>& regions) {
  std::vector<detail::PolygonWithHoles> all;
  for (const Region& r : regions) {
    all.insert(all.end(), r.impl_->pieces.begin(), r.impl_->pieces.end());
  }
  if (all.empty()) return Region();
  detail::PolygonSet set;
  set.symmetric_difference(all.begin(), all.end());
  return detail::from_set(set);
}

double Region::area() const {
  double a = 0.0;
  for (const Component& c : detail::cached_components(*impl_)) a += c.area;
  return a;
}

Box Region::bbox() const {
  Box b;
  for (const Component& c : detail::cached_components(*impl_)) b.expand(c.bbox);
  return b;
}

bool Region::contains(Point p) const {
  if (empty()) return false;
  // Fast path on the cached double boundary (every curve within ~1e-15 of
  // the exact one): a point farther than a safe margin from every loop is
  // decided by even-odd counting; near the boundary the exact set decides.
  const auto& comps = detail::cached_components(*impl_);
  Box box;
  for (const Component& c : comps) box.expand(c.bbox);
  const double margin = 1e-9 * std::max({box.width(), box.height(), std::abs(p.x), std::abs(p.y), 1e-300});
  if (std::isfinite(p.x) && std::isfinite(p.y)) {
    bool near = false, in = false;
    for (const Component& c : comps) {
      if (distance_to_boundary(c, p) <= margin) { near = true; break; }
      in = in || inside(c, p);
    }
    if (!near) return in;
  }
  const detail::PolygonSet set = detail::to_set(*impl_);
  const detail::OnePoint q(detail::CoordNT(detail::FT(p.x)), detail::CoordNT(detail::FT(p.y)));
  return set.oriented_side(q) != CGAL::ON_NEGATIVE_SIDE;
}

std::vector<Component> Region::components(double min_area) const {
  std::vector<Component> out;
  for (const Component& c : detail::cached_components(*impl_)) {
    if (c.area >= min_area) out.push_back(c);
  }
  return out;
}

std::vector<Loop> Region::loops() const {
  std::vector<Loop> out;
  for (const Component& c : detail::cached_components(*impl_)) {
    out.push_back(c.outer);
    out.insert(out.end(), c.holes.begin(), c.holes.end());
  }
  return out;
}

std::size_t Region::curve_count() const {
  detail::cached_components(*impl_);
  return impl_->curve_count;
}

}  // namespace pkmws::geometry
