// The regular workspace: the largest axis-aligned rectangle inside a
// component (free aspect, a given aspect ratio or a given width), found by a
// branch and bound over the rectangle's x-range with a certified upper bound,
// and "does this task polygon fit, with what margin". No CGAL: the final
// rectangle is checked against the exact Region through its public interface.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "pkmws/geometry/region.hpp"
#include "pkmws/geometry/types.hpp"

namespace pkmws::geometry {

/// Which rectangles compete: any (`free`), those with height / width equal to
/// `value` (`aspect`), or those of width `value` in the region's length unit
/// (`width`).
struct RectangleShape {
  enum class Kind { free, aspect, width };
  Kind kind = Kind::free;
  double value = 0.0;
};

struct InscribedRectangle {
  /// The rectangle in a frame turned by `angle`: the rectangle is `box`
  /// rotated by `angle` about the origin (`corners()`); for the axis-aligned
  /// search `angle` is 0 and `box` is the rectangle itself. Empty: none found.
  Box box;
  double area = 0.0;             // area of the rectangle: a certified lower bound
  double area_upper = 0.0;       // no rectangle of the shape inside is larger
  std::size_t evaluations = 0;   // branch-and-bound cells evaluated
  bool verified = false;         // the rectangle was checked inside the exact region
  double angle = 0.0;            // radians, counter-clockwise, of the side `box.width()`
  std::size_t orientations = 0;  // orientations searched (free-orientation search only)
  /// The four corners in the region's frame, counter-clockwise from
  /// `box.min` turned by `angle`.
  std::array<Point, 4> corners() const;
};

/// Free vertical extent of the strip x0 <= x <= x1 in the component: the
/// longest interval [y0, y1] with [x0, x1] x [y0, y1] inside, as {y0, y1}
/// (y0 > y1 when there is none). `slack` >= 0 is subtracted from both ends of
/// every blocking interval and from the strip's sides, so that the result is
/// an upper bound despite rounding; a negative slack widens them (lower bound).
struct FreeInterval {
  double y0 = 1.0;
  double y1 = -1.0;
  double length() const { return y1 > y0 ? y1 - y0 : 0.0; }
};
FreeInterval free_interval(const Component& component, double x0, double x1, double slack);

/// Largest rectangle of the shape inside `component`, to a relative width
/// (area_upper - area) / area_upper <= `precision` when the search converges
/// within `max_evaluations` cells (otherwise the bounds reached so far).
/// When `region` is given, the result is shrunk until it lies inside the
/// exact region (`verified`).
InscribedRectangle largest_inscribed_rectangle(const Component& component, double precision,
                                               RectangleShape shape = {},
                                               const Region* region = nullptr,
                                               std::size_t max_evaluations = 4'000'000);

/// Largest rectangle of the shape inside `component` at any orientation
/// (free aspect or a given aspect ratio; a given width is refused): a branch
/// and bound over the angle around the axis-aligned search of the component
/// turned by -angle. A rectangle inside at angle t contains, shrunk by
/// 1 / (cos d + rho sin d), a rectangle at any angle within d of t (rho: its
/// aspect ratio, at most diameter^2 / best area), which bounds every
/// orientation of an angle interval from one search at its middle
/// (docs/theory/regular_workspace.md). `precision`, `region` and
/// `max_evaluations` (over all orientations) as above; the result's `angle`
/// is in [0, pi/2) for a free aspect, [0, pi) for a given aspect ratio.
InscribedRectangle largest_inscribed_rectangle_any_angle(const Component& component, double precision,
                                                         RectangleShape shape = {},
                                                         const Region* region = nullptr,
                                                         std::size_t max_evaluations = 4'000'000);

/// Does the task polygon (vertices, any orientation) fit inside the region?
struct TaskFit {
  bool inside = false;      // exact: polygon minus region is empty
  double area_outside = 0;  // area of polygon minus region (exact boundary)
  /// Signed clearance: inside, the distance from the polygon's boundary to
  /// the region's boundary; outside, minus the largest distance of a point
  /// of the polygon from the region (within `margin_error`).
  double margin = 0.0;
  double margin_error = 0.0;
};
TaskFit fit(const Region& region, const std::vector<Point>& polygon, double precision);

}  // namespace pkmws::geometry
