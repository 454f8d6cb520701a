// Biglide: two parallel horizontal guides with sliders S_1 = (q_1, -B) and
// S_2 = (q_2, +B) (table width 2B) and links of constant length ([Strutynskyi];
// docs/theory/biglide.md).
//
// Simplified scheme ([Strutynskyi] fig. 1, 3): rods l_1 from S_1 and l_2 from S_2
// meet at the tool P.
// Real scheme (fig. 2, 4): the first link is a rigid triangle S_1 J T with
// |S_1 J| = l_1, |S_1 T| = l_3, |J T| = l_4; rod l_2 joins S_2 to J and the tool
// is T. The simplified scheme is the real one with T = J (l_3 = l_1, l_4 = 0).
//
// Angles of the paper are measured from +y, clockwise (x = l sin φ, y = l cos φ).
// The paper's branch takes the minus roots of eq. 5-8: the tool is ahead (+x) of
// slider 1 and J ahead of slider 2; its assembly mode puts J on the +x side of
// S_1 S_2. Lengths in the file's unit.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "pkmws/mechanisms/mechanism.hpp"

namespace pkmws::mechanisms {

/// The tool link of the real scheme ([Strutynskyi] fig. 4).
struct BiglideTool {
  double l3 = 0.0;  // |S_1 T|
  double l4 = 0.0;  // |J T|
};

struct BiglideParams {
  double half_width = 0.0;                        // B
  std::array<double, 2> rods{};                   // l_1 (S_1 to J), l_2 (S_2 to J)
  std::array<std::array<double, 2>, 2> strokes{}; // [q_min, q_max] of each slider
  std::optional<BiglideTool> tool;                // real scheme
  double meters_per_unit = 1e-3;                  // the file's length unit in metres (moments in N m)
};

/// One DK solution.
struct BiglideAssembly {
  Point tool;   // P (simplified) or T (real)
  Point joint;  // J, where rod 2 meets link 1 (= tool for the simplified scheme)
  int sign = 0; // sign of (S_2 - S_1) x (J - S_1): -1 is the paper's (eq. 1), 0 tangent
};

class Biglide final : public Mechanism {
 public:
  /// Throws std::invalid_argument on non-positive lengths, empty strokes or a
  /// tool triangle that violates the triangle inequality.
  explicit Biglide(BiglideParams params);

  const BiglideParams& params() const { return params_; }
  bool real_scheme() const { return params_.tool.has_value(); }
  /// |S_1 T|: l_3, or l_1 for the simplified scheme.
  double tool_distance() const;
  /// γ: angle at S_1 between S_1 J and S_1 T, cos γ = (l_1² + l_3² - l_4²) / (2 l_1 l_3); 0 when simplified.
  double gamma() const;
  Point slider(int i, double q) const;
  /// Leg 1 alone, exactly: the tool within l_3 of slider 1 and ahead of it
  /// (the paper's branch) over slider 1's stroke. The workspace of the
  /// simplified scheme is this band intersected with leg 2's; the real
  /// scheme's is this band cut by leg 2's chain (a coupler curve).
  geometry::Region tool_band() const;

  /// Joint J of a pose: J = S_1 + (l_1 / l_3) R(γ) (T - S_1) (the triangle is rigid).
  Point joint_of(Point tool, double q1) const;
  /// Geometric IK for branches b_i (-1: the paper's minus roots, eq. 5-8; +1 the
  /// others); nullopt when a link cannot reach.
  std::optional<std::array<double, 2>> inverse_joints(Point tool, int b1 = -1, int b2 = -1) const;
  /// The paper's closed forms: eq. 5-6 (simplified) or eq. 7-8 (real, needs
  /// l_4 > 0). Eq. 8's last term is printed with -acos(.) where the geometry of
  /// eq. 3-4 needs +acos(.); `as_printed` evaluates the printed sign.
  std::optional<std::array<double, 2>> inverse_closed_form(Point tool, bool as_printed = false) const;

  /// Robust DK: J from circle(S_1, l_1) ∩ circle(S_2, l_2), then T on the rigid triangle.
  std::vector<BiglideAssembly> direct_all(double q1, double q2) const;
  /// The paper's closed form eq. 1-2 (simplified) or eq. 3-4 (real); nullopt
  /// where the arccos argument leaves [-1, 1].
  std::optional<Point> direct_closed_form(double q1, double q2) const;

  /// dq/dx (rows q_1, q_2; columns x, y) for branches b_i; infinite entries at
  /// type-1 singularities. Note dq_i/dx = 1.
  Eigen::Matrix2d inverse_jacobian(Point tool, int b1 = -1, int b2 = -1) const;
  /// The paper's velocity ratio ([Strutynskyi] fig. 8): V_i / V_y = |∂q_i/∂y| for a
  /// tool moving along y at constant x, paper's branches.
  std::array<double, 2> velocity_ratio_y(Point tool) const;

  /// [Strutynskyi] eq. 9, in the form consistent with eq. 3-4: the rod length l_2
  /// that puts the tool on y = 0 at q_1 = q_2: l_2² = 4B² + l_1² - 4B l_1 cos(acos(B/l_3) - γ).
  static double zero_position_rod_length(double half_width, double l1, double l3, double l4);
  /// [Strutynskyi] eq. 9 as printed: cos(π/2 - (γ - asin(B/l_3))) (see docs/theory/biglide.md).
  static double zero_position_rod_length_as_printed(double half_width, double l1, double l3, double l4);

  // Mechanism
  std::string_view kind() const override { return "biglide"; }
  int dof() const override { return 2; }
  std::vector<JointInfo> joints() const override;
  std::vector<JointSolution> inverse(const Pose& pose) const override;
  std::vector<PoseSolution> direct(std::span<const double> joints) const override;
  std::vector<Evaluation> evaluate(const Pose& pose, const Criteria& criteria) const override;
  /// Simplified scheme: the exact intersection of the two leg bands. Real
  /// scheme: throws std::runtime_error (its boundary contains coupler curves of
  /// a slider-crank, neither circles nor lines; docs/theory/biglide.md).
  geometry::Region workspace() const override;
  /// Simplified scheme: exact. Real scheme: certified — the leg-1 band
  /// (|T - S_1| = l_3 along the stroke) is exact, and a quadtree with an
  /// interval-arithmetic cell test of the leg-2 chain (J, q_2 within its
  /// stroke) encloses the coupler-curve parts of the boundary.
  certified::CertifiedRegion workspace_enclosure(int max_depth = 9) const override;
  bool reachable(const Pose& pose) const override;
  Drawing draw(const Pose& pose) const override;
  geometry::Box bounds() const override;

  /// Capabilities (module.cpp): criterion fields.
  Offer provide(std::type_index which) const override;

 private:
  std::string stroke_problem(int i, double q) const;
  BiglideParams params_;
};

}  // namespace pkmws::mechanisms
