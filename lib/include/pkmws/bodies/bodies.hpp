// Bodies and link interference (docs/format.md (bodies); [Vasilic] §4 end, figures 5, 7, 11).
//
// A mechanism file may list the solid parts that can collide: guide housings
// and slider blocks (rectangles), rods and links (capsules: segment plus
// radius), the platform joint (disk) and fixed obstacles (polygons). The
// interference region of a pair of parts is the set of platform positions P
// (in the reachable workspace) at which the two parts overlap; the real
// workspace is reachable − ∪ interference.
//
// Every part is a `Shape`: the points within `radius` of a core (a point, a
// segment or a filled simple polygon). Lengths are in the file's unit, angles
// in radians. No CGAL here: exact regions come from the Region primitives.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "pkmws/certified/cell_region.hpp"
#include "pkmws/geometry/region.hpp"
#include "pkmws/geometry/types.hpp"
#include "pkmws/mechanisms/mechanism.hpp"

namespace pkmws::bodies {

using geometry::Box;
using geometry::Point;

/// The closed set { x : dist(x, core) <= radius }. core: 1 point (a disk), 2
/// points (a capsule), >= 3 points (a filled simple polygon, either orientation).
struct Shape {
  std::vector<Point> core;
  double radius = 0.0;
};

/// Distance between two cores (0 when they intersect, including containment).
double core_distance(const std::vector<Point>& a, const std::vector<Point>& b);
/// Clearance between two shapes: core distance − radii (< 0: they overlap by that depth,
/// = 0 when the cores intersect and both radii are 0).
double clearance(const Shape& a, const Shape& b);
/// The closed shapes intersect (clearance <= 0).
bool overlap(const Shape& a, const Shape& b);
/// Convex hull (counter-clockwise, no repeated or collinear points; 1 or 2 points for degenerate input).
std::vector<Point> convex_hull(std::vector<Point> points);

enum class PartKind {
  platform_joint,  // disk of `radius` centred on the platform point P (C of a five-bar)
  link,            // capsule of `radius` on a rod (MOMA: slider S_i to P) or a link (five-bar: proximal A_i B_i, distal B_i C)
  slider_block,    // MOMA: rectangle `length` along the guide × `width`, centred on the slider S_i
  housing,         // MOMA: fixed rectangle along guide i, guide coordinate [from, to] from R_i, `width` across (centred)
  obstacle,        // fixed simple polygon `polygon` (base frame)
};

struct Part {
  std::string name;       // "platform", "rod1", "slider2", "housing1", "proximal1", "distal2", or an obstacle's name
  PartKind kind = PartKind::obstacle;
  int leg = -1;           // 0 or 1 for leg parts, -1 otherwise
  bool proximal = false;  // five-bar links: proximal (crank) rather than distal
  double radius = 0.0;    // platform joint, links
  double length = 0.0;    // slider block: along the guide
  double width = 0.0;     // slider block, housing: across the guide
  double from = 0.0;      // housing: guide coordinate range [from, to] (same as the stroke p)
  double to = 0.0;
  std::vector<Point> polygon;  // obstacle
  bool fixed() const { return kind == PartKind::housing || kind == PartKind::obstacle; }
  /// A part with an empty interior (zero radius and no area) cannot obstruct anything.
  bool solid() const;
};

/// One pair of parts that may collide.
struct PartPair {
  int a = 0, b = 0;  // indices into BodyModel::parts
};

struct BodyModel {
  std::vector<Part> parts;
  /// Minimum angle between the two links that meet at the platform joint
  /// (rods of MOMA, distal links of the five-bar), from the joint housings;
  /// 0: no limit. Radians.
  double min_link_angle = 0.0;
  /// Pairs allowed to touch, besides the pairs joined by a joint (which always are).
  std::vector<std::pair<std::string, std::string>> allowed_contacts;

