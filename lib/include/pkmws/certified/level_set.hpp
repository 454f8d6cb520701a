// Certified sub-level sets of a scalar field over an exact workspace:
//
//   S = { p ∈ W : F(p) <= level },   inner ⊆ S ⊆ outer,   area_lower <= area(S) <= area_upper,
//
// with the level curve F = level traced (points solved onto it to machine
// precision). Two layers (docs/theory/level_sets.md):
//  (a) the cell quadtree of cell_region.hpp with an interval test of F
//      (`certify_cells`): always valid, bound width ~ curve length x cell size;
//  (b) `sublevel_set`: the same quadtree, then in every undecided cell where the
//      interval gradient proves the level curve is the graph of a function
//      (|∂F/∂v| > 0 over the cell), the curve is sampled by certified root
//      brackets and the area between curve and chords is bounded by the interval
//      Hessian (|g''| bound) or, near the cell's edges, by the Lipschitz constant
//      |∂F/∂u| / |∂F/∂v|. Cells where this fails are split; at the depth limit
//      they stay undecided (in outer, not in inner).
//
// Lengths in the field's unit, areas in unit².
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "pkmws/certified/cell_region.hpp"
#include "pkmws/certified/disk_area.hpp"
#include "pkmws/certified/interval.hpp"
#include "pkmws/geometry/region.hpp"
#include "pkmws/geometry/types.hpp"

