// Certified regions: a set known only through a conservative test of boxes
// (interval arithmetic, Lipschitz bounds, exact sub-tests), enclosed between an
// inner and an outer region whose areas bound the true area by construction.
//
//   inner ⊆ true set ⊆ outer,   area_lower = area(inner) <= area(true) <= area(outer) = area_upper.
//
// The cover is a quadtree over an analysis window: a cell the test calls
// `inside` is in the set as a whole, `outside` has no point of the set, and an
// `undecided` cell is split until `max_depth`, where it stays undecided (it is
// in `outer`, not in `inner`). Nothing here is CGAL: regions are built from
// rectangles through the public Region API.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "pkmws/geometry/region.hpp"
#include "pkmws/geometry/types.hpp"

namespace pkmws::certified {

enum class CellState : std::int8_t { outside = -1, undecided = 0, inside = 1 };

/// Conservative classification of a closed axis-aligned box (length unit):
/// `inside` only if every point of the box is in the set, `outside` only if no
/// point is; `undecided` is always allowed. Called concurrently from several
/// threads: it must not mutate shared state.
using CellTest = std::function<CellState(const geometry::Box&)>;

struct CellOptions {
  /// The analysis window; the certified set is (set ∩ window). Must be non-empty.
  geometry::Box window;
  /// Cells per side of the base grid (cells are window/base, not necessarily square).
  int base = 16;
  /// Rows of the base grid, where they differ from `base` (0: `base`): a
  /// window much wider than high in its own units gets cells closer to square.
  int base_rows = 0;
  /// Subdivisions of an undecided base cell (each halves the cell side).
  int max_depth = 8;
  /// 0: every hardware thread, 1: serial, K: K threads. Results do not depend on it.
  int threads = 0;
};

/// The quadtree's leaves that matter, in a deterministic order.
struct CellCover {
  std::vector<geometry::Box> inside;     // certified in the set (horizontal runs merged)
  std::vector<geometry::Box> undecided;  // at max_depth, not decided
  double area_inside = 0.0;              // sum of the inside cells' areas
  double area_undecided = 0.0;           // sum of the undecided cells' areas
  std::uint64_t tests = 0;               // calls of the cell test
  int depth = 0;                         // deepest level reached
};

/// Runs the quadtree. Throws std::invalid_argument for an empty window,
/// base < 1 or max_depth outside [0, 24].
CellCover cover(const CellTest& test, const CellOptions& options);

/// The union of axis-aligned boxes as one exact region (horizontally adjacent
/// boxes of equal rows are merged first, then one aggregated union).
geometry::Region boxes_region(const std::vector<geometry::Box>& boxes);

/// The union of simple polygons whose interiors are disjoint and whose shared
/// edges are axis-aligned (cells of a quadtree and pieces inside them) as one
/// exact region: shared edges cancel, the rest is chained into loops (split
/// where pieces touch at a point), then one aggregated symmetric difference.
/// Vertices are used exactly as given: a shared edge cancels only where both
/// pieces give the same coordinate.
geometry::Region polygons_region(const std::vector<std::vector<geometry::Point>>& pieces);

/// inner ⊆ true ⊆ outer with the areas of both; `exact` when inner and outer
/// are the same region (every boundary piece is an arc or a segment).
struct CertifiedRegion {
  geometry::Region inner;
  geometry::Region outer;
  double area_lower = 0.0;
  double area_upper = 0.0;
  bool exact = false;
  /// "exact" or "certified" (the `method` of `pkmws area --json`).
  std::string method() const { return exact ? "exact" : "certified"; }
  /// The midpoint of the bounds; its error is at most width()/2.
  double area_estimate() const { return 0.5 * (area_lower + area_upper); }
  double width() const { return area_upper - area_lower; }
};

/// An exact region as a (degenerate) certified one.
CertifiedRegion from_exact(const geometry::Region& region);

/// (set given by `test`) ∩ `within`, for an exact `within` (e.g. a reachable
/// workspace): inner = within ∩ inside cells, outer = within ∩ (inside ∪
/// undecided cells). The window defaults to within's bbox when `options.window`
/// is empty.
CertifiedRegion certify(const CellTest& test, const geometry::Region& within, CellOptions options);

/// Set algebra on enclosures: every result is again a valid enclosure.
/// a ∩ b: [a.inner ∩ b.inner, a.outer ∩ b.outer]
CertifiedRegion intersect(const CertifiedRegion& a, const CertifiedRegion& b);
/// a ∪ b: [a.inner ∪ b.inner, a.outer ∪ b.outer]
CertifiedRegion unite(const CertifiedRegion& a, const CertifiedRegion& b);
/// a − b: [a.inner − b.outer, a.outer − b.inner]
CertifiedRegion subtract(const CertifiedRegion& a, const CertifiedRegion& b);

}  // namespace pkmws::certified
