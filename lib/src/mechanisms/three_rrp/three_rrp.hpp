// 3-RRP and 3-PRP planar parallel mechanisms ([Mitsi]; docs/theory/three_dof.md): three
// actuated chains move the external revolutes A_i of the Assur group RP-RP-RP
// (assur_rprprp.hpp), whose slider i runs on side line i = B_i B_{i+1} of the
// platform triangle.
//
//   3-RRP: A_i = O_i + r_i (cos φ_i, sin φ_i), joint φ_i the crank angle   ([Mitsi] eq. 1)
//   3-PRP: A_i = O_i + s_i (cos δ_i, sin δ_i), joint s_i along direction δ_i (eq. 2)
//
// Pose: the platform frame's origin P (the tool point) and its rotation phi;
// the platform points B'_i are given in that frame, counter-clockwise.
// Lengths in the file's unit, angles in radians.
//
// Velocity relation (docs/theory/three_dof.md): side line i is
// {X : n_i . X = n_i . B_i}, n_i = R(phi) n'_i its outward normal; keeping A_i
// on it gives A [v_P; ω] = B q̇ with
//   A row i = [n_i^T, (A_i - P) x n_i]   (the wrench of the force chain i transmits:
//                                         along n_i through A_i, a slider carries no force along its rail)
//   B_ii   = r_i (u(φ_i) x n_i)          (3-RRP)   or   n_i . d_i   (3-PRP).
// det A = 0: type-2 singularity (the three normals through the A_i concurrent
// or parallel; the assembly modes meet there); B_ii = 0: type-1 (crank
// perpendicular to its side line / guide parallel to it).
//
// Working modes (3-RRP): crank i reaches side line i at up to two angles;
// σ_i = sign((A_i - O_i) . u_i), u_i the side's direction: 8 working modes.
// The 3-PRP has one. Assembly modes: the sign of det A.
//
// Constant-orientation workspace: at fixed phi the condition on chain i is
// linear in P, n_i . P = n_i . A_i(q_i) - h_i, so with the joint range of the
// chain P lies in a strip: the workspace is the intersection of three strips
// (exact). Without limits a 3-RRP crank still gives a strip of width 2 r_i; an
// unlimited 3-PRP slider gives a half-plane or the whole plane, and the
// workspace is unbounded (workspace() throws).
#pragma once

#include <array>
#include <optional>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "mechanisms/three_rrp/assur_rprprp.hpp"
#include "pkmws/mechanisms/mechanism.hpp"
#include "pkmws/mechanisms/planar_transmission.hpp"

namespace pkmws::mechanisms {

enum class ThreeRrpDrive {
  crank,   // 3-RRP: actuated base revolute with a crank O_i A_i
  slider,  // 3-PRP: actuated prismatic joint along a fixed direction
};

struct ThreeRrpChain {
  Point base;                  // O_i
  double crank_length = 0.0;   // r_i = |O_i A_i| (3-RRP)
  double direction = 0.0;      // δ_i, direction of the actuated slider (3-PRP), radians
  /// Joint range: crank angles [min, max] (radians, 0 < max - min <= 2 pi) for
  /// the 3-RRP, displacements [min, max] for the 3-PRP; none: unlimited.
  std::optional<std::array<double, 2>> limits;
};

/// Velocity relation A [v_P; ω] = B q̇ (v_P in unit/s, ω and crank rates in rad/s).
struct ThreeRrpJacobians {
  Eigen::Matrix3d A;  // rows [n_i^T, (A_i - P) x n_i]
  Eigen::Matrix3d B;  // diagonal
};

/// One chain's inverse kinematics: the joint value putting A_i on side line i.
struct ThreeRrpChainSolution {
  int sigma = 1;         // working mode σ_i (+1 / -1; always +1 for the 3-PRP)
  double joint = 0.0;    // φ_i (radians, in [min, min + 2 pi) with limits, else (-pi, pi]) or s_i
  Point external_joint;  // A_i
};

class ThreeRrp final : public Mechanism, public PoseSlice, public Elimination {
 public:
  /// Throws std::invalid_argument on a bad platform triangle (not
  /// counter-clockwise or degenerate), non-positive cranks or bad limits.
  ThreeRrp(ThreeRrpDrive drive, std::array<ThreeRrpChain, 3> chains, std::array<Point, 3> platform,
           double orientation = 0.0);

