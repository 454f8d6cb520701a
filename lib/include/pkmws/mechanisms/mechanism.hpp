// The interface every planar parallel mechanism implements. Values are in the
// mechanism file's length unit and in radians; the CLI converts angles to degrees.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <typeindex>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "pkmws/certified/cell_region.hpp"
#include "pkmws/geometry/region.hpp"
#include "pkmws/geometry/types.hpp"
#include "pkmws/mechanisms/capability.hpp"

namespace pkmws::mechanisms {

using geometry::Point;

/// Platform pose: position of the platform point P and orientation phi (radians;
/// ignored by 2-DOF mechanisms; for the 1-DOF Pi-joint `phi` is the crank angle).
struct Pose {
  double x = 0.0;
  double y = 0.0;
  double phi = 0.0;
};

/// What a joint value is, so that output can be labelled and converted.
struct JointInfo {
  std::string name;   // e.g. "p1", "theta1"
  bool angle = false; // radians inside, degrees in files and output
  /// The joint's travel [min, max] where the file bounds it (stroke, crank
  /// limits; radians for angles), absent where it is free or unknown.
  std::optional<std::array<double, 2>> range;
};

/// One inverse-kinematics solution (one working mode).
struct JointSolution {
  std::string mode;            // working mode label, e.g. "(-1,-1)"
  std::vector<double> joints;  // one per actuator
  bool valid = false;          // within strokes/limits
  std::string reason;          // why not valid (empty when valid)
};

/// One direct-kinematics solution (one assembly mode).
struct PoseSolution {
  std::string mode;                     // assembly mode label
  Pose pose;
  std::vector<Point> platform_points;   // 3-DOF: B1, B2, B3 in the base frame
  bool valid = false;                   // consistent with the working mode / limits
  std::string reason;
};

/// Load applied at the platform point P: force of norm `force_N` in any
/// direction, moment +-`moment_Nm` (docs/theory/three_dof.md).
struct Load {
  double force_N = 0.0;
  double moment_Nm = 0.0;
};

/// Optional criteria from the mechanism file (docs/format.md).
struct Criteria {
  std::optional<double> max_pressure_angle_deg;
  std::optional<double> max_reaction_N;
  std::optional<Load> load;
  std::optional<double> max_velocity_ratio;
  std::optional<double> max_condition_number;
  /// L of the homogenised Jacobian dq/dx', x' = (x, y, L φ), of a 3-DOF
  /// mechanism (condition number, velocity ratio); none: the mechanism's default.
  std::optional<double> characteristic_length;
  /// Lower limit on the distance in the plane from P to the type-2 singular
  /// set of the working mode inside the workspace (length unit, > 0).
  std::optional<double> min_singularity_distance;
  bool any() const {
    return max_pressure_angle_deg || max_reaction_N || max_velocity_ratio || max_condition_number ||
           min_singularity_distance;
  }
};

/// Every criterion at one pose, for one working/assembly mode (`pkmws eval`).
struct Evaluation {
  std::string mode;
  bool reachable = false;
  std::string reason;                       // why not reachable
  std::vector<double> joints;
  double jacobian_det = 0.0;                // det of dq/dx (inverse-kinematic Jacobian)
  double condition_number = 0.0;            // 2-norm condition number of dq/dx (inf if singular)
  bool singular = false;
  std::string singularity;                  // "", "type1" (serial), "type2" (parallel), "both"
  std::vector<double> pressure_angle_deg;   // one per leg
  std::vector<double> reactions_N;          // R_i,max per leg for the load (empty without load)
  std::optional<double> velocity_ratio;     // actuator speed / tool speed, worst direction
  std::vector<std::pair<std::string, double>> extra;  // mechanism-specific figures
};

/// A mechanism drawn at one pose, for figures.
struct Drawing {
  struct Segment { Point a, b; };
  std::vector<Segment> guides;     // fixed guides / base lines (drawn dashed)
  std::string guides_legend = "guide";  // what the dashed lines are, in a figure's legend
  std::vector<Segment> links;      // rods, cranks, platform sides
  std::vector<Point> joints;       // revolute joints
  std::vector<Point> sliders;      // prismatic joints (sliders)
  std::vector<Point> base_points;  // fixed joints
  Point tool;                      // the platform point P
  /// 3-DOF: the platform's vertices B_1, B_2, ... at the pose (drawn filled); empty otherwise.
  std::vector<Point> platform;
  /// Type-2 (parallel) singularity loci in task space, as polylines (drawn dashed).
  std::vector<std::vector<Point>> singular_curves;
};

class Mechanism {
 public:
  virtual ~Mechanism() = default;

