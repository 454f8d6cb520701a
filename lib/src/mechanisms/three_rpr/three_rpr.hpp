// 3-RPR planar parallel mechanism ([Briot]; docs/theory/three_dof.md): base revolutes A_i,
// legs A_i B_i of variable length ρ_i (prismatic), platform revolutes
// B_i = P + R(phi) b'_i. Two actuations:
//  * revolute (R̲PR, the planar PAMINSA): the base angles q_i of the legs are
//    actuated; leg i transmits a force through B_i perpendicular to the leg;
//  * prismatic (RP̲R): the leg lengths ρ_i are actuated; the force is along the leg.
//
// Transmission ([Briot]): A rows f_i = [r_i; (B_i - Q) x r_i] about a
// reference point Q (the paper reduces to B_1), w = -A^T R; twists, pressure
// angles and R_i,max from planar_transmission.hpp. Type-2 singularity:
// det A = 0. Velocity relation A [v_P; ω] = B q̇: prismatic B = I
// (ρ̇_i = u_i . v_B_i), revolute B = diag(ρ_i) (ρ_i q̇_i = u_i^⊥ . v_B_i).
//
// Direct kinematics (docs/theory/three_dof.md):
//  * prismatic: with Y = B_1, the differences of the three circle equations are
//    linear in Y; substituting into |Y - A_1|^2 = ρ_1^2 and t = tan((phi - phi0)/2)
//    gives a polynomial of degree 8 in t that always has the factor 1 + t^2
//    (the circular points): the eliminant is the remaining sextic, whose real
//    roots (Sturm-certified) give up to 6 assembly modes;
//  * revolute: the legs are fixed lines through the A_i; B_i on them is linear
//    in P for each phi, and the consistency of the three equations is
//    C cos phi + S sin phi = E: 0, 1, 2 assembly modes (or a continuum when
//    C = S = E = 0, e.g. PAMINSA with cos phi = R_p / R_b).
//
// Lengths in the file's unit, angles in radians.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "pkmws/mechanisms/mechanism.hpp"
#include "pkmws/mechanisms/planar_transmission.hpp"
#include "pkmws/mechanisms/polynomial_roots.hpp"

namespace pkmws::mechanisms {

enum class ThreeRprActuation {
  revolute,   // R̲PR: base-joint angles actuated (PAMINSA)
  prismatic,  // RP̲R: leg lengths actuated
};

/// Velocity relation A [v_P; ω] = B q̇.
struct ThreeRprJacobians {
  Eigen::Matrix3d A;  // rows [r_i^T, (B_i - P) x r_i]
  Eigen::Matrix3d B;  // identity (prismatic) or diag(ρ_i) (revolute)
};

/// Every pose of the direct kinematics with the eliminant it came from.
struct ThreeRprDirect {
  std::vector<Pose> poses;              // sorted by phi; phi in (-pi, pi]
  bool continuum = false;               // the joint values admit a continuum of poses (none listed)
  // Prismatic actuation only:
  double phi_offset = 0.0;              // phi0 of t = tan((phi - phi0) / 2)
  std::vector<long double> eliminant;   // the sextic in t, ascending (lengths scaled by `length_scale`)
  std::array<long double, 2> circular_remainder{};  // remainder of the degree-8 polynomial by 1 + t^2 (~0)
  double length_scale = 1.0;
  PolynomialRoots roots;                // of the sextic
};

class ThreeRpr final : public Mechanism, public PoseSlice, public Elimination {
 public:
  /// `base` A_i and `platform` b'_i (platform frame); `orientation` is the
  /// constant orientation of workspace(); `leg_limits` [ρ_min, ρ_max] per leg.
  /// Throws std::invalid_argument on non-finite input, coincident base or
  /// platform points, or bad limits (0 <= ρ_min < ρ_max).
  /// `analysis_window` (optional): a box of positions of P that bounds the
  /// workspace where no leg limits do (PAMINSA's criterion-limited regions).
  ThreeRpr(std::array<Point, 3> base, std::array<Point, 3> platform, ThreeRprActuation actuation,
           double orientation = 0.0, std::optional<std::array<std::array<double, 2>, 3>> leg_limits = std::nullopt,
           std::optional<geometry::Box> analysis_window = std::nullopt);

