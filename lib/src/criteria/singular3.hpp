// The singular values of a 3x3 Jacobian as fields (private; included by the
// modules' criteria.cpp only). Written for the three-actuator platforms at a
// fixed orientation, whose dq/dx' (x' = (x, y, L phi), L the characteristic
// length) has rows rational in the platform point.
//
// The squared singular values λ_1 >= λ_2 >= λ_3 >= 0 of M are the roots of
//   p(μ) = det(μ I - MᵀM) = μ³ - c_2 μ² + c_1 μ - c_0,
//   c_2 = |M|_F², c_1 = Σ (2x2 minors of M)² (Cauchy-Binet), c_0 = det(M)²,
// polynomials in the entries of M. The largest and the smallest root are
// evaluated for every arithmetic of certified/template_field.hpp:
//  * double: the trigonometric form of the cubic's roots, polished by Newton;
//  * Interval (over a box, the coefficients enclosing their values there): a
//    root is enclosed by sign tests of p with interval coefficients at two
//    points (p(U) > 0, p'(U) > 0, p''(U) > 0 puts every root below U; p(L) < 0
//    puts a root above L; mirrored for the smallest root), widening around the
//    centre's root, with λ_1 ∈ [c_2 / 3, c_2] and λ_3 ∈ [0, c_2 / 3] as the
//    fallback (true for every positive semi-definite matrix);
//  * jets and gradients: implicit differentiation of p(λ(x, y); x, y) = 0,
//    λ_x = -p_x / p_μ, λ_xx = -(p_xx + 2 p_μx λ_x + p_μμ λ_x²) / p_μ, ...
//    With λ and the coefficients' jets enclosed over a box, these formulas
//    enclose the derivatives over the box (each is the formula at the true
//    values, which lie in the enclosures). They need a simple root, p_μ ≠ 0:
//    `simple_roots` checks it over a box (the fields' smooth domain).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <tuple>
#include <type_traits>
#include <utility>

#include "pkmws/certified/cell_region.hpp"
#include "pkmws/certified/interval.hpp"

