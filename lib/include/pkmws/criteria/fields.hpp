// Transmission criteria as scalar fields over the plane of the platform point
// P for one working mode ([Briot]; docs/theory/five_bar.md, §1.5), in the form the
// certified level-set module needs: each criterion c has a smooth surrogate s
// with the same sub-level sets, c(p) <= t  <=>  s(p) <= level(t), evaluable at
// points (double), over boxes (intervals) and with derivatives (jets).
//
//  * five-bar pressure angle α = acos|sin ε| ([Briot]): s = cos²ε,
//    level(α_max) = sin²α_max; reaction R = f / |sin ε| (no moment reaches C):
//    the same s with level(R_max) = 1 - (f / R_max)².
//  * planar 3-DOF (3-RPR) reaction of leg i: R_i,max = f |v_P,i| + |m| |ω_i|
//    (docs/theory/three_dof.md), s = R_i itself (N); pressure angle of leg i:
//    cos α_i = 1 / |v_B_i| ([Briot]: r_i . v_i = 1), s = |v_B_i|², level = 1 / cos²α.
//  * biglide velocity ratio V_i / V_y = |∂q_i/∂y| ([Strutynskyi] fig. 8), one field
//    per leg: s = (∂q_i/∂y)², level(t) = t².
//  * MOMA: pressure angle and reaction as the five-bar's (cos²ε of the rods).
//  * MOMA and five-bar: velocity ratio σ_max(dq/dP), s = σ_max², level(t) = t²;
//    condition number κ of dq/dP, s = -(det / F)², level(t) = -1 / (t + 1/t)².
//
// Units: lengths in the mechanism's unit, angles in degrees at this interface,
// forces in N.
#pragma once

#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "pkmws/certified/level_set.hpp"
#include "pkmws/mechanisms/mechanism.hpp"

