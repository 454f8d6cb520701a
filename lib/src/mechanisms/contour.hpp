// The zero set of a smooth scalar field over a box, as polylines for figures
// (singularity curves of the 3-DOF mechanisms at constant orientation).
// Marching squares on an n x n grid; every crossing of a cell edge is refined
// by bisection on the sign of f, so the vertices lie on the curve to the
// bisection's resolution (about 1e-13 of the cell side). Not a certified
// enclosure: a component smaller than a cell can be missed.
#pragma once

#include <functional>
#include <vector>

#include "pkmws/geometry/types.hpp"

namespace pkmws::mechanisms {

std::vector<std::vector<geometry::Point>> zero_contours(const std::function<double(geometry::Point)>& f,
                                                        const geometry::Box& box, int n);

}  // namespace pkmws::mechanisms