  /// File keyword: "moma", "five_bar", ...
  virtual std::string_view kind() const = 0;
  /// Degrees of freedom of the platform (1, 2 or 3).
  virtual int dof() const = 0;
  virtual std::vector<JointInfo> joints() const = 0;

  /// Every working mode at a pose, each flagged valid or not with the reason.
  virtual std::vector<JointSolution> inverse(const Pose& pose) const = 0;
  /// Every assembly mode for joint values (size dof()), flagged valid or not.
  virtual std::vector<PoseSolution> direct(std::span<const double> joints) const = 0;
  /// Every criterion at a pose, one entry per working/assembly mode.
  virtual std::vector<Evaluation> evaluate(const Pose& pose, const Criteria& criteria) const = 0;

  /// Exact reachable workspace (for 3-DOF: at the file's constant orientation).
  virtual geometry::Region workspace() const = 0;
  /// The reachable workspace as an enclosure inner ⊆ true ⊆ outer with area
  /// bounds. Default: the exact workspace() (inner = outer). Mechanisms whose
  /// boundary is not made of arcs and segments only override it with a
  /// certified region; `max_depth` is the quadtree depth below the base grid
  /// (each level halves the bound width).
  virtual certified::CertifiedRegion workspace_enclosure(int max_depth = 9) const;
  /// Point-membership test of the reachable workspace in double arithmetic
  /// (the grid baseline's test; docs/theory/grid.md).
  virtual bool reachable(const Pose& pose) const = 0;
  /// The mechanism at a pose, for figures.
  virtual Drawing draw(const Pose& pose) const = 0;
  /// The mechanism at a pose with given joint values (an assembly mode of
  /// direct kinematics): the actuators drawn where `joints` puts them, not where
  /// the file's working mode would. Default: draw(pose).
  virtual Drawing draw_with_joints(const Pose& pose, std::span<const double> joints) const;
  /// The platform orientation (radians) at which workspace() is computed: the
  /// file's constant orientation for 3-DOF mechanisms, 0 otherwise.
  virtual double orientation() const { return 0.0; }
  /// A bounding box that contains the whole reachable workspace.
  virtual geometry::Box bounds() const = 0;
  /// What workspace() is, in words, for legends: "reachable workspace", or the
  /// file's analysis window where the mechanism has no limits of its own.
  virtual std::string workspace_label() const { return "reachable workspace"; }

  /// A capability only some mechanisms have (capability.hpp), or the reason
  /// it is not available. Never cast to a concrete mechanism type: ask.
  template <class C>
  Capability<C> capability() const {
    Offer offer = provide(std::type_index(typeid(C)));
    if (offer.value) return Capability<C>(std::static_pointer_cast<const C>(offer.value));
    if (offer.reason.empty()) offer.reason = std::string(kind()) + " has no " + std::string(C::capability_name);
    return Capability<C>(std::move(offer.reason));
  }
  /// The hook behind capability<C>(): an Offer for the capability type `which`
  /// (Offer::of / Offer::owned / Offer::refuse). Default: none.
  virtual Offer provide(std::type_index which) const;
};

/// One design as the analyses see it: a mechanism with the criteria limits
/// stated for it, without the file format (io::MechanismFile is one, read
/// from a file).
struct Design {
  std::string path;  // where it came from (a file path or an origin): errors name it
  std::shared_ptr<const Mechanism> model;
  Criteria criteria;
  /// criteria.reaction_legs: the legs (1-based) whose R_i,max is limited by
  /// max_reaction_N ([Briot] figs. 12-13 limit the joint B_1 only); empty: every leg.
  std::vector<int> reaction_legs;
};

}  // namespace pkmws::mechanisms
