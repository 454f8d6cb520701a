// Active Π-joint ([Milutinovic]): inverse/direct kinematics eq. 1-5, Jacobians
// eq. 7, 9-11, statics eq. 12-15, accelerations eq. 17-20, singularities at
// θ = ±90°, and the data of the paper's figures 8-12 and 15-17.
#include "mechanisms/common.hpp"
#include "mechanisms/pi_joint/pi_joint.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace pkmws::mechanisms {

using detail::format_number;

namespace {

constexpr double pi = std::numbers::pi;
constexpr double rad2deg = 180.0 / pi;
constexpr double inf = std::numeric_limits<double>::infinity();
// Relative tolerance of the range and singularity tests.
constexpr double tol = 1e-9;

}  // namespace

// ---------------------------------------------------------------------------
// PiJointKinematics

double PiJointKinematics::length(double theta) const {
  // [Milutinovic] eq. 2; the radicand (1 - k)² + 2k (1 + sin θ) is never negative.
  const double g = 1.0 + k * k + 2.0 * k * std::sin(theta);
  return a * std::sqrt(std::max(0.0, g));
}

double PiJointKinematics::sin_theta(double d) const {
  return (d * d - a * a * (1.0 + k * k)) / (2.0 * a * a * k);  // [Milutinovic] eq. 3
}

std::optional<double> PiJointKinematics::angle(double d) const {
  const double s = sin_theta(d);
  if (!(std::abs(s) <= 1.0 + 1e-12)) return std::nullopt;
  const double sc = std::clamp(s, -1.0, 1.0);
  const double c = std::sqrt((1.0 - sc) * (1.0 + sc));  // [Milutinovic] eq. 4 (cos θ >= 0)
  return std::atan2(sc, c);                              // [Milutinovic] eq. 5
}

double PiJointKinematics::length_min() const { return a * std::abs(1.0 - k); }
double PiJointKinematics::length_max() const { return a * (1.0 + k); }

double PiJointKinematics::jacobian(double theta) const {
  // [Milutinovic] eq. 7: J = a k cos θ / sqrt(1 + k² + 2k sin θ) = a² k cos θ / d
  const double d = length(theta);
  return d > 0.0 ? a * a * k * std::cos(theta) / d : 0.0;
}

double PiJointKinematics::jacobian_d(double theta) const { return 2.0 * length(theta); }  // eq. 10

double PiJointKinematics::jacobian_theta(double theta) const {
  return 2.0 * a * a * k * std::cos(theta);  // [Milutinovic] eq. 11
}

double PiJointKinematics::jacobian_derivative(double theta) const {
  // d/dθ of eq. 7: -a k (k + sin θ)(1 + k sin θ) / g^{3/2}, g = 1 + k² + 2k sin θ
  const double s = std::sin(theta);
  const double g = 1.0 + k * k + 2.0 * k * s;
  return -a * k * (k + s) * (1.0 + k * s) / (g * std::sqrt(g));
}

double PiJointKinematics::motor_torque(double force, double lead, double efficiency) {
  return force * lead / (2.0 * pi * efficiency);  // [Milutinovic] eq. 15
}

double PiJointKinematics::acceleration_from_angular_acceleration(double theta, double theta_ddot) const {
  return jacobian(theta) * theta_ddot;  // [Milutinovic] eq. 19 (the paper omits the factor θ̈)
}

double PiJointKinematics::acceleration_from_angular_velocity(double theta, double theta_dot) const {
  // [Milutinovic] eq. 20: J_d⁻¹ (J̇_θ - J̇_d J) θ̇ with J̇_θ = -2a²k sin θ θ̇ and
  // J̇_d = 2ḋ = 2 J θ̇, which equals (dJ/dθ) θ̇².
  const double jt_dot = -2.0 * a * a * k * std::sin(theta) * theta_dot;
  const double jd_dot = 2.0 * jacobian(theta) * theta_dot;
  return (jt_dot - jd_dot * jacobian(theta)) * theta_dot / jacobian_d(theta);
}

double PiJointKinematics::acceleration(double theta, double theta_dot, double theta_ddot) const {
  return acceleration_from_angular_acceleration(theta, theta_ddot) +
         acceleration_from_angular_velocity(theta, theta_dot);  // [Milutinovic] eq. 18
}

double PiJointKinematics::passive_angle(double theta) const {
  return std::atan2(k + std::sin(theta), std::cos(theta));
}

double PiJointKinematics::transmission_angle(double theta) const {
  return passive_angle(theta) - theta;
}

// ---------------------------------------------------------------------------
// PiJoint

