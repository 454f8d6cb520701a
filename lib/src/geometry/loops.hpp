// Chaining directed boundary edges into simple loops (internal: the certified
// regions' union of cell pieces and the exports' rings share it).
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "pkmws/geometry/types.hpp"

namespace pkmws::geometry {

/// Directed edges (from, to) with the region on their left, as many edges
/// into every vertex as out of it, chained into closed loops: where several
/// edges leave a vertex (pieces of the region touching at a point), the
/// sharpest left turn, which keeps each loop to one side of the touching
/// point; each loop is then split at repeated vertices, so that every loop
/// is simple. The loops as indices of their edges, in order. Vertices are
/// matched exactly.
std::vector<std::vector<std::size_t>> left_turn_loops(const std::vector<std::pair<Point, Point>>& edges);

}  // namespace pkmws::geometry
