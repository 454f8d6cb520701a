// WKT, GeoJSON and CSV export: rings inscribed within the stated bound, oriented
// rings, the error against the tolerance, one CSV row per curve.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <unistd.h>

#include "pkmws/geometry/primitives.hpp"
#include "pkmws/io/export.hpp"
#include "pkmws/io/mechanism_file.hpp"
#include "support/export_cases.hpp"
#include "support/fixtures.hpp"

namespace {

using pkmws::geometry::Point;
using pkmws::geometry::Region;
namespace geo = pkmws::geometry;
namespace io = pkmws::io;
using pkmws::test::cases;
using pkmws::test::cross2;
using pkmws::test::curve_total;
using pkmws::test::rel;

constexpr double pi = std::numbers::pi;

using Ring = std::vector<Point>;
using Polygon = std::vector<Ring>;

std::vector<Polygon> parse_wkt(const std::string& text) {
  std::istringstream in(text);
  std::string word;
  in >> word;
  EXPECT_EQ(word, "MULTIPOLYGON");
  std::vector<Polygon> out;
  auto expect = [&in](char c) {
    char got = 0;
    in >> got;
    EXPECT_EQ(got, c);
  };
  auto peek = [&in] { in >> std::ws; return static_cast<char>(in.peek()); };
  if (peek() == 'E') return out;  // EMPTY
  expect('(');
  do {
    Polygon poly;
    expect('(');
    do {
      Ring ring;
      expect('(');
      do {
        Point p;
        in >> p.x >> p.y;
        EXPECT_TRUE(in) << "bad WKT number";
        ring.push_back(p);
      } while (peek() == ',' && in.get());
      expect(')');
      poly.push_back(ring);
    } while (peek() == ',' && in.get());
    expect(')');
    out.push_back(poly);
  } while (peek() == ',' && in.get());
  expect(')');
  return out;
}

double shoelace(const Ring& ring) {
  double twice = 0.0;
  const Point o = ring.front();
  for (std::size_t i = 0; i + 1 < ring.size(); ++i) twice += cross2(ring[i] - o, ring[i + 1] - o);
  return 0.5 * twice;
}

// Signed area of every ring, checking closure and orientation (outer ccw, holes cw).
double rings_area(const std::vector<Polygon>& polys) {
  double a = 0.0;
  for (const auto& poly : polys) {
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const Ring& ring = poly[i];
      EXPECT_GE(ring.size(), 4u);
      EXPECT_EQ(ring.front(), ring.back()) << "ring not closed";
      const double s = shoelace(ring);
      if (i == 0) {
        EXPECT_GT(s, 0.0) << "exterior ring must be counter-clockwise";
      } else {
        EXPECT_LT(s, 0.0) << "hole ring must be clockwise";
      }
      a += s;
    }
  }
  return a;
}

std::vector<Polygon> geojson_polygons(const nlohmann::json& geometry) {
  std::vector<Polygon> out;
  for (const auto& poly : geometry.at("coordinates")) {
    Polygon p;
    for (const auto& ring : poly) {
      Ring r;
      for (const auto& pt : ring) r.push_back({pt.at(0).get<double>(), pt.at(1).get<double>()});
      p.push_back(r);
    }
    out.push_back(p);
  }
  return out;
}

std::vector<std::string> split(const std::string& line, char sep) {
  std::vector<std::string> out;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, sep)) out.push_back(field);
  if (!line.empty() && line.back() == sep) out.emplace_back();
  return out;
}

TEST(ExportWkt, RingsAreInscribedWithinTheStatedBound) {
  for (const auto& c : cases()) {
    SCOPED_TRACE(c.name);
    const double exact = c.region.area();
    double previous_error = -1.0;
    for (const double tol : {1e-2, 1e-4, 1e-6}) {
      io::ExportOptions o;
      o.tolerance = tol;
      const auto polys = parse_wkt(io::to_wkt(c.region, o));
      EXPECT_EQ(polys.size(), c.region.components().size());
      const double err = std::abs(rings_area(polys) - exact);
      const double bound = io::polyline_area_error_bound(c.region, o);
      EXPECT_LE(err, bound) << "tolerance " << tol;
      if (previous_error > 1e-12 * exact) {
      EXPECT_LT(err, 0.05 * previous_error);
    }
      previous_error = err;
    }
  }
}