PiJoint::PiJoint(PiJointParams p) : params_(std::move(p)) {
  const PiJointKinematics& kin = params_.kinematics;
  if (!(kin.a > 0.0) || !std::isfinite(kin.a)) throw std::invalid_argument("pi_joint: crank length a must be positive");
  if (!(kin.k > 0.0) || !std::isfinite(kin.k)) throw std::invalid_argument("pi_joint: k must be positive");
  if (!(params_.theta_min < params_.theta_max) || !(params_.theta_min > -pi / 2) ||
      !(params_.theta_max < pi / 2)) {
    throw std::invalid_argument("pi_joint: theta range must be [min, max] inside (-90, 90) degrees");
  }
  if (params_.stroke_min.has_value() != params_.stroke_max.has_value()) {
    throw std::invalid_argument("pi_joint: stroke needs both ends");
  }
  if (params_.stroke_min && !(*params_.stroke_min < *params_.stroke_max && *params_.stroke_min >= 0.0)) {
    throw std::invalid_argument("pi_joint: stroke must be [min, max] with 0 <= min < max");
  }
  if (params_.stroke_min && (*params_.stroke_max < kin.length(params_.theta_min) ||
                             *params_.stroke_min > kin.length(params_.theta_max))) {
    throw std::invalid_argument("pi_joint: the stroke does not meet the d range of the theta range");
  }
  if (!(params_.meters_per_unit > 0.0)) throw std::invalid_argument("pi_joint: bad length unit");
}

double PiJoint::d_min() const {
  const double d = params_.kinematics.length(params_.theta_min);
  return params_.stroke_min ? std::max(d, *params_.stroke_min) : d;
}

double PiJoint::d_max() const {
  const double d = params_.kinematics.length(params_.theta_max);
  return params_.stroke_max ? std::min(d, *params_.stroke_max) : d;
}

PiJoint::Points PiJoint::points(double theta) const {
  const PiJointKinematics& kin = params_.kinematics;
  const Point u{std::sin(theta), std::cos(theta)};
  Points p;
  p.o = {0.0, 0.0};
  p.o_prime = {kin.b(), 0.0};
  p.q = p.o + kin.a * u;
  p.a = p.o_prime + kin.a * u;
  return p;
}

std::vector<JointInfo> PiJoint::joints() const { return {{"d", false, std::array{d_min(), d_max()}}}; }

std::string PiJoint::range_problem(double theta, double d) const {
  const double span = params_.theta_max - params_.theta_min;
  if (theta < params_.theta_min - tol * span || theta > params_.theta_max + tol * span) {
    return "theta = " + format_number(theta * rad2deg) + " deg outside [" + format_number(params_.theta_min * rad2deg) + ", " +
           format_number(params_.theta_max * rad2deg) + "] deg";
  }
  if (params_.stroke_min) {
    const double s = tol * (*params_.stroke_max - *params_.stroke_min);
    if (d < *params_.stroke_min - s || d > *params_.stroke_max + s) {
      return "d = " + format_number(d) + " outside stroke [" + format_number(*params_.stroke_min) + ", " + format_number(*params_.stroke_max) + "]";
    }
  }
  return "";
}

std::vector<JointSolution> PiJoint::inverse(const Pose& pose) const {
  const double theta = pose.phi;
  JointSolution s;
  s.mode = "0";  // one inverse solution (docs/format.md (modes))
  if (!(std::abs(theta) < pi / 2)) {
    s.reason = "theta = " + format_number(theta * rad2deg) + " deg outside (-90, 90) deg ([Milutinovic] eq. 1)";
    return {s};
  }
  s.joints = {params_.kinematics.length(theta)};  // [Milutinovic] eq. 2
  s.reason = range_problem(theta, s.joints[0]);
  s.valid = s.reason.empty();
  return {s};
}

std::vector<PoseSolution> PiJoint::direct(std::span<const double> q) const {
  if (q.size() != 1) throw std::invalid_argument("pi_joint: direct kinematics needs d");
  const double d = q[0];
  const auto theta = params_.kinematics.angle(d);
  std::vector<PoseSolution> out;
  if (!theta || !(d >= 0.0)) return out;
  // [Milutinovic] eq. 4 takes cos θ >= 0; the other root π - θ flattens or crosses
  // the parallelogram and lies outside (-90°, 90°).
  for (int branch : {1, -1}) {
    PoseSolution s;
    s.mode = branch > 0 ? "+" : "-";  // the sign of cos theta
    double t = branch > 0 ? *theta : (*theta >= 0.0 ? pi - *theta : -pi - *theta);
    if (branch < 0 && std::abs(std::abs(t) - pi / 2) <= 1e-12) continue;  // double root at ±90°
    s.pose = {0.0, 0.0, t};
    const Points p = points(t);
    s.platform_points = {p.a};
    s.pose.x = p.a.x;
    s.pose.y = p.a.y;
    if (branch < 0) {
      s.reason = "cos theta < 0: outside (-90, 90) deg ([Milutinovic] eq. 4 takes cos theta >= 0)";
    } else {
      s.reason = range_problem(t, d);
    }
    s.valid = s.reason.empty();
    out.push_back(s);
  }
  return out;
}

