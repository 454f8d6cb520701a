// MOMA: reconfigurable 2-DOF planar parallel mechanism with two prismatic
// actuated guides and two rods of constant length meeting at the platform
// point P ([Vasilic]; docs/theory/moma.md).
#pragma once

#include <array>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "pkmws/mechanisms/mechanism.hpp"

namespace pkmws::mechanisms {

/// One leg: slider at S = R + p a, a = (cos alpha, sin alpha), p in the stroke,
/// rod of length l from S to P.
struct MomaLeg {
  Point reference;             // R_i
  double guide_angle = 0.0;    // alpha_i in radians
  double stroke_min = 0.0;     // p_i range
  double stroke_max = 0.0;
  double rod_length = 0.0;     // l_i
  int branch = -1;             // -1: [Vasilic] eq. 5 (minus root); +1: the other root
};

/// A P of the DK with the rods' geometry at that pose.
struct MomaAssembly {
  Point platform;
  int sign = 0;  // +1 / -1: side of the line S1S2 on which P lies (cross(S2-S1, P-S1))
};

/// Velocity relation A dP = B dp from differentiating [Vasilic] eq. 3.
struct MomaJacobians {
  Eigen::Matrix2d A;  // rows (P - S_i)^T
  Eigen::Matrix2d B;  // diag((P - S_i) . a_i)
};

class Moma final : public Mechanism, public GuidedRodLegs {
 public:
  /// Throws std::invalid_argument on non-positive rods or empty strokes.
  explicit Moma(std::array<MomaLeg, 2> legs);

  const std::array<MomaLeg, 2>& legs() const { return legs_; }
  /// Guide unit vector a_i.
  Point guide_direction(int leg) const;
  /// Slider position S_i = R_i + p a_i.
  Point slider(int leg, double p) const;

  /// [Vasilic] eq. 5-6 for leg i with the given branch (-1 eq. 5, +1 other root);
  /// nullopt when B^2 - C < 0 (P out of reach of the rod).
  std::optional<double> inverse_leg(int leg, Point p, int branch) const;

  /// Robust direct kinematics: circle-circle intersection of the two rods'
  /// circles about S1, S2; 0, 1 (tangent) or 2 assembly modes.
  std::vector<MomaAssembly> direct_all(double p1, double p2) const;

  /// The paper's closed form ([Vasilic] eq. 9-12), kept as a cross-check:
  /// nullopt where it is undefined (v4 == v1, or a negative discriminant).
  /// `sign` is the +- of eq. 10 (+1 for M2, -1 otherwise).
  std::optional<Point> direct_closed_form(double p1, double p2, int sign) const;

  MomaJacobians jacobians(Point p, double p1, double p2) const;

  // Mechanism
  std::string_view kind() const override { return "moma"; }
  int dof() const override { return 2; }
  std::vector<JointInfo> joints() const override;
  std::vector<JointSolution> inverse(const Pose& pose) const override;
  std::vector<PoseSolution> direct(std::span<const double> joints) const override;
  std::vector<Evaluation> evaluate(const Pose& pose, const Criteria& criteria) const override;
  geometry::Region workspace() const override;
  bool reachable(const Pose& pose) const override;
  Drawing draw(const Pose& pose) const override;
  /// The sliders at p_i = joints[i] (an assembly mode of dk), rods to the pose.
  Drawing draw_with_joints(const Pose& pose, std::span<const double> joints) const override;
  geometry::Box bounds() const override;

  /// GuidedRodLegs: the legs for the vectorised grid kernel.
  std::vector<GuidedRodLegs::Leg> guided_rod_legs() const override;
  Offer provide(std::type_index which) const override;

 private:
  std::array<MomaLeg, 2> legs_;
};

}  // namespace pkmws::mechanisms