  /// The symmetric design of [Briot] (PAMINSA): A_i = R_b u(θ_i),
  /// b'_i = R_p u(θ_i), θ = -90°, 30°, 150°.
  static ThreeRpr symmetric(double base_radius, double platform_radius, ThreeRprActuation actuation,
                            double orientation = 0.0,
                            std::optional<std::array<std::array<double, 2>, 3>> leg_limits = std::nullopt);

  const std::array<Point, 3>& base() const { return base_; }
  const std::array<Point, 3>& platform() const { return platform_; }
  ThreeRprActuation actuation() const { return actuation_; }
  double orientation() const override { return orientation_; }
  const std::optional<std::array<std::array<double, 2>, 3>>& leg_limits() const { return leg_limits_; }
  const std::optional<geometry::Box>& analysis_window() const { return window_; }

  /// B_i at a pose.
  std::array<Point, 3> platform_points(const Pose& pose) const;
  /// ρ_i = |B_i - A_i|.
  std::array<double, 3> leg_lengths(const Pose& pose) const;
  /// q_i = angle of B_i - A_i (radians, (-pi, pi]).
  std::array<double, 3> leg_angles(const Pose& pose) const;

  /// Lines of action of the forces the legs transmit: through B_i, along the
  /// leg (prismatic) or perpendicular to it, r_i = (-sin q_i, cos q_i) (revolute).
  std::array<ActuationLine, 3> actuation_lines(const Pose& pose) const;
  /// [Briot]'s A (w = -A^T R) referred to `reference` (the paper uses B_1).
  Eigen::Matrix3d wrench_matrix(const Pose& pose, Point reference) const;
  /// Twists, pressure angles, levers about P (planar_transmission.hpp).
  Transmission transmission(const Pose& pose) const;
  /// R_i,max = f |v_P,i| + |m| |ω_i| (docs/theory/three_dof.md), N.
  std::array<double, 3> reaction_max(const Pose& pose, const Load& load) const;
  ThreeRprJacobians jacobians(const Pose& pose) const;
  /// det A = 0 (within 1e-9 of the scale): lines of action concurrent or parallel.
  bool type2_singular(const Pose& pose) const;

  /// Direct kinematics from leg lengths (any actuation: the geometric problem).
  ThreeRprDirect direct_from_lengths(const std::array<double, 3>& lengths) const;
  /// Direct kinematics from base angles (any actuation). Poses whose legs would
  /// need a negative length (B_i behind A_i) are kept; direct() flags them.
  ThreeRprDirect direct_from_angles(const std::array<double, 3>& angles) const;

  /// Exact workspace at orientation phi with the leg limits: the intersection
  /// of the annuli ρ_min <= |P - (A_i - R(phi) b'_i)| <= ρ_max, clipped to the
  /// analysis window when one is given. Throws std::runtime_error with neither
  /// (the workspace is then the plane).
  geometry::Region workspace_at(double phi) const override;
  /// The direct-kinematics eliminant for joint values q (capability Elimination).
  Elimination::Report elimination(std::span<const double> joints) const override;
  /// PoseSlice and Elimination (mechanism.hpp: capability<C>()).
  Offer provide(std::type_index which) const override;

  // Mechanism. Joints: base angles q_i (revolute) or leg lengths ρ_i (prismatic).
  std::string_view kind() const override { return "three_rpr"; }
  int dof() const override { return 3; }
  std::vector<JointInfo> joints() const override;
  std::vector<JointSolution> inverse(const Pose& pose) const override;
  std::vector<PoseSolution> direct(std::span<const double> joints) const override;
  std::vector<Evaluation> evaluate(const Pose& pose, const Criteria& criteria) const override;
  geometry::Region workspace() const override;
  bool reachable(const Pose& pose) const override;
  Drawing draw(const Pose& pose) const override;
  geometry::Box bounds() const override;
  std::string workspace_label() const override;

  /// Platform circumradius-like length for the conditioning of dq/dx: the
  /// largest |b'_i - centroid|.
  double characteristic_length() const { return characteristic_length_; }

 private:
  std::string leg_problem(int leg, double length) const;
  std::array<Point, 3> base_;
  std::array<Point, 3> platform_;
  ThreeRprActuation actuation_;
  double orientation_ = 0.0;
  std::optional<std::array<std::array<double, 2>, 3>> leg_limits_;
  std::optional<geometry::Box> window_;
  double characteristic_length_ = 1.0;
};

}  // namespace pkmws::mechanisms
