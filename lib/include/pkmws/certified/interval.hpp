// Interval arithmetic with outward rounding, and second-order jets, for the
// certified cell tests and curve tracing of the level-set module
// (docs/theory/level_sets.md).
//
// Interval: every operation is computed in round-to-nearest and its bounds are
// then moved outwards by |r| 2^-52 + 2^-1074 (at least one ulp). IEEE 754 +, -,
// *, / and sqrt are correctly rounded (error <= 1/2 ulp), so the result
// encloses the exact one at any optimisation level; no rounding-mode switches
// (Boost.Interval's approach) are needed, so the type is safe under -O2 and in
// TBB tasks. Empty intervals do not occur: operations whose argument leaves the
// domain (sqrt of a negative number) clamp to the domain, which is what the
// fields want (they are only evaluated over boxes ∩ their domain, see
// criteria/field.hpp); division by an interval with 0 inside gives the whole line,
// by one with 0 at an end a half-line (the quotient over the nonzero points).
//
// Jet<S>: value, gradient and Hessian of a function of (x, y) by forward
// automatic differentiation, over any scalar S (double for points, Interval for
// boxes: then every component encloses the corresponding derivative over the box).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

namespace pkmws::certified {

struct Interval {
  double lo = 0.0;
  double hi = 0.0;

  Interval() = default;
  constexpr Interval(double v) : lo(v), hi(v) {}  // NOLINT: implicit from a point value
  constexpr Interval(double l, double h) : lo(l), hi(h) {}

