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

}  // namespace pkmws::criteria::detail

namespace pkmws::criteria {

// The names every module's criterion fields use (their criteria.cpp only).
using certified::CellState;
using certified::Interval;
using certified::Jet;
using detail::deg;
using detail::dist2;
using detail::nan;
using detail::pi;
using geometry::Box;
using geometry::Point;

}  // namespace pkmws::criteria
