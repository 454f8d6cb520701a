// The active Π-joint's curves as line charts: the data of [Milutinovic]
// figures 8-12 and 15-17 (pkmws plot, capability io::Charts).
#include "mechanisms/pi_joint/charts.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

namespace pkmws::mechanisms {

namespace {
constexpr double rad2deg = 180.0 / std::numbers::pi;

// The capability object: the figures of one joint.
class PiJointCharts final : public io::Charts {
 public:
  explicit PiJointCharts(const PiJoint* joint) : joint_(joint) {}
  std::vector<io::NamedChart> charts() const override {
    std::vector<io::NamedChart> out;
    for (auto& f : pi_joint_figures(*joint_)) out.push_back({f.stem, std::move(f.chart)});
    return out;
  }

 private:
  const PiJoint* joint_;
};
}  // namespace

Offer PiJoint::provide(std::type_index which) const {
  if (Offer::asks<io::Charts>(which)) return Offer::owned<io::Charts>(std::make_shared<PiJointCharts>(this));
  return Mechanism::provide(which);
}

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