namespace pkmws::criteria {

/// A criterion over the plane of P, with its surrogate field for level sets.
struct CriterionField {
  std::string name;   // "pressure_angle", "reaction"
  std::string unit;   // "deg", "N"
  /// Identifies the surrogate: two criteria with the same key and levels
  /// l1, l2 have the intersection of their sub-level sets at min(l1, l2).
  std::string key;
  std::shared_ptr<const certified::ScalarField> surrogate;
  /// Criterion threshold -> surrogate level (non-decreasing).
  std::function<double(double)> level;
  /// The thresholds that mean something: the open interval (threshold_min,
  /// threshold_max) (pressure angles (0, 90) deg; reactions and ratios > 0).
  double threshold_min = 0.0;
  double threshold_max = std::numeric_limits<double>::infinity();
  /// The criterion itself at a point (NaN where undefined, +inf at a singularity).
  std::function<double(geometry::Point)> value;
  /// Conservative test box ⊆ workspace (for cells that need no exact clipping).
  certified::WithinTest within_test;
  /// Non-empty when the criterion is infinite (or undefined) at every point,
  /// with the reason: every sub-level set is empty, nothing needs refining.
  std::string nowhere;
  /// The length L of x' = (x, y, L φ) the criterion uses (velocity ratio and
  /// condition number of the 3-DOF mechanisms, in the mechanism's unit); 0 when
  /// the criterion does not depend on one. Reports state it beside the threshold.
  double characteristic_length = 0.0;
};

/// Capability (Mechanism::capability): the criteria of a mechanism as fields.
/// Each mechanism module implements it beside its kinematics.
struct CriterionFields {
  static constexpr std::string_view capability_name =
      "certified criterion fields (level sets of the pressure angle, reaction, velocity ratio or condition number)";
  virtual ~CriterionFields() = default;
  /// The fields of criterion `name` ("pressure_angle", "reaction",
  /// "velocity_ratio", "condition_number") for the file's criteria and reaction legs (1-based,
  /// empty: every leg); throws std::invalid_argument with a one-line reason
  /// when this mechanism cannot give them.
  virtual std::vector<CriterionField> fields(const std::string& name, const mechanisms::Criteria& criteria,
                                             const std::vector<int>& reaction_legs) const = 0;
  /// The type-2 (parallel) singularity of the working mode at the file's
  /// orientation as the zero set of a signed determinant g = det A (A the
  /// direct-kinematics Jacobian; the criterion `singularity_distance`):
  /// `surrogate` is g (C² where its domain test says inside), `within_test`
  /// classifies boxes against the workspace, `value` is g at a point, level 0.
  /// Throws std::invalid_argument with a one-line reason when this mechanism
  /// cannot give it (the default).
  virtual CriterionField singular_determinant(const mechanisms::Criteria& criteria) const;
  /// A workspace W not bounded by arcs and segments only (the real-scheme
  /// biglide: a coupler curve, docs/theory/biglide.md) as an exact region cut
  /// by sub-level sets of smooth fields, W = within ∩ ⋂_k { F_k <= level_k }:
  /// their level curves are traced with the criteria's, so that a limited
  /// workspace is certified against W itself. `within_test` classifies boxes
  /// against W. Absent (the default): W is the exact Mechanism::workspace().
  struct WorkspaceCut {
    std::shared_ptr<const certified::ScalarField> field;
    double level = 0.0;
  };
  struct WorkspaceSets {
    geometry::Region within;
    certified::WithinTest within_test;
    std::vector<WorkspaceCut> cuts;
  };
  virtual std::optional<WorkspaceSets> workspace_sets() const { return std::nullopt; }
  /// Charts (docs/theory/level_sets.md, "Charts"): where the fields are
  /// singular on W's boundary (a leg stretched) or at a point of W (a base
  /// joint of equal links), every level curve ends there and no cell touching
  /// it can be traced. W is then cut into `rest`, traced in (x, y), and parts
  /// each traced in a chart whose coordinates make the fields smooth up to the
  /// singular set, with the chart's area element. Absent (the default): W is
  /// traced in (x, y) alone.
  struct Chart {
    geometry::Box window;                 // in the chart's coordinates (u, v)
    certified::AreaWeight weight;         // dA = ρ du dv
    std::vector<WorkspaceCut> cuts;       // the chart's part of W: ⋂ {F_k <= level_k} in the window
    double overlap = 0.0;                 // a bound on the area the window counts twice (taken off lower bounds)
    double uncovered = 0.0;               // a bound on the area of W in neither the rest nor a window (added to upper bounds)
    std::function<geometry::Point(geometry::Point)> to_plane;  // (u, v) -> (x, y), for the traced curves
    /// The surrogate of the criterion field with this key in the chart's
    /// coordinates; null when the chart does not have it.
    std::function<std::shared_ptr<const certified::ScalarField>(const std::string& key)> field;
  };
  struct Charts {
    geometry::Region rest;                // W minus the charts' parts (exact)
    certified::WithinTest rest_test;      // boxes against rest (inside only if box ⊆ rest)
    /// rest as an intersection of disks and complements of disks, when it is
    /// one (LevelSetOptions::within_disks; empty: not known).
    std::vector<certified::SignedDisk> rest_disks;
    std::vector<Chart> charts;
  };
  /// `workspace`: W (the exact Mechanism::workspace()).
  virtual std::optional<Charts> charts(const geometry::Region& /*workspace*/) const { return std::nullopt; }
};

/// The fields of a criterion for a design (a mechanism file is one), one per limited leg (their
/// sub-level sets are intersected; for the 3-RPR also the assembly mode of the
/// workspace's centre). `name`: "pressure_angle", "reaction" or (biglide)
/// "velocity_ratio".
/// `threshold`: the limit they will be used at, in place of the file's (a
/// field's form may depend on it: a point platform's transmission limits take
/// the better conditioned of two forms of the same set; any form holds for
/// every threshold through its `level`).
/// Throws InputError (pkmws/core/error.hpp) when the mechanism does not support it.
std::vector<CriterionField> fields_for(const mechanisms::Design& file, const std::string& name,
                                       std::optional<double> threshold = std::nullopt);

/// One limit of the file's `criteria`: a criterion and its threshold.
struct Limit {
  std::string name;
  double threshold = 0.0;
};
/// The limits in the file (max_pressure_angle_deg, max_reaction_N, ...,
/// min_singularity_distance as "singularity_distance", a lower limit; throws
/// InputError (pkmws/core/error.hpp) for max_velocity_ratio where unsupported).
std::vector<Limit> file_limits(const mechanisms::Design& file);

/// Result of a criteria-limited workspace: W ∩ ⋂ {c_k <= t_k}.
struct LimitedWorkspace {
  certified::CertifiedRegion region;     // inner/outer built when asked
  std::vector<certified::CurvePiece> curves;  // the criteria's traced level curves (charts' mapped to the plane)
  certified::LevelSetResult detail;      // pieces and statistics (region and curves moved out)
  double time_ms = 0.0;
  /// Parts of W were traced in charts (docs/theory/level_sets.md, "Charts"):
  /// detail's pieces (inside_boxes, inner_polygons) then cover the rest only.
  bool charted = false;
  /// Why the region is empty without any refinement (a field's `nowhere`), or "".
  std::string note;
  /// With min_singularity_distance (docs/theory/level_sets.md, distance to
  /// the type-2 singularity): the traced singular set S ∩ W as chord
  /// polylines, their certified distance bound w to the true curve (each
  /// point of S outside `singular_undecided` boxes is within w of a chord and
  /// each chord point within w of S), and the boxes where S was not traced.
  std::vector<std::vector<geometry::Point>> singular_curves;
  double singular_error = 0.0;
  std::vector<geometry::Box> singular_undecided;
};
/// The workspace of `file` limited by `limits` (same surrogate: the stricter
/// level; several surrogates: one certified intersection of sub-level sets).
LimitedWorkspace limited_workspace(const mechanisms::Design& file, const std::vector<Limit>& limits,
                                   const certified::LevelSetOptions& options);

/// The grid samplers' view of a criteria-limited workspace: the file's
/// mechanism whose reachable() also asks every criterion surrogate to be within
/// its level (the same fields and levels as limited_workspace). Everything else
/// is delegated; workspace() throws (that region is certified, not exact).
std::shared_ptr<const mechanisms::Mechanism> limited_mechanism(const mechanisms::Design& file);

/// d(P) = dist(P, S), S the working mode's type-2 singular set inside the
/// workspace (as min_singularity_distance uses it), for `pkmws eval`.
struct SingularityDistance {
  double lower = 0.0, upper = 0.0;  // certified bounds on d(P) (infinite: S ∩ W is empty)
  double error = 0.0;               // the traced chords' distance bound w
  std::string note;                 // S ∩ W empty, or S all of W
};
/// S traced to 1e-6 of the workspace's diagonal; nothing when the mechanism
/// has no singular-determinant field.
std::optional<SingularityDistance> singularity_distance_at(const mechanisms::Design& file, geometry::Point p);

/// The workspace the criteria are restricted to: Mechanism::workspace(), or
/// for a workspace cut by level sets (CriterionFields::workspace_sets) the
/// outer enclosure Mechanism::workspace_enclosure() gives (for figures and
/// tables; limited_workspace certifies against W itself).
geometry::Region criteria_domain(const mechanisms::Design& file);
/// False when criteria_domain is an outer enclosure (a workspace cut by level sets).
bool criteria_domain_exact(const mechanisms::Design& file);
/// The mechanism's workspace cut by level sets (CriterionFields::workspace_sets),
/// or nothing when its workspace is exact.
std::optional<CriterionFields::WorkspaceSets> workspace_sets(const mechanisms::Design& file);
/// The workspace as an enclosure: for a workspace cut by level sets, the
/// traced sets at `relative_tolerance` (regions following the traced curves),
/// else Mechanism::workspace_enclosure() (exact where it can be).
certified::CertifiedRegion workspace_enclosure(const mechanisms::Design& file, double relative_tolerance = 1e-6);

}  // namespace pkmws::criteria
