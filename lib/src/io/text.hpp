// Text helpers shared by the SVG, DXF and chart writers. Private.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "pkmws/io/export.hpp"

namespace pkmws::io::detail {

using io::xml_escape;

/// Pixel coordinates and sizes: two decimals, trailing zeros trimmed
/// ("12.50" -> "12.5", "3.00" -> "3", "-0" -> "0").
inline std::string px(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  std::string s = buf;
  while (!s.empty() && s.back() == '0') s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  if (s == "-0") s = "0";
  return s;
}

/// 1-2-5 step giving at most about `target` intervals over `range`.
inline double nice_step(double range, int target) {
  const double raw = range / std::max(1, target);
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0}) {
    if (m * mag >= raw * (1.0 - 1e-12)) return m * mag;
  }
  return 10.0 * mag;
}

/// Tick label of `value` with the step's decimals and a typographic minus
/// (none for a value that prints as zero).
inline std::string tick_label(double value, double step) {
  const int decimals = std::max(0, static_cast<int>(std::ceil(-std::log10(step) - 1e-9)));
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, std::abs(value));
  std::string s = buf;
  const bool zero = s.find_first_not_of("0.") == std::string::npos;
  return (value < 0 && !zero ? "\u2212" : "") + s;
}

}  // namespace pkmws::io::detail