  int find(const std::string& name) const;  // -1 if absent
  /// Parts joined by a joint (always allowed to touch).
  bool joined(int a, int b) const;
  bool allowed(int a, int b) const;
  /// Every pair that may collide: not both fixed, both solid, not joined, not allowed.
  std::vector<PartPair> pairs() const;
};

/// A mechanism with bodies: part shapes at a pose, and enclosures of them over
/// a box of platform positions (the conservative test of the certified regions).
class BodyRig {
 public:
  virtual ~BodyRig() = default;
  const BodyModel& model() const { return model_; }

  /// Every part's shape at platform point p in the mechanism's working mode;
  /// nullopt when p is not reachable (IK fails or a stroke is exceeded).
  virtual std::optional<std::vector<Shape>> shapes_at(Point p) const = 0;

  /// Over a box X of platform positions, for every part: `outer` contains the
  /// part at every reachable p in X; `inner` (when present) is contained in the
  /// part at every reachable p in X.
  struct Enclosure {
    Shape outer;
    std::optional<Shape> inner;
  };
  struct BoxParts {
    std::vector<Enclosure> parts;
    /// The vectors from the platform joint to the other end of the two links
    /// that meet there: each in the set hull ⊕ disk(radius), for every reachable p in X.
    std::array<Shape, 2> link_vectors;
  };
  /// nullopt when no point of X is reachable (certainly).
  virtual std::optional<BoxParts> enclose(const Box& box) const = 0;

  /// The two vectors from the platform joint along the links that meet there, at p.
  virtual std::optional<std::array<Point, 2>> link_vectors_at(Point p) const = 0;
  /// The shape of a fixed part (housing or obstacle), by index into model().parts.
  virtual Shape fixed_part(std::size_t index) const = 0;
  /// Names of the two links meeting at the platform joint.
  virtual std::array<std::string, 2> joint_links() const = 0;
  /// What the mechanism calls a link that is not proximal, for legends ("rod", "link").
  virtual std::string link_noun() const { return "link"; }

 protected:
  explicit BodyRig(BodyModel model) : model_(std::move(model)) {}
  BodyModel model_;
};

/// Pose-level collision test (the oracle of the certified regions and `pkmws explain`).
struct Contact {
  std::string a, b;         // part names; for the link angle: the two links
  std::string kind;         // "overlap" or "link_angle"
  double clearance = 0.0;   // overlap: distance − radii (< 0 overlaps); link_angle: angle − minimum (rad)
  bool collides = false;
};
struct PoseCheck {
  bool reachable = false;
  std::vector<Contact> contacts;  // one per checked pair (and the link angle when limited)
  bool collides() const;
};
PoseCheck check_pose(const BodyRig& rig, Point p);

/// Unsigned angle between two vectors, in [0, pi].
double unsigned_angle(Point u, Point v);

/// One interference region: the platform positions (within the reachable
/// workspace) where the pair collides.
struct Interference {
  std::string a, b;                 // part names (the link angle: the two links)
  std::string kind;                 // "overlap" or "link_angle"
  certified::CertifiedRegion region;
};

struct RealWorkspace {
  certified::CertifiedRegion reachable;
  std::vector<Interference> interference;   // every pair (empty regions included)
  certified::CertifiedRegion real;          // reachable − ∪ interference
  bool exact() const { return real.exact; }
};

struct InterferenceOptions {
  int base = 16;        // base grid of the certified quadtree
  int max_depth = 7;    // its depth (each level about halves the bound width)
  int threads = 0;      // 0: all hardware threads
};

/// The cell test of one pair's interference region (exposed for tests).
certified::CellTest interference_test(const BodyRig& rig, const PartPair& pair, double margin);
certified::CellTest link_angle_test(const BodyRig& rig, double margin);

/// Platform joint (disk of radius r) against a fixed part: the exact Minkowski sum
/// part ⊕ disk(r) = polygon ∪ stadiums on its edges (disks at its vertices).
geometry::Region minkowski_with_disk(const Shape& fixed_part, double r);

RealWorkspace real_workspace(const BodyRig& rig, const geometry::Region& reachable,
                             const InterferenceOptions& options = {});

}  // namespace pkmws::bodies
