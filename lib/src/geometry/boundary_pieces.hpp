// A component's boundary curves prepared for many point queries (even-odd
// membership, distance): shared by the inscribed circle and rectangle searches
// (inscribed.cpp, inscribed_rectangle.cpp). Internal to the geometry layer.
#pragma once

#include <vector>

#include "pkmws/geometry/types.hpp"

namespace pkmws::geometry::detail {

// A boundary curve, with what the many point queries of a search need of an
// arc computed once: its end directions from the centre, ordered
// counter-clockwise (a cw arc from S to T is the ccw arc from T to S), and
// whether it spans more than a half turn. Unused for segments. Points into
// the component it was made from.
struct BoundaryPiece {
  const Curve* curve;
  Point from, to;  // ccw: the arc covers the directions from `from` to `to`
  bool major = false;
};

/// The outer loop's and the holes' curves.
std::vector<BoundaryPiece> boundary_pieces(const Component& component);
/// Even-odd membership of p (boundary points are ambiguous).
bool inside(const std::vector<BoundaryPiece>& boundary, Point p);

/// The pieces binned by their y-extent, for even-odd membership tests that
/// look only at the pieces a horizontal ray at p's height can cross (the same
/// answer as `inside` over all pieces; a search on a region of thousands of
/// curves asks it ~1e5 times).
class BoundaryIndex {
 public:
  explicit BoundaryIndex(const Component& component);
  bool inside(Point p) const;
  const std::vector<BoundaryPiece>& pieces() const { return pieces_; }

 private:
  std::vector<BoundaryPiece> pieces_;
  double y0_ = 0.0, bin_height_ = 1.0;
  std::vector<std::vector<std::size_t>> bins_;  // pieces whose y-extent meets each bin
};

}  // namespace pkmws::geometry::detail
