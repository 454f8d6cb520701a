// The polygons of WKT / GeoJSON on regions built to be hard for them: two
// disks tangent externally (a pinch), a crank-limited five-bar whose loop
// pinches, slivers thinner than the tolerance, a hole tangent internally.
// Each result is checked by an independent brute-force validity test (the
// OGC rules GEOS applies) and against the exact area; and the tolerance
// refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <numbers>
#include <string>
#include <vector>

#include <unistd.h>

#include "pkmws/geometry/inscribed.hpp"
#include "pkmws/geometry/polyline.hpp"
#include "pkmws/geometry/primitives.hpp"
#include "pkmws/io/export.hpp"
#include "pkmws/io/mechanism_file.hpp"

namespace {

namespace fs = std::filesystem;
namespace geo = pkmws::geometry;
namespace io = pkmws::io;
using geo::Point;
using geo::Region;
using Ring = std::vector<Point>;

constexpr double pi = std::numbers::pi;

long double orient(Point a, Point b, Point c) {
  return (static_cast<long double>(b.x) - a.x) * (static_cast<long double>(c.y) - a.y) -
         (static_cast<long double>(b.y) - a.y) * (static_cast<long double>(c.x) - a.x);
}

bool on_segment(Point p, Point a, Point b) {
  return orient(a, b, p) == 0 && p.x >= std::min(a.x, b.x) && p.x <= std::max(a.x, b.x) &&
         p.y >= std::min(a.y, b.y) && p.y <= std::max(a.y, b.y);
}

// Segments ab and cd share a point other than a common endpoint (or overlap).
bool touch_elsewhere(Point a, Point b, Point c, Point d) {
  const bool shared = a == c || a == d || b == c || b == d;
  if (shared) {
    // Only the shared point: the other ends must not lie on the other segment.
    const Point x = (a == c || a == d) ? a : b;
    const Point p = x == a ? b : a, q = x == c ? d : c;
    return (p != q && on_segment(q, x, p)) || (p != q && on_segment(p, x, q)) || p == q;
  }
  const long double o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
  if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0))) return true;
  return on_segment(c, a, b) || on_segment(d, a, b) || on_segment(a, c, d) || on_segment(b, c, d);
}

double shoelace(const Ring& r) {
  double twice = 0.0;
  for (std::size_t i = 0; i + 1 < r.size(); ++i) twice += (r[i].x - r[0].x) * (r[i + 1].y - r[0].y) -
                                                          (r[i].y - r[0].y) * (r[i + 1].x - r[0].x);
  return 0.5 * twice;
}

bool inside(const Ring& ring, Point p) {
  bool in = false;
  for (std::size_t i = 0, j = ring.size() - 2; i + 1 < ring.size(); j = i++) {
    const Point a = ring[i], b = ring[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) in = !in;
  }
  return in;
}