namespace pkmws::criteria::detail {

// Coefficients of p(μ) = μ³ - c2 μ² + c1 μ - c0.
template <class T> struct Cubic {
  T c2, c1, c0;
};

// The invariants of MᵀM for M with rows m_j = a_j / sqrt(w_j) (w_j > 0: the
// rows' weights, e.g. ρ_j⁴ for a leg angle; none: unit weights), without
// square roots:
//   c_2 = Σ |a_j|² / w_j, c_1 = Σ_{i<j} |a_i x a_j|² / (w_i w_j), c_0 = det(A)² / (w_0 w_1 w_2).
template <class T> Cubic<T> gram_invariants_weighted(const T (&a)[3][3], const T (*w)[3]) {
  using certified::sqr;
  const auto row = [&](int j) {
    const T n = sqr(a[j][0]) + sqr(a[j][1]) + sqr(a[j][2]);
    return w ? n / (*w)[j] : n;
  };
  T c2 = row(0);
  for (int j = 1; j < 3; ++j) c2 = c2 + row(j);
  T c1 = T(0.0);
  T cof[3];  // a_1 x a_2: the cofactors of row 0
  for (int i = 0; i < 3; ++i) {
    for (int j = i + 1; j < 3; ++j) {
      const T w0 = a[i][1] * a[j][2] - a[i][2] * a[j][1];
      const T w1 = a[i][2] * a[j][0] - a[i][0] * a[j][2];
      const T w2 = a[i][0] * a[j][1] - a[i][1] * a[j][0];
      const T n = sqr(w0) + sqr(w1) + sqr(w2);
      c1 = c1 + (w ? n / ((*w)[i] * (*w)[j]) : n);
      if (i == 1) {
        cof[0] = w0;
        cof[1] = w1;
        cof[2] = w2;
      }
    }
  }
  const T det2 = sqr(a[0][0] * cof[0] + a[0][1] * cof[1] + a[0][2] * cof[2]);
  return {c2, c1, w ? det2 / (((*w)[0] * (*w)[1]) * (*w)[2]) : det2};
}
template <class T> Cubic<T> gram_invariants(const T (&a)[3][3], const T (&w)[3]) { return gram_invariants_weighted(a, &w); }
template <class T> Cubic<T> gram_invariants(const T (&a)[3][3]) { return gram_invariants_weighted<T>(a, nullptr); }

inline certified::Interval tighter(const certified::Interval& a, const certified::Interval& b) {
  const certified::Interval both = certified::intersect(a, b);
  return both.lo <= both.hi ? both : a;
}

// The inverted point u = d / |d|² of d = (x - e_x, y - e_y) over a box, as
// gradients or jets (T = Grad<Interval> or Jet<Interval>) with derivatives in
// closed form: w = u_x + i u_y = 1 / conj(z), z = d_x + i d_y, is
// anti-holomorphic, so ∂w/∂x = -w², ∂w/∂y = i w², ∂²w/∂x² = 2w³,
// ∂²w/∂x∂y = -2i w³, ∂²w/∂y² = -2w³. Each is a power of u's enclosure, whose
// width is u's relative width times its size; the product rule through 1/|d|²
// instead adds terms of size |d|⁻⁴ that cancel, and its enclosures of a row's
// Hessian were ten times wider than these (the 3-RPR's rows: leg angles).
// u itself: the natural form, tightened by the mean-value form about the
// box's centre.
template <class T> std::array<T, 2> inverted_point(const certified::Interval& x, const certified::Interval& y, double ex, double ey) {
  using certified::Interval;
  using certified::sqr;
  const auto inverse = [&](const Interval& dx, const Interval& dy) {
    const Interval r2 = sqr(dx) + sqr(dy);
    return std::array<Interval, 2>{dx / r2, dy / r2};
  };
  const double xm = x.mid(), ym = y.mid();
  std::array<Interval, 2> u = inverse(x - Interval(ex), y - Interval(ey));
  const auto square = [](const std::array<Interval, 2>& v) {  // w²
    return std::array<Interval, 2>{sqr(v[0]) - sqr(v[1]), 2.0 * (v[0] * v[1])};
  };
  if (x.width() > 0.0 || y.width() > 0.0) {
    const std::array<Interval, 2> um = inverse(Interval(xm) - Interval(ex), Interval(ym) - Interval(ey));
    const std::array<Interval, 2> w2 = square(u);
    const Interval hx = x - Interval(xm), hy = y - Interval(ym);
    u[0] = tighter(u[0], um[0] - w2[0] * hx - w2[1] * hy);
    u[1] = tighter(u[1], um[1] - w2[1] * hx + w2[0] * hy);
  }
  const std::array<Interval, 2> w2 = square(u);
  if constexpr (std::is_same_v<T, certified::Grad<Interval>>) {
    return {T{u[0], -w2[0], -w2[1]}, T{u[1], -w2[1], w2[0]}};
  } else {
    const Interval w3r = w2[0] * u[0] - w2[1] * u[1], w3i = w2[0] * u[1] + w2[1] * u[0];
    return {T{u[0], -w2[0], -w2[1], twice(w3r), twice(w3i), -twice(w3r)},
            T{u[1], -w2[1], w2[0], twice(w3i), -twice(w3r), -twice(w3i)}};
  }
}

enum class Root { largest, smallest };

template <class S> S cubic_value(const Cubic<S>& c, const S& mu) { return ((mu - c.c2) * mu + c.c1) * mu - c.c0; }
template <class S> S cubic_slope(const Cubic<S>& c, const S& mu) { return (3.0 * mu - 2.0 * c.c2) * mu + c.c1; }
template <class S> S cubic_curvature(const Cubic<S>& c, const S& mu) { return 6.0 * mu - 2.0 * c.c2; }

// Where the search for a root's ends starts (root_start): the centre's root r
// and the first step.
struct RootStart {
  double r = 0.0, first = 0.0;
};

// The cubics of a box: coefficients c enclosed there and, when known, their
// values at the box's centre m and gradients over the box, for p(μ) in its
// mean-value form in (x, y):
//   p(μ; B) ⊆ p(μ; m) + ∂p/∂x(μ; B) dx + ∂p/∂y(μ; B) dy,  ∂p/∂x = -c2_x μ² + c1_x μ - c0_x.
// The coefficients move together (they are invariants of one matrix), and
// their independent enclosures c admit cubics whose roots are far closer than
// any in the box: near λ_1 ≈ λ_2 the sign tests on p(μ) from c alone failed
// where this form decides them.
struct CubicBox {
  Cubic<certified::Interval> c;
  bool has_gradients = false;
  Cubic<certified::Interval> m, gx, gy;
  certified::Interval dx, dy;
  CubicBox(const Cubic<certified::Interval>& coefficients) : c(coefficients) {}  // NOLINT: coefficients alone
  CubicBox(const Cubic<certified::Interval>& coefficients, const Cubic<certified::Interval>& at_centre,
           const Cubic<certified::Interval>& grad_x, const Cubic<certified::Interval>& grad_y, const certified::Interval& ddx,
           const certified::Interval& ddy)
      : c(coefficients), has_gradients(true), m(at_centre), gx(grad_x), gy(grad_y), dx(ddx), dy(ddy) {}
  // The x- and y-slopes of p at μ, times the box's offsets from m.
  certified::Interval moved(const certified::Interval& mu) const {
    const auto slope = [&](const Cubic<certified::Interval>& g) { return (-(g.c2 * mu) + g.c1) * mu - g.c0; };
    return slope(gx) * dx + slope(gy) * dy;
  }
  // Half the width of p(μ) over the box at μ (the coefficients' spread there).
  double spread(double mu) const {
    const double s = 0.5 * (c.c2.width() * mu * mu + c.c1.width() * std::abs(mu) + c.c0.width());
    return has_gradients ? std::min(s, 0.5 * moved(certified::Interval(mu)).width()) : s;
  }
  certified::Interval value(const certified::Interval& mu) const {
    const certified::Interval natural = cubic_value(c, mu);
    if (!has_gradients) return natural;
    return tighter(natural, cubic_value(m, mu) + moved(mu));
  }
  // p'(μ) in the same mean-value form (∂p'/∂x = -2 c2_x μ + c1_x).
  certified::Interval slope(const certified::Interval& mu) const {
    const certified::Interval natural = cubic_slope(c, mu);
    if (!has_gradients) return natural;
    const certified::Interval slope_moved = (gx.c1 - twice(gx.c2 * mu)) * dx + (gy.c1 - twice(gy.c2 * mu)) * dy;
    return tighter(natural, cubic_slope(m, mu) + slope_moved);
  }
  // root_start and root_end of this box, each computed once: a box's roots
  // are asked for several times (each root's enclosure, p' at it, the other
  // root's end for both).
  mutable std::array<bool, 2> has_start{};
  mutable std::array<RootStart, 2> starts{};
  mutable std::array<bool, 4> has_end{};
  mutable std::array<double, 4> ends{};
  mutable bool has_middle = false;  // middle_root, once searched
  mutable certified::Interval middle{0.0, -1.0};  // empty: not proved
};

// The root in double: trigonometric form of the depressed cubic (three real
// roots: p is the characteristic polynomial of a symmetric matrix), then Newton.
inline double cubic_root(Root which, const Cubic<double>& c) {
  const double a = c.c2 / 3.0;
  const double p = c.c1 - c.c2 * a;                                 // <= 0
  const double q = ((-2.0 / 27.0) * c.c2 * c.c2 + c.c1 / 3.0) * c.c2 - c.c0;  // p(a)
  double r = a;
  if (p < 0.0) {
    const double m = 2.0 * std::sqrt(-p / 3.0);
    const double arg = std::clamp(3.0 * q / (p * m), -1.0, 1.0);
    const double theta = std::acos(arg) / 3.0;  // ν_k = m cos(θ - 2πk/3); ν(θ) largest, ν(θ - 2π/3)... smallest
    r = which == Root::largest ? a + m * std::cos(theta) : a + m * std::cos(theta + 2.0 * std::numbers::pi / 3.0);
  }
  if (which == Root::smallest) {
    r = std::max(r, 0.0);
  }
  // Polish (the trigonometric form loses digits of a small root) while Newton
  // lowers |p|: next to a double root p' is about 0 and a step could jump to
  // another root or beyond.
  for (int it = 0; it < 3; ++it) {
    const double d = cubic_slope(c, r);
    if (!(d > 0.0)) break;
    const double value = cubic_value(c, r);
    const double next = r - value / d;
    if (!std::isfinite(next) || !(std::abs(cubic_value(c, next)) < std::abs(value))) break;
    r = next;
  }
  return which == Root::smallest ? std::max(r, 0.0) : r;
}

// The root over a box: every root of every p with coefficients in `c`. Its
// two ends are proved separately, each from the centre's root r outwards by
// steps δ growing 4× (a side that cannot be proved keeps the fallback):
//  * largest, upper end U = r + δ: p(U) > 0, p'(U) > 0, p''(U) > 0 (no root
//    above U: Taylor from U with the monic cube); lower end L = r - δ:
//    p(L) < 0 (a root above L, p growing without bound);
//  * smallest, lower end L: L <= 0, or p(L) < 0, p'(L) > 0, p''(L) < 0 (no
//    root below L); upper end U: p(U) > 0 (a root in (0, U), p(0) = -c_0 <= 0).
// The first step is the root's first-order displacement by the coefficients'
// spread, spread / |p'(r)|, or, where r is (nearly) a double root
// (p'(r) ≈ 0, two singular values about equal), the second-order one,
// sqrt(2 spread / |p''(r)|), or for a triple root (all three equal) the
// third-order one, cbrt(spread): a multiple root moves like a root of the
// coefficients' change, and a first step from spread / |p'| alone would
// start at the fallback's width.
inline RootStart root_start(Root which, const CubicBox& box) {
  const int slot = which == Root::largest ? 0 : 1;
  if (box.has_start[slot]) return box.starts[slot];
  const Cubic<certified::Interval>& c = box.c;
  const double top = c.c2.hi;
  const Cubic<double> mid{c.c2.mid(), c.c1.mid(), c.c0.mid()};
  const double r = cubic_root(which, mid);
  const double slope = std::abs(cubic_slope(mid, r)), curvature = std::abs(cubic_curvature(mid, r));
  // How far the coefficients' spread moves the root, and a floor.
  const double spread = box.spread(r);
  double delta = slope > 0.0 ? spread / slope : top;
  if (curvature > 0.0) delta = std::min(delta, std::sqrt(2.0 * spread / curvature));
  delta = std::min(delta, std::cbrt(spread));  // a triple root (isotropy): the third derivative is 6
  box.starts[slot] = {r, std::max(std::isfinite(delta) ? delta : top, 1e-12 * std::max(top, 1e-300))};
  box.has_start[slot] = true;
  return box.starts[slot];
}

// The first step δ = first·4^k (k < attempts, stopping where `beyond(δ)`) at
// which `proves(δ)` holds, narrowed by two bisections towards the last step
// that failed: the steps grow 4×, and the first that holds may be that much
// wider than needed (a first step that holds, the spread's own estimate, is
// kept). NaN where none holds.
template <class Beyond, class Proves>
double proved_step(double first, int attempts, const Beyond& beyond, const Proves& proves) {
  double delta = first, failed = 0.0;
  for (int attempt = 0; attempt < attempts && !beyond(delta); ++attempt, failed = delta, delta *= 4.0) {
    if (!proves(delta)) continue;
    for (int k = 0; k < 2 && failed > 0.0; ++k) {
      const double mid = 0.5 * (failed + delta);
      if (proves(mid)) delta = mid;
      else failed = mid;
    }
    return delta;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

// One end of the enclosure (upper_end: U, else L), or the fallback's end.
inline double root_end_search(Root which, bool upper_end, const CubicBox& box, const RootStart& start) {
  using certified::Interval;
  const Cubic<Interval>& c = box.c;
  const double top = c.c2.hi;
  const double fallback_end = which == Root::largest ? (upper_end ? top : std::max(0.0, c.c2.lo / 3.0))
                                                     : (upper_end ? std::max(0.0, top / 3.0) : 0.0);
  const double r = start.r;
  const auto proves = [&](double delta) {
    const Interval u(upper_end ? r + delta : r - delta);
    if (which == Root::largest) {
      return upper_end ? box.value(u).lo > 0.0 && cubic_slope(c, u).lo > 0.0 && cubic_curvature(c, u).lo > 0.0
                       : box.value(u).hi < 0.0;
    }
    return upper_end ? box.value(u).lo > 0.0
                     : box.value(u).hi < 0.0 && cubic_slope(c, u).lo > 0.0 && cubic_curvature(c, u).hi < 0.0;
  };
  const auto beyond = [&](double delta) {  // no better than the fallback
    const double at = upper_end ? r + delta : r - delta;
    return upper_end ? at >= fallback_end : at <= fallback_end;
  };
  const double delta = proved_step(start.first, 16, beyond, proves);
  return std::isnan(delta) ? fallback_end : (upper_end ? r + delta : r - delta);
}
// The same, searched once per box and end (CubicBox keeps it).
inline double root_end(Root which, bool upper_end, const CubicBox& box) {
  const int slot = (which == Root::largest ? 0 : 2) + (upper_end ? 1 : 0);
  if (!box.has_end[slot]) {
    box.ends[slot] = root_end_search(which, upper_end, box, root_start(which, box));
    box.has_end[slot] = true;
  }
  return box.ends[slot];
}

inline certified::Interval cubic_root(Root which, const CubicBox& box) {
  using certified::Interval;
  const Cubic<Interval>& c = box.c;
  if (!c.c2.finite() || !c.c1.finite() || !c.c0.finite()) return Interval(0.0, Interval::inf);
  double lo = std::max(root_end(which, false, box), 0.0), hi = root_end(which, true, box);
  // A double root λ_1 = λ_2 leaves λ_1's lower end to the fallback (p > 0 on
  // both sides of it), λ_2 = λ_3 λ_3's upper end. The trace gives them:
  // λ_1 + λ_2 = c_2 - λ_3 with λ_1 >= λ_2, so λ_1 >= (c_2 - λ_3) / 2, and
  // likewise λ_3 <= (c_2 - λ_1) / 2.
  if (which == Root::largest && lo <= c.c2.lo / 3.0) {
    const double l3_hi = root_end(Root::smallest, true, box);
    lo = std::max(lo, ((Interval(c.c2.lo) - Interval(l3_hi)) * Interval(0.5)).lo);
  } else if (which == Root::smallest && hi >= c.c2.hi / 3.0) {
    const double l1_lo = root_end(Root::largest, false, box);
    hi = std::min(hi, ((Interval(c.c2.hi) - Interval(l1_lo)) * Interval(0.5)).hi);
  }
  // Ends that contradict each other cannot come from a family of real-rooted
  // cubics; the enclosure of every positive semi-definite case is kept.
  return lo <= hi ? Interval(lo, hi) : Interval(0.0, std::max(0.0, c.c2.hi));
}

// The middle root λ_2 over a box, [a, b] with u_3 < a < b < l_1 (u_3 λ_3's
// proved upper end, l_1 λ_1's lower end), p(a) > 0 and p(b) < 0: p is positive
// on (λ_3, λ_2) and negative on (λ_2, λ_1), so λ_3 < a < λ_2 < b < λ_1 for every
// cubic of the box. Searched from the centre's λ_2 = c_2 - λ_1 - λ_3 outwards
// like the other roots' ends; empty (lo > hi) where a side is not proved.
inline certified::Interval middle_root(const CubicBox& box) {
  using certified::Interval;
  if (box.has_middle) return box.middle;
  box.has_middle = true;
  const Cubic<Interval>& c = box.c;
  const double u3 = root_end(Root::smallest, true, box), l1 = root_end(Root::largest, false, box);
  if (!(u3 < l1) || !c.c2.finite() || !c.c1.finite() || !c.c0.finite()) return box.middle;
  const Cubic<double> mid{c.c2.mid(), c.c1.mid(), c.c0.mid()};
  const double r = std::clamp(mid.c2 - root_start(Root::largest, box).r - root_start(Root::smallest, box).r, u3, l1);
  const double spread = box.spread(r);
  const double slope = std::abs(cubic_slope(mid, r));
  const double first = std::max(slope > 0.0 ? std::min(spread / slope, l1 - u3) : l1 - u3, 1e-12 * std::max(std::abs(r), 1e-300));
  // One side: the nearest point r ± δ with the sign, inside (u3, l1); NaN
  // where none.
  const auto side = [&](bool upper) {
    const auto proves = [&](double delta) {
      const double at = upper ? r + delta : r - delta;
      if (!(at > u3 && at < l1)) return false;
      const Interval v = box.value(Interval(at));
      return upper ? v.hi < 0.0 : v.lo > 0.0;
    };
    const double delta = proved_step(first, 12, [&](double d) { return !(d < l1 - u3); }, proves);
    return upper ? r + delta : r - delta;
  };
  const double a = side(false), b = side(true);
  if (a < b) box.middle = Interval(a, b);
  return box.middle;
}

// p'(λ) over a box, λ ∈ l the root `which` of every cubic with coefficients
// in c: the natural form, raised by a lower bound from the factorisations
//   p'(λ_1) = (λ_1 - λ_2)(λ_1 - λ_3),  p'(λ_3) = (λ_1 - λ_3)(λ_2 - λ_3)
// and a point that separates the roots (the natural form loses them to
// cancellation: terms of size c_2² for a product that may be far smaller):
//  * λ_1: s < l.lo with p(s) < 0 and s above λ_3's proved upper end u_3 lies
//    between λ_2 and λ_1, so p'(λ_1) >= (l.lo - s)(l.lo - u_3);
//  * λ_3: t > l.hi with p(t) > 0 and t below λ_1's proved lower end l_1 lies
//    between λ_3 and λ_2, so p'(λ_3) >= (l_1 - l.hi)(t - l.hi).
// Over a box with its mean-value form (a CubicBox with gradients), where λ_2
// is enclosed (middle_root), the factorisations themselves with the three
// roots' enclosures bound p' on both sides first.
inline certified::Interval root_slope(Root which, const CubicBox& box, const certified::Interval& l) {
  using certified::Interval;
  const Cubic<Interval>& c = box.c;
  Interval natural = cubic_slope(c, l);
  if (!l.finite() || !c.c2.finite() || !c.c1.finite() || !c.c0.finite()) return natural;
  // The factorisations with λ_2 enclosed: p'(λ_1) = (λ_1 - λ_2)(λ_1 - λ_3),
  // p'(λ_3) = (λ_1 - λ_3)(λ_2 - λ_3), each factor positive where the
  // enclosures are apart. Without cancellation: the natural form's width is
  // of the size of c_2 |λ| |Λ| while these are of the roots' own widths.
  if (box.has_gradients) {
    const Interval m2 = middle_root(box);
    if (m2.lo <= m2.hi) {
      const bool largest = which == Root::largest;
      const Interval l1 = largest ? l : Interval(root_end(Root::largest, false, box), root_end(Root::largest, true, box));
      const Interval l3 = largest ? Interval(std::max(0.0, root_end(Root::smallest, false, box)), root_end(Root::smallest, true, box)) : l;
      const Interval g12 = l1 - m2, g13 = l1 - l3, g23 = m2 - l3;
      if (g13.lo > 0.0 && (largest ? g12.lo > 0.0 : g23.lo > 0.0)) {
        natural = tighter(natural, largest ? g12 * g13 : g13 * g23);
      }
    }
  }
  if (natural.lo > 0.0) return natural;
  const bool largest = which == Root::largest;
  // The other root's proved end, and the gap to this root's end.
  const double other = largest ? root_end(Root::smallest, true, box) : root_end(Root::largest, false, box);
  const double end = largest ? l.lo : l.hi;
  if (!(largest ? other < end : end < other)) return natural;
  for (const double f : {0.5, 0.125, 1.0 / 32.0}) {
    const double at = end + (other - end) * f;  // between the two ends
    const Interval pa = box.value(Interval(at));
    if (largest ? pa.hi < 0.0 : pa.lo > 0.0) {
      const Interval gap_other = largest ? Interval(end) - Interval(other) : Interval(other) - Interval(end);
      const Interval gap_point = largest ? Interval(end) - Interval(at) : Interval(at) - Interval(end);
      const double bound = (gap_other * gap_point).lo;
      return bound > natural.lo ? Interval(bound, std::max(bound, natural.hi)) : natural;
    }
  }
  return natural;
}

// λ over a box with its coefficients there, in second-order centred forms
// (m the box's centre, d = B - m): each coefficient and its first derivatives
//   c(B) ⊆ c(m) + ∇c(m)·d + ½ dᵀ H_c(B) d,   ∇c(B) ⊆ ∇c(m) + H_c(B) d,
// a first enclosure Λ₀ of the root from them, then
//   λ(B) ⊆ λ(m) + ∇λ(m)·d + ½ dᵀ H_λ(B) d
// with ∇λ, H_λ by implicit differentiation (at m, and over B with Λ₀: Taylor's
// theorem along the segment from m, valid when p_μ(Λ₀) excludes 0, i.e. λ is
// smooth over the box). Naive interval arithmetic on the coefficients
// (rational in P, many terms) loses their correlations; these forms are tight
// to second order in the box size.
// (root_jet: pm = p'(λ), enclosed as root_slope does over a box.)
template <class S>
certified::Jet<S> root_jet(const Cubic<certified::Jet<S>>& c, const S& l, const Cubic<S>& v, const S& pm,
                           const S* gx = nullptr, const S* gy = nullptr);
template <class S>
certified::Grad<S> root_jet(const Cubic<certified::Grad<S>>& c, const S& l, const Cubic<S>& v, const S& pm);

struct BoxRoot {
  certified::Interval largest, smallest;  // λ_1, λ_3 (smallest only when asked)
  Cubic<certified::Interval> coefficients;
  Cubic<certified::Interval> dx, dy;  // the coefficients' first derivatives over the box
  certified::Interval slope_largest, slope_smallest;  // p'(λ_1), p'(λ_3) (root_slope)
  // Over a box (not a point): the coefficients' jets there, values and first
  // derivatives as above (the field's jet over the box reuses them).
  Cubic<certified::Jet<certified::Interval>> jets;
  bool has_jets = false;
  // With the jets: the roots' own jets over the box (value the root's jet
  // value, not `largest`; derivatives tightened by root_over_box's rounds).
  certified::Jet<certified::Interval> jet_largest, jet_smallest;
  bool has_jet_largest = false, has_jet_smallest = false;
  const certified::Interval& operator[](Root which) const { return which == Root::largest ? largest : smallest; }
};
// The discriminant of p, Δ = c₂²c₁² − 4c₁³ − 4c₂³c₀ + 18c₂c₁c₀ − 27c₀²
// = Π (λ_i − λ_j)² over the pairs: positive exactly where the three roots are
// distinct. As p′(λ₁)² = Δ / (λ₂ − λ₃)² and p′(λ₃)² = Δ / (λ₁ − λ₂)², with
// both differences in [0, c₂], every root's p′ is at least √Δ / c₂: a bound
// that holds where the roots' enclosures overlap (close roots, the natural
// form and root_slope both fail), if Δ's centred form is positive.
template <class T> T discriminant(const Cubic<T>& c) {
  using certified::sqr;
  const T c21 = c.c2 * c.c1;
  return sqr(c21) - 4.0 * (sqr(c.c1) * c.c1) - 4.0 * ((sqr(c.c2) * c.c2) * c.c0) + 18.0 * (c21 * c.c0) -
         27.0 * sqr(c.c0);
}

// `cubic_of(u, v)`: the coefficients at (u, v) for u, v Interval, Grad<Interval>
// or Jet<Interval>. A point (both widths 0) needs no centred form.
template <class F>
BoxRoot root_over_box(const F& cubic_of, const certified::Interval& x, const certified::Interval& y, bool smallest) {
  using certified::Interval;
  using certified::sqr;
  using J = certified::Jet<Interval>;
  using G = certified::Grad<Interval>;
  BoxRoot out;
  if (x.width() == 0.0 && y.width() == 0.0) {
    const Cubic<G> m = cubic_of(G::variable_x(x), G::variable_y(y));
    out.coefficients = {m.c2.v, m.c1.v, m.c0.v};
    out.dx = {m.c2.dx, m.c1.dx, m.c0.dx};
    out.dy = {m.c2.dy, m.c1.dy, m.c0.dy};
    out.largest = cubic_root(Root::largest, out.coefficients);
    out.slope_largest = root_slope(Root::largest, out.coefficients, out.largest);
    if (smallest) {
      out.smallest = cubic_root(Root::smallest, out.coefficients);
      out.slope_smallest = root_slope(Root::smallest, out.coefficients, out.smallest);
    }
    return out;
  }
  const double xm = x.mid(), ym = y.mid();
  const Interval dx = x - Interval(xm), dy = y - Interval(ym);
  const Interval dx2 = sqr(dx), dxy = dx * dy, dy2 = sqr(dy);
  // At m only the value and the gradient are used: a gradient is a third of a jet.
  const Cubic<G> m = cubic_of(G::variable_x(Interval(xm)), G::variable_y(Interval(ym)));
  const Cubic<J> b = cubic_of(J::variable_x(x), J::variable_y(y));
  // The second-order form of a function with its gradient at m and its jet over B.
  const auto value = [&](const G& at_m, const J& over) {
    return tighter(over.v, at_m.v + at_m.dx * dx + at_m.dy * dy +
                               0.5 * (over.dxx * dx2 + 2.0 * over.dxy * dxy + over.dyy * dy2));
  };
  const auto slope_x = [&](const G& at_m, const J& over) {
    return tighter(over.dx, at_m.dx + over.dxx * dx + over.dxy * dy);
  };
  const auto slope_y = [&](const G& at_m, const J& over) {
    return tighter(over.dy, at_m.dy + over.dxy * dx + over.dyy * dy);
  };
  out.coefficients = {value(m.c2, b.c2), value(m.c1, b.c1), value(m.c0, b.c0)};
  out.dx = {slope_x(m.c2, b.c2), slope_x(m.c1, b.c1), slope_x(m.c0, b.c0)};
  out.dy = {slope_y(m.c2, b.c2), slope_y(m.c1, b.c1), slope_y(m.c0, b.c0)};
  const Cubic<Interval> vm{m.c2.v, m.c1.v, m.c0.v};
  Cubic<J> bt = b;
  for (auto [c, v, gx, gy] : {std::tuple{&bt.c2, out.coefficients.c2, out.dx.c2, out.dy.c2},
                              std::tuple{&bt.c1, out.coefficients.c1, out.dx.c1, out.dy.c1},
                              std::tuple{&bt.c0, out.coefficients.c0, out.dx.c0, out.dy.c0}}) {
    c->v = v;
    c->dx = gx;
    c->dy = gy;
  }
  out.jets = bt;
  out.has_jets = true;
  const CubicBox box(out.coefficients, vm, out.dx, out.dy, dx, dy);
  // p′ over B from Δ's second-order centred form, asked only where
  // root_slope fails (a few multiplications of the jets at hand).
  double discriminant_slope = -1.0;  // not computed yet
  const auto with_discriminant = [&](const Interval& pm) {
    if (!pm.contains_zero() || !(out.coefficients.c2.hi > 0.0)) return pm;
    if (discriminant_slope < 0.0) {
      discriminant_slope = 0.0;
      const Interval d = value(discriminant(m), discriminant(bt));
      if (d.lo > 0.0 && d.finite()) discriminant_slope = (certified::sqrt(Interval(d.lo)) / Interval(out.coefficients.c2.hi)).lo;
    }
    return discriminant_slope > 0.0 ? Interval(std::max(pm.lo, discriminant_slope), std::max(pm.hi, discriminant_slope)) : pm;
  };
  const auto root = [&](Root which) {
    const Interval l0 = cubic_root(which, box);
    const Interval pm = with_discriminant(root_slope(which, box, l0));
    if (pm.contains_zero()) return l0;
    // λ and its gradient at m (thin coefficients), and its Hessian over B.
    const Interval lmv = cubic_root(which, vm);
    const G lm = root_jet(m, lmv, vm, root_slope(which, vm, lmv));
    J rj = root_jet(bt, l0, out.coefficients, pm);  // the jet's value is l0
    Interval l = value(lm, rj);
    // The root's gradient over B in its centred form ∇λ(m) + H_λ(B) d, and
    // H_λ from it again: H_λ's formula is a sum of terms several times its
    // size (p_xx, 2 p_μx λ_x and p_μμ λ_x², over p_μ), so the natural λ_x's
    // width comes back multiplied; a few rounds while they narrow.
    for (int round = 0; round < 2; ++round) {
      const Interval gx = tighter(rj.dx, lm.dx + rj.dxx * dx + rj.dxy * dy);
      const Interval gy = tighter(rj.dy, lm.dy + rj.dxy * dx + rj.dyy * dy);
      const Interval pml = with_discriminant(root_slope(which, box, l));
      if (pml.contains_zero()) break;
      const J next = root_jet(bt, l, out.coefficients, tighter(pml, pm), &gx, &gy);
      const double before = rj.dxx.width() + rj.dyy.width(), after = next.dxx.width() + next.dyy.width();
      rj = next;
      l = value(lm, rj);
      if (!(after < 0.7 * before)) break;
    }
    (which == Root::largest ? out.jet_largest : out.jet_smallest) = rj;
    (which == Root::largest ? out.has_jet_largest : out.has_jet_smallest) = true;
    return l;
  };
  out.largest = root(Root::largest);
  out.slope_largest = with_discriminant(root_slope(Root::largest, box, out.largest));
  if (smallest) {
    out.smallest = root(Root::smallest);
    out.slope_smallest = with_discriminant(root_slope(Root::smallest, box, out.smallest));
  }
  return out;
}

// The parameters that fix a field's cubic (its mechanism's, filled in by the
// field; unused entries 0): with the box, the key of a one-entry cache per
// thread. A cell's tests ask for the same box's roots up to four times (its
// value, its smooth domain, its gradient and its jet), each costing a jet and a
// gradient of the cubic's coefficients.
using CubicKey = std::array<double, 32>;
struct RootCacheEntry {
  bool valid = false, smallest = false;
  CubicKey key{};
  double x0 = 0.0, x1 = 0.0, y0 = 0.0, y1 = 0.0;
  BoxRoot root;
};
// One entry per thread for every field (every lambda type of cubic_of).
inline RootCacheEntry& root_cache() {
  thread_local RootCacheEntry last;
  return last;
}
template <class F>
BoxRoot root_over_box_cached(const CubicKey* key, const F& cubic_of, const certified::Interval& x,
                             const certified::Interval& y, bool smallest) {
  if (!key) return root_over_box(cubic_of, x, y, smallest);
  RootCacheEntry& last = root_cache();
  if (last.valid && (last.smallest || !smallest) && last.x0 == x.lo && last.x1 == x.hi && last.y0 == y.lo &&
      last.y1 == y.hi && last.key == *key) {
    return last.root;
  }
  last.root = root_over_box(cubic_of, x, y, smallest);
  last.valid = true;
  last.smallest = smallest;
  last.key = *key;
  last.x0 = x.lo;
  last.x1 = x.hi;
  last.y0 = y.lo;
  last.y1 = y.hi;
  return last.root;
}

// Implicit differentiation (gradients), the root's value and the coefficients'
// values given (root_over_box over a box; the point values at a point).
template <class S>
certified::Grad<S> root_jet(const Cubic<certified::Grad<S>>& c, const S& l, const Cubic<S>& /*v*/, const S& pm) {
  const S l2 = l * l;
  const S px = (c.c1.dx * l - c.c2.dx * l2) - c.c0.dx;
  const S py = (c.c1.dy * l - c.c2.dy * l2) - c.c0.dy;
  return {l, -(px / pm), -(py / pm)};
}

// Implicit differentiation to second order (jets).
template <class S>
certified::Jet<S> root_jet(const Cubic<certified::Jet<S>>& c, const S& l, const Cubic<S>& v, const S& pm, const S* gx,
                           const S* gy) {
  const S l2 = l * l;
  const S pmm = cubic_curvature(v, l);
  // p_x = -c2_x λ² + c1_x λ - c0_x, p_μx = -2 c2_x λ + c1_x, p_xx = -c2_xx λ² + c1_xx λ - c0_xx.
  const S px = (c.c1.dx * l - c.c2.dx * l2) - c.c0.dx;
  const S py = (c.c1.dy * l - c.c2.dy * l2) - c.c0.dy;
  const S pmx = c.c1.dx - 2.0 * c.c2.dx * l;
  const S pmy = c.c1.dy - 2.0 * c.c2.dy * l;
  const S pxx = (c.c1.dxx * l - c.c2.dxx * l2) - c.c0.dxx;
  const S pxy = (c.c1.dxy * l - c.c2.dxy * l2) - c.c0.dxy;
  const S pyy = (c.c1.dyy * l - c.c2.dyy * l2) - c.c0.dyy;
  S lx = -(px / pm), ly = -(py / pm);
  if constexpr (std::is_same_v<S, certified::Interval>) {
    if (gx) lx = tighter(lx, *gx);
    if (gy) ly = tighter(ly, *gy);
  }
  const S lxx = -((pxx + 2.0 * pmx * lx + pmm * lx * lx) / pm);
  const S lxy = -((pxy + pmx * ly + pmy * lx + pmm * lx * ly) / pm);
  const S lyy = -((pyy + 2.0 * pmy * ly + pmm * ly * ly) / pm);
  return {l, lx, ly, lxx, lxy, lyy};
}

// The value part of an arithmetic (the point or the box).
inline double value_part(double v) { return v; }
inline certified::Interval value_part(const certified::Interval& v) { return v; }
template <class S> S value_part(const certified::Grad<S>& v) { return v.v; }
template <class S> S value_part(const certified::Jet<S>& v) { return v.v; }

template <class T> Cubic<decltype(value_part(std::declval<T>()))> values(const Cubic<T>& c) {
  return {value_part(c.c2), value_part(c.c1), value_part(c.c0)};
}

// Which side of `level` a conditioning field lies on over a box, from the
// signs of p at one or two points chosen from the centre's roots, without
// enclosing the roots (ScalarField::side; tried before every enclosure):
//  * all roots below a: p(a) > 0, p'(a) > 0, p''(a) > 0 (Taylor from a with
//    the monic cube); all above b: p(b) < 0, p'(b) > 0, p''(b) < 0;
//  * a root above a (so λ_1 > a): p(a) < 0 (p grows without bound); a root
//    below b (so λ_3 < b): p(b) > 0 (p(0) = -c_0 <= 0).
// The velocity ratio (F = λ_1): inside where every root is below the level,
// outside where one is above it. The condition number (F = -λ_3/λ_1, level
// -t): inside where the roots lie in (a t, a) for one a, outside where λ_1 > a
// and λ_3 < a t; a leaves both roots equal room in units of their first-order
// spreads over the box (from the centre's gradients). p is enclosed at each
// point in the mean-value form of CubicBox: with the coefficients' gradients
// over the box (root_over_box's second-order forms take the boxes this leaves).
template <class Model>
certified::CellState conditioning_side(const Model& model, const certified::Interval& x, const certified::Interval& y,
                                       bool ratio, double level) {
  using certified::CellState;
  using certified::Interval;
  using G = certified::Grad<Interval>;
  using Gd = certified::Grad<double>;
  const auto cubic = [&model](const auto& u, const auto& v) { return model.jacobian_cubic(u, v); };
  const double xm = x.mid(), ym = y.mid();
  const double t = -level;
  if (ratio && !(t > 0.0 && t < 1.0)) return CellState::undecided;
  // The centre's roots and their first-order spread over the box (in
  // double: they only choose the test point).
  const Cubic<Gd> cg = cubic(Gd::variable_x(xm), Gd::variable_y(ym));
  const Cubic<double> cd = values(cg);
  if (!std::isfinite(cd.c2) || !std::isfinite(cd.c1) || !std::isfinite(cd.c0)) return CellState::undecided;
  const double hx = 0.5 * x.width(), hy = 0.5 * y.width();
  const auto spread = [&](Root which, double& l) {
    l = cubic_root(which, cd);
    const Gd j = root_jet(cg, l, cd, cubic_slope(cd, l));
    return std::abs(j.dx) * hx + std::abs(j.dy) * hy;
  };
  double l1 = 0.0, l3 = 0.0;
  const double d1 = spread(Root::largest, l1);
  double a = level;
  bool inside = l1 <= level;
  if (ratio) {
    const double d3 = spread(Root::smallest, l3);
    // The point a with equal room on both sides in units of the spreads:
    // inside, λ_1 + d1 s = a = (λ_3 - d3 s) / t; outside, λ_1 - d1 s = a = (λ_3 + d3 s) / t.
    inside = l1 * t <= l3;
    const double room = std::abs(l3 / t - l1), per = d1 + d3 / t;
    // (No spread at all: the geometric mean of λ_1 and λ_3 / t.)
    a = per > 0.0 ? (inside ? l1 + d1 * (room / per) : l1 - d1 * (room / per)) : std::sqrt(l1 * l3 / t);
  }
  if (!(a > 0.0) || !std::isfinite(a)) return CellState::undecided;
  const Interval dx = x - Interval(xm), dy = y - Interval(ym);
  const Cubic<Interval> vm = cubic(Interval(xm), Interval(ym));
  Cubic<G> g = cubic(G::variable_x(x), G::variable_y(y));
  for (auto [over, at_m] : {std::pair{&g.c2, vm.c2}, std::pair{&g.c1, vm.c1}, std::pair{&g.c0, vm.c0}}) {
    over->v = tighter(over->v, at_m + over->dx * dx + over->dy * dy);
  }
  const Cubic<Interval> c = values(g);
  if (!c.c2.finite() || !c.c1.finite() || !c.c0.finite()) return CellState::undecided;
  // The tests with p and p' enclosed in the box's mean-value form.
  const CubicBox box(c, vm, {g.c2.dx, g.c1.dx, g.c0.dx}, {g.c2.dy, g.c1.dy, g.c0.dy}, dx, dy);
  const auto value = [&](double mu) { return box.value(Interval(mu)); };
  const auto slope = [&](double mu) { return box.slope(Interval(mu)); };
  const auto curvature = [&](double mu) { return Interval(6.0) * Interval(mu) - twice(c.c2); };
  const auto above_all = [&](double mu) { return value(mu).lo > 0.0 && slope(mu).lo > 0.0 && curvature(mu).lo > 0.0; };
  const auto below_all = [&](double mu) { return value(mu).hi < 0.0 && slope(mu).lo > 0.0 && curvature(mu).hi < 0.0; };
  if (!ratio) {
    if (inside) return above_all(a) ? CellState::inside : CellState::undecided;  // λ_1 < level
    return value(a).hi < 0.0 ? CellState::outside : CellState::undecided;        // λ_1 > level
  }
  const Interval at = Interval(a) * Interval(t);
  if (inside) return above_all(a) && below_all(at.hi) ? CellState::inside : CellState::undecided;  // λ_3 / λ_1 > a t / a
  return value(a).hi < 0.0 && value(at.lo).lo > 0.0 ? CellState::outside : CellState::undecided;  // λ_3 / λ_1 < a t / a
}

// The conditioning fields over a box from the rows' squared norms n_j = |m_j|²
// alone: every row of a square M has σ_min <= |m_j| <= σ_max (m_j = Mᵀe_j),
// so λ_1 >= max_j n_j and λ_3 <= min_j n_j, hence -λ_3/λ_1 >= -min_j n_j / max_j n_j
// (and >= -1). Wide in general, but where one row grows without bound (a
// leg of zero length: the 3-RPR's base joint points, where the roots'
// enclosures fail at every scale) it decides the boxes around it.
inline certified::Interval conditioning_from_rows(const std::array<certified::Interval, 3>& n, bool ratio) {
  using certified::Interval;
  double largest = 0.0, smallest = Interval::inf;
  for (const Interval& r : n) {
    largest = std::max(largest, r.lo);
    smallest = std::min(smallest, r.hi);
  }
  if (!ratio) return {largest, Interval::inf};
  if (!(largest > 0.0) || !std::isfinite(smallest)) return {-1.0, 0.0};
  return {std::max(-1.0, -(Interval(smallest) / Interval(largest)).hi), 0.0};
}

// Whether x and y (gradients or jets over a box) are the plane's coordinates
// themselves: derivatives 1 and 0.
inline bool exactly(const certified::Interval& a, double v) { return a.lo == v && a.hi == v; }
template <class T> bool plain_coordinates(const T& x, const T& y) {
  bool plain = exactly(x.dx, 1.0) && exactly(x.dy, 0.0) && exactly(y.dx, 0.0) && exactly(y.dy, 1.0);
  if constexpr (requires { x.dxx; }) {
    for (const certified::Interval* d : {&x.dxx, &x.dxy, &x.dyy, &y.dxx, &y.dxy, &y.dyy}) plain = plain && exactly(*d, 0.0);
  }
  return plain;
}

// The largest root λ_1 and (when `smallest`) the smallest λ_3 of the cubic
// `cubic_of(x, y)` in arithmetic T (double, Interval, Grad<.>, Jet<.>): over a
// box (interval arithmetics) by root_over_box, with derivatives by implicit
// differentiation.
template <class T, class F>
std::pair<T, T> cubic_roots_field(const F& cubic_of, const T& x, const T& y, bool smallest, const CubicKey* key = nullptr) {
  using S = decltype(value_part(std::declval<T>()));
  std::pair<T, T> out{T(0.0), T(0.0)};
  if constexpr (std::is_same_v<T, certified::Interval>) {
    if (x.width() == 0.0 && y.width() == 0.0) {
      // At a point the value needs no derivatives: plain intervals.
      const Cubic<T> c = cubic_of(x, y);
      return {cubic_root(Root::largest, c), smallest ? cubic_root(Root::smallest, c) : T(0.0)};
    }
  }
  if constexpr (std::is_same_v<S, certified::Interval>) {
    const BoxRoot b = root_over_box_cached(key, cubic_of, value_part(x), value_part(y), smallest);
    if constexpr (std::is_same_v<T, S>) {
      out = {b.largest, b.smallest};
    } else {
      // The coefficients' derivatives: root_over_box's own when x and y are
      // the plane's coordinates (no second evaluation), else evaluated here
      // and tightened by them.
      Cubic<T> c;
      bool reused = false;
      if (plain_coordinates(x, y)) {
        if constexpr (std::is_same_v<T, certified::Grad<S>>) {
          c = {{b.coefficients.c2, b.dx.c2, b.dy.c2}, {b.coefficients.c1, b.dx.c1, b.dy.c1},
               {b.coefficients.c0, b.dx.c0, b.dy.c0}};
          reused = true;
        } else if (b.has_jets) {
          c = b.jets;
          reused = true;
        }
      }
      if (!reused) {
        c = cubic_of(x, y);
        for (auto [mine, gx, gy] : {std::tuple{&c.c2, b.dx.c2, b.dy.c2}, std::tuple{&c.c1, b.dx.c1, b.dy.c1},
                                    std::tuple{&c.c0, b.dx.c0, b.dy.c0}}) {
          mine->dx = tighter(mine->dx, gx);
          mine->dy = tighter(mine->dy, gy);
        }
      }
      // Where root_over_box's rounds tightened a root's gradient (the same
      // coefficients: reused), its Hessian is formed from that gradient.
      const auto jet_of = [&](const S& l, const S& pm, bool known, const certified::Jet<S>& j) {
        if constexpr (std::is_same_v<T, certified::Jet<S>>) {
          if (reused && known) {
            T r = root_jet(c, l, b.coefficients, pm, &j.dx, &j.dy);
            r.dxx = tighter(r.dxx, j.dxx);
            r.dxy = tighter(r.dxy, j.dxy);
            r.dyy = tighter(r.dyy, j.dyy);
            return r;
          }
          return root_jet(c, l, b.coefficients, pm);
        } else {
          T r = root_jet(c, l, b.coefficients, pm);
          if (reused && known) {
            r.dx = tighter(r.dx, j.dx);
            r.dy = tighter(r.dy, j.dy);
          }
          return r;
        }
      };
      out.first = jet_of(b.largest, b.slope_largest, b.has_jet_largest, b.jet_largest);
      if (smallest) out.second = jet_of(b.smallest, b.slope_smallest, b.has_jet_smallest, b.jet_smallest);
    }
  } else {
    const Cubic<T> c = cubic_of(x, y);
    const Cubic<S> v = values(c);
    const S l1 = cubic_root(Root::largest, v);
    if constexpr (std::is_same_v<T, S>) {
      out.first = l1;
      if (smallest) out.second = cubic_root(Root::smallest, v);
    } else {
      out.first = root_jet(c, l1, v, cubic_slope(v, l1));
      if (smallest) {
        const S l3 = cubic_root(Root::smallest, v);
        out.second = root_jet(c, l3, v, cubic_slope(v, l3));
      }
    }
  }
  return out;
}

// Whether the roots used are simple over a box, from the centred enclosures:
// p_μ > 0 at λ_1 (λ_1 > λ_2) and λ_1 > 0, and with `smallest` at λ_3 (λ_3 < λ_2)
// (root_slope).
template <class F>
bool simple_roots_over_box(const F& cubic_of, const certified::Interval& x, const certified::Interval& y,
                           bool smallest, const CubicKey* key = nullptr) {
  const BoxRoot b = root_over_box_cached(key, cubic_of, x, y, smallest);
  return b.largest.lo > 0.0 && b.slope_largest.lo > 0.0 && (!smallest || b.slope_smallest.lo > 0.0);
}

}  // namespace pkmws::criteria::detail
