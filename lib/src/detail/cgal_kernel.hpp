// The one place that names the CGAL kernel and traits. Included
// only by lib/src/geometry/*.cpp, the translation units that pay CGAL's
// compile cost.
#pragma once

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/General_polygon_set_2.h>
#include <CGAL/Gps_circle_segment_traits_2.h>

#include <mutex>
#include <vector>

#include "pkmws/geometry/region.hpp"

namespace pkmws::geometry::detail {

using Kernel = CGAL::Epeck;
using FT = Kernel::FT;
using KPoint = Kernel::Point_2;
using Circle = Kernel::Circle_2;
using Traits = CGAL::Gps_circle_segment_traits_2<Kernel>;
using PolygonSet = CGAL::General_polygon_set_2<Traits>;
using Polygon = Traits::General_polygon_2;
using PolygonWithHoles = Traits::General_polygon_with_holes_2;
using Curve = Traits::Curve_2;
using XCurve = Traits::X_monotone_curve_2;
using OnePoint = Traits::Point_2;  // coordinates a0 + a1 sqrt(r)
using CoordNT = Traits::CoordNT;

/// An exact rational unit vector (ux^2 + uy^2 == 1 exactly).
struct ExactDirection {
  FT x, y;
};

/// Splits curves into x-monotone pieces (boost::variant in CGAL 5.5,
/// std::variant in 6.0: kept behind this one helper).
void append_x_monotone(const Curve& curve, std::vector<XCurve>& out);

/// Region from polygons with holes that are pairwise interior-disjoint and
/// valid (outer ccw, holes cw).
Region make_region(std::vector<PolygonWithHoles> pieces);
/// Region bounded by one closed ccw loop of curves (segments and arcs).
Region region_from_loop(const std::vector<Curve>& loop);

/// A one-root number as a double within 2^-51 of its magnitude (a few ulp):
/// from the lazy interval when it is that tight, else from the exact value
/// (to_double on a lazy number only guarantees ~1e-5, docs/theory/regions.md).
double to_double_exact(const CoordNT& value);
double to_double_exact(const FT& value);

}  // namespace pkmws::geometry::detail

namespace pkmws::geometry {

struct Region::Impl {
  std::vector<detail::PolygonWithHoles> pieces;
  // Lazily computed double boundary, shared by every query.
  mutable std::once_flag loops_once;
  mutable std::vector<Component> components;  // loops + figures, slivers kept
  mutable std::size_t curve_count = 0;
};

}  // namespace pkmws::geometry