TEST(ExportWkt, DiskPolygonLiesOnTheCircleWithinTheTolerance) {
  const Point c{1.5, -2.0};
  const double r = 3.0, tol = 1e-3;
  io::ExportOptions o;
  o.tolerance = tol;
  const auto polys = parse_wkt(io::to_wkt(geo::disk(c, r), o));
  ASSERT_EQ(polys.size(), 1u);
  const Ring& ring = polys[0][0];
  double max_dev = 0.0;
  for (std::size_t i = 0; i + 1 < ring.size(); ++i) {
    EXPECT_NEAR(geo::norm(ring[i] - c), r, 1e-14 * r);
    const Point mid = 0.5 * (ring[i] + ring[i + 1]);
    max_dev = std::max(max_dev, r - geo::norm(mid - c));
  }
  EXPECT_LE(max_dev, tol);
  EXPECT_GT(max_dev, 0.25 * tol);  // not needlessly dense
  // Inscribed regular polygon: area (n/2) r^2 sin(2pi/n), below pi r^2.
  const double n = static_cast<double>(ring.size() - 1);
  EXPECT_NEAR(shoelace(ring), 0.5 * n * r * r * std::sin(2 * pi / n), 1e-12 * r * r);
  const double err = pi * r * r - shoelace(ring);
  std::printf("  WKT disk r=3 tol=1e-3: %g vertices, area error %.3g, bound %.3g\n", n, err,
              io::polyline_area_error_bound(geo::disk(c, r), o));
}

TEST(ExportGeoJson, FeatureCollectionWithOrientedRings) {
  for (const auto& c : cases()) {
    SCOPED_TRACE(c.name);
    io::ExportOptions o;
    o.tolerance = 1e-5;
    o.units = "mm";
    const auto doc = nlohmann::json::parse(io::to_geojson(c.region, o));
    EXPECT_EQ(doc.at("type"), "FeatureCollection");
    ASSERT_EQ(doc.at("features").size(), 1u);
    const auto& f = doc.at("features")[0];
    EXPECT_EQ(f.at("type"), "Feature");
    EXPECT_EQ(f.at("geometry").at("type"), "MultiPolygon");
    const auto& props = f.at("properties");
    EXPECT_EQ(props.at("area").get<double>(), c.region.area());  // exact digits
    EXPECT_EQ(props.at("tolerance").get<double>(), 1e-5);
    EXPECT_EQ(props.at("units"), "mm");
    const double bound = props.at("area_error_bound").get<double>();
    EXPECT_EQ(bound, io::polyline_area_error_bound(c.region, o));
    const double err = std::abs(rings_area(geojson_polygons(f.at("geometry"))) - c.region.area());
    EXPECT_LE(err, bound);
  }
}

TEST(ExportGeoJson, ErrorShrinksWithTheTolerance) {
  const Region r = geo::annulus({0.0, 0.0}, 50.0, 250.0) - geo::stadium({-100, 0}, {100, 0}, 20);
  double last = 0.0;
  for (const double tol : {1.0, 1e-1, 1e-2, 1e-3}) {
    io::ExportOptions o;
    o.tolerance = tol;
    const auto doc = nlohmann::json::parse(io::to_geojson(r, o));
    const double err =
        std::abs(rings_area(geojson_polygons(doc["features"][0]["geometry"])) - r.area());
    const double bound = io::polyline_area_error_bound(r, o);
    EXPECT_LE(err, bound);
    EXPECT_GT(err, 0.1 * bound);  // the bound is not loose by orders of magnitude
    if (last > 0.0) {
      EXPECT_LT(err, 0.2 * last);
    }
    last = err;
    std::printf("  GeoJSON annulus-stadium tol=%g: area error %.4g (bound %.4g)\n", tol, err, bound);
  }
}

TEST(ExportCsv, OneRowPerCurveAndTheExactArea) {
  double worst = 0.0;
  for (const auto& c : cases()) {
    SCOPED_TRACE(c.name);
    std::istringstream in(io::to_csv(c.region));
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "component,loop,hole,kind,x0,y0,x1,y1,cx,cy,r,sweep_deg");
    std::size_t rows = 0;
    std::map<std::pair<int, int>, std::pair<Point, double>> loops;  // origin, twice area
    while (std::getline(in, line)) {
      const auto f = split(line, ',');
      ASSERT_EQ(f.size(), 12u) << line;
      ++rows;
      auto d = [&f](int i) { return std::strtod(f[i].c_str(), nullptr); };
      const Point p{d(4), d(5)}, q{d(6), d(7)};
      auto& [o, twice] = loops.try_emplace({std::stoi(f[0]), std::stoi(f[1])}, p, 0.0).first->second;
      EXPECT_EQ(f[2] == "1", std::stoi(f[1]) > 0);  // loop 0 is the outer one
      if (f[3] == "segment") {
        EXPECT_TRUE(f[8].empty() && f[9].empty() && f[10].empty());
        twice += cross2(p - o, q - o);
      } else {
        ASSERT_EQ(f[3], "arc");
        const Point ctr{d(8), d(9)};
        const double r = d(10);
        EXPECT_NEAR(geo::norm(p - ctr), r, 1e-12 * r);
        twice += cross2(ctr - o, q - p) + r * r * d(11) * pi / 180.0;
      }
    }
    EXPECT_EQ(rows, curve_total(c.region));
    double area = 0.0;
    for (const auto& [key, v] : loops) area += 0.5 * v.second;
    EXPECT_LT(rel(area, c.region.area()), 1e-12);
    worst = std::max(worst, rel(area, c.region.area()));
  }
  std::printf("  CSV round trip: worst relative area error %.3g\n", worst);
}

// --------------------------------------------------------- atomic writes

}  // namespace