// OGC validity, brute force: closed rings of >= 4 points without zero-length
// edges; no ring touches itself; rings of one polygon and different polygons
// meet at most at shared vertices; shells counter-clockwise, holes clockwise
// and inside their shell. Returns the polygons' total area.
double expect_valid(const std::vector<io::ExportPolygon>& polys) {
  std::vector<const Ring*> rings;
  double area = 0.0;
  for (const auto& p : polys) {
    rings.push_back(&p.shell);
    EXPECT_GT(shoelace(p.shell), 0.0) << "shell not counter-clockwise";
    area += shoelace(p.shell);
    for (const Ring& h : p.holes) {
      rings.push_back(&h);
      EXPECT_LT(shoelace(h), 0.0) << "hole not clockwise";
      area += shoelace(h);
      std::size_t in = 0, out = 0;
      for (const Point& q : h) {
        if (std::find(p.shell.begin(), p.shell.end(), q) != p.shell.end()) continue;
        (inside(p.shell, q) ? in : out) += 1;
      }
      EXPECT_EQ(out, 0u) << "hole outside its shell";
    }
  }
  for (const Ring* r : rings) {
    EXPECT_GE(r->size(), 4u);
    if (r->size() < 4) continue;
    EXPECT_EQ(r->front(), r->back()) << "ring not closed";
    std::map<std::pair<double, double>, int> seen;
    for (std::size_t i = 0; i + 1 < r->size(); ++i) {
      EXPECT_NE((*r)[i], (*r)[i + 1]) << "zero-length edge";
      const int visits = ++seen[std::make_pair((*r)[i].x, (*r)[i].y)];
      EXPECT_EQ(visits, 1) << "ring touches itself at (" << (*r)[i].x << ", " << (*r)[i].y << ")";
    }
  }
  std::size_t bad = 0;
  for (std::size_t ra = 0; ra < rings.size(); ++ra) {
    const Ring& A = *rings[ra];
    if (A.size() < 4) continue;
    const std::size_t na = A.size() - 1;
    for (std::size_t rb = ra; rb < rings.size(); ++rb) {
      const Ring& B = *rings[rb];
      if (B.size() < 4) continue;
      const std::size_t nb = B.size() - 1;
      for (std::size_t i = 0; i < na; ++i) {
        for (std::size_t j = ra == rb ? i + 1 : 0; j < nb; ++j) {
          const bool adjacent = ra == rb && (j == i + 1 || (i == 0 && j == na - 1));
          const Point a = A[i], b = A[i + 1], c = B[j], d = B[j + 1];
          if (adjacent) {
            const Point x = (b == c) ? b : a;
            const Point p = x == a ? b : a, q = x == c ? d : c;
            if (on_segment(q, x, p) || on_segment(p, x, q)) ++bad;  // overlap
            continue;
          }
          if (ra == rb && (a == c || a == d || b == c || b == d)) { ++bad; continue; }  // self-touch
          if (touch_elsewhere(a, b, c, d)) ++bad;
        }
      }
    }
  }
  EXPECT_EQ(bad, 0u) << "edges crossing or touching";
  return area;
}

std::size_t vertex_count(const std::vector<io::ExportPolygon>& polys) {
  std::size_t n = 0;
  for (const auto& p : polys) {
    n += p.shell.size();
    for (const Ring& h : p.holes) n += h.size();
  }
  return n;
}

// Checks the polygons for every bound; returns the chord polygons.
std::vector<io::ExportPolygon> check_all_bounds(const Region& r, double tolerance, bool one_sided = true) {
  std::vector<io::ExportPolygon> chords;
  for (const io::Bound bound : {io::Bound::exact, io::Bound::inner, io::Bound::outer}) {
    if (!one_sided && bound != io::Bound::exact) continue;
    SCOPED_TRACE(std::string(io::bound_name(bound)));
    io::ExportOptions o;
    o.tolerance = tolerance;
    o.bound = bound;
    std::vector<io::ExportPolygon> polys;
    try {
      polys = io::export_polygons(r, o);
    } catch (const io::InputError& e) {
      ADD_FAILURE() << io::bound_name(bound) << ": " << e.what();
      continue;
    }
    const double area = expect_valid(polys);
    const double exact = r.area();
    const double err = io::polyline_area_error_bound(r, o);
    EXPECT_LE(std::abs(area - exact), err);
    if (bound == io::Bound::inner) {
      EXPECT_LE(area, exact * (1 + 1e-14));
      // Every vertex in the region (boundary points count as inside).
      for (const auto& p : polys) {
        for (const Point& q : p.shell) {
          // Inside, or on the boundary up to the rounding of cos / sin.
          double d = std::numeric_limits<double>::infinity();
          for (const auto& c : r.components()) d = std::min(d, geo::distance_to_boundary(c, q));
          EXPECT_TRUE(r.contains(q) || d <= 1e-14 * std::max(1.0, geo::norm(q))) << q.x << ", " << q.y << " " << d;
        }
      }
    }
    if (bound == io::Bound::outer) {
      EXPECT_GE(area, exact * (1 - 1e-14));
    }
    if (bound == io::Bound::exact) chords = polys;
  }
  return chords;
}

TEST(ExportPolygons, TwoDisksTangentExternally) {
  // One component in CGAL's model whose loop passes (1, 0) twice.
  const Region r = geo::disk({0.0, 0.0}, 1.0) | geo::disk({2.0, 0.0}, 1.0);
  const auto chords = check_all_bounds(r, 1e-3);
  // Chords and inner polygons: two polygons meeting at the tangency point.
  ASSERT_EQ(chords.size(), 2u);
  const auto& a = chords[0].shell;
  const auto& b = chords[1].shell;
  std::size_t common = 0;
  for (std::size_t i = 0; i + 1 < a.size(); ++i) common += std::count(b.begin(), b.end() - 1, a[i]);
  EXPECT_EQ(common, 1u);
  // Outer polygons contain a neighbourhood of the tangency point: one polygon.
  io::ExportOptions o;
  o.tolerance = 1e-3;
  o.bound = io::Bound::outer;
  EXPECT_EQ(io::export_polygons(r, o).size(), 1u);
}

