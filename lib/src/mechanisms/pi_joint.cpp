// Active Π-joint ([Milutinovic]): inverse/direct kinematics eq. 1-5, Jacobians
// eq. 7, 9-11, statics eq. 12-15, accelerations eq. 17-20, singularities at
// θ = ±90°, and the data of the paper's figures 8-12 and 15-17.
#include "mechanisms/common.hpp"
#include "pkmws/mechanisms/pi_joint.hpp"

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

std::vector<JointInfo> PiJoint::joints() const { return {{"d", false}}; }

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

// ---------------------------------------------------------------------------
// Figures

namespace {

std::vector<double> linspace(double lo, double hi, int n) {
  std::vector<double> v(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) v[static_cast<std::size_t>(i)] = lo + (hi - lo) * i / (n - 1);
  return v;
}

std::string k_label(double k) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "k = %.1f", k);
  return buf;
}

template <class F>
io::PlotSeries series(const std::string& label, const std::vector<double>& theta_deg, F f) {
  io::PlotSeries s;
  s.label = label;
  s.x = theta_deg;
  for (double t : theta_deg) s.y.push_back(f(t / rad2deg));
  return s;
}

}  // namespace

std::vector<PiJointFigure> pi_joint_figures(const PiJoint& joint, int samples) {
  if (samples < 3) throw std::invalid_argument("pi_joint_figures: samples must be >= 3");
  const char* source = "[Milutinovic] (Milutinović et al., active Π-joint)";
  std::vector<PiJointFigure> out;
  const std::vector<double> ks{0.3, 0.4, 0.5};

  {  // Figure 8: d(θ) for a = 1 m, k = 0.3, 0.4, 0.5, 1.0, 1.5, θ in [-90°, 90°] (eq. 2)
    PiJointFigure f{8, "pi_joint_fig08_length", {}};
    f.chart.title = "Diagonal length d(θ), a = 1 m ([Milutinovic] fig. 8)";
    f.chart.x_label = "θ [°]";
    f.chart.y_label = "d [m]";
    const auto th = linspace(-90.0, 90.0, samples);
    for (double k : {0.3, 0.4, 0.5, 1.0, 1.5}) {
      const PiJointKinematics kin{1.0, k};
      f.chart.series.push_back(series(k_label(k), th, [&](double t) { return kin.length(t); }));
    }
    f.chart.x_range = std::array<double, 2>{-90.0, 90.0};
    f.chart.x_tick_step = 30.0;
    f.chart.caption = std::string(source) + ", eq. 2: d = a sqrt(1 + k² + 2k sin θ)";
    out.push_back(std::move(f));
  }
  {  // Figure 9: passive angle φ of the diagonal
    PiJointFigure f{9, "pi_joint_fig09_passive_angle", {}};
    f.chart.title = "Passive angle φ of the diagonal ([Milutinovic] fig. 9)";
    f.chart.x_label = "θ [°]";
    f.chart.y_label = "φ [°]";
    const auto th = linspace(-89.5, 89.5, samples);
    for (double k : ks) {
      const PiJointKinematics kin{1.0, k};
      f.chart.series.push_back(series(k_label(k), th, [&](double t) { return kin.passive_angle(t) * rad2deg; }));
    }
    f.chart.x_range = std::array<double, 2>{-90.0, 90.0};
    f.chart.x_tick_step = 30.0;
    f.chart.caption = std::string(source) + "; φ = atan2(k + sin θ, cos θ) from the normal of the fixed link";
    out.push_back(std::move(f));
  }
  {  // Figure 10: transmission angle μ
    PiJointFigure f{10, "pi_joint_fig10_transmission_angle", {}};
    f.chart.title = "Transmission angle μ ([Milutinovic] fig. 10)";
    f.chart.x_label = "θ [°]";
    f.chart.y_label = "μ [°]";
    const auto th = linspace(-90.0, 90.0, samples);
    for (double k : ks) {
      const PiJointKinematics kin{1.0, k};
      f.chart.series.push_back(
          series(k_label(k), th, [&](double t) { return kin.transmission_angle(t) * rad2deg; }));
    }
    f.chart.x_range = std::array<double, 2>{-90.0, 90.0};
    f.chart.x_tick_step = 30.0;
    f.chart.caption = std::string(source) + "; μ = φ − θ, J = a sin μ";
    out.push_back(std::move(f));
  }
  {  // Figure 11: J(θ), a = 1 m, θ in [-75°, 75°] (eq. 7)
    PiJointFigure f{11, "pi_joint_fig11_jacobian", {}};
    f.chart.title = "Jacobian J(θ), a = 1 m ([Milutinovic] fig. 11)";
    f.chart.x_label = "θ [°]";
    f.chart.y_label = "J [m/rad]";
    const auto th = linspace(-75.0, 75.0, samples);
    for (double k : ks) {
      const PiJointKinematics kin{1.0, k};
      f.chart.series.push_back(series(k_label(k), th, [&](double t) { return kin.jacobian(t); }));
    }
    f.chart.x_range = std::array<double, 2>{-75.0, 75.0};
    f.chart.x_tick_step = 15.0;
    f.chart.caption = std::string(source) + ", eq. 7: J = a k cos θ / sqrt(1 + k² + 2k sin θ)";
    out.push_back(std::move(f));
  }
  {  // Figure 12: J⁻¹(θ) (eq. 8)
    PiJointFigure f{12, "pi_joint_fig12_inverse_jacobian", {}};
    f.chart.title = "Inverse Jacobian J⁻¹(θ), a = 1 m ([Milutinovic] fig. 12)";
    f.chart.x_label = "θ [°]";
    f.chart.y_label = "J⁻¹ [rad/m]";
    const auto th = linspace(-75.0, 75.0, samples);
    for (double k : ks) {
      const PiJointKinematics kin{1.0, k};
      f.chart.series.push_back(series(k_label(k), th, [&](double t) { return 1.0 / kin.jacobian(t); }));
    }
    f.chart.x_range = std::array<double, 2>{-75.0, 75.0};
    f.chart.x_tick_step = 15.0;
    f.chart.caption = std::string(source) + ", eq. 8: θ̇ = ḋ / J";
    out.push_back(std::move(f));
  }
  if (!joint.params().actuator) return out;

  // Figures 15-17: the prototype over its θ range with the actuator of Table 1.
  const PiJointParams& p = joint.params();
  const PiJointKinematics& kin = p.kinematics;
  const PiJointActuator& act = *p.actuator;
  const auto th = linspace(p.theta_min * rad2deg, p.theta_max * rad2deg, samples);
  char proto[160];
  std::snprintf(proto, sizeof proto, "a = %g, k = %g, θ in [%g°, %g°]", kin.a, kin.k, p.theta_min * rad2deg,
                p.theta_max * rad2deg);
  const std::array<double, 2> xr{p.theta_min * rad2deg, p.theta_max * rad2deg};
  const std::string unit = p.meters_per_unit == 1.0 ? "m" : (p.meters_per_unit == 1e-3 ? "mm" : "length unit");
  {
    PiJointFigure f{15, "pi_joint_fig15_resolution", {}};
    f.chart.title = "Output angular resolution ([Milutinovic] fig. 15)";
    f.chart.x_label = "θ [°]";
    f.chart.y_label = "Δθ [°/step]";
    char label[64];
    std::snprintf(label, sizeof label, "Δd = %g %s/step", act.resolution_per_step, unit.c_str());
    f.chart.series.push_back(
        series(label, th, [&](double t) { return act.resolution_per_step / kin.jacobian(t) * rad2deg; }));
    f.chart.x_range = xr;
    f.chart.x_tick_step = 10.0 * std::ceil((xr[1] - xr[0]) / 120.0);
    f.chart.caption = std::string(source) + "; prototype " + proto + "; Δθ = Δd / J";
    out.push_back(std::move(f));
  }
  {
    PiJointFigure f{16, "pi_joint_fig16_angular_velocity", {}};
    f.chart.title = "Output angular velocity ([Milutinovic] fig. 16)";
    f.chart.x_label = "θ [°]";
    f.chart.y_label = "θ̇ [°/s]";
    char label[64];
    std::snprintf(label, sizeof label, "ḋ = %g %s/s", act.max_speed, unit.c_str());
    f.chart.series.push_back(series(label, th, [&](double t) { return act.max_speed / kin.jacobian(t) * rad2deg; }));
    f.chart.x_range = xr;
    f.chart.x_tick_step = 10.0 * std::ceil((xr[1] - xr[0]) / 120.0);
    f.chart.caption = std::string(source) + "; prototype " + proto + "; θ̇ = ḋ / J (eq. 8)";
    out.push_back(std::move(f));
  }
  {
    PiJointFigure f{17, "pi_joint_fig17_torque", {}};
    f.chart.title = "Output static torque ([Milutinovic] fig. 17)";
    f.chart.x_label = "θ [°]";
    f.chart.y_label = "T [N·m]";
    char label[64];
    std::snprintf(label, sizeof label, "F = %g N", act.max_force_N);
    f.chart.series.push_back(series(
        label, th, [&](double t) { return kin.torque(t, act.max_force_N) * p.meters_per_unit; }));
    f.chart.x_range = xr;
    f.chart.x_tick_step = 10.0 * std::ceil((xr[1] - xr[0]) / 120.0);
    f.chart.caption = std::string(source) + "; prototype " + proto + "; T = J F (eq. 13)";
    out.push_back(std::move(f));
  }
  return out;
}

}  // namespace pkmws::mechanisms