  static constexpr double inf = std::numeric_limits<double>::infinity();
  static Interval whole() { return {-inf, inf}; }
  bool contains(double v) const { return lo <= v && v <= hi; }
  bool contains_zero() const { return lo <= 0.0 && 0.0 <= hi; }
  double width() const { return hi - lo; }
  double mid() const { return 0.5 * lo + 0.5 * hi; }
  double mag() const { return std::max(std::abs(lo), std::abs(hi)); }  // max |x|
  double mig() const { return contains_zero() ? 0.0 : std::min(std::abs(lo), std::abs(hi)); }  // min |x|
  bool finite() const { return std::isfinite(lo) && std::isfinite(hi); }
};

namespace interval_detail {
// r - (|r| 2^-52 + 2^-1074) rounds to a double <= r - ulp(r)/2 for every finite
// r (|r| 2^-52 is at least one ulp of r; the tiny term covers subnormals).
// NaN (from 0 * inf or inf - inf) widens to the whole line.
inline double down(double v) {
  const double d = v - (std::abs(v) * 0x1p-52 + 0x1p-1074);
  return d == d ? d : (v == v ? v : -Interval::inf);
}
inline double up(double v) {
  const double d = v + (std::abs(v) * 0x1p-52 + 0x1p-1074);
  return d == d ? d : (v == v ? v : Interval::inf);
}
inline Interval out(double l, double h) { return {down(l), up(h)}; }
}  // namespace interval_detail

inline Interval hull(const Interval& a, const Interval& b) { return {std::min(a.lo, b.lo), std::max(a.hi, b.hi)}; }
inline Interval intersect(const Interval& a, const Interval& b) { return {std::max(a.lo, b.lo), std::min(a.hi, b.hi)}; }

inline Interval operator+(const Interval& a, const Interval& b) { return interval_detail::out(a.lo + b.lo, a.hi + b.hi); }
inline Interval operator-(const Interval& a, const Interval& b) { return interval_detail::out(a.lo - b.hi, a.hi - b.lo); }
inline Interval operator-(const Interval& a) { return {-a.hi, -a.lo}; }
[[gnu::always_inline]] inline Interval operator*(const Interval& a, const Interval& b) {
  double lo, hi;
  // An exact zero times any set of reals is {0} (also where the other factor
  // is unbounded, which 0 * inf would widen to the whole line): the structural
  // zeros of jets (derivatives of constants, of x in y) cost nothing.
  if ((a.lo == 0.0 && a.hi == 0.0) || (b.lo == 0.0 && b.hi == 0.0)) return {0.0, 0.0};
  if (a.lo >= 0.0) {
    if (b.lo >= 0.0) { lo = a.lo * b.lo; hi = a.hi * b.hi; }
    else if (b.hi <= 0.0) { lo = a.hi * b.lo; hi = a.lo * b.hi; }
    else { lo = a.hi * b.lo; hi = a.hi * b.hi; }
  } else if (a.hi <= 0.0) {
    if (b.lo >= 0.0) { lo = a.lo * b.hi; hi = a.hi * b.lo; }
    else if (b.hi <= 0.0) { lo = a.hi * b.hi; hi = a.lo * b.lo; }
    else { lo = a.lo * b.hi; hi = a.lo * b.lo; }
  } else {
    if (b.lo >= 0.0) { lo = a.lo * b.hi; hi = a.hi * b.hi; }
    else if (b.hi <= 0.0) { lo = a.hi * b.lo; hi = a.lo * b.lo; }
    else {
      lo = std::min(a.lo * b.hi, a.hi * b.lo);
      hi = std::max(a.lo * b.lo, a.hi * b.hi);
    }
  }
  return interval_detail::out(lo, hi);  // NaN from 0 * inf widens to infinity
}
inline Interval operator/(const Interval& a, const Interval& b) {
  // 1/b over b's nonzero points: a half-line when 0 is an end of b (the
  // quotient grows without bound towards it), the whole line when 0 is inside.
  if (b.lo == 0.0 && b.hi > 0.0) return a * Interval(interval_detail::down(1.0 / b.hi), Interval::inf);
  if (b.hi == 0.0 && b.lo < 0.0) return a * Interval(-Interval::inf, interval_detail::up(1.0 / b.lo));
  if (b.contains_zero()) return Interval::whole();
  const Interval r{1.0 / b.hi, 1.0 / b.lo};
  return a * interval_detail::out(r.lo, r.hi);
}
inline Interval& operator+=(Interval& a, const Interval& b) { return a = a + b; }
inline Interval& operator-=(Interval& a, const Interval& b) { return a = a - b; }
inline Interval& operator*=(Interval& a, const Interval& b) { return a = a * b; }

/// 2x, exact (a power of two scales without rounding; an overflow gives the
/// infinite end, which still encloses).
inline Interval twice(const Interval& a) { return {2.0 * a.lo, 2.0 * a.hi}; }

/// x², tight (never negative).
inline Interval sqr(const Interval& a) {
  const double l = a.mig(), h = a.mag();
  return {a.contains_zero() ? 0.0 : std::max(0.0, interval_detail::down(l * l)), interval_detail::up(h * h)};
}
/// sqrt of the part of `a` in [0, inf).
inline Interval sqrt(const Interval& a) {
  const double l = std::max(0.0, a.lo), h = std::max(0.0, a.hi);
  return {l == 0.0 ? 0.0 : std::max(0.0, interval_detail::down(std::sqrt(l))), h == 0.0 ? 0.0 : interval_detail::up(std::sqrt(h))};
}
inline Interval abs(const Interval& a) { return {a.mig(), a.mag()}; }
inline Interval max(const Interval& a, double v) { return {std::max(a.lo, v), std::max(a.hi, v)}; }
inline Interval clamp(const Interval& a, double l, double h) {
  return {std::clamp(a.lo, l, h), std::clamp(a.hi, l, h)};
}

namespace interval_detail {
// cos or sin (f) over an interval: the end values (glibc's cos and sin are
// within 1 ulp; widened by 2 ulps), and 1 / -1 where a maximum (θ = 2π(k + m))
// / minimum (θ = 2π(k + m + 1/2)) lies inside, tested with a margin (an
// extremum next to an end is then taken: that only widens).
inline Interval periodic(const Interval& a, double (*f)(double), double m) {
  constexpr double two_pi = 6.283185307179586, slack = 1e-12;
  if (!(a.width() < 6.0)) return {-1.0, 1.0};
  auto widen = [](double v, int dir) { return v + dir * (std::abs(v) * 0x1p-51 + 0x1p-1000); };
  const double f0 = f(a.lo), f1 = f(a.hi);
  double lo = widen(std::min(f0, f1), -1), hi = widen(std::max(f0, f1), 1);
  const auto reached = [&](double phase) {
    return std::ceil((a.lo - slack) / two_pi - phase) <= std::floor((a.hi + slack) / two_pi - phase);
  };
  if (reached(m)) hi = 1.0;
  if (reached(m + 0.5)) lo = -1.0;
  return {std::max(lo, -1.0), std::min(hi, 1.0)};
}
}  // namespace interval_detail

/// cos and sin over an interval, for the charts of the level sets (angles
/// about a base joint).
inline Interval cos(const Interval& a) { return interval_detail::periodic(a, [](double x) { return std::cos(x); }, 0.0); }
inline Interval sin(const Interval& a) { return interval_detail::periodic(a, [](double x) { return std::sin(x); }, 0.25); }

// Point counterparts, so that fields are written once for both scalar types.
inline double sqr(double a) { return a * a; }
inline double twice(double a) { return 2.0 * a; }
inline double clamp(double a, double l, double h) { return std::clamp(a, l, h); }
inline double max(double a, double v) { return std::max(a, v); }

/// f, ∂f/∂x, ∂f/∂y, ∂²f/∂x², ∂²f/∂x∂y, ∂²f/∂y² at a point or over a box.
template <class S>
struct Jet {
  S v{}, dx{}, dy{}, dxx{}, dxy{}, dyy{};
  Jet() = default;
  Jet(double c) : v(c), dx(0.0), dy(0.0), dxx(0.0), dxy(0.0), dyy(0.0) {}  // NOLINT: constants
  Jet(S value, S gx, S gy, S hxx, S hxy, S hyy) : v(value), dx(gx), dy(gy), dxx(hxx), dxy(hxy), dyy(hyy) {}
  static Jet variable_x(S x) { return {x, S(1.0), S(0.0), S(0.0), S(0.0), S(0.0)}; }
  static Jet variable_y(S y) { return {y, S(0.0), S(1.0), S(0.0), S(0.0), S(0.0)}; }
};

template <class S> Jet<S> operator+(const Jet<S>& a, const Jet<S>& b) {
  return {a.v + b.v, a.dx + b.dx, a.dy + b.dy, a.dxx + b.dxx, a.dxy + b.dxy, a.dyy + b.dyy};
}
template <class S> Jet<S> operator-(const Jet<S>& a, const Jet<S>& b) {
  return {a.v - b.v, a.dx - b.dx, a.dy - b.dy, a.dxx - b.dxx, a.dxy - b.dxy, a.dyy - b.dyy};
}
template <class S> Jet<S> operator-(const Jet<S>& a) { return {-a.v, -a.dx, -a.dy, -a.dxx, -a.dxy, -a.dyy}; }
template <class S> Jet<S> operator*(const Jet<S>& a, const Jet<S>& b) {
  return {a.v * b.v,
          a.dx * b.v + a.v * b.dx,
          a.dy * b.v + a.v * b.dy,
          a.dxx * b.v + twice(a.dx * b.dx) + a.v * b.dxx,
          a.dxy * b.v + a.dx * b.dy + a.dy * b.dx + a.v * b.dxy,
          a.dyy * b.v + twice(a.dy * b.dy) + a.v * b.dyy};
}
// With a constant (a double, or an S: a derived constant enclosed with its
// rounding), only the terms that are not zero.
template <class S> using Const = std::type_identity_t<S>;
template <class S> Jet<S> operator*(const Const<S>& k, const Jet<S>& a) {
  return {k * a.v, k * a.dx, k * a.dy, k * a.dxx, k * a.dxy, k * a.dyy};
}
template <class S> Jet<S> operator*(const Jet<S>& a, const Const<S>& c) { return c * a; }
template <class S> Jet<S> operator+(const Jet<S>& a, const Const<S>& c) { Jet<S> r = a; r.v = a.v + c; return r; }
template <class S> Jet<S> operator+(const Const<S>& c, const Jet<S>& a) { return a + c; }
template <class S> Jet<S> operator-(const Jet<S>& a, const Const<S>& c) { Jet<S> r = a; r.v = a.v - c; return r; }
template <class S> Jet<S> operator-(const Const<S>& c, const Jet<S>& a) { return (-a) + c; }

/// g(a) for a scalar function g with g(a.v) = g0, g'(a.v) = g1, g''(a.v) = g2 (chain rule).
template <class S> Jet<S> compose(const Jet<S>& a, const S& g0, const S& g1, const S& g2) {
  return {g0,
          g1 * a.dx,
          g1 * a.dy,
          g1 * a.dxx + g2 * sqr(a.dx),
          g1 * a.dxy + g2 * (a.dx * a.dy),
          g1 * a.dyy + g2 * sqr(a.dy)};
}
template <class S> Jet<S> sqr(const Jet<S>& a) {
  const S v2 = twice(a.v);
  return {sqr(a.v),           v2 * a.dx, v2 * a.dy, v2 * a.dxx + twice(sqr(a.dx)), v2 * a.dxy + twice(a.dx * a.dy),
          v2 * a.dyy + twice(sqr(a.dy))};
}
template <class S> Jet<S> reciprocal(const Jet<S>& a) {
  const S r = S(1.0) / a.v;
  const S r2 = sqr(r);
  return compose(a, r, -r2, twice(r2 * r));
}
template <class S> Jet<S> operator/(const Jet<S>& a, const Jet<S>& b) { return a * reciprocal(b); }
template <class S> Jet<S> operator/(const Jet<S>& a, const Const<S>& c) { return (S(1.0) / c) * a; }
template <class S> Jet<S> operator/(const Const<S>& c, const Jet<S>& a) { return c * reciprocal(a); }
template <class S> Jet<S> sqrt(const Jet<S>& a) {
  using std::sqrt;
  const S r = sqrt(a.v);
  const S d1 = S(0.5) / r;              // infinite at 0: the derivative does not exist there
  return compose(a, r, d1, -twice(d1 * d1 * d1));  // (sqrt)'' = -1/(4 r^3) = -2 d1^3
}
template <class S> Jet<S> cos(const Jet<S>& a) {
  using std::cos;
  using std::sin;
  const S c = cos(a.v);
  return compose(a, c, -sin(a.v), -c);
}
template <class S> Jet<S> sin(const Jet<S>& a) {
  using std::cos;
  using std::sin;
  const S s = sin(a.v);
  return compose(a, s, cos(a.v), -s);
}
template <class S> Jet<S> max(const Jet<S>& a, double v) {
  Jet<S> r = a;
  r.v = max(a.v, v);
  return r;  // used only to keep radicands non-negative on the domain's boundary
}

/// f, ∂f/∂x, ∂f/∂y only (first-order forward differentiation).
template <class S>
struct Grad {
  S v{}, dx{}, dy{};
  Grad() = default;
  Grad(double c) : v(c), dx(0.0), dy(0.0) {}  // NOLINT: constants
  Grad(S value, S gx, S gy) : v(value), dx(gx), dy(gy) {}
  static Grad variable_x(S x) { return {x, S(1.0), S(0.0)}; }
  static Grad variable_y(S y) { return {y, S(0.0), S(1.0)}; }
};
template <class S> Grad<S> operator+(const Grad<S>& a, const Grad<S>& b) { return {a.v + b.v, a.dx + b.dx, a.dy + b.dy}; }
template <class S> Grad<S> operator-(const Grad<S>& a, const Grad<S>& b) { return {a.v - b.v, a.dx - b.dx, a.dy - b.dy}; }
template <class S> Grad<S> operator-(const Grad<S>& a) { return {-a.v, -a.dx, -a.dy}; }
template <class S> Grad<S> operator*(const Grad<S>& a, const Grad<S>& b) {
  return {a.v * b.v, a.dx * b.v + a.v * b.dx, a.dy * b.v + a.v * b.dy};
}
template <class S> Grad<S> operator*(const Const<S>& k, const Grad<S>& a) { return {k * a.v, k * a.dx, k * a.dy}; }
template <class S> Grad<S> operator*(const Grad<S>& a, const Const<S>& c) { return c * a; }
template <class S> Grad<S> operator+(const Grad<S>& a, const Const<S>& c) { Grad<S> r = a; r.v = a.v + c; return r; }
template <class S> Grad<S> operator+(const Const<S>& c, const Grad<S>& a) { return a + c; }
template <class S> Grad<S> operator-(const Grad<S>& a, const Const<S>& c) { Grad<S> r = a; r.v = a.v - c; return r; }
template <class S> Grad<S> operator-(const Const<S>& c, const Grad<S>& a) { return (-a) + c; }
template <class S> Grad<S> compose(const Grad<S>& a, const S& g0, const S& g1) { return {g0, g1 * a.dx, g1 * a.dy}; }
template <class S> Grad<S> sqr(const Grad<S>& a) { return compose(a, sqr(a.v), twice(a.v)); }
template <class S> Grad<S> reciprocal(const Grad<S>& a) { const S r = S(1.0) / a.v; return compose(a, r, -sqr(r)); }
template <class S> Grad<S> operator/(const Grad<S>& a, const Grad<S>& b) { return a * reciprocal(b); }
template <class S> Grad<S> operator/(const Grad<S>& a, const Const<S>& c) { return (S(1.0) / c) * a; }
template <class S> Grad<S> operator/(const Const<S>& c, const Grad<S>& a) { return c * reciprocal(a); }
template <class S> Grad<S> sqrt(const Grad<S>& a) {
  using std::sqrt;
  const S r = sqrt(a.v);
  return compose(a, r, S(0.5) / r);
}
template <class S> Grad<S> cos(const Grad<S>& a) {
  using std::cos;
  using std::sin;
  return compose(a, cos(a.v), -sin(a.v));
}
template <class S> Grad<S> sin(const Grad<S>& a) {
  using std::cos;
  using std::sin;
  return compose(a, sin(a.v), cos(a.v));
}
template <class S> Grad<S> max(const Grad<S>& a, double v) { Grad<S> r = a; r.v = max(a.v, v); return r; }
inline Grad<double> abs(const Grad<double>& a) { return a.v < 0.0 ? -a : a; }
inline Grad<Interval> abs(const Grad<Interval>& a) {
  if (a.v.lo >= 0.0) return a;
  if (a.v.hi <= 0.0) return -a;
  return {abs(a.v), hull(a.dx, -a.dx), hull(a.dy, -a.dy)};
}

/// |a| for a jet: exact away from 0; over an interval containing 0 the gradient
/// is enclosed by the hull of ±grad and the Hessian is unbounded.
inline Jet<double> abs(const Jet<double>& a) { return a.v < 0.0 ? -a : a; }
inline Jet<Interval> abs(const Jet<Interval>& a) {
  if (a.v.lo >= 0.0) return a;
  if (a.v.hi <= 0.0) return -a;
  const Interval w = Interval::whole();
  return {abs(a.v), hull(a.dx, -a.dx), hull(a.dy, -a.dy), w, w, w};
}

/// The scalar a value type is built on: double or Interval itself, S for
/// Jet<S> and Grad<S> (for constants derived in a field's formulas).
template <class T> struct ScalarOf { using type = T; };
template <class S> struct ScalarOf<Jet<S>> { using type = S; };
template <class S> struct ScalarOf<Grad<S>> { using type = S; };
template <class T> using scalar_t = typename ScalarOf<T>::type;

}  // namespace pkmws::certified
