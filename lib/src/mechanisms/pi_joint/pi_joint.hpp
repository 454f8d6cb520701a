// Active Π-joint ([Milutinovic]; docs/theory/pi_joint.md): a planar parallelogram with links a
// (cranks) and b = k a (fixed link and coupler) and a telescopic diagonal of
// length d (the actuator). Its output is the crank angle θ, -90° < θ < 90°,
// measured from the normal of the fixed link; the coupler translates on a
// circle of radius a, so the joint replaces an actuated revolute joint plus a
// proximal link of length a ([Milutinovic] figure 5).
//
// Frame (docs/theory/pi_joint.md): fixed pivots O = (0, 0) and O' = (b, 0),
// crank direction u(θ) = (sin θ, cos θ), coupler ends Q = O + a u, A = O' + a u;
// the diagonal is O A, so d² = a² + b² + 2ab sin θ ([Milutinovic] eq. 1).
//
// Lengths are in the caller's unit; angles in radians.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "pkmws/mechanisms/mechanism.hpp"

namespace pkmws::mechanisms {

/// Kinematics and statics of the Π-joint with crank length a and ratio k = b / a
/// ([Milutinovic] §4.1). Pure functions of (a, k); θ in radians, lengths in a's unit.
struct PiJointKinematics {
  double a = 1.0;  // crank length
  double k = 0.4;  // b / a

  double b() const { return k * a; }
  /// [Milutinovic] eq. 2: d = a sqrt(1 + k² + 2k sin θ).
  double length(double theta) const;
  /// [Milutinovic] eq. 3: sin θ = (d² - a²(1 + k²)) / (2a²k).
  double sin_theta(double d) const;
  /// [Milutinovic] eq. 3-5 with cos θ >= 0 (eq. 4); nullopt when |sin θ| > 1.
  std::optional<double> angle(double d) const;
  /// Range of d over -90° <= θ <= 90°: [a |1 - k|, a (1 + k)].
  double length_min() const;
  double length_max() const;

  /// [Milutinovic] eq. 7: J = dd/dθ = a k cos θ / sqrt(1 + k² + 2k sin θ) (length / rad).
  double jacobian(double theta) const;
  /// [Milutinovic] eq. 10: J_d = -∂F/∂d = 2d.
  double jacobian_d(double theta) const;
  /// [Milutinovic] eq. 11: J_θ = ∂F/∂θ = 2 a² k cos θ.
  double jacobian_theta(double theta) const;
  /// dJ/dθ = -a k (k + sin θ)(1 + k sin θ) / (1 + k² + 2k sin θ)^{3/2} (length / rad²).
  double jacobian_derivative(double theta) const;

  /// [Milutinovic] eq. 13: output torque T = J F (force x length unit).
  double torque(double theta, double force) const { return jacobian(theta) * force; }
  /// [Milutinovic] eq. 14: actuator force F = T / J.
  double force(double theta, double torque) const { return torque / jacobian(theta); }
  /// [Milutinovic] eq. 15: motor torque T_M = F h / (2π η) for a screw of lead h.
  static double motor_torque(double force, double lead, double efficiency);

  /// [Milutinovic] eq. 19: the part J θ̈ of the diagonal's acceleration.
  double acceleration_from_angular_acceleration(double theta, double theta_ddot) const;
  /// [Milutinovic] eq. 20: the part J_d⁻¹(J̇_θ - J̇_d J) θ̇ = (dJ/dθ) θ̇²
  /// (the paper prints θ̇; the factor is θ̇², docs/theory/pi_joint.md).
  double acceleration_from_angular_velocity(double theta, double theta_dot) const;
  /// [Milutinovic] eq. 18: d̈ = J θ̈ + J_d⁻¹(J̇_θ - J̇_d J) θ̇.
  double acceleration(double theta, double theta_dot, double theta_ddot) const;

  /// Passive angle φ of the diagonal O A, measured like θ from the normal of the
  /// fixed link: φ = atan2(k + sin θ, cos θ) ([Milutinovic] figure 9).
  double passive_angle(double theta) const;
  /// Transmission angle μ = φ - θ between the diagonal and the crank at A,
  /// 0 < μ <= 90° inside (-90°, 90°); J = a sin μ ([Milutinovic] figure 10).
  double transmission_angle(double theta) const;
};

/// The telescopic actuator of the prototype ([Milutinovic] Table 1). Lengths in the
/// file's unit.
struct PiJointActuator {
  double lead = 0.0;                 // screw lead h (per revolution)
  double resolution_per_step = 0.0;  // linear resolution
  double max_speed = 0.0;            // linear speed (per second)
  double max_force_N = 0.0;          // recommended thrust
  std::optional<double> efficiency;  // η of the screw (eq. 15), if known
};

struct PiJointParams {
  PiJointKinematics kinematics;
  double theta_min = 0.0;                // output angle range, radians, inside (-pi/2, pi/2)
  double theta_max = 0.0;
  std::optional<double> stroke_min;      // d range of the telescopic actuator, if given
  std::optional<double> stroke_max;
  std::optional<PiJointActuator> actuator;
  double meters_per_unit = 1e-3;         // the file's length unit in metres (torques in N m)
};

class PiJoint final : public Mechanism {
 public:
  /// Throws std::invalid_argument on a non-positive a or k, a θ range outside
  /// (-90°, 90°) or an empty stroke.
  explicit PiJoint(PiJointParams params);

  const PiJointParams& params() const { return params_; }
  const PiJointKinematics& kinematics() const { return params_.kinematics; }
  /// d range actually reachable: the θ range's image intersected with the stroke.
  double d_min() const;
  double d_max() const;

  /// Joint points in the frame of the header comment: O, O', Q, A.
  struct Points { Point o, o_prime, q, a; };
  Points points(double theta) const;

  // Mechanism (Pose.phi is θ; the one joint is d)
  std::string_view kind() const override { return "pi_joint"; }
  int dof() const override { return 1; }
  std::vector<JointInfo> joints() const override;
  std::vector<JointSolution> inverse(const Pose& pose) const override;
  std::vector<PoseSolution> direct(std::span<const double> joints) const override;
  std::vector<Evaluation> evaluate(const Pose& pose, const Criteria& criteria) const override;
  /// A lone Π-joint has no planar workspace: throws std::runtime_error.
  geometry::Region workspace() const override;
  bool reachable(const Pose& pose) const override;
  Drawing draw(const Pose& pose) const override;
  geometry::Box bounds() const override;
  /// io::Charts: the paper's figures (charts.cpp).
  Offer provide(std::type_index which) const override;

 private:
  std::string range_problem(double theta, double d) const;
  PiJointParams params_;
};

}  // namespace pkmws::mechanisms
