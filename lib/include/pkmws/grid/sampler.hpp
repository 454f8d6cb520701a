// Grid samplers of the reachable workspace (docs/theory/grid.md): the papers' methods
// and an adaptive variant, through one result type.
//  - cartesian(): IK test at cell centres of a uniform grid ([Vasilic] §4.2,
//    fig. 8 with Cartesian q1, q2); area = inside count x cell area.
//  - polar():     the same on a polar grid about a centre (fig. 8 with polar
//    q1, q2; figs. 9-11a); area = sum of the inside cells' ring-cell areas.
//  - joint_sweep(): the DK over a grid of joint values ([Vasilic] §4.1, fig. 4),
//    the valid poses rasterised onto a uniform grid for an area.
//  - adaptive():  a quadtree that refines only cells that straddle the boundary.
// Parallel through one module (lib/src/detail/parallel): fixed blocks, integer
// counts summed in block order, so every result is bit-identical for any
// thread count. Lengths in the mechanism file's unit, areas in unit^2.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "pkmws/geometry/types.hpp"
#include "pkmws/grid/kernel.hpp"
#include "pkmws/mechanisms/mechanism.hpp"

namespace pkmws::grid {

using geometry::Box;

struct Execution {
  /// 0: every hardware thread; 1: serial; K: K threads (a tbb::task_arena).
  int threads = 0;
  Isa isa = Isa::best;
  /// Orientation (radians) for the generic kernel of 3-DOF mechanisms;
  /// unset: the mechanism's own (Mechanism::orientation(), the file's orientation_deg).
  std::optional<double> phi;
};

/// One sampler run. `area_lower`/`area_upper` are set only when they are a
/// guarantee (certified cell test) or, for `bounds_certified == false`, a
/// bracket that holds when every boundary feature is wider than a cell (see
/// the sampler's comment).
struct SampleResult {
  std::string method;              // "cartesian", "polar", "adaptive", "joint_sweep"
  std::string kernel;              // "moma" or "generic"
  std::string isa;                 // instruction set of the kernel
  int threads = 1;                 // threads used
  double area = 0.0;               // the estimate (unit^2)
  std::optional<double> area_lower;
  std::optional<double> area_upper;
  bool bounds_certified = false;
  std::uint64_t cells = 0;         // grid cells (cartesian, polar, raster) or quadtree leaves
  std::uint64_t points_tested = 0; // membership tests (or DK evaluations for the sweep)
  std::uint64_t inside = 0;        // cells / points found inside
  double time_ms = 0.0;            // wall time of the whole run
  double points_per_second = 0.0;  // points_tested / time
  double bounds_time_ms = 0.0;     // part of time_ms spent on the certified bounds pass
};

struct CartesianOptions {
  std::size_t cells_x = 100;       // cells per side; the cells are (width / cells_x) x (height / cells_y)
  std::size_t cells_y = 100;
  std::optional<Box> box;          // default: Mechanism::bounds()
  /// Also classify every cell with the certified test (MOMA): area_lower =
  /// cells certainly inside, area_upper = + undecided cells. Costs a second pass.
  bool certified_bounds = false;
  /// Keep the centre-test mask (row-major, cells_y rows of cells_x, y upwards).
  bool keep_mask = false;
};

struct CartesianResult : SampleResult {
  Box box;
  std::vector<std::uint8_t> mask;
};

CartesianResult cartesian(const mechanisms::Mechanism& mechanism, const CartesianOptions& options,
                          const Execution& execution = {});

struct PolarOptions {
  std::size_t rings = 100;         // radial divisions of [0, radius]
  std::size_t sectors = 314;       // angular divisions of [0, 2 pi)
  std::optional<geometry::Point> centre;  // default: centre of Mechanism::bounds()
  std::optional<double> radius;    // default: distance from the centre to the farthest corner of bounds()
  bool certified_bounds = false;
  bool keep_mask = false;          // mask[ring * sectors + sector]
};

struct PolarResult : SampleResult {
  geometry::Point centre;
  double radius = 0.0;
  std::vector<std::uint8_t> mask;
};

/// Cell (ring k, sector j) spans r in [k dr, (k+1) dr], theta in [j dth, (j+1) dth];
/// it is tested at r = sqrt((r_in^2 + r_out^2) / 2) (the radius halving the
/// cell's area), theta at mid-sector; area of a cell (r_out^2 - r_in^2) dth / 2.
PolarResult polar(const mechanisms::Mechanism& mechanism, const PolarOptions& options,
                  const Execution& execution = {});

/// Rule deciding whether a quadtree cell straddles the boundary.
enum class StraddleRule {
  automatic,  // certified when the kernel has it, else sampled
  certified,  // |F(centre)| > half-diagonal (MOMA's 1-Lipschitz bound): never misses a boundary
  sampled,    // centre and four corners disagree; misses features thinner than a cell
};

struct AdaptiveOptions {
  std::size_t base_cells = 32;     // the root grid is base_cells x base_cells cells over the box
  int depth = 8;                   // levels of refinement below the root grid
  std::optional<Box> box;
  StraddleRule rule = StraddleRule::automatic;
};

struct AdaptiveResult : SampleResult {
  Box box;
  std::string rule;                       // "certified" or "sampled"
  /// inside + leaves of the finest level whose centre is inside (a centre-test
  /// estimate restricted to the boundary band).
  double area_centre = 0.0;
  std::uint64_t undecided = 0;            // undecided leaves at the finest level
  std::vector<std::uint64_t> cells_per_level;  // cells evaluated at each level (root first)
  std::size_t effective_cells = 0;       // base_cells * 2^depth: the uniform grid of the same resolution
};

/// area = inside cells + half of the undecided leaves of the finest level
/// (the midpoint of [area_lower, area_upper]); area_upper - area_lower = the
/// total area of the undecided leaves.
AdaptiveResult adaptive(const mechanisms::Mechanism& mechanism, const AdaptiveOptions& options,
                        const Execution& execution = {});

struct JointSweepOptions {
  std::size_t samples = 400;       // joint samples per joint (2-DOF: samples^2 DK evaluations)
  /// Joint ranges (radians for angles). Default: MOMA and biglide strokes,
  /// five-bar crank limits, else [-pi, pi] for angle joints.
  std::vector<std::pair<double, double>> ranges;
  std::size_t raster_cells = 100;  // raster cells per side over the box
  std::optional<Box> box;
  bool keep_points = false;
  bool keep_mask = false;          // raster hits, as CartesianResult::mask
};

struct JointSweepResult : SampleResult {
  Box box;
  std::vector<std::pair<double, double>> ranges;
  std::uint64_t poses = 0;          // valid DK poses found
  std::uint64_t boundary_cells = 0; // hit cells with a 4-neighbour not hit
  std::vector<geometry::Point> points;
  std::vector<std::uint8_t> mask;
};

/// [Vasilic] fig. 4: every joint sample's valid assembly modes are platform
/// points of the workspace. Area by rasterisation: with a sweep dense enough
/// (task-space spacing below a raster cell) every raster cell meeting the
/// workspace is hit, so area_upper = hit cells x cell area over-estimates by
/// about half the boundary cells (hit cells with a 4-neighbour not hit);
/// area_lower = area_upper - boundary cells' area; area = their midpoint.
/// Not certified: near type-2 singularities the DK spreads the samples apart
/// and cells can be missed; a feature thinner than a cell is smeared.
JointSweepResult joint_sweep(const mechanisms::Mechanism& mechanism, const JointSweepOptions& options,
                             const Execution& execution = {});

/// Default joint ranges of `joint_sweep` for a mechanism; throws
/// std::invalid_argument when they are unknown (pass them explicitly).
std::vector<std::pair<double, double>> default_joint_ranges(const mechanisms::Mechanism& mechanism);

}  // namespace pkmws::grid
