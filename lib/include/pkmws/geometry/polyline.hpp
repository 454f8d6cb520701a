// Polylines of boundary curves at a max deviation: inscribed chords, or
// one-sided polygons (inside / containing the region) for enclosures.
#pragma once

#include <vector>

#include "pkmws/geometry/types.hpp"

namespace pkmws::geometry {

/// How a polyline stands to the region on the left of its loop (outer loops
/// counter-clockwise, holes clockwise: the region is always on the left).
enum class Approximation {
  chords,   ///< every vertex on the curves; deviation <= tolerance to either side
  inside,   ///< a polygon inside the region: convex arcs by chords, concave ones by tangents
  outside,  ///< a polygon containing the region: convex arcs by tangents, concave ones by chords
};

/// True when `approximation` puts the arc's polyline on its tangents (outside
/// the circle) rather than on its chords. A counter-clockwise arc has the
/// region on the centre's side, so its chords lie inside the region.
bool tangent_polyline(const Curve& curve, Approximation approximation);

/// Pieces of the curve's polyline at max deviation `tolerance` (> 0): 1 for a
/// segment; saturates at 2^53 for absurdly small tolerances, so that callers
/// can refuse before allocating.
double polyline_pieces(const Curve& curve, double tolerance, Approximation approximation);

/// Appends the curve's polyline from its source up to, not including, its
/// target: chords (vertices on the arc, deviation r (1 - cos(h/2))) or tangent
/// pieces (vertices r / cos(h/2) from the centre, deviation r (sec(h/2) - 1)),
/// both <= tolerance.
void append_polyline(const Curve& curve, double tolerance, Approximation approximation,
                     std::vector<Point>& out);

/// The closed polyline of a loop (first point not repeated at the end).
std::vector<Point> polyline(const Loop& loop, double tolerance, Approximation approximation);

}  // namespace pkmws::geometry
