// three_rpr files (docs/format.md): base [[x, y] x 3] (A_i), platform [[x, y] x 3]
// (B_i in the platform frame), actuation "revolute" (R̲PR: base angles, the
// planar PAMINSA) or "prismatic" (RP̲R: leg lengths), orientation_deg (the
// constant orientation of the workspace), optional leg_limits [[min, max] x 3],
// optional analysis_window [[xmin, ymin], [xmax, ymax]] (positions of P).
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "io/registry.hpp"
#include "mechanisms/three_rpr/three_rpr.hpp"

namespace pkmws::io::detail {

namespace {
constexpr double max_length = 1e15;
}  // namespace

MechanismPtr load_three_rpr(JsonReader& document) {
  const auto base = document.points("base", 3);
  const auto platform = document.points("platform", 3);
  for (const auto* pts : {&base, &platform}) {
    const std::string key = pts == &base ? "base" : "platform";
    for (std::size_t i = 0; i < 3; ++i) {
      if (!(std::abs((*pts)[i].x) <= max_length && std::abs((*pts)[i].y) <= max_length)) {
        throw InputError(item(document.field(key), i) + ": magnitude must not exceed 1e15");
      }
      if ((*pts)[i] == (*pts)[(i + 1) % 3]) {
        throw InputError(item(document.field(key), (i + 1) % 3) + ": coincides with " + item(document.field(key), i));
      }
    }
  }
  const std::string actuation = document.one_of("actuation", {"revolute", "prismatic"});
  const double orientation = std::fmod(document.number("orientation_deg"), 360.0) * std::numbers::pi / 180.0;
  std::optional<std::array<std::array<double, 2>, 3>> limits;
  if (document.has("leg_limits")) {
    const auto& v = document.raw("leg_limits");
    const std::string f = document.field("leg_limits");
    if (!v.is_array() || v.size() != 3) throw InputError(f + ": expected three entries [min, max], one per leg");
    std::array<std::array<double, 2>, 3> l{};
    for (std::size_t i = 0; i < 3; ++i) {
      const std::string where = item(f, i);
      if (!v[i].is_array() || v[i].size() != 2 || !v[i][0].is_number() || !v[i][1].is_number()) {
        throw InputError(where + ": expected [min, max] (numbers)");
      }
      l[i] = {v[i][0].get<double>(), v[i][1].get<double>()};
      if (!std::isfinite(l[i][0]) || !std::isfinite(l[i][1])) throw InputError(where + ": expected finite numbers");
      if (!(l[i][0] >= 0.0)) throw InputError(where + ": the shortest leg length must not be negative");
      if (!(l[i][0] < l[i][1])) throw InputError(where + ": expected [min, max] with min < max");
      if (!(l[i][1] <= max_length)) throw InputError(where + ": magnitude must not exceed 1e15");
    }
    limits = l;
  }
  std::optional<geometry::Box> window;
  if (document.has("analysis_window")) {
    const auto corners = document.points("analysis_window", 2);
    const std::string f = document.field("analysis_window");
    for (const auto& c : corners) {
      if (!(std::abs(c.x) <= max_length && std::abs(c.y) <= max_length)) {
        throw InputError(f + ": magnitude must not exceed 1e15");
      }
    }
    if (!(corners[0].x < corners[1].x) || !(corners[0].y < corners[1].y)) {
      throw InputError(f + ": expected [[xmin, ymin], [xmax, ymax]] with xmin < xmax and ymin < ymax");
    }
    geometry::Box b;
    b.min = corners[0];
    b.max = corners[1];
    window = b;
  }
  try {
    return std::make_shared<mechanisms::ThreeRpr>(
        std::array<geometry::Point, 3>{base[0], base[1], base[2]},
        std::array<geometry::Point, 3>{platform[0], platform[1], platform[2]},
        actuation == "revolute" ? mechanisms::ThreeRprActuation::revolute : mechanisms::ThreeRprActuation::prismatic,
        orientation, limits, window);
  } catch (const std::invalid_argument& e) {
    throw InputError(std::string("three_rpr: ") + e.what());
  }
}

// The module's file keywords with their loaders and top-level fields (docs/format.md).
std::vector<Kind> three_rpr_kinds() {
  return {{"three_rpr", load_three_rpr, {"base", "platform", "actuation", "orientation_deg", "leg_limits", "analysis_window"}}};
}

}  // namespace pkmws::io::detail
