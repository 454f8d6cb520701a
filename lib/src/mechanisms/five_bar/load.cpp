// five_bar files (docs/format.md): base [[x, y], [x, y]], proximal [l1, l1'],
// distal [l2, l2'], working_mode [s1, s2], optional actuator_limits_deg
// [[min, max] | null, [min, max] | null] and optional pi_joints (two objects
// {k, stroke [d_min, d_max], base_angle_deg, sense?}: Π-joints driving the
// cranks, [Milutinovic] figure 5; docs/theory/five_bar.md).
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "io/registry.hpp"
#include "mechanisms/five_bar/five_bar.hpp"

namespace pkmws::io::detail {

namespace {

constexpr double deg2rad = std::numbers::pi / 180.0;

}  // namespace

MechanismPtr load_five_bar(JsonReader& document) {
  std::array<mechanisms::FiveBarLeg, 2> legs;
  const auto base = document.points("base", 2);
  const auto proximal = document.numbers("proximal", 2);
  const auto distal = document.numbers("distal", 2);
  const auto& mode = document.raw("working_mode");
  const std::string mode_field = document.field("working_mode");
  if (!mode.is_array() || mode.size() != 2) throw InputError(mode_field + ": expected [s1, s2] with each -1 or 1");
  for (std::size_t i = 0; i < 2; ++i) {
    mechanisms::FiveBarLeg& leg = legs[i];
    leg.base = base[i];
    leg.proximal = proximal[i];
    leg.distal = distal[i];
    if (!(leg.proximal > 0.0)) throw InputError(item(document.field("proximal"), i) + ": must be positive");
    if (!(leg.distal > 0.0)) throw InputError(item(document.field("distal"), i) + ": must be positive");
    const auto& s = mode[i];
    if (!s.is_number_integer() || (s.get<int>() != 1 && s.get<int>() != -1)) {
      throw InputError(item(mode_field, i) + ": expected -1 or 1");
    }
    leg.working_mode = s.get<int>();
  }
  if (document.has("actuator_limits_deg")) {
    const auto& lim = document.raw("actuator_limits_deg");
    const std::string f = document.field("actuator_limits_deg");
    if (!lim.is_array() || lim.size() != 2) {
      throw InputError(f + ": expected two entries [min, max] (degrees) or null, one per leg");
    }
    for (std::size_t i = 0; i < 2; ++i) {
      const std::string where = item(f, i);
      if (lim[i].is_null()) continue;
      if (!lim[i].is_array() || lim[i].size() != 2) throw InputError(where + ": expected [min, max] in degrees, or null");
      const double lo = JsonReader::as_number(lim[i][0], where + "[0]"), hi = JsonReader::as_number(lim[i][1], where + "[1]");
      if (!(lo < hi)) throw InputError(where + ": expected [min, max] with min < max");
      if (hi - lo > 360.0) throw InputError(where + ": the range must not exceed 360 degrees");
      legs[i].crank_limits = std::array<double, 2>{lo * deg2rad, hi * deg2rad};
    }
  }
  if (document.has("pi_joints")) {
    if (document.has("actuator_limits_deg")) {
      document.fail("pi_joints", "give either actuator_limits_deg or pi_joints (whose strokes limit the cranks), not both");
    }
    auto readers = document.objects("pi_joints", 2);
    for (std::size_t i = 0; i < 2; ++i) {
      JsonReader& r = readers[i];
      r.declare_fields({"k", "stroke", "base_angle_deg", "sense"});
      mechanisms::FiveBarPiDrive p;
      p.k = r.positive("k");
      const auto stroke = r.interval("stroke");
      p.stroke_min = stroke[0];
      p.stroke_max = stroke[1];
      p.base_angle = r.number("base_angle_deg") * deg2rad;
      p.sense = r.has("sense") ? r.sign("sense") : 1;
      r.finish();
      const mechanisms::PiJointKinematics kin{legs[i].proximal, p.k};
      if (!(p.stroke_min > kin.length_min()) || !(p.stroke_max < kin.length_max())) {
        r.fail("stroke", "must lie strictly inside (a|1 - k|, a(1 + k)) = (" + nlohmann::json(kin.length_min()).dump() +
                             ", " + nlohmann::json(kin.length_max()).dump() +
                             ") with a = proximal[" + std::to_string(i) +
                             "] (beyond it the parallelogram flattens at theta = +-90 degrees)");
      }
      legs[i].pi_joint = p;
    }
  }
  try {
    return std::make_shared<mechanisms::FiveBar>(legs);
  } catch (const std::invalid_argument& e) {
    throw InputError(std::string("five_bar: ") + e.what());
  }
}

// The module's file keywords with their loaders and top-level fields (docs/format.md).
std::vector<Kind> five_bar_kinds() {
  return {{"five_bar", load_five_bar, {"base", "proximal", "distal", "working_mode", "actuator_limits_deg", "pi_joints"}}};
}

}  // namespace pkmws::io::detail
