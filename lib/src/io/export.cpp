// Boundary exports (docs/format.md): SVG with true arcs, DXF R12 with LINE / ARC /
// CIRCLE, WKT and GeoJSON polylines at a stated tolerance, CSV of the exact
// curves; and the atomic file writer used for every output file.
//
// All lengths are in the mechanism file's unit, angles in the file formats'
// own convention (SVG: flags, DXF: degrees ccw, CSV: degrees signed).
#include "geometry/loops.hpp"
#include "io/text.hpp"
#include "pkmws/geometry/polyline.hpp"
#include "pkmws/io/export.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <map>
#include <numbers>
#include <stdexcept>
#include <utility>
#include <system_error>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace pkmws::io {

using geometry::Component;
using geometry::Curve;
using geometry::Loop;
using geometry::Point;
using geometry::Region;

namespace {

constexpr double pi = std::numbers::pi;
constexpr double rad2deg = 180.0 / pi;

// Shortest decimal text that reads back (strtod) as the same double; at most
// 17 significant digits, which always round-trips.
// A value that is not finite (coordinates near the largest double) is refused:
// no export ever writes nan or inf.
std::string num(double v) {
  if (!std::isfinite(v)) {
    throw InputError("cannot export: a coordinate or size is not a finite number (lengths too large for double precision)");
  }
  if (v == 0.0) return "0";  // also folds -0
  char buf[40];
  for (int digits = 6; digits < 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    if (std::strtod(buf, nullptr) == v) return buf;
  }
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

double diagonal(const Region& r) {
  const auto b = r.bbox();
  return std::hypot(b.width(), b.height());
}

// Size of a region for relative thresholds: its diagonal or its largest
// coordinate, whichever is larger (rounding grows with the coordinates).
double region_size(const Region& r) {
  const auto b = r.bbox();
  if (b.empty()) return 0.0;
  return std::max({std::hypot(b.width(), b.height()), std::abs(b.min.x), std::abs(b.min.y),
                   std::abs(b.max.x), std::abs(b.max.y)});
}

// Pieces of the exact boundary shorter than this are below the rounding of
// their coordinates (e.g. 1e-14-long pieces between nearly coincident
// intersections): left out of DXF / CSV / SVG, merged into their neighbours
// in polygons.
double snap_length(const Region& r) { return 256.0 * std::numeric_limits<double>::epsilon() * region_size(r); }

std::vector<Component> components_of(const Region& region, const ExportOptions& options) {
  return region.components(effective_min_area(region, options));
}

bool degenerate(const Curve& c, double snap) {
  if (c.kind == Curve::Kind::segment) return norm(c.target - c.source) <= snap;
  return c.length() <= snap;
}

// Outer loop then holes, in the order of the component.
std::vector<const Loop*> loops_of(const Component& c) {
  std::vector<const Loop*> loops{&c.outer};
  for (const Loop& h : c.holes) loops.push_back(&h);
  return loops;
}

bool full_circle(const Curve& c) { return c.kind == Curve::Kind::arc && c.source == c.target; }

// Number of SVG `A` commands used for an arc of signed sweep s (radians).
// An SVG arc is given by its endpoints, so its centre is recomputed by the
// reader at distance d = r |cos(s/2)| from the chord; rounding the endpoints
// by e moves the centre by e |tan(s/2)| (large near s = pi) and tilts the chord
// by e / (2 r sin(s/2)) (large near s = 2 pi). One command is used where both
// factors are <= 2 (|s| <= 2pi/3 or 4pi/3 <= |s| <= 5pi/3, the latter with the
// large-arc flag), otherwise equal pieces of at most 2pi/3 (a full circle: 3).
int svg_arc_pieces(double s) {
  const double a = std::abs(s);
  if (a <= 2.0 * pi / 3.0 || (a >= 4.0 * pi / 3.0 && a <= 5.0 * pi / 3.0)) return 1;
  return static_cast<int>(std::ceil(a / (2.0 * pi / 3.0)));
}

// Sum of arc lengths over the exported loops and the largest |coordinate|.
struct LoopMeasure {
  double arc_length = 0.0;
  double perimeter = 0.0;
  double extent = 0.0;
};

LoopMeasure measure(const std::vector<Component>& comps) {
  LoopMeasure m;
  for (const Component& c : comps) {
    for (const Loop* loop : loops_of(c)) {
      for (const Curve& cv : loop->curves) {
        const double len = cv.length();
        m.perimeter += len;
        if (cv.kind == Curve::Kind::arc) m.arc_length += len;
      }
    }
    m.extent = std::max({m.extent, std::abs(c.bbox.min.x), std::abs(c.bbox.min.y),
                         std::abs(c.bbox.max.x), std::abs(c.bbox.max.y)});
  }
  return m;
}

std::string json_escape(std::string_view text) {
  std::string out;
  for (char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else {
      out += c;
    }
  }
  return out;
}

// DXF angle in degrees in [0, 360) of point p seen from the centre c.
double dxf_angle(Point p, Point c) {
  double a = std::atan2(p.y - c.y, p.x - c.x) * rad2deg;
  if (a < 0.0) a += 360.0;
  if (a >= 360.0) a -= 360.0;
  return a;
}

}  // namespace

ExportFormat parse_export_format(std::string_view name) {
  if (name == "svg") return ExportFormat::svg;
  if (name == "dxf") return ExportFormat::dxf;
  if (name == "wkt") return ExportFormat::wkt;
  if (name == "geojson") return ExportFormat::geojson;
  if (name == "csv") return ExportFormat::csv;
  throw InputError("--format: unknown format \"" + std::string(name) +
                   "\" (expected svg, dxf, wkt, geojson or csv)");
}

std::string_view format_name(ExportFormat format) {
  switch (format) {
    case ExportFormat::svg: return "svg";
    case ExportFormat::dxf: return "dxf";
    case ExportFormat::wkt: return "wkt";
    case ExportFormat::geojson: return "geojson";
    case ExportFormat::csv: return "csv";
  }
  return "";
}

std::string_view bound_name(Bound bound) {
  switch (bound) {
    case Bound::exact: return "exact";
    case Bound::inner: return "inner";
    case Bound::outer: return "outer";
  }
  return "";
}

double min_tolerance(const Region& region) { return 1e-12 * region_size(region); }

double max_tolerance(const Region& region) { return 0.1 * diagonal(region); }

double effective_tolerance(const Region& region, const ExportOptions& options) {
  if (options.tolerance > 0.0) return options.tolerance;
  const double d = diagonal(region);
  return d > 0.0 ? std::max(1e-6 * d, min_tolerance(region)) : 1e-9;
}

double effective_min_area(const Region& region, const ExportOptions& options) {
  if (options.min_area > 0.0) return options.min_area;
  const auto b = region.bbox();
  return 1e-12 * b.width() * b.height();
}

namespace {

geometry::Approximation approximation_of(Bound bound) {
  switch (bound) {
    case Bound::inner: return geometry::Approximation::inside;
    case Bound::outer: return geometry::Approximation::outside;
    case Bound::exact: break;
  }
  return geometry::Approximation::chords;
}

double polygon_vertices(const std::vector<Component>& comps, double tolerance, geometry::Approximation a) {
  double n = 0.0;
  for (const Component& c : comps) {
    for (const Loop* loop : loops_of(c)) {
      for (const Curve& cv : loop->curves) n += geometry::polyline_pieces(cv, tolerance, a);
    }
  }
  return n;
}

}  // namespace

void check_tolerance(const Region& region, const ExportOptions& options) {
  const double t = options.tolerance;
  if (!std::isfinite(t) || t < 0.0) throw InputError("--tolerance: must be a positive finite length");
  if (region.empty()) return;
  const double tol = effective_tolerance(region, options);
  char buf[320];
  if (tol < min_tolerance(region)) {
    std::snprintf(buf, sizeof buf,
                  "--tolerance: %.3g is below the attainable %.3g (double precision at coordinates up to %.3g); "
                  "use at least %.3g",
                  tol, min_tolerance(region), region_size(region), min_tolerance(region));
    throw InputError(buf);
  }
  if (tol > max_tolerance(region)) {
    std::snprintf(buf, sizeof buf, "--tolerance: %.3g is above %.3g (a tenth of the workspace's diagonal)", tol,
                  max_tolerance(region));
    throw InputError(buf);
  }
  const double n = polygon_vertices(components_of(region, options), tol, approximation_of(options.bound));
  if (n > max_polygon_vertices) {
    // Vertices grow as tolerance^(-1/2): suggest the tolerance that fits.
    const double suggest = 1.1 * tol * (n / max_polygon_vertices) * (n / max_polygon_vertices);
    std::snprintf(buf, sizeof buf,
                  "--tolerance: %.3g would give %.3g polygon vertices (more than %.0f); use at least %.3g", tol, n,
                  max_polygon_vertices, suggest);
    throw InputError(buf);
  }
}

double polyline_area_error_bound(const Region& region, const ExportOptions& options) {
  // A chord spanning h <= pi of an arc of radius r cuts off a circular segment
  // of area (r^2/2) (h - sin h), which is at most (pi/4) * (r h) * sagitta
  // (ratio 2/3 as h -> 0, pi/4 at h = pi); a tangent piece of angle h <= pi/2
  // adds r^2 (tan(h/2) - h/2) <= (1/3) * (r h) * r (sec(h/2) - 1). Each
  // deviation is <= tolerance, so the polygons' area is within (pi/4) *
  // tolerance * (total arc length) of the exact one. Add the shoelace
  // rounding (~eps * |coordinate| per unit of perimeter, 16x margin) and the
  // vertices merged with a neighbour closer than snap_length.
  const double tol = effective_tolerance(region, options);
  const LoopMeasure m = measure(components_of(region, options));
  return 0.25 * pi * tol * m.arc_length +
         16.0 * std::numeric_limits<double>::epsilon() * m.perimeter * (m.extent + tol) +
         snap_length(region) * m.perimeter;
}

namespace {

// ------------------------------------------------------------ polygons

// An open ring (first point not repeated) and, per edge pts[i] -> pts[i+1],
// the index of the boundary curve it approximates.
struct IRing {
  std::vector<Point> pts;
  std::vector<std::size_t> curve;
  double area = 0.0;
};

double ring_area(const std::vector<Point>& pts) {
  if (pts.size() < 3) return 0.0;
  const Point o = pts.front();
  double twice = 0.0;
  for (std::size_t i = 1; i + 1 < pts.size(); ++i) twice += cross(pts[i] - o, pts[i + 1] - o);
  return 0.5 * twice;
}

double ring_perimeter(const std::vector<Point>& pts) {
  double s = 0.0;
  for (std::size_t i = 0; i < pts.size(); ++i) s += norm(pts[(i + 1) % pts.size()] - pts[i]);
  return s;
}

// u and v (from one vertex) point along one line in the same direction, up to
// rounding: the two edges overlap.
bool overlapping(Point u, Point v) {
  return std::abs(cross(u, v)) <= 1e-10 * norm(u) * norm(v) && dot(u, v) > 0.0;
}

struct RVertex {
  Point p;
  std::size_t curve;  // of the edge leaving p
  bool exact;         // a curve's end (kept in preference to polyline points)
};

// Where two curves meet tangentially with the region between them (a cusp,
// e.g. a crank-limited five-bar's pinch or a hole tangent internally), no
// one-sided polyline can reach the tip: the tangent pieces of the concave
// curve run along the common tangent, outside the region and across the
// convex curve's chords. The tip is cut at the first crossing of the two
// polylines; what remains is on the right side of both curves.
bool crossing(Point a, Point b, Point c, Point d, Point& q) {
  const Point r = b - a, s = d - c;
  const double den = cross(r, s);
  if (den == 0.0) return false;
  const double t = cross(c - a, s) / den, u = cross(c - a, r) / den;
  if (!(t > 0.0 && t < 1.0 && u > 0.0 && u < 1.0)) return false;
  q = a + t * r;
  return true;
}

void cut_cusps(std::vector<RVertex>& v) {
  constexpr std::size_t k = 4;  // edges looked at on either side of a curve's end
  const std::size_t n = v.size();
  if (n < 4) return;
  std::vector<char> drop(n, 0);
  std::vector<std::pair<std::size_t, Point>> replace;  // vertex index -> crossing point
  for (std::size_t p = 0; p < n; ++p) {
    if (!v[p].exact) continue;
    const std::size_t prev_curve = v[(p + n - 1) % n].curve, next_curve = v[p].curve;
    if (prev_curve == next_curve) continue;
    bool done = false;
    // e_i = (v[p-i], v[p-i+1]) on the previous curve, f_j = (v[p+j-1], v[p+j]) on the next one.
    for (std::size_t i = 1; i <= k && !done; ++i) {
      if (v[(p + n - i) % n].curve != prev_curve) break;
      for (std::size_t j = 1; j <= k && !done; ++j) {
        if (i == 1 && j == 1) continue;
        if (v[(p + j - 1) % n].curve != next_curve || i + j >= n) break;
        Point q;
        if (crossing(v[(p + n - i) % n].p, v[(p + n - i + 1) % n].p, v[(p + j - 1) % n].p, v[(p + j) % n].p, q)) {
          // Keep v[p-i], then q, then v[p+j]: drop the vertices between.
          for (std::size_t m = p + n - i + 1; m < p + n + j; ++m) drop[m % n] = 1;
          replace.emplace_back((p + n - i + 1) % n, q);
          done = true;
        }
      }
    }
  }
  if (replace.empty()) return;
  for (const auto& [idx, q] : replace) drop[idx] = 2;
  std::vector<RVertex> out;
  for (std::size_t i = 0; i < n; ++i) {
    if (drop[i] == 1) continue;
    if (drop[i] == 2) {
      for (const auto& [idx, q] : replace) {
        if (idx == i) out.push_back({q, v[i].curve, false});
      }
      continue;
    }
    out.push_back(v[i]);
  }
  v.swap(out);
}

// The rings of one loop: its polyline with the curves' ids; vertices within
// `snap` of their predecessor merged; spikes (an edge going straight back
// along the previous one, e.g. where tangent polylines of two tangent circles
// meet) removed; then split at every vertex visited twice (a pinch), so that
// no ring touches itself.
void loop_rings(const Loop& loop, std::size_t first_id, const std::vector<double>& tol, geometry::Approximation a,
                double snap, std::vector<IRing>& out) {
  std::vector<RVertex> raw;
  std::vector<Point> buf;
  for (std::size_t k = 0; k < loop.curves.size(); ++k) {
    buf.clear();
    geometry::append_polyline(loop.curves[k], tol[first_id + k], a, buf);
    for (std::size_t i = 0; i < buf.size(); ++i) raw.push_back({buf[i], first_id + k, i == 0});
  }
  std::vector<RVertex> v;
  v.reserve(raw.size());
  for (const RVertex& r : raw) {
    if (!v.empty() && norm(r.p - v.back().p) <= snap) {
      if (r.exact && !v.back().exact) v.back().p = r.p, v.back().exact = true;
      v.back().curve = r.curve;
      continue;
    }
    v.push_back(r);
  }
  while (v.size() > 1 && norm(v.back().p - v.front().p) <= snap) {
    if (v.back().exact && !v.front().exact) v.front().p = v.back().p, v.front().exact = true;
    v.pop_back();
  }
  if (a != geometry::Approximation::chords) cut_cusps(v);
  // Spikes, repeatedly (removing one may expose another).
  for (bool changed = true; changed && v.size() >= 3;) {
    changed = false;
    std::vector<RVertex> w;
    w.reserve(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) {
      const Point prev = w.empty() ? v.back().p : w.back().p;
      const Point next = v[(i + 1) % v.size()].p;
      const Point cur = v[i].p;
      if (overlapping(prev - cur, next - cur) || prev == next) {
        changed = true;
        if (!w.empty()) w.back().curve = v[i].curve;
        continue;
      }
      w.push_back(v[i]);
    }
    v.swap(w);
    while (v.size() > 1 && v.back().p == v.front().p) v.pop_back();
  }
  if (v.size() < 3) return;
  // Split at repeated points.
  std::map<std::pair<double, double>, std::size_t> seen;
  std::vector<RVertex> stack;
  auto emit = [&out, snap](std::vector<RVertex>::const_iterator b, std::vector<RVertex>::const_iterator e) {
    IRing r;
    for (auto it = b; it != e; ++it) {
      r.pts.push_back(it->p);
      r.curve.push_back(it->curve);
    }
    r.area = ring_area(r.pts);
    if (r.pts.size() >= 3 && std::abs(r.area) > snap * ring_perimeter(r.pts)) out.push_back(std::move(r));
  };
  for (const RVertex& x : v) {
    const auto key = std::make_pair(x.p.x, x.p.y);
    const auto it = seen.find(key);
    if (it == seen.end()) {
      seen.emplace(key, stack.size());
      stack.push_back(x);
      continue;
    }
    const std::size_t j = it->second;
    emit(stack.begin() + static_cast<std::ptrdiff_t>(j), stack.end());
    for (std::size_t i = j + 1; i < stack.size(); ++i) seen.erase({stack[i].p.x, stack[i].p.y});
    stack.resize(j + 1);
    stack[j].curve = x.curve;
  }
  emit(stack.begin(), stack.end());
}

// Crossing-number test; points on the boundary may go either way.
bool inside_ring(const std::vector<Point>& ring, Point p) {
  bool in = false;
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const Point a = ring[i], b = ring[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) in = !in;
  }
  return in;
}

struct IPolygon {
  IRing shell;
  std::vector<IRing> holes;
};

// Where rings of one component meet at a vertex (a hole touching its shell,
// or another hole, at two points cuts the interior in two, which GEOS's model
// refuses), the rings are traced again: the region lies left of every edge
// (shells counter-clockwise, holes clockwise), and at a vertex with several
// ways on the sharpest left turn keeps to one piece of the interior; each
// loop is then split at repeated vertices. Rings that meet nowhere stay.
void retrace(std::vector<IRing>& rings) {
  std::vector<std::pair<Point, Point>> edges;
  std::vector<std::size_t> curve;  // per edge
  std::map<std::pair<double, double>, int> starts;
  bool meet = false;
  for (const IRing& r : rings) {
    for (std::size_t i = 0; i < r.pts.size(); ++i) {
      meet = meet || ++starts[{r.pts[i].x, r.pts[i].y}] > 1;
      edges.push_back({r.pts[i], r.pts[(i + 1) % r.pts.size()]});
      curve.push_back(r.curve[i]);
    }
  }
  if (!meet) return;
  std::vector<IRing> out;
  for (const auto& loop : geometry::left_turn_loops(edges)) {
    IRing r;
    for (const std::size_t e : loop) {
      r.pts.push_back(edges[e].first);
      r.curve.push_back(curve[e]);
    }
    r.area = ring_area(r.pts);
    if (r.pts.size() >= 3 && r.area != 0.0) out.push_back(std::move(r));
  }
  rings.swap(out);
}

// Rings of one component -> polygons: counter-clockwise rings are shells,
// clockwise ones holes, each in the smallest shell that contains it.
void assemble(std::vector<IRing>& rings, std::vector<IPolygon>& out) {
  retrace(rings);
  const std::size_t first = out.size();
  std::vector<IRing> holes;
  for (IRing& r : rings) {
    if (r.area > 0.0) out.push_back({std::move(r), {}});
    else holes.push_back(std::move(r));
  }
  if (out.size() == first) return;  // holes without a shell: nothing left of the component
  for (IRing& h : holes) {
    std::size_t best = first;
    if (out.size() - first > 1) {
      double best_area = std::numeric_limits<double>::infinity();
      for (std::size_t k = first; k < out.size(); ++k) {
        const auto& shell = out[k].shell.pts;
        // A hole vertex not shared with the shell (shared ones are pinches) decides.
        for (const Point& p : h.pts) {
          if (std::find(shell.begin(), shell.end(), p) != shell.end()) continue;
          if (inside_ring(shell, p) && out[k].shell.area < best_area) {
            best = k;
            best_area = out[k].shell.area;
          }
          break;
        }
      }
    }
    out[best].holes.push_back(std::move(h));
  }
}

// ------------------------------------------------------ conflict search

struct Edge {
  Point a, b;
  std::size_t ring, index, size, curve;
};

// Sign of (b - a) x (c - a); 0 when within a rounding bound (nearly collinear).
int orient(Point a, Point b, Point c) {
  const double l = (b.x - a.x) * (c.y - a.y);
  const double r = (b.y - a.y) * (c.x - a.x);
  const double det = l - r;
  if (std::abs(det) <= 1e-12 * (std::abs(l) + std::abs(r))) return 0;
  return det > 0.0 ? 1 : -1;
}

bool in_box(Point p, Point a, Point b) {
  return p.x >= std::min(a.x, b.x) && p.x <= std::max(a.x, b.x) && p.y >= std::min(a.y, b.y) &&
         p.y <= std::max(a.y, b.y);
}

// Edges that cross, overlap, or where one touches the other away from a
// shared vertex: what GEOS would call a self-intersection (or, between rings,
// more than a point of contact). Edges sharing an exact vertex may touch there.
bool conflict(const Edge& e, const Edge& f) {
  const bool ea_fa = e.a == f.a, ea_fb = e.a == f.b, eb_fa = e.b == f.a, eb_fb = e.b == f.b;
  const int shared = int(ea_fa) + int(ea_fb) + int(eb_fa) + int(eb_fb);
  if (shared >= 2) return true;
  if (shared == 1) {
    const Point x = (ea_fa || ea_fb) ? e.a : e.b;
    const Point u = (x == e.a ? e.b : e.a) - x;
    const Point v = (x == f.a ? f.b : f.a) - x;
    return overlapping(u, v);
  }
  const int o1 = orient(e.a, e.b, f.a), o2 = orient(e.a, e.b, f.b);
  const int o3 = orient(f.a, f.b, e.a), o4 = orient(f.a, f.b, e.b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return (o1 == 0 && in_box(f.a, e.a, e.b)) || (o2 == 0 && in_box(f.b, e.a, e.b)) ||
         (o3 == 0 && in_box(e.a, f.a, f.b)) || (o4 == 0 && in_box(e.b, f.a, f.b));
}

// Curves whose edges conflict, found through a uniform grid of about one
// edge per cell.
std::vector<std::size_t> conflicting_curves(const std::vector<IPolygon>& polys) {
  std::vector<Edge> edges;
  std::size_t ring = 0;
  auto add = [&edges, &ring](const IRing& r) {
    for (std::size_t i = 0; i < r.pts.size(); ++i) {
      edges.push_back({r.pts[i], r.pts[(i + 1) % r.pts.size()], ring, i, r.pts.size(), r.curve[i]});
    }
    ++ring;
  };
  for (const IPolygon& p : polys) {
    add(p.shell);
    for (const IRing& h : p.holes) add(h);
  }
  if (edges.size() < 2) return {};
  geometry::Box box;
  for (const Edge& e : edges) box.expand(e.a);
  const double g = std::clamp(std::floor(std::sqrt(static_cast<double>(edges.size()))), 1.0, 2048.0);
  const double cw = box.width() > 0.0 ? box.width() / g : 1.0;
  const double ch = box.height() > 0.0 ? box.height() / g : 1.0;
  auto cell = [&](double v, double lo, double w) {
    return static_cast<std::size_t>(std::clamp(std::floor((v - lo) / w), 0.0, g - 1.0));
  };
  const auto gs = static_cast<std::size_t>(g);
  std::vector<std::pair<std::size_t, std::size_t>> entries;  // (cell, edge)
  for (std::size_t k = 0; k < edges.size(); ++k) {
    const Edge& e = edges[k];
    const std::size_t x0 = cell(std::min(e.a.x, e.b.x), box.min.x, cw), x1 = cell(std::max(e.a.x, e.b.x), box.min.x, cw);
    const std::size_t y0 = cell(std::min(e.a.y, e.b.y), box.min.y, ch), y1 = cell(std::max(e.a.y, e.b.y), box.min.y, ch);
    for (std::size_t x = x0; x <= x1; ++x) {
      for (std::size_t y = y0; y <= y1; ++y) entries.emplace_back(y * gs + x, k);
    }
  }
  std::sort(entries.begin(), entries.end());
  std::vector<std::size_t> bad;
  for (std::size_t i = 0; i < entries.size();) {
    std::size_t j = i;
    while (j < entries.size() && entries[j].first == entries[i].first) ++j;
    for (std::size_t p = i; p < j; ++p) {
      for (std::size_t q = p + 1; q < j; ++q) {
        const Edge& e = edges[entries[p].second];
        const Edge& f = edges[entries[q].second];
        if (e.ring == f.ring && (e.index + 1) % e.size != f.index && (f.index + 1) % f.size != e.index) {
          // non-adjacent edges of one ring: no contact allowed at all
          if (conflict(e, f) || e.a == f.a || e.a == f.b || e.b == f.a || e.b == f.b) {
            bad.push_back(e.curve);
            bad.push_back(f.curve);
          }
        } else if (e.ring == f.ring) {
          // adjacent edges share one vertex: only an overlap is wrong
          if (conflict(e, f)) {
            bad.push_back(e.curve);
            bad.push_back(f.curve);
          }
        } else if (conflict(e, f)) {
          bad.push_back(e.curve);
          bad.push_back(f.curve);
        }
      }
    }
    i = j;
  }
  std::sort(bad.begin(), bad.end());
  bad.erase(std::unique(bad.begin(), bad.end()), bad.end());
  return bad;
}

std::vector<Point> closed(const std::vector<Point>& pts) {
  std::vector<Point> r = pts;
  if (!r.empty()) r.push_back(r.front());
  return r;
}

}  // namespace

std::vector<ExportPolygon> export_polygons(const Region& region, const ExportOptions& options) {
  check_tolerance(region, options);
  const auto comps = components_of(region, options);
  if (comps.empty()) return {};
  const geometry::Approximation a = approximation_of(options.bound);
  const double snap = snap_length(region);
  const double floor = min_tolerance(region);
  std::vector<const Curve*> curves;
  for (const Component& c : comps) {
    for (const Loop* loop : loops_of(c)) {
      for (const Curve& cv : loop->curves) curves.push_back(&cv);
    }
  }
  std::vector<double> tol(curves.size(), effective_tolerance(region, options));
  // Polylines of arcs closer to each other than the tolerance may cross or
  // touch: refine the arcs concerned (a quarter of the tolerance each round,
  // doubling their vertices) until no edges conflict. The exact curves meet
  // only at shared vertices, so this ends once the pieces are fine enough.
  for (int round = 0;; ++round) {
    std::vector<IPolygon> polys;
    std::size_t id = 0;
    for (const Component& c : comps) {
      std::vector<IRing> rings;
      for (const Loop* loop : loops_of(c)) {
        loop_rings(*loop, id, tol, a, snap, rings);
        id += loop->curves.size();
      }
      assemble(rings, polys);
    }
    const std::vector<std::size_t> bad = conflicting_curves(polys);
    if (bad.empty()) {
      std::vector<ExportPolygon> out;
      for (const IPolygon& p : polys) {
        ExportPolygon e;
        e.shell = closed(p.shell.pts);
        for (const IRing& h : p.holes) e.holes.push_back(closed(h.pts));
        out.push_back(std::move(e));
      }
      return out;
    }
    bool progress = false;
    double vertices = 0.0;
    for (const std::size_t k : bad) {
      if (curves[k]->kind == Curve::Kind::arc && tol[k] >= 4.0 * floor) {
        tol[k] *= 0.25;
        progress = true;
      }
    }
    for (std::size_t k = 0; k < curves.size(); ++k) vertices += geometry::polyline_pieces(*curves[k], tol[k], a);
    if (!progress || round >= 60 || vertices > max_polygon_vertices) {
      throw InputError(
          "cannot export valid polygons: boundary pieces closer to each other than double precision resolves "
          "(use dxf, csv or svg, which keep the exact curves)");
    }
  }
}

std::string svg_path(const Region& region, const ExportOptions& options) {
  // Path data in mathematical coordinates (the caller flips y). Arc command:
  // A r r 0 large-arc sweep x y, with sweep = 1 for counter-clockwise (the
  // positive-angle direction of the path's own, unflipped coordinates) and
  // large-arc = 1 when the piece sweeps more than pi. See svg_arc_pieces.
  std::string d;
  const double snap = snap_length(region);
  for (const Component& c : components_of(region, options)) {
    for (const Loop* loop : loops_of(c)) {
      std::vector<const Curve*> kept;
      for (const Curve& cv : loop->curves) {
        if (!degenerate(cv, snap)) kept.push_back(&cv);
      }
      if (kept.empty()) continue;
      if (!d.empty()) d += ' ';
      d += "M" + num(kept.front()->source.x) + " " + num(kept.front()->source.y);
      for (const Curve* pc : kept) {
        const Curve& cv = *pc;
        if (cv.kind == Curve::Kind::segment) {
          d += " L" + num(cv.target.x) + " " + num(cv.target.y);
          continue;
        }
        const double sweep = cv.sweep();
        const int n = svg_arc_pieces(sweep);
        const std::string r = num(cv.radius);
        const std::string large = std::abs(sweep / n) > pi ? " 1" : " 0";
        const std::string flag = cv.ccw ? " 1 " : " 0 ";
        for (int k = 1; k <= n; ++k) {
          const Point q = k == n ? cv.target : cv.at(static_cast<double>(k) / n);
          d += " A" + r + " " + r + " 0" + large + flag + num(q.x) + " " + num(q.y);
        }
      }
      d += " Z";
    }
  }
  return d;
}

std::string to_svg(const Region& region, const ExportOptions& options) {
  // y is flipped by the group's transform, so the viewBox spans [-max.y, -min.y].
  auto b = region.bbox();
  if (b.empty()) b = geometry::Box{{0.0, 0.0}, {1.0, 1.0}};
  const double size = std::max({b.width(), b.height(), 1e-300});
  const double margin = 0.05 * size;
  std::string s = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  const double w = b.width() + 2 * margin, h = b.height() + 2 * margin;
  // Physical size (SVG has mm but not m): one drawing unit is one file unit,
  // so CAD and vector editors import the boundary at 1:1.
  const double mm = options.units == "mm" ? 1.0 : options.units == "m" ? 1000.0 : 0.0;
  s += "<svg xmlns=\"http://www.w3.org/2000/svg\"";
  if (mm > 0.0) s += " width=\"" + num(mm * w) + "mm\" height=\"" + num(mm * h) + "mm\"";
  s += " viewBox=\"" + num(b.min.x - margin) + " " + num(-b.max.y - margin) + " " + num(w) + " " + num(h) +
       "\">\n";
  s += "  <!-- pkmws workspace boundary (" + std::string(bound_name(options.bound)) +
       (options.bound == Bound::exact ? " region" : " enclosure") +
       "): line segments and true circular arcs in the mechanism's coordinates (y up, flipped by the group"
       " transform)";
  if (!options.units.empty()) s += "; unit: " + detail::xml_escape(options.units);
  s += "; area = " + num(region.area());
  if (std::isfinite(options.area_lower) && std::isfinite(options.area_upper)) {
    s += "; certified area of the true region: " + num(options.area_lower) + " .. " + num(options.area_upper);
  }
  s += " -->\n";
  s += "  <g transform=\"scale(1,-1)\">\n";
  s += "    <path fill=\"#f4a6a6\" fill-rule=\"evenodd\" stroke=\"#7a1010\" stroke-width=\"" +
       num(0.004 * size) + "\" stroke-linejoin=\"round\" d=\"" + svg_path(region, options) +
       "\"/>\n";
  s += "  </g>\n</svg>\n";
  return s;
}

std::string to_dxf(const Region& region, const ExportOptions& options) {
  // AutoCAD R12 ASCII DXF: HEADER, TABLES (LTYPE, LAYER), ENTITIES, EOF.
  std::string s;
  auto pair = [&s](int code, std::string_view value) {
    s += std::to_string(code);
    s += '\n';
    s += value;
    s += '\n';
  };
  const auto comps = components_of(region, options);
  auto b = region.bbox();
  if (b.empty()) b = geometry::Box{{0.0, 0.0}, {0.0, 0.0}};

  pair(999, "pkmws exact workspace boundary: LINE, ARC (counter-clockwise) and CIRCLE entities");
  pair(999, "layers: BOUNDARY (outer loops), HOLES; unit: " +
                (options.units.empty() ? std::string("drawing unit") : options.units));
  {
    std::string what = "bound: " + std::string(bound_name(options.bound)) +
                       (options.bound == Bound::exact ? " (the exact region)"
                        : options.bound == Bound::inner ? " enclosure (only points of the true region)"
                                                        : " enclosure (every point of the true region)");
    what += "; area " + num(region.area());
    if (std::isfinite(options.area_lower) && std::isfinite(options.area_upper)) {
      what += "; certified area of the true region " + num(options.area_lower) + " .. " + num(options.area_upper);
    }
    pair(999, what);
  }
  pair(0, "SECTION");
  pair(2, "HEADER");
  pair(9, "$ACADVER");
  pair(1, "AC1009");
  pair(9, "$MEASUREMENT");  // 1 = metric
  pair(70, options.units == "in" || options.units == "ft" ? "0" : "1");
  // Drawing units (read by CAD programs whatever the version): 4 mm, 6 m, 0 unitless.
  pair(9, "$INSUNITS");
  pair(70, options.units == "mm" ? "4" : options.units == "m" ? "6" : "0");
  pair(9, "$EXTMIN");
  pair(10, num(b.min.x)); pair(20, num(b.min.y)); pair(30, "0");
  pair(9, "$EXTMAX");
  pair(10, num(b.max.x)); pair(20, num(b.max.y)); pair(30, "0");
  pair(0, "ENDSEC");

  pair(0, "SECTION");
  pair(2, "TABLES");
  pair(0, "TABLE");
  pair(2, "LTYPE");
  pair(70, "1");
  pair(0, "LTYPE");
  pair(2, "CONTINUOUS");
  pair(70, "0");
  pair(3, "Solid line");
  pair(72, "65");
  pair(73, "0");
  pair(40, "0");
  pair(0, "ENDTAB");
  pair(0, "TABLE");
  pair(2, "LAYER");
  pair(70, "2");
  for (const auto& [name, color] : {std::pair{"BOUNDARY", "1"}, std::pair{"HOLES", "5"}}) {
    pair(0, "LAYER");
    pair(2, name);
    pair(70, "0");
    pair(62, color);  // ACI colour: 1 red, 5 blue
    pair(6, "CONTINUOUS");
  }
  pair(0, "ENDTAB");
  pair(0, "ENDSEC");

  pair(0, "SECTION");
  pair(2, "ENTITIES");
  const double snap = snap_length(region);
  for (const Component& c : comps) {
    for (const Loop* loop : loops_of(c)) {
      const std::string layer = loop->hole ? "HOLES" : "BOUNDARY";
      for (const Curve& cv : loop->curves) {
        if (degenerate(cv, snap)) continue;  // shorter than the rounding of its ends
        if (cv.kind == Curve::Kind::segment) {
          pair(0, "LINE");
          pair(8, layer);
          pair(10, num(cv.source.x)); pair(20, num(cv.source.y)); pair(30, "0");
          pair(11, num(cv.target.x)); pair(21, num(cv.target.y)); pair(31, "0");
          continue;
        }
        if (full_circle(cv)) {
          pair(0, "CIRCLE");
          pair(8, layer);
          pair(10, num(cv.center.x)); pair(20, num(cv.center.y)); pair(30, "0");
          pair(40, num(cv.radius));
          continue;
        }
        // DXF arcs always run counter-clockwise from the start to the end angle:
        // a clockwise curve is written with its ends swapped.
        const Point from = cv.ccw ? cv.source : cv.target;
        const Point to = cv.ccw ? cv.target : cv.source;
        const std::string a0 = num(dxf_angle(from, cv.center)), a1 = num(dxf_angle(to, cv.center));
        if (a0 == a1) continue;  // a sliver of arc whose angles round to one value (not a full turn)
        pair(0, "ARC");
        pair(8, layer);
        pair(10, num(cv.center.x)); pair(20, num(cv.center.y)); pair(30, "0");
        pair(40, num(cv.radius));
        pair(50, a0);
        pair(51, a1);
      }
    }
  }
  pair(0, "ENDSEC");
  pair(0, "EOF");
  return s;
}

// Polygons of export_polygons(): valid in GEOS's model, outer rings
// counter-clockwise, holes clockwise, first point repeated.
std::string to_wkt(const Region& region, const ExportOptions& options) {
  const auto polys = export_polygons(region, options);
  if (polys.empty()) return "MULTIPOLYGON EMPTY\n";
  std::string out = "MULTIPOLYGON (";
  auto ring_text = [&out](const std::vector<Point>& pts) {
    out += "(";
    for (std::size_t j = 0; j < pts.size(); ++j) {
      if (j) out += ", ";
      out += num(pts[j].x) + " " + num(pts[j].y);
    }
    out += ")";
  };
  for (std::size_t k = 0; k < polys.size(); ++k) {
    out += k ? ", (" : "(";
    ring_text(polys[k].shell);
    for (const auto& h : polys[k].holes) {
      out += ", ";
      ring_text(h);
    }
    out += ")";
  }
  return out + ")\n";
}

std::string to_geojson(const Region& region, const ExportOptions& options) {
  // RFC 7946 §3.1.6: exterior rings counter-clockwise, holes clockwise. The
  // coordinates are the mechanism's plane coordinates (not longitude/latitude).
  const double tol = effective_tolerance(region, options);
  const auto polys = export_polygons(region, options);
  std::string coords = "[";
  double polygon_area = 0.0;
  auto ring_text = [&coords, &polygon_area](const std::vector<Point>& pts) {
    coords += "[";
    for (std::size_t j = 0; j < pts.size(); ++j) {
      coords += (j ? ", [" : "[") + num(pts[j].x) + ", " + num(pts[j].y) + "]";
    }
    coords += "]";
    std::vector<Point> open(pts.begin(), pts.end() - 1);
    polygon_area += ring_area(open);
  };
  for (std::size_t k = 0; k < polys.size(); ++k) {
    coords += k ? ", [" : "[";
    ring_text(polys[k].shell);
    for (const auto& h : polys[k].holes) {
      coords += ", ";
      ring_text(h);
    }
    coords += "]";
  }
  coords += "]";
  const auto comps = components_of(region, options);
  double area = 0.0;
  for (const Component& c : comps) area += c.area;
  std::string props = "\"bound\": \"" + std::string(bound_name(options.bound)) + "\", \"area\": " + num(area) +
                      ", \"tolerance\": " + num(tol) +
                      ", \"area_error_bound\": " + num(polyline_area_error_bound(region, options)) +
                      ", \"polygon_area\": " + num(polygon_area) +
                      ", \"components\": " + std::to_string(comps.size()) +
                      ", \"polygons\": " + std::to_string(polys.size());
  if (std::isfinite(options.area_lower) && std::isfinite(options.area_upper)) {
    props += ", \"area_lower\": " + num(options.area_lower) + ", \"area_upper\": " + num(options.area_upper);
  }
  if (!options.units.empty()) props += ", \"units\": \"" + json_escape(options.units) + "\"";
  return "{\"type\": \"FeatureCollection\", \"features\": [{\"type\": \"Feature\", "
         "\"properties\": {" + props + "}, "
         "\"geometry\": {\"type\": \"MultiPolygon\", \"coordinates\": " + coords + "}}]}\n";
}

std::string to_csv(const Region& region, const ExportOptions& options) {
  // One row per exact boundary curve; cx, cy, r empty for segments; sweep_deg
  // signed (positive counter-clockwise), 0 for segments.
  std::string out = "component,loop,hole,kind,x0,y0,x1,y1,cx,cy,r,sweep_deg\n";
  const auto comps = components_of(region, options);
  const double snap = snap_length(region);
  for (std::size_t k = 0; k < comps.size(); ++k) {
    const auto loops = loops_of(comps[k]);
    for (std::size_t i = 0; i < loops.size(); ++i) {
      for (const Curve& c : loops[i]->curves) {
        if (degenerate(c, snap)) continue;  // shorter than the rounding of its ends
        const bool arc = c.kind == Curve::Kind::arc;
        out += std::to_string(k) + "," + std::to_string(i) + "," + (loops[i]->hole ? "1" : "0") +
               "," + (arc ? "arc" : "segment") + "," + num(c.source.x) + "," + num(c.source.y) +
               "," + num(c.target.x) + "," + num(c.target.y) + "," +
               (arc ? num(c.center.x) : "") + "," + (arc ? num(c.center.y) : "") + "," +
               (arc ? num(c.radius) : "") + "," + (arc ? num(c.sweep() * rad2deg) : "0") + "\n";
      }
    }
  }
  return out;
}

std::string to_format(const Region& region, ExportFormat format, const ExportOptions& options) {
  switch (format) {
    case ExportFormat::svg: return to_svg(region, options);
    case ExportFormat::dxf: return to_dxf(region, options);
    case ExportFormat::wkt: return to_wkt(region, options);
    case ExportFormat::geojson: return to_geojson(region, options);
    case ExportFormat::csv: return to_csv(region, options);
  }
  throw std::invalid_argument("to_format: unknown format");
}

std::string xml_escape(std::string_view text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

void write_file_atomic(const std::filesystem::path& path, std::string_view content) {
  // The temporary file lives in the target's directory so that rename(2) is
  // atomic; any failure removes it. Missing directories are not created.
  namespace fs = std::filesystem;
  auto fail = [&path](const std::string& reason) {
    throw InputError(path.string() + ": cannot write: " + reason);
  };
  if (path.empty() || !path.has_filename()) fail("not a file name");
  const fs::path dir = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) fail("directory " + dir.string() + " does not exist");
  if (fs::is_directory(path, ec)) fail("is a directory");

  const fs::path tmp = path.string() + ".tmp-" + std::to_string(::getpid());
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) fail(std::strerror(errno));
  auto abandon = [&](const std::string& reason) {
    std::error_code ignore;
    fs::remove(tmp, ignore);
    fail(reason);
  };
  const char* data = content.data();
  std::size_t left = content.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, data, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      const std::string reason = std::strerror(errno);
      ::close(fd);
      abandon(reason);
    }
    data += n;
    left -= static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0 && errno != EINVAL && errno != EROFS) {
    const std::string reason = std::strerror(errno);
    ::close(fd);
    abandon(reason);
  }
  if (::close(fd) != 0) abandon(std::strerror(errno));
  fs::rename(tmp, path, ec);
  if (ec) abandon(ec.message());
}

}  // namespace pkmws::io
