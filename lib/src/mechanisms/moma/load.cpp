// moma files (docs/format.md): two legs {reference [x, y], guide_angle_deg,
// stroke [pmin, pmax], rod_length, branch}. Lengths in the file's unit.
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "io/registry.hpp"
#include "mechanisms/moma/moma.hpp"

namespace pkmws::io::detail {

namespace {

// Lengths beyond this (in the file's unit) would overflow squared lengths in
// the kinematics and the exact region; no real mechanism comes near it.
constexpr double max_length = 1e15;

void check_magnitude(const JsonReader& r, const std::string& key, double v) {
  if (!(std::abs(v) <= max_length)) r.fail(key, "magnitude must not exceed 1e15");
}

}  // namespace

MechanismPtr load_moma(JsonReader& document) {
  std::array<mechanisms::MomaLeg, 2> legs;
  auto readers = document.objects("legs", 2);
  for (std::size_t i = 0; i < 2; ++i) {
    JsonReader& r = readers[i];
    r.declare_fields({"reference", "guide_angle_deg", "stroke", "rod_length", "branch"});
    mechanisms::MomaLeg& leg = legs[i];
    leg.reference = r.point("reference");
    check_magnitude(r, "reference", leg.reference.x);
    check_magnitude(r, "reference", leg.reference.y);
    // Degrees in the file, radians inside. fmod keeps 270 as 270 (so that
    // 270 * pi / 180 folds to an exact axis direction) and tames huge angles.
    leg.guide_angle = std::fmod(r.number("guide_angle_deg"), 360.0) * std::numbers::pi / 180.0;
    // [Vasilic] §4.2: 0 <= p_i <= h_max; any pmin < pmax is accepted (a slider
    // may start behind its reference point).
    const auto stroke = r.interval("stroke");
    leg.stroke_min = stroke[0];
    leg.stroke_max = stroke[1];
    check_magnitude(r, "stroke", stroke[0]);
    check_magnitude(r, "stroke", stroke[1]);
    leg.rod_length = r.positive("rod_length");
    check_magnitude(r, "rod_length", leg.rod_length);
    leg.branch = r.sign("branch");
    r.finish();
  }
  try {
    return std::make_shared<mechanisms::Moma>(legs);
  } catch (const std::invalid_argument& e) {
    // Every field is validated above; this only guards later additions to Moma's checks.
    throw InputError(document.field("legs") + ": " + e.what());
  }
}

// The module's file keywords with their loaders and top-level fields (docs/format.md).
std::vector<Kind> moma_kinds() {
  return {{"moma", load_moma, {"legs"}}};
}

}  // namespace pkmws::io::detail
