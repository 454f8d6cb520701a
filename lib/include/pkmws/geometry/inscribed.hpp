// Largest inscribed circle of a component (pole of inaccessibility), found by
// a branch-and-bound search over square cells with exact distances to the
// segments and arcs of the boundary. No CGAL.
#pragma once

#include "pkmws/geometry/types.hpp"

namespace pkmws::geometry {

/// Distance from p to a boundary curve (segment or arc).
double distance(const Curve& curve, Point p);
/// Distance from p to the component's boundary (outer loop and holes).
double distance_to_boundary(const Component& component, Point p);
/// Even-odd membership of p in the component (boundary points are ambiguous).
bool inside(const Component& component, Point p);

struct InscribedCircle {
  Point center;
  double radius = 0.0;        // a circle of this radius at `center` fits (certified)
  double radius_upper = 0.0;  // no inscribed circle is larger than this
};
/// Branch and bound until radius_upper - radius <= precision.
InscribedCircle largest_inscribed_circle(const Component& component, double precision);

}  // namespace pkmws::geometry