namespace pkmws::certified {

/// A scalar field F over the plane (a criterion or a smooth surrogate of it).
/// All methods are const and thread-safe.
class ScalarField {
 public:
  virtual ~ScalarField() = default;
  /// F at a point (NaN outside the domain where it is defined).
  virtual double value(geometry::Point p) const = 0;
  /// F with gradient and Hessian at a point (double arithmetic).
  virtual Jet<double> jet(geometry::Point p) const = 0;
  /// F with its gradient at a point, and enclosed over a box.
  virtual Grad<double> grad(geometry::Point p) const = 0;
  virtual Grad<Interval> grad(const geometry::Box& box) const = 0;
  /// Encloses F over box ∩ domain (also for degenerate boxes: points, edges).
  virtual Interval enclose(const geometry::Box& box) const = 0;
  /// A cheaper enclosure of F over the box than enclose(), possibly wider: the
  /// cell tests try it first and call enclose() only where it decides
  /// nothing. Default: none (the whole line).
  virtual Interval enclose_cheap(const geometry::Box& /*box*/) const { return Interval::whole(); }
  /// The box's side of `level` where a test cheaper than any enclosure can
  /// tell it: `inside` only if F <= level on the whole box (∩ domain),
  /// `outside` only if F > level there; else `undecided` (the default), and
  /// the cell tests go on with the enclosures.
  virtual CellState side(const geometry::Box& /*box*/, double /*level*/) const { return CellState::undecided; }
  /// Encloses F and its derivatives over the box; meaningful only for boxes
  /// the domain test calls `inside` (F is C² there).
  virtual Jet<Interval> jet(const geometry::Box& box) const = 0;
  /// Conservative position of the box with respect to the open set where F is
  /// C² (and defined): `inside` only if the whole box is in it.
  virtual CellState domain(const geometry::Box& box) const = 0;
  /// True only if F is undefined on the whole box (its constraint fails
  /// there): domain(box) == outside, which a field may answer without the
  /// smoothness part of its domain test (the cells a level set decides by
  /// enclose() alone need no more).
  virtual bool excluded(const geometry::Box& box) const { return domain(box) == CellState::outside; }
};

/// The area element of the plane the fields are written in: dA = ρ dx dy with
/// ρ = c0 + cx x + cy y, non-negative over the window (a chart's coordinates,
/// e.g. polar ones: ρ = r; docs/theory/level_sets.md). Default: the plane
/// itself, ρ = 1. Terms of one sign only (no cancellation in ρ).
struct AreaWeight {
  double c0 = 1.0, cx = 0.0, cy = 0.0;
  bool unit() const { return c0 == 1.0 && cx == 0.0 && cy == 0.0; }
  double at(geometry::Point p) const { return c0 + cx * p.x + cy * p.y; }
  /// ∫∫ ρ over a box (exact for an affine ρ: the box's area times ρ at its centre).
  double box(const geometry::Box& b) const {
    const double a = b.width() * b.height();
    return unit() ? a : a * at({0.5 * (b.min.x + b.max.x), 0.5 * (b.min.y + b.max.y)});
  }
};

struct LevelSetOptions {
  /// Target bound width relative to the area: area_upper - area_lower <= tol * area (aimed at, reported).
  double relative_tolerance = 1e-6;
  /// A target width in area units instead, where it is larger than the
  /// relative one (0: none). A part of a larger set (a chart's) is traced to
  /// its share of the whole's width, whatever its own area.
  double absolute_tolerance = 0.0;
  /// Quadtree before tracing: base cells per side and levels of the cover.
  int base = 16;
  /// Rows of the base grid where they differ from `base` (0: `base`; CellOptions::base_rows).
  int base_rows = 0;
  /// 0: chosen from the target (4 for relative targets of 1e-7 and wider,
  /// where the traced cells of a level coarser pay; 5 for tighter ones).
  int cover_depth = 0;
  /// Further splits of a cell that cannot be traced (depth below the cover's leaves).
  int refine_depth = 8;
  /// 0: every hardware thread, 1: serial. Results do not depend on it.
  int threads = 0;
  /// Build the inner/outer regions (exact: the cells certified in S, and in
  /// each traced cell its part on S's side of a few chords that follow its
  /// envelopes within τ/4, so area(inner) <= area_lower and area(outer) >=
  /// area_upper, each within about half the traced width). Costly; the bounds
  /// do not need it.
  bool build_regions = false;
  /// Which of them build_regions builds: both, or the one a caller uses (an
  /// export writes one; the other is left empty).
  enum class Regions { both, inner, outer };
  Regions regions = Regions::both;
  /// Whether a caller that knows charts of the fields (criteria::limited_workspace)
  /// may trace parts of W in them: the bounds are then narrower and faster, but
  /// the pieces for figures (inside_boxes, inner_polygons) cover the part traced
  /// in (x, y) only. Figures ask for false.
  bool charts = true;
  /// W as an intersection of disks and complements of disks, where it is one
  /// (empty: not known; it must describe the `within` region given): the
  /// areas of cells and traced pieces across W's boundary are then enclosed
  /// in closed form (area_in_disks) instead of clipped to W with exact
  /// Boolean operations, which stay the fallback where that cannot decide.
  std::vector<SignedDisk> within_disks;
  /// The area element (a chart's); the bounds are of ∫∫_S ρ. Regions are not
  /// built for a weighted plane (they would be in the chart's coordinates).
  AreaWeight weight;
  /// Trace curves (layer b); false gives the pure cell baseline (layer a).
  bool trace = true;
  /// Refine again where the first pass misses the tolerance (the retries of
  /// docs/theory/level_sets.md). A figure's pieces ask for one pass: its
  /// refine_depth is what the drawing resolves.
  bool retries = true;
  /// A bound on the work: past this instant no cell is split or traced any
  /// more; the cells not yet decided stay undecided, so the bounds remain
  /// valid, only wider (LevelSetResult::stopped says so). Default: no bound.
  std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
  /// Called now and then with the fraction of the refinement done (0..1), from
  /// one thread at a time (any thread). Empty: no reports.
  std::function<void(double fraction)> progress;
};

/// A piece of the traced level curve: points on F = level (to a few ulps).
using CurvePiece = std::vector<geometry::Point>;

struct LevelSetResult {
  /// inner/outer (when built) and the certified area bounds. Without regions,
  /// inner/outer are empty and area_lower/area_upper still hold; with them,
  /// area(inner) <= area_lower <= area(S) <= area_upper <= area(outer).
  CertifiedRegion region;
  std::vector<CurvePiece> curves;
  /// For each piece of `curves`, the index of the constraint whose level
  /// curve it is (with several constraints, a cut's curves are not a criterion's).
  std::vector<std::size_t> curve_constraints;
  std::uint64_t traced_cells = 0;      // cells where the curve was traced
  std::uint64_t undecided_cells = 0;   // cells left undecided at the depth limit
  std::uint64_t curve_points = 0;      // certified root brackets computed
  std::uint64_t cell_tests = 0;
  /// The deadline of the options passed before the work was done: the bounds
  /// are valid but may be wider than the tolerance asked for, and the
  /// inner/outer regions are not built (even with build_regions).
  bool stopped = false;
  double undecided_area = 0.0;         // part of the width from undecided cells
  double traced_width = 0.0;           // part of the width from traced cells
  double tolerance_per_length = 0.0;   // τ used (area per unit curve length)
  /// Cover leaves traced again with τ / 4 where the first pass's traced
  /// width missed the target (0: none; the retry then, if any, was a new pass).
  std::uint64_t retraced_leaves = 0;
  /// Pieces for figures (no exact arithmetic): cells certified in S (before
  /// clipping to W), the traced cells' inner polygons, undecided cells.
  std::vector<geometry::Box> inside_boxes;
  std::vector<std::vector<geometry::Point>> inner_polygons;
  std::vector<geometry::Box> undecided_boxes;
};

/// One constraint F <= level of an intersection of sub-level sets.
struct Constraint {
  const ScalarField* field = nullptr;
  double level = 0.0;
};

/// Conservative classification of a box against the workspace W (inside only
/// if box ⊆ W); used to avoid exact region operations for cells inside W.
using WithinTest = CellTest;

/// S = { p ∈ within : F(p) <= level } as a certified region with traced curves.
/// `within_test` classifies boxes against `within` (may always answer
/// undecided: then every cell goes through exact region operations).
LevelSetResult sublevel_set(const ScalarField& field, double level, const geometry::Region& within,
                            const WithinTest& within_test, const LevelSetOptions& options);
/// ⋂_k { p ∈ within : F_k(p) <= level_k }: cells where all but one constraint
/// hold are traced along that one's level curve.
LevelSetResult sublevel_set(const std::vector<Constraint>& constraints, const geometry::Region& within,
                            const WithinTest& within_test, const LevelSetOptions& options);

/// Layer (a) only: certify() with the interval test of F (quadtree depth
/// `max_depth` below `base`).
CertifiedRegion certify_cells(const ScalarField& field, double level, const geometry::Region& within, int base,
                              int max_depth, int threads = 0);

/// Bands between consecutive levels: band k = { l_{k-1} < F <= l_k } (band 0:
/// F <= l_0), as enclosures from the sub-level sets (a − b algebra), with the
/// sub-level results for the curves.
struct Band {
  double lower_level = 0.0;   // -inf for band 0
  double upper_level = 0.0;
  double area_lower = 0.0;
  double area_upper = 0.0;
};
std::vector<Band> bands_from_sublevels(const std::vector<double>& levels, const std::vector<LevelSetResult>& sublevels);

}  // namespace pkmws::certified
