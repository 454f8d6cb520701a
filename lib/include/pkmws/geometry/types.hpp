// Plain double-based geometric value types shared by every public header.
// No CGAL here: exact types live only in lib/src/detail/cgal_kernel.hpp.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace pkmws::geometry {

/// A point or vector in the plane, in the mechanism's length unit.
struct Point {
  double x = 0.0;
  double y = 0.0;
  friend bool operator==(const Point&, const Point&) = default;
};

inline Point operator+(Point a, Point b) { return {a.x + b.x, a.y + b.y}; }
inline Point operator-(Point a, Point b) { return {a.x - b.x, a.y - b.y}; }
inline Point operator*(double s, Point a) { return {s * a.x, s * a.y}; }
inline double dot(Point a, Point b) { return a.x * b.x + a.y * b.y; }
inline double cross(Point a, Point b) { return a.x * b.y - a.y * b.x; }
inline double norm(Point a) { return std::hypot(a.x, a.y); }

/// Axis-aligned box; `empty()` when min > max (the default).
struct Box {
  Point min{1.0, 1.0};
  Point max{-1.0, -1.0};
  bool empty() const { return min.x > max.x || min.y > max.y; }
  double width() const { return empty() ? 0.0 : max.x - min.x; }
  double height() const { return empty() ? 0.0 : max.y - min.y; }
  void expand(Point p) {
    if (empty()) { min = max = p; return; }
    min.x = std::min(min.x, p.x); min.y = std::min(min.y, p.y);
    max.x = std::max(max.x, p.x); max.y = std::max(max.y, p.y);
  }
  void expand(const Box& b) { if (!b.empty()) { expand(b.min); expand(b.max); } }
  bool contains(Point p) const {
    return p.x >= min.x && p.x <= max.x && p.y >= min.y && p.y <= max.y;
  }
};

/// One boundary curve: a line segment or a circular arc. Consecutive pieces on
/// one supporting circle are merged, so an arc may sweep up to a full turn.
/// Source and target follow the loop's orientation.
struct Curve {
  enum class Kind { segment, arc };
  Kind kind = Kind::segment;
  Point source;
  Point target;
  Point center;          // arcs only
  double radius = 0.0;   // arcs only
  bool ccw = true;       // arcs only: direction of travel from source to target
  /// Signed swept angle (radians) when known from the exact pieces; NaN means
  /// "derive it from the endpoints" (closed endpoints then mean a full turn).
  double swept = std::numeric_limits<double>::quiet_NaN();
  /// Signed swept angle of an arc in radians (positive = counter-clockwise).
  double sweep() const;
  double length() const;
  /// Point at parameter t in [0, 1] (uniform in angle for arcs).
  Point at(double t) const;
};

/// A closed boundary loop; outer loops are counter-clockwise, holes clockwise.
struct Loop {
  std::vector<Curve> curves;
  bool hole = false;
  double signed_area() const;  // Green's theorem, exact per curve
  double perimeter() const;
  Box bbox() const;
  /// Polyline with every point on the curve and max deviation <= tolerance.
  /// Closed: the first point is not repeated at the end.
  std::vector<Point> polyline(double tolerance) const;
};

/// A connected component: one outer loop and its holes.
struct Component {
  Loop outer;
  std::vector<Loop> holes;
  double area = 0.0;
  double perimeter = 0.0;
  Point centroid;
  Box bbox;
};

}  // namespace pkmws::geometry
