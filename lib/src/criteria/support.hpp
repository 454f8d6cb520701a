// What the criterion fields of several mechanisms share (private; included by
// the modules' criteria.cpp only).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "pkmws/certified/interval.hpp"
#include "pkmws/certified/template_field.hpp"
#include "pkmws/geometry/types.hpp"

namespace pkmws::criteria::detail {

inline constexpr double pi = std::numbers::pi;
inline constexpr double deg = pi / 180.0;
inline constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// |p - c|² over a box (tight: separable).
inline certified::Interval dist2(const geometry::Box& b, geometry::Point c) {
  return certified::sqr(certified::Interval(b.min.x, b.max.x) - certified::Interval(c.x)) +
         certified::sqr(certified::Interval(b.min.y, b.max.y) - certified::Interval(c.y));
}

// dq/dP of a two-actuator point platform, by rows (m_0, m_1).
template <class T> struct Rows2 {
  T x0, y0, x1, y1;
  T frobenius2() const { return x0 * x0 + y0 * y0 + x1 * x1 + y1 * y1; }  // F = σ_1² + σ_2²
  T det() const { return x0 * y1 - y0 * x1; }                              // ± σ_1 σ_2
};

// σ_max² = (F + sqrt(F² - 4 det²)) / 2: the squared velocity ratio (worst
// direction); C² where the singular values differ (F² - 4 det² > 0).
template <class T> T sigma_max2(const Rows2<T>& m) {
  using certified::max;
  using certified::sqrt;
  using std::sqrt;
  const T f = m.frobenius2(), d = m.det();
  return 0.5 * (f + sqrt(max((f - 2.0 * d) * (f + 2.0 * d), 0.0)));
}

// The condition number κ = σ_1 / σ_2 >= 1 satisfies κ + 1/κ = F / |det|, so
// κ <= t  <=>  -(det / F)² <= -1 / (t + 1/t)²: a surrogate smooth wherever
// F > 0, also across type-2 singularities (det = 0, κ infinite).
template <class T> T kappa_surrogate(const Rows2<T>& m) {
  const T q = m.det() / m.frobenius2();
  return -(q * q);
}
inline double kappa_level(double t) {
  if (!(t >= 1.0)) return -std::numeric_limits<double>::infinity();  // empty: κ >= 1
  const double k = t + 1.0 / t;
  return -1.0 / (k * k);
}

// Whether the singular values of dq/dP differ over a box (σ_max² is C² there).
inline bool distinct_singular_values(const Rows2<certified::Interval>& m) {
  const certified::Interval f = m.frobenius2(), d = m.det();
  return ((f - 2.0 * d) * (f + 2.0 * d)).lo > 0.0;
}

}  // namespace pkmws::criteria::detail

namespace pkmws::criteria {

// The names every module's criterion fields use (their criteria.cpp only).
using certified::CellState;
using certified::Interval;
using certified::Jet;
using detail::deg;
using detail::dist2;
using detail::kappa_level;
using detail::kappa_surrogate;
using detail::Rows2;
using detail::sigma_max2;
using detail::nan;
using detail::pi;
using geometry::Box;
using geometry::Point;

}  // namespace pkmws::criteria
