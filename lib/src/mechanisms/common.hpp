// Pieces shared by the mechanism implementations. Private to the library.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>

#include <Eigen/Core>

#include "pkmws/mechanisms/mechanism.hpp"

namespace pkmws::mechanisms::detail {

inline constexpr double infinity = std::numeric_limits<double>::infinity();

/// Unit vector at angle a (radians).
inline Point unit(double a) { return {std::cos(a), std::sin(a)}; }
/// v rotated counter-clockwise by phi (radians).
inline Point rotate(Point v, double phi) {
  const double c = std::cos(phi), s = std::sin(phi);
  return {c * v.x - s * v.y, s * v.x + c * v.y};
}
/// Angle in (-pi, pi].
inline double wrap_pi(double q) {
  constexpr double two_pi = 2.0 * std::numbers::pi;
  double r = std::remainder(q, two_pi);
  if (r <= -std::numbers::pi) r += two_pi;
  return r;
}
/// Angle in [lo, lo + 2 pi).
inline double wrap_from(double q, double lo) {
  constexpr double two_pi = 2.0 * std::numbers::pi;
  double r = std::fmod(q - lo, two_pi);
  if (r < 0.0) r += two_pi;
  if (r >= two_pi) r -= two_pi;
  return lo + r;
}

/// A value for a one-line reason ("p2 = 212.3 outside stroke [0, 200]").
inline std::string format_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

/// The sign character of a mode label (docs/format.md (modes)): '+' for a
/// positive branch, '-' for a negative one, '0' for none (a leg with one
/// inverse solution, two assembly modes that meet).
inline char mode_sign(double sign) { return sign > 0 ? '+' : (sign < 0 ? '-' : '0'); }

/// Label of a two-leg working mode: one sign per leg, e.g. "-+" for branches (-1, 1).
inline std::string mode_label(int first, int second) { return {mode_sign(first), mode_sign(second)}; }

/// The evaluation of one working mode started from its IK solution (mode,
/// reachability, reason, joint values). Without all `dof` joint values there
/// is nothing more to evaluate: the Jacobian figures are NaN.
inline Evaluation start_evaluation(const JointSolution& s, std::size_t dof) {
  Evaluation e;
  e.mode = s.mode;
  e.reachable = s.valid;
  e.reason = s.reason;
  e.joints = s.joints;
  if (s.joints.size() != dof) {
    e.jacobian_det = std::numeric_limits<double>::quiet_NaN();
    e.condition_number = std::numeric_limits<double>::quiet_NaN();
  }
  return e;
}

/// Fills jacobian_det, condition_number and velocity_ratio (largest singular
/// value: worst-case |dq| / |dx|) from the inverse-kinematic Jacobian dq/dx;
/// infinite at a type-1 singularity, infinite conditioning at a type-2 one.
void set_velocity_figures(Evaluation& e, const Eigen::Matrix2d& dq_dx, bool type1, bool type2);

/// Two legs meeting at a point platform: leg i pushes along its distal rod, and
/// with actuator j locked the point moves perpendicular to rod j, so
/// cos(alpha_i) = |sin eps| with eps the angle between the rods ([Briot]). The
/// worst force of norm f loads each rod with f / |sin eps|; a point transmits
/// no moment. Fills pressure_angle_deg and (with a load) reactions_N.
void set_point_platform_transmission(Evaluation& e, double abs_sin_eps, const Criteria& criteria);

}  // namespace pkmws::mechanisms::detail
