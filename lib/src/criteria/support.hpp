// What the criterion fields of several mechanisms share (private).
#pragma once

#include <limits>
#include <numbers>

#include "pkmws/certified/interval.hpp"
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

}  // namespace pkmws::criteria::detail
