// Certified areas of polygons clipped to a set bounded by circles, in closed
// form (interval arithmetic): what the level sets need where W is an
// intersection of disks and complements of disks (the five-bar's rest,
// docs/theory/level_sets.md, "Charts"), instead of exact Boolean operations.
#pragma once

#include <optional>
#include <span>

#include "pkmws/certified/interval.hpp"
#include "pkmws/geometry/types.hpp"

namespace pkmws::certified {

/// The disk |p - centre| <= radius (inside), or its complement (!inside).
struct SignedDisk {
  geometry::Point centre;
  double radius = 0.0;
  bool inside = true;
};

/// An enclosure of area(P ∩ ⋂ disks) for a simple polygon P (either
/// orientation), or nothing where the closed form cannot decide: P's bounding
/// box crosses more than one of the circles, a vertex lies on a circle or an
/// edge touches one (to rounding), or an edge spans a quarter turn or more
/// seen from a circle's centre. Each edge's part is a triangle or a circular
/// sector seen from the centre; the areas are summed with signs (Green).
std::optional<Interval> area_in_disks(std::span<const geometry::Point> polygon, std::span<const SignedDisk> disks);

}  // namespace pkmws::certified
