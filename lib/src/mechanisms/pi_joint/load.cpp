// pi_joint files (docs/theory/pi_joint.md, [Milutinovic]): crank_length a, k = b / a,
// theta_limits_deg [min, max] inside (-90, 90), optional stroke [d_min, d_max]
// and optional actuator {lead, resolution_per_step, max_speed, max_force_N,
// efficiency?} (Table 1; lengths in the file's unit).
#include <numbers>
#include <stdexcept>

#include "io/registry.hpp"
#include "mechanisms/pi_joint/pi_joint.hpp"

namespace pkmws::io::detail {

MechanismPtr load_pi_joint(JsonReader& document) {
  constexpr double deg2rad = std::numbers::pi / 180.0;
  mechanisms::PiJointParams p;
  p.meters_per_unit = document.string("units") == "m" ? 1.0 : 1e-3;
  p.kinematics.a = document.positive("crank_length");
  p.kinematics.k = document.positive("k");
  const auto theta = document.interval("theta_limits_deg");
  if (!(theta[0] > -90.0) || !(theta[1] < 90.0)) {
    document.fail("theta_limits_deg", "must lie inside (-90, 90) degrees (the parallelogram flattens at +-90)");
  }
  p.theta_min = theta[0] * deg2rad;
  p.theta_max = theta[1] * deg2rad;
  if (document.has("stroke")) {
    const auto d = document.interval("stroke");
    if (!(d[0] >= 0.0)) document.fail("stroke", "d_min must not be negative");
    const double reach_lo = p.kinematics.length(p.theta_min), reach_hi = p.kinematics.length(p.theta_max);
    if (d[1] < reach_lo || d[0] > reach_hi) {
      document.fail("stroke", "does not meet the d range [" + nlohmann::json(reach_lo).dump() + ", " +
                                  nlohmann::json(reach_hi).dump() + "] of theta_limits_deg ([Milutinovic] eq. 2)");
    }
    p.stroke_min = d[0];
    p.stroke_max = d[1];
  }
  if (document.has("actuator")) {
    auto r = document.object("actuator");
    r.declare_fields({"lead", "resolution_per_step", "max_speed", "max_force_N", "efficiency"});
    mechanisms::PiJointActuator a;
    a.lead = r.positive("lead");
    a.resolution_per_step = r.positive("resolution_per_step");
    a.max_speed = r.positive("max_speed");
    a.max_force_N = r.positive("max_force_N");
    if (r.has("efficiency")) {
      const double eta = r.number("efficiency");
      if (!(eta > 0.0 && eta <= 1.0)) r.fail("efficiency", "must lie in (0, 1]");
      a.efficiency = eta;
    }
    r.finish();
    p.actuator = a;
  }
  try {
    return std::make_shared<mechanisms::PiJoint>(p);
  } catch (const std::invalid_argument& e) {
    throw InputError(e.what());
  }
}

// The module's file keywords with their loaders and top-level fields (docs/format.md).
std::vector<Kind> pi_joint_kinds() {
  return {{"pi_joint", load_pi_joint, {"crank_length", "k", "theta_limits_deg", "stroke", "actuator"}}};
}

}  // namespace pkmws::io::detail