  ThreeRrpDrive drive() const { return drive_; }
  const std::array<ThreeRrpChain, 3>& chains() const { return chains_; }
  const AssurTriangle& triangle() const { return triangle_; }
  /// The constant orientation of workspace() (the file's orientation_deg), radians.
  double orientation() const override { return orientation_; }

  /// A_i from the joint value ([Mitsi] eq. 1-2).
  Point external_joint(int chain, double joint) const;
  /// Platform points B_1, B_2, B_3 at a pose.
  std::array<Point, 3> platform_points(const Pose& pose) const;
  /// Every joint value of chain i putting A_i on side line i at the pose (0, 1
  /// or 2 for a crank; 0 or 1 for a slider), regardless of limits.
  std::vector<ThreeRrpChainSolution> inverse_chain(int chain, const Pose& pose) const;
  /// Why joint value q is outside chain i's limits ("" when inside).
  std::string limit_problem(int chain, double joint) const;

  /// Direct kinematics by the closed form (assur_closed_form) and by the
  /// paper's elimination (assur_elimination), for joint values q (size 3).
  std::vector<AssurAssembly> direct_closed_form(std::span<const double> joints) const;
  AssurElimination direct_elimination(std::span<const double> joints) const;

  ThreeRrpJacobians jacobians(const Pose& pose, std::span<const double> joints) const;
  /// Lines of action (through A_i along n_i) and the [Briot] analysis about P.
  Transmission transmission(const Pose& pose, std::span<const double> joints) const;

  /// Range [lo, hi] of n_i . P allowed by chain i at orientation phi (the
  /// strip of the constant-orientation workspace); nullopt when unbounded.
  std::optional<std::array<double, 2>> strip_range(int chain, double phi) const;
  /// Exact constant-orientation workspace at orientation phi.
  geometry::Region workspace_at(double phi) const override;
  /// The direct-kinematics eliminant for joint values q (capability Elimination).
  Elimination::Report elimination(std::span<const double> joints) const override;
  /// PoseSlice and Elimination (mechanism.hpp: capability<C>()).
  Offer provide(std::type_index which) const override;
  /// A box holding the workspace at orientation phi (throws when unbounded).
  geometry::Box bounds_at(double phi) const;

  // Mechanism (workspace, bounds, reachable: at orientation()). Joints: crank
  // angles φ_i (3-RRP) or displacements s_i (3-PRP).
  std::string_view kind() const override { return drive_ == ThreeRrpDrive::crank ? "three_rrp" : "three_prp"; }
  int dof() const override { return 3; }
  std::vector<JointInfo> joints() const override;
  std::vector<JointSolution> inverse(const Pose& pose) const override;
  std::vector<PoseSolution> direct(std::span<const double> joints) const override;
  std::vector<Evaluation> evaluate(const Pose& pose, const Criteria& criteria) const override;
  geometry::Region workspace() const override;
  bool reachable(const Pose& pose) const override;
  Drawing draw(const Pose& pose) const override;
  /// The cranks / sliders at the given joint values (an assembly mode of dk).
  Drawing draw_with_joints(const Pose& pose, std::span<const double> joints) const override;
  geometry::Box bounds() const override;

  /// Characteristic length used to make the angular column of dq/dx
  /// commensurate in condition_number: the platform's circumradius.
  double characteristic_length() const { return characteristic_length_; }

 private:
  std::array<Point, 3> external_joints(std::span<const double> joints) const;
  ThreeRrpDrive drive_;
  std::array<ThreeRrpChain, 3> chains_;
  AssurTriangle triangle_;
  double orientation_ = 0.0;
  double characteristic_length_ = 1.0;
};

}  // namespace pkmws::mechanisms