TEST(ExportPolygons, HoleTangentInternallyAndDisksTouchingAHole) {
  // A hole touching the outer circle at (2, 0), and two holes touching each other.
  const Region r = geo::disk({0.0, 0.0}, 2.0) - geo::disk({1.0, 0.0}, 1.0);
  // Chords only: inner polygons of a cusp between two loops are refused
  // (no one-sided polyline reaches the tip; the CLI exports exact regions
  // with chords and only certified enclosures one-sided).
  check_all_bounds(r, 1e-3, false);
  const Region s = geo::disk({0.0, 0.0}, 5.0) - geo::disk({-1.0, 0.0}, 1.0) - geo::disk({1.0, 0.0}, 1.0);
  check_all_bounds(s, 1e-3);
}

TEST(ExportPolygons, SliverThinnerThanTheTolerance) {
  // A crescent 1e-7 thick between two unit circles: the chords at the
  // requested 1e-4 would cross, so the arcs are refined where they do.
  const Region crescent = geo::disk({0.0, 0.0}, 1.0) - geo::disk({1e-7, 0.0}, 1.0);
  ASSERT_EQ(crescent.components().size(), 1u);
  const auto polys = check_all_bounds(crescent, 1e-4);
  EXPECT_EQ(polys.size(), 1u);
  // A thin lens (two circles crossing at a small angle) and a thin strip
  // along an arc.
  const Region lens = geo::disk({0.0, 0.0}, 1.0) & geo::disk({1.9999999, 0.0}, 1.0);
  check_all_bounds(lens, 1e-6);
  const Region band = geo::annulus({0.0, 0.0}, 1.0, 1.0 + 1e-6) & geo::rectangle({{-2.0, 0.0}, {2.0, 2.0}});
  check_all_bounds(band, 1e-3);
}

fs::path write_temp(const std::string& name, const std::string& text) {
  const fs::path p = fs::temp_directory_path() / ("pkmws_export_polygons_" + std::to_string(::getpid()) + name);
  std::ofstream(p) << text;
  return p;
}

TEST(ExportPolygons, PinchOfACrankLimitedFiveBar) {
  // Unequal links and crank limits: GEOS found the old polygons
  // self-intersecting at (149.282, -40.000), and the DXF had LINEs 1e-14 long.
  const fs::path f = write_temp("five_bar.json", R"({"name": "pinch", "mechanism": "five_bar", "units": "mm",
    "base": [[-80, 0], [80, 0]], "proximal": [200, 180], "distal": [250, 260],
    "working_mode": [1, -1], "actuator_limits_deg": [[30, 170], [10, 150]]})");
  const Region r = io::load_mechanism(f).model->workspace();
  fs::remove(f);
  // The region's own loops pinch (a vertex visited twice) or carry pieces
  // shorter than the rounding of their ends: what the export must clean.
  bool pinch = false, tiny = false;
  for (const auto& loop : r.loops()) {
    std::map<std::pair<double, double>, int> seen;
    for (const auto& c : loop.curves) {
      pinch |= ++seen[std::make_pair(c.source.x, c.source.y)] > 1;
      tiny |= c.length() < 1e-9;
    }
  }
  EXPECT_TRUE(pinch || tiny);
  for (const double tol : {1.0, 1e-2}) {  // the brute-force check is quadratic
    SCOPED_TRACE(tol);
    check_all_bounds(r, tol);
  }
  // DXF and CSV: no entity shorter than 1e-12 of the size.
  io::ExportOptions o;
  o.units = "mm";
  const std::string dxf = io::to_dxf(r, o);
  EXPECT_NE(dxf.find("$INSUNITS\n70\n4\n"), std::string::npos);
  std::istringstream in(io::to_csv(r, o));
  std::string line;
  std::getline(in, line);
  std::size_t rows = 0;
  while (std::getline(in, line)) {
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    char kind[16] = {};
    ASSERT_EQ(std::sscanf(line.c_str(), "%*d,%*d,%*d,%15[a-z],%lf,%lf,%lf,%lf", kind, &x0, &y0, &x1, &y1), 5) << line;
    if (std::string(kind) == "segment") {
      EXPECT_GT(std::hypot(x1 - x0, y1 - y0), 1e-12 * 500) << line;
    }
    ++rows;
  }
  EXPECT_GT(rows, 3u);
}

