// three_rrp / three_prp files (docs/format.md): base [[x, y] x 3] (O_i), platform
// [[x, y] x 3] (B_1, B_2, B_3 in the platform frame, counter-clockwise; the
// slider of chain i runs on side B_i B_{i+1}); three_rrp: crank_lengths [3],
// optional crank_limits_deg [[min, max] x 3]; three_prp: directions_deg
// [3], optional strokes [[min, max] x 3]; optional orientation_deg (the
// constant orientation of the workspace, default 0). Lengths in the file's unit.
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "io/registry.hpp"
#include "mechanisms/three_rrp/three_rrp.hpp"

namespace pkmws::io::detail {

namespace {

constexpr double deg2rad = std::numbers::pi / 180.0;
constexpr double max_length = 1e15;

void check_points(const JsonReader& r, const std::string& key, const std::vector<geometry::Point>& points) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!(std::abs(points[i].x) <= max_length && std::abs(points[i].y) <= max_length)) {
      throw InputError(item(r.field(key), i) + ": magnitude must not exceed 1e15");
    }
  }
}

// [[min, max] x 3]; `angles`: degrees converted to radians, span <= 360. A null
// entry is refused (it read as "no limit" without saying so); a chain without
// limits is a file without the key.
std::array<std::optional<std::array<double, 2>>, 3> read_ranges(JsonReader& r, const std::string& key, bool angles) {
  std::array<std::optional<std::array<double, 2>>, 3> out;
  if (!r.has(key)) return out;
  const auto& v = r.raw(key);
  const std::string f = r.field(key);
  if (!v.is_array() || v.size() != 3) throw InputError(f + ": expected three entries [min, max], one per chain");
  for (std::size_t i = 0; i < 3; ++i) {
    const std::string where = item(f, i);
    if (v[i].is_null()) {
      throw InputError(where + ": expected [min, max], got null (omit `" + key + "` for chains without limits)");
    }
    if (!v[i].is_array() || v[i].size() != 2) throw InputError(where + ": expected [min, max]");
    const double lo = JsonReader::as_number(v[i][0], where + "[0]"), hi = JsonReader::as_number(v[i][1], where + "[1]");
    if (!(lo < hi)) throw InputError(where + ": expected [min, max] with min < max");
    if (angles && hi - lo > 360.0) throw InputError(where + ": the range must not exceed 360 degrees");
    if (!angles && !(std::abs(lo) <= max_length && std::abs(hi) <= max_length)) {
      throw InputError(where + ": magnitude must not exceed 1e15");
    }
    out[i] = angles ? std::array<double, 2>{lo * deg2rad, hi * deg2rad} : std::array<double, 2>{lo, hi};
  }
  return out;
}

MechanismPtr load(JsonReader& document, mechanisms::ThreeRrpDrive drive) {
  const auto base = document.points("base", 3);
  check_points(document, "base", base);
  const auto platform = document.points("platform", 3);
  check_points(document, "platform", platform);
  const double cr = geometry::cross(platform[1] - platform[0], platform[2] - platform[0]);
  if (!(cr > 0.0)) {
    document.fail("platform", cr < 0.0 ? "B1, B2, B3 must be counter-clockwise (the slider of chain i runs on side "
                                         "B_i B_{i+1})"
                                       : "B1, B2, B3 must not be collinear");
  }
  std::array<mechanisms::ThreeRrpChain, 3> chains;
  const bool crank = drive == mechanisms::ThreeRrpDrive::crank;
  const auto values = document.numbers(crank ? "crank_lengths" : "directions_deg", 3);
  const auto limits = read_ranges(document, crank ? "crank_limits_deg" : "strokes", crank);
  for (std::size_t i = 0; i < 3; ++i) {
    chains[i].base = base[i];
    if (crank) {
      if (!(values[i] > 0.0)) throw InputError(item(document.field("crank_lengths"), i) + ": must be positive");
      if (!(values[i] <= max_length)) throw InputError(item(document.field("crank_lengths"), i) + ": magnitude must not exceed 1e15");
      chains[i].crank_length = values[i];
    } else {
      chains[i].direction = std::fmod(values[i], 360.0) * deg2rad;
    }
    chains[i].limits = limits[i];
  }
  const double orientation =
      document.has("orientation_deg") ? std::fmod(document.number("orientation_deg"), 360.0) * deg2rad : 0.0;
  try {
    return std::make_shared<mechanisms::ThreeRrp>(drive, chains,
                                                  std::array<geometry::Point, 3>{platform[0], platform[1], platform[2]},
                                                  orientation);
  } catch (const std::invalid_argument& e) {
    throw InputError(std::string(crank ? "three_rrp: " : "three_prp: ") + e.what());
  }
}

}  // namespace

MechanismPtr load_three_rrp(JsonReader& document) { return load(document, mechanisms::ThreeRrpDrive::crank); }

MechanismPtr load_three_prp(JsonReader& document) { return load(document, mechanisms::ThreeRrpDrive::slider); }

// The module's file keywords with their loaders and top-level fields (docs/format.md).
std::vector<Kind> three_rrp_kinds() {
  return {{"three_rrp", load_three_rrp, {"base", "platform", "crank_lengths", "crank_limits_deg", "orientation_deg"}},
          {"three_prp", load_three_prp, {"base", "platform", "directions_deg", "strokes", "orientation_deg"}}};
}

}  // namespace pkmws::io::detail
