// The distance to the type-2 singularity as a criterion (private to the
// criteria layer; docs/theory/level_sets.md, "Distance to the type-2
// singularity"): d(P) = dist(P, S), S = closure{ Q ∈ W : det A(Q) = 0 } of the
// file's working mode (and orientation), limited from below, d >= δ.
#pragma once

#include <string>
#include <vector>

#include "pkmws/certified/cell_region.hpp"
#include "pkmws/certified/level_set.hpp"
#include "pkmws/criteria/fields.hpp"
#include "pkmws/geometry/region.hpp"

namespace pkmws::criteria::detail {

/// The mechanism's signed determinant field (InputError naming the file and
/// the field when the mechanism cannot give it).
CriterionField singular_field(const mechanisms::Design& file);

/// The traced S and the two tubes around it.
struct SingularTubes {
  std::vector<std::vector<geometry::Point>> curves;
  std::vector<geometry::Box> undecided;
  double error = 0.0;                 // w
  geometry::Region inner_tube;        // ⊇ { P : d(P) < δ }   (radius δ + w, undecided boxes inflated)
  geometry::Region outer_tube;        // ⊆ { P : d(P) < δ }   (radius δ − w, traced pieces only)
  bool empty_set = false;             // S ∩ W is empty
  std::string nowhere;                // S is all of W (the field's `nowhere`): d = 0 everywhere
  bool stopped = false;
};

/// Traces S ∩ W for the file and builds the tubes for threshold δ, aiming at
/// a bound width of `relative_tolerance` × `area_estimate` for the area of
/// W ∩ {d >= δ}; `build_tubes` false traces only.
SingularTubes singular_tubes(const mechanisms::Design& file, const geometry::Region& within, double delta,
                             double area_estimate, const certified::LevelSetOptions& options, bool build_tubes);

/// The tube of radius r around a polyline (⊇ the union of its segments'
/// capsules when `superset`, ⊆ it otherwise), exact through Region.
geometry::Region polyline_tube(const std::vector<geometry::Point>& piece, double r, bool superset);
/// The same as parts to unite (one polygon and its end disks, or stadiums).
void polyline_tube_parts(const std::vector<geometry::Point>& piece, double r, bool superset,
                         std::vector<geometry::Region>& parts);

/// d(P) from the traced curves (brute force over the segments; for tests,
/// eval and the grid view): the distance to the chord polylines.
double distance_to_curves(const std::vector<std::vector<geometry::Point>>& curves, geometry::Point p);

}  // namespace pkmws::criteria::detail