std::vector<Evaluation> PiJoint::evaluate(const Pose& pose, const Criteria& criteria) const {
  const PiJointKinematics& kin = params_.kinematics;
  const JointSolution s = inverse(pose).front();
  Evaluation e = detail::start_evaluation(s, 1);
  if (s.joints.empty()) {
    return {e};
  }
  const double theta = pose.phi;
  const double j = kin.jacobian(theta);  // [Milutinovic] eq. 7
  const double d = s.joints[0];
  // Singularities ([Milutinovic] eq. 9-11): J_θ = 0 at θ = ±90° (direct kinematics),
  // J_d = 2d = 0 only for k = 1 at θ = -90° (inverse kinematics).
  const bool type2 = std::abs(std::cos(theta)) <= tol;
  const bool type1 = d <= tol * kin.a;
  e.singular = type1 || type2;
  e.singularity = type1 && type2 ? "both" : type1 ? "type1" : type2 ? "type2" : "";
  e.jacobian_det = j;                          // dq/dx = dd/dθ (1x1)
  e.condition_number = type2 ? inf : 1.0;      // a 1x1 matrix
  e.velocity_ratio = std::abs(j);              // |ḋ| / |θ̇| (length unit per rad)
  const double mu = kin.transmission_angle(theta);
  e.pressure_angle_deg = {90.0 - mu * rad2deg};  // angle between the diagonal's force and A's velocity
  const double j_m = j * params_.meters_per_unit;  // J in metres per rad
  if (criteria.load) {
    // Actuator force for an output torque of ±m ([Milutinovic] eq. 14); a force at A is
    // carried by the parallelogram's links, not by the actuator alone.
    e.reactions_N = {type2 ? inf : std::abs(criteria.load->moment_Nm / j_m)};
  }
  e.extra.push_back({"d", d});
  e.extra.push_back({"theta_deg", theta * rad2deg});
  e.extra.push_back({"jacobian", j});
  e.extra.push_back({"jacobian_inverse", type2 ? inf : 1.0 / j});
  e.extra.push_back({"jacobian_d", kin.jacobian_d(theta)});
  e.extra.push_back({"jacobian_theta", kin.jacobian_theta(theta)});
  e.extra.push_back({"passive_angle_deg", kin.passive_angle(theta) * rad2deg});
  e.extra.push_back({"transmission_angle_deg", mu * rad2deg});
  if (params_.actuator && !type2) {
    const PiJointActuator& act = *params_.actuator;
    e.extra.push_back({"output_resolution_deg_per_step", act.resolution_per_step / std::abs(j) * rad2deg});
    e.extra.push_back({"angular_velocity_deg_s_at_max_speed", act.max_speed / std::abs(j) * rad2deg});
    e.extra.push_back({"torque_Nm_at_max_force", act.max_force_N * std::abs(j_m)});
    if (act.efficiency) {
      e.extra.push_back({"motor_torque_Nm_at_max_force",
                         PiJointKinematics::motor_torque(act.max_force_N, act.lead * params_.meters_per_unit,
                                                         *act.efficiency)});
    }
  }
  return {e};
}

geometry::Region PiJoint::workspace() const {
  throw std::runtime_error(
      "pi_joint: a lone Π-joint has one degree of freedom (the crank angle theta) and no planar "
      "workspace region; use its ik/dk/eval curves, or a five_bar file with pi_joints to get a workspace");
}

bool PiJoint::reachable(const Pose& pose) const {
  const auto s = inverse(pose);
  return !s.empty() && s.front().valid;
}

Drawing PiJoint::draw(const Pose& pose) const {
  const double theta = std::clamp(pose.phi, params_.theta_min, params_.theta_max);
  const Points p = points(theta);
  Drawing d;
  d.guides.push_back({p.o, p.o_prime});  // the fixed link
  d.guides_legend = "fixed link";
  d.links = {{p.o, p.q}, {p.o_prime, p.a}, {p.q, p.a}, {p.o, p.a}};
  d.joints = {p.o, p.o_prime, p.q, p.a};
  d.base_points = {p.o, p.o_prime};
  d.tool = p.a;
  return d;
}

geometry::Box PiJoint::bounds() const {
  geometry::Box box;
  const Points base = points(0.0);
  box.expand(base.o);
  box.expand(base.o_prime);
  // The coupler ends sweep arcs of radius a about O and O' over the θ range;
  // the arcs' extreme points are at the ends or at θ = 0 (top).
  for (double t : {params_.theta_min, params_.theta_max, std::clamp(0.0, params_.theta_min, params_.theta_max)}) {
    const Points p = points(t);
    box.expand(p.q);
    box.expand(p.a);
  }
  return box;
}

}  // namespace pkmws::mechanisms