TEST(ExportPolygons, PolylinePiecesStayBoundedBelowTinyTolerances) {
  // The old step 2 acos(1 - tol/r) rounded to 0 below tol/r ~ 1e-16 and the
  // piece count overflowed to one chord (a 4-vertex MOMA polygon at 1e-15).
  geo::Curve arc;
  arc.kind = geo::Curve::Kind::arc;
  arc.center = {0.0, 0.0};
  arc.radius = 250.0;
  arc.source = arc.target = {250.0, 0.0};
  arc.swept = 2 * pi;
  const double n = geo::polyline_pieces(arc, 1e-15, geo::Approximation::chords);
  // Chord angle h with 250 (1 - cos(h/2)) = 1e-15: n = 2 pi / h ~ 1.1e9.
  EXPECT_NEAR(n, std::ceil(2 * pi / (4 * std::asin(std::sqrt(0.5 * 1e-15 / 250.0)))), 1.0);
  EXPECT_GT(geo::polyline_pieces(arc, 1e-300, geo::Approximation::chords), 1e15);
  // Tangent pieces: deviation r (sec(h/2) - 1) <= tolerance, at most pi/2 each.
  EXPECT_EQ(geo::polyline_pieces(arc, 1e6, geo::Approximation::outside), 4.0);
  std::vector<Point> pts;
  geo::append_polyline(arc, 1.0, geo::Approximation::outside, pts);
  for (std::size_t i = 1; i < pts.size(); ++i) {
    EXPECT_GE(geo::norm(pts[i]), 250.0);
    EXPECT_LE(geo::norm(pts[i]), 251.0 + 1e-12);
  }
}

TEST(ExportPolygons, ToleranceOutOfRangeIsRefused) {
  const Region r = geo::disk({0.0, 0.0}, 1.0) | geo::disk({3.0, 0.0}, 1.0) | geo::disk({6.0, 0.0}, 1.0) |
                   geo::disk({9.0, 0.0}, 1.0);
  auto refused = [&r](double tol, const std::string& what) {
    io::ExportOptions o;
    o.tolerance = tol;
    try {
      (void)io::to_wkt(r, o);
      ADD_FAILURE() << "tolerance " << tol << " accepted";
    } catch (const io::InputError& e) {
      const std::string m = e.what();
      EXPECT_EQ(m.rfind("--tolerance: ", 0), 0u) << m;
      EXPECT_NE(m.find(what), std::string::npos) << m;
      EXPECT_EQ(m.find('\n'), std::string::npos);
    }
  };
  refused(1e-300, "below the attainable");
  refused(0.5 * io::min_tolerance(r), "below the attainable");
  refused(1e308, "above");
  refused(2.0 * io::max_tolerance(r), "above");
  refused(std::nan(""), "positive finite");
  refused(std::numeric_limits<double>::infinity(), "positive finite");
  refused(-1.0, "positive finite");
  // Just above the attainable tolerance, four unit circles need ~2.7e6 vertices.
  refused(1.01 * io::min_tolerance(r), "polygon vertices");
  // In range: accepted, and the polygons keep their bound.
  io::ExportOptions o;
  o.tolerance = io::max_tolerance(r);
  EXPECT_LE(std::abs(expect_valid(io::export_polygons(r, o)) - r.area()), io::polyline_area_error_bound(r, o));
  o.tolerance = 1e-6;
  const auto fine = io::export_polygons(r, o);
  EXPECT_LE(std::abs(expect_valid(fine) - r.area()), io::polyline_area_error_bound(r, o));
  EXPECT_GT(vertex_count(fine), 4u * 1000u);
}

TEST(ExportPolygons, NonFiniteValuesAreRefused) {
  // A region whose size overflows: the SVG's width / margins are not finite.
  const Region r = geo::rectangle({{-1.7e308, -1.0}, {1.7e308, 1.0}});
  io::ExportOptions o;
  o.units = "mm";
  EXPECT_THROW((void)io::to_svg(r, o), io::InputError);
  EXPECT_THROW((void)io::to_geojson(r, o), io::InputError);
}

}  // namespace
