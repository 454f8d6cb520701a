// What every report shares (pkmws/report/common.hpp).
#include "pkmws/report/common.hpp"

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <vector>

#include "pkmws/geometry/inscribed.hpp"
#include "report/text.hpp"

namespace pkmws::report {

namespace detail {

std::string format(const char* fmt, ...) {
  va_list args;
  va_start(args, fmt);
  va_list again;
  va_copy(again, args);
  const int n = std::vsnprintf(nullptr, 0, fmt, args);
  va_end(args);
  std::string out(n > 0 ? static_cast<std::size_t>(n) : 0, '\0');
  if (n > 0) std::vsnprintf(out.data(), out.size() + 1, fmt, again);
  va_end(again);
  return out;
}

}  // namespace detail

std::string area_unit(const io::MechanismFile& file) { return file.units + "²"; }

AreaBounds exact_area_bounds(double area) {
  const double rounding = 64 * std::numeric_limits<double>::epsilon() * area;
  return {area - rounding, area + rounding};
}

mechanisms::Pose sample_pose(const io::MechanismFile& file, const geometry::Region& region) {
  // 3-DOF: the platform at the file's constant orientation (the workspace's).
  const double phi = file.model->orientation();
  const auto comps = region.components();
  if (comps.empty()) {
    const auto b = file.model->bounds();
    return {(b.min.x + b.max.x) / 2, (b.min.y + b.max.y) / 2, phi};
  }
  std::size_t k = 0;
  for (std::size_t i = 1; i < comps.size(); ++i) {
    if (comps[i].area > comps[k].area) k = i;
  }
  const auto& c = comps[k];
  // Candidates: the centroid, the centre of the largest inscribed circle, and
  // points around it; the first reachable, non-singular pose wins (a drawing at
  // a singular pose, e.g. DexTAR's centre, hides the mechanism's shape).
  const auto circle = geometry::largest_inscribed_circle(c, 1e-3 * std::sqrt(c.area));
  std::vector<geometry::Point> candidates{c.centroid, circle.center};
  for (int i = 0; i < 8; ++i) {
    const double a = i * std::numbers::pi / 4 + 0.3;
    candidates.push_back({circle.center.x + 0.5 * circle.radius * std::cos(a),
                          circle.center.y + 0.5 * circle.radius * std::sin(a)});
  }
  for (const auto& p : candidates) {
    if (!geometry::inside(c, p) || geometry::distance_to_boundary(c, p) < 0.05 * std::sqrt(c.area)) continue;
    const mechanisms::Pose pose{p.x, p.y, phi};
    try {
      const auto ev = file.model->evaluate(pose, {});
      if (!ev.empty() && ev.front().reachable && !ev.front().singular) return pose;
    } catch (const std::exception&) {
      // a mechanism without evaluate at this pose: try the next candidate
    }
  }
  return {circle.center.x, circle.center.y, phi};
}

std::optional<double> decimal_number(const std::string& text, std::string& problem) {
  std::size_t i = 0;
  if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
  std::size_t digits = 0;
  while (i < text.size() && text[i] >= '0' && text[i] <= '9') ++i, ++digits;
  if (i < text.size() && text[i] == '.') {
    ++i;
    while (i < text.size() && text[i] >= '0' && text[i] <= '9') ++i, ++digits;
  }
  if (digits > 0 && i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    std::size_t j = i + 1;
    if (j < text.size() && (text[j] == '+' || text[j] == '-')) ++j;
    const std::size_t exp_start = j;
    while (j < text.size() && text[j] >= '0' && text[j] <= '9') ++j;
    if (j > exp_start) i = j;
  }
  if (text.empty() || digits == 0 || i != text.size()) {
    problem = "expected a decimal number, got \"" + text + "\"";
    return std::nullopt;
  }
  // The syntax is checked: strtod reads exactly this (underflow gives 0 or a subnormal).
  const double v = std::strtod(text.c_str(), nullptr);
  if (!std::isfinite(v)) {
    problem = "\"" + text + "\" is out of the range of a double";
    return std::nullopt;
  }
  return v;
}

double parse_number(const std::string& text, const std::string& what) {
  std::string problem;
  const auto v = decimal_number(text, problem);
  if (!v) throw io::InputError(what + ": " + problem);
  return *v;
}

}  // namespace pkmws::report
