// Region: an immutable exact planar set bounded by line segments and circular
// arcs. The representation (CGAL General_polygon_set_2 over
// Gps_circle_segment_traits_2<Epeck>) is private; this header is double-based.
//
// Every double given to a primitive is taken as the exact rational it
// represents, so booleans are exact. Results come back as doubles rounded from
// the exact values (coordinates to ~1 ulp, areas to ~1e-16 relative).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "pkmws/geometry/types.hpp"

namespace pkmws::geometry {

class Region {
 public:
  /// The empty set.
  Region();
  ~Region();
  Region(const Region&);
  Region(Region&&) noexcept;
  Region& operator=(const Region&);
  Region& operator=(Region&&) noexcept;

  bool empty() const;

  /// Boolean operations; the operands are unchanged.
  Region unite(const Region& other) const;
  Region intersect(const Region& other) const;
  Region subtract(const Region& other) const;
  Region symmetric_difference(const Region& other) const;
  /// Union of many regions at once (faster than folding `unite`).
  static Region unite_all(const std::vector<Region>& regions);
  /// The points covered by an odd number of the regions, in one aggregated
  /// sweep (for nested, non-crossing loops: the set they bound).
  static Region symmetric_difference_all(const std::vector<Region>& regions);

  /// Area from the exact boundary (Green's theorem per segment and arc).
  double area() const;
  Box bbox() const;
  /// Exact point-membership test; boundary points count as inside.
  bool contains(Point p) const;
  /// Connected components with their boundaries, areas, perimeters, centroids.
  /// Components of area below `min_area` (slivers from near-tangencies) are dropped.
  std::vector<Component> components(double min_area = 0.0) const;
  /// All boundary loops (outer loops and holes).
  std::vector<Loop> loops() const;
  /// Number of curves on the boundary (x-monotone pieces).
  std::size_t curve_count() const;

  struct Impl;  // defined in lib/src/geometry (CGAL)
  explicit Region(std::shared_ptr<const Impl> impl);
  const Impl& impl() const { return *impl_; }

 private:
  std::shared_ptr<const Impl> impl_;
};

inline Region operator|(const Region& a, const Region& b) { return a.unite(b); }
inline Region operator&(const Region& a, const Region& b) { return a.intersect(b); }
inline Region operator-(const Region& a, const Region& b) { return a.subtract(b); }
inline Region operator^(const Region& a, const Region& b) { return a.symmetric_difference(b); }

}  // namespace pkmws::geometry
