// Five-bar 5R planar parallel mechanism ([Briot], DexTAR; docs/theory/five_bar.md): base
// joints A_1 = A, A_2 = E, actuated cranks (proximal links) A_i B_i of length
// l_i1 at angle q_i, distal links B_i C of length l_i2 meeting at the tool C.
// Leg 1 is A B C, leg 2 is E D C. Optionally each crank is driven by an active
// Π-joint ([Milutinovic] figure 5), whose telescopic length d is then the joint.
//
// Working mode of leg i (docs/theory/five_bar.md): s_i = sign((C - A_i) x (B_i - A_i)).
// Assembly mode of a DK solution: the side of B->D on which C lies.
//
// Lengths are in the file's unit, angles in radians.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "pkmws/mechanisms/mechanism.hpp"
#include "mechanisms/pi_joint/pi_joint.hpp"

namespace pkmws::mechanisms {

/// A Π-joint driving the crank of a five-bar leg ([Milutinovic] figure 5): its crank
/// length a is the leg's proximal length, so it only adds k, the d stroke and
/// how it is mounted: crank angle q = base_angle + sense * θ_Π.
struct FiveBarPiDrive {
  double k = 0.4;               // b / a
  double stroke_min = 0.0;      // d range of the telescopic actuator
  double stroke_max = 0.0;
  double base_angle = 0.0;      // crank angle at θ_Π = 0 (the normal of the Π-joint's fixed link)
  int sense = 1;                // +1: q grows with θ_Π, -1: mirrored mounting
};

struct FiveBarLeg {
  Point base;                   // A_i
  double proximal = 0.0;        // l_i1 = |A_i B_i|
  double distal = 0.0;          // l_i2 = |B_i C|
  int working_mode = 1;         // s_i (+1 or -1)
  /// Crank-angle limits [min, max] (radians), 0 < max - min <= 2 pi; none: free rotation.
  std::optional<std::array<double, 2>> crank_limits;
  /// Π-joint drive (then crank_limits are derived from its stroke; give not both).
  std::optional<FiveBarPiDrive> pi_joint;
};

/// One DK solution: the tool C with its elbows B_1, B_2 (= B, D).
struct FiveBarAssembly {
  Point tool;
  std::array<Point, 2> elbows;
  int sign = 0;  // sign of (D - B) x (C - B); 0 for a tangent (type-2 singular) pose
};

/// Velocity relation A dC = B dq from differentiating |C - B_i(q_i)|² = l_i2².
struct FiveBarJacobians {
  Eigen::Matrix2d A;  // rows (C - B_i)^T; det A = 0: type-2 (parallel) singularity
  Eigen::Matrix2d B;  // diag(l_i1 (u_i x (C - B_i))), u_i = (cos q_i, sin q_i); B_ii = 0: type 1
};

class FiveBar final : public Mechanism {
 public:
  /// Throws std::invalid_argument on non-positive lengths, a bad working mode,
  /// bad limits or a Π-joint whose stroke does not fit its parallelogram.
  explicit FiveBar(std::array<FiveBarLeg, 2> legs);

  const std::array<FiveBarLeg, 2>& legs() const { return legs_; }
  /// Crank-angle limits in force (explicit or from the Π-joint), if any.
  std::optional<std::array<double, 2>> crank_limits(int leg) const;

  /// Elbow B_i = A_i + l_i1 (cos q, sin q).
  Point elbow(int leg, double q) const;
  /// s = sign((C - A_i) x (B_i - A_i)); 0 when C, A_i, B_i are collinear.
  static int working_mode_sign(Point base, Point elbow, Point tool);
  /// Crank angle q of leg i reaching C in working mode s (+-1):
  /// q = ψ + s β, ψ = angle of C - A_i, cos β = (ρ² + l1² - l2²) / (2 ρ l1);
  /// nullopt when C is outside the leg's annulus. Result in (-pi, pi], or in
  /// [min, min + 2 pi) when the leg has crank limits.
  std::optional<double> inverse_leg(int leg, Point c, int s) const;
  /// Robust DK: circle-circle intersection of |C - B| = l_12, |C - D| = l_22.
  std::vector<FiveBarAssembly> direct_all(double q1, double q2) const;
  FiveBarJacobians jacobians(Point c, double q1, double q2) const;
  /// ε: signed angle from distal link 1 (C - B) to distal link 2 (C - D), in (-pi, pi].
  double transmission_angle(Point c, double q1, double q2) const;

  /// Π-driven legs: d from a crank angle ([Milutinovic] eq. 2) and back (eq. 3-5).
  /// nullopt when θ_Π leaves (-90°, 90°) / d is out of the parallelogram's range.
  std::optional<double> pi_length(int leg, double q) const;
  std::optional<double> crank_from_pi_length(int leg, double d) const;

  /// Exact reachable workspace of one leg alone (its annulus, or with crank
  /// limits the region swept by its distal circle in its working mode).
  geometry::Region leg_workspace(int leg) const;

  // Mechanism. Joints are the crank angles q_i, or d_i for Π-driven legs.
  std::string_view kind() const override { return "five_bar"; }
  int dof() const override { return 2; }
  std::vector<JointInfo> joints() const override;
  std::vector<JointSolution> inverse(const Pose& pose) const override;
  std::vector<PoseSolution> direct(std::span<const double> joints) const override;
  std::vector<Evaluation> evaluate(const Pose& pose, const Criteria& criteria) const override;
  geometry::Region workspace() const override;
  bool reachable(const Pose& pose) const override;
  Drawing draw(const Pose& pose) const override;
  geometry::Box bounds() const override;

  /// Capabilities (module.cpp): criterion fields, body model.
  Offer provide(std::type_index which) const override;

 private:
  /// Joint value of leg i (crank angle or d) from a crank angle; nullopt if the
  /// Π-joint cannot take that angle.
  std::optional<double> joint_from_crank(int leg, double q) const;
  std::optional<double> crank_from_joint(int leg, double value) const;
  /// Why crank angle q is not allowed for leg i ("" if it is).
  std::string limit_problem(int leg, double q) const;
  std::array<FiveBarLeg, 2> legs_;
  std::array<std::optional<std::array<double, 2>>, 2> limits_;  // effective crank limits
};

/// The type-2 (parallel) singularity locus in the plane of C, as polylines for
/// plots: the poses where the distal links are aligned (ε = 0 or π), traced over
/// the cranks' joint space (see docs/theory/five_bar.md). With `all_modes`
/// false only the pieces in the mechanism's working mode and inside its crank
/// limits are returned. About `samples` points per closed branch.
std::vector<std::vector<Point>> type2_singularity_curves(const FiveBar& mechanism, bool all_modes = false,
                                                         int samples = 1024);

}  // namespace pkmws::mechanisms
