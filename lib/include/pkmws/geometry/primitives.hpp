// Exact primitive regions. Lengths are in the caller's unit; angles in radians.
//
// Directions at irrational angles are replaced by the rational unit vector
// ((1 - t^2) / (1 + t^2), 2t / (1 + t^2)) with t = tan(angle / 2) rounded to a
// double (angle error ~1e-16 rad, see docs/theory.md), so that offset points
// and arc endpoints stay rational and every primitive is exact.
#pragma once

#include <vector>

#include "pkmws/geometry/region.hpp"

namespace pkmws::geometry {

/// Rational unit vector closest (to ~1e-16 rad) to the direction `angle`.
/// |result| == 1 holds exactly in rational arithmetic on the returned doubles
/// only through the parametrisation; use it for every direction you build.
struct RationalDirection {
  double t = 0.0;      // tan(angle/2), the exact parameter (|t| <= 1 after folding)
  int quadrant = 0;    // rotation by quadrant * pi/2 applied after the parametrisation
  Point unit() const;  // the (rounded) double unit vector, for display only
  double angle() const;
};
RationalDirection rational_direction(double angle);

/// Closed disk of centre c and radius r > 0.
Region disk(Point c, double r);
/// Closed annulus r_inner <= |p - c| <= r_outer (r_inner may be 0: a disk).
Region annulus(Point c, double r_inner, double r_outer);
/// Half-plane { p : (p - point) . normal(angle) >= 0 } clipped to `clip`;
/// `normal_angle` is the direction of the inward normal.
Region half_plane(Point point, double normal_angle, const Box& clip);
/// Strip { p : 0 <= (p - point) . n <= width }, n = normal(normal_angle), clipped.
Region strip(Point point, double normal_angle, double width, const Box& clip);
/// Simple polygon (either orientation; must not self-intersect).
Region polygon(const std::vector<Point>& vertices);
/// Axis-aligned rectangle.
Region rectangle(const Box& box);
/// Rectangle of length `length` along direction `angle` from `start`, and
/// half-width `half_width` on each side of that centre line.
Region oriented_rectangle(Point start, double angle, double length, double half_width);
/// Stadium: the Minkowski sum of segment [a, b] and a disk of radius r
/// (the segment direction is rounded to a rational direction).
Region stadium(Point a, Point b, double r);
/// Band: a half circle of radius r swept along a segment. The segment runs from
/// `start` for `length` along direction `angle`; the half circle lies on the
/// side `side * u` (side = +1 ahead of the moving centre, -1 behind), where u is
/// the segment direction. The MOMA leg workspace (docs/theory/moma.md). Area = 2 r length.
Region band(Point start, double angle, double length, double r, int side);
/// Sector of an annulus: r_inner <= |p - c| <= r_outer with polar angle in
/// [angle_from, angle_from + sweep], sweep in (0, 2pi]; angles rounded to rational directions.
Region annulus_sector(Point c, double r_inner, double r_outer, double angle_from, double sweep);

}  // namespace pkmws::geometry
