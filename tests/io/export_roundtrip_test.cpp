// Exports re-read: the SVG path's arcs and DXF entities give back the exact
// area; WKT/GeoJSON polylines are within their stated tolerance; failures of
// write_file_atomic leave nothing behind.
#include <gtest/gtest.h>
#include <unistd.h>

#include <map>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <regex>
#include <sstream>

#include <nlohmann/json.hpp>

#include "pkmws/geometry/primitives.hpp"
#include "pkmws/io/export.hpp"

using namespace pkmws;
using geometry::Point;

namespace {

std::vector<geometry::Region> samples() {
  return {geometry::band({-100, 0}, 1.5 * std::numbers::pi, 200, 250, 1)
              .intersect(geometry::band({100, 0}, 1.5 * std::numbers::pi - 0.0873, 200, 250, 1)),
          geometry::annulus({1, 2}, 1.0, 3.0),
          geometry::disk({0, 0}, 2).unite(geometry::disk({10, 0}, 1)),
          geometry::stadium({0, 0}, {5, 3}, 1).subtract(geometry::rectangle({{1, -5}, {2, 5}}))};
}

// Green's-theorem contribution of a circular arc of radius r from p to q,
// at most a half turn, counter-clockwise when ccw.
double arc_term(Point p, Point q, double r, bool ccw) {
  const Point m{(p.x + q.x) / 2, (p.y + q.y) / 2};
  const double dx = q.x - p.x, dy = q.y - p.y, len = std::hypot(dx, dy);
  const double half = std::min(1.0, len / (2 * r));
  const double h = std::sqrt(std::max(0.0, r * r - len * len / 4));
  const Point left{-dy / len, dx / len};  // a ccw minor arc has its centre on the left
  const double side = ccw ? 1.0 : -1.0;
  const Point c{m.x + side * h * left.x, m.y + side * h * left.y};
  const double sweep = side * 2 * std::asin(half);
  return 0.5 * (c.x * (q.y - p.y) - c.y * (q.x - p.x) + r * r * sweep);
}

double svg_area(const std::string& d) {
  std::istringstream in(d);
  std::string tok;
  double area = 0;
  Point cur{}, start{};
  while (in >> tok) {
    if (tok[0] == 'M') {
      cur.x = std::stod(tok.substr(1));
      in >> cur.y;
      start = cur;
    } else if (tok[0] == 'L') {
      Point q;
      q.x = std::stod(tok.substr(1));
      in >> q.y;
      area += 0.5 * (cur.x * q.y - q.x * cur.y);
      cur = q;
    } else if (tok[0] == 'A') {
      double r = std::stod(tok.substr(1)), ry, rot, large, sweep;
      Point q;
      in >> ry >> rot >> large >> sweep >> q.x >> q.y;
      EXPECT_EQ(large, 0.0);
      area += arc_term(cur, q, r, sweep == 1.0);
      cur = q;
    } else if (tok == "Z") {
      EXPECT_NEAR(cur.x, start.x, 1e-9);
      EXPECT_NEAR(cur.y, start.y, 1e-9);
    }
  }
  return area;
}

double shoelace_rings(const std::vector<std::vector<Point>>& rings) {
  double a = 0;
  for (const auto& ring : rings) {
    for (std::size_t i = 0; i + 1 < ring.size(); ++i) a += 0.5 * (ring[i].x * ring[i + 1].y - ring[i + 1].x * ring[i].y);
  }
  return a;
}

double perimeter(const geometry::Region& r) {
  double p = 0;
  for (const auto& l : r.loops()) p += l.perimeter();
  return p;
}

}  // namespace

TEST(ExportRoundTrip, SvgArcsGiveBackTheExactArea) {
  for (const auto& r : samples()) {
    const std::string svg = io::to_svg(r);
    std::smatch m;
    ASSERT_TRUE(std::regex_search(svg, m, std::regex(" d=\"([^\"]*)\"")));
    EXPECT_NEAR(svg_area(m[1]), r.area(), 1e-12 * r.area());
  }
}

TEST(ExportRoundTrip, DxfEntitiesMatchTheCurves) {
  for (const auto& r : samples()) {
    std::istringstream in(io::to_dxf(r));
    std::string code, value;
    std::vector<std::pair<std::string, std::map<int, double>>> entities;
    while (std::getline(in, code) && std::getline(in, value)) {
      const int c = std::stoi(code);
      if (c == 0) {
        if (value == "LINE" || value == "ARC" || value == "CIRCLE") entities.push_back({value, {}});
      } else if (!entities.empty() && c >= 10 && c <= 51 && c != 999) {
        entities.back().second[c] = std::stod(value);
      }
    }
    std::size_t curves = 0;
    for (const auto& l : r.loops()) curves += l.curves.size();
    EXPECT_EQ(entities.size(), curves);
    for (const auto& [kind, g] : entities) {
      if (kind == "LINE") continue;
      EXPECT_GT(g.at(40), 0.0);  // radius
      if (kind == "ARC") {
        EXPECT_NE(g.at(50), g.at(51));
      }
    }
  }
  // A region without holes: chaining the entities end to end closes the loop
  // and Green's theorem over the chain gives the exact area.
  const auto r = samples()[0];
  std::istringstream in(io::to_dxf(r));
  std::string code, value;
  struct E { bool arc; Point a, b; Point c; double r; };
  std::vector<E> es;
  std::map<int, double> g;
  std::string kind;
  auto flush = [&] {
    if (kind == "LINE") es.push_back({false, {g[10], g[20]}, {g[11], g[21]}, {}, 0});
    if (kind == "ARC") {
      const double a0 = g[50] * std::numbers::pi / 180, a1 = g[51] * std::numbers::pi / 180;
      es.push_back({true, {g[10] + g[40] * std::cos(a0), g[20] + g[40] * std::sin(a0)},
                    {g[10] + g[40] * std::cos(a1), g[20] + g[40] * std::sin(a1)}, {g[10], g[20]}, g[40]});
    }
    g.clear();
  };
  while (std::getline(in, code) && std::getline(in, value)) {
    if (std::stoi(code) == 0) { flush(); kind = value; } else if (std::stoi(code) >= 10 && std::stoi(code) <= 51) g[std::stoi(code)] = std::stod(value);
  }
  ASSERT_FALSE(es.empty());
  double twice = 0;
  Point cur = es[0].a;
  std::vector<bool> used(es.size(), false);
  for (std::size_t step = 0; step < es.size(); ++step) {
    bool moved = false;
    for (std::size_t i = 0; i < es.size() && !moved; ++i) {
      if (used[i]) continue;
      for (int dir : {1, -1}) {
        const Point from = dir > 0 ? es[i].a : es[i].b, to = dir > 0 ? es[i].b : es[i].a;
        if (std::hypot(from.x - cur.x, from.y - cur.y) > 1e-9) continue;
        if (es[i].arc) {
          double s = std::atan2(es[i].b.y - es[i].c.y, es[i].b.x - es[i].c.x) - std::atan2(es[i].a.y - es[i].c.y, es[i].a.x - es[i].c.x);
          while (s <= 0) s += 2 * std::numbers::pi;
          s *= dir;
          twice += es[i].c.x * (to.y - from.y) - es[i].c.y * (to.x - from.x) + es[i].r * es[i].r * s;
        } else {
          twice += from.x * to.y - to.x * from.y;
        }
        cur = to;
        used[i] = moved = true;
        break;
      }
    }
    ASSERT_TRUE(moved) << "DXF entities do not chain";
  }
  EXPECT_NEAR(std::hypot(cur.x - es[0].a.x, cur.y - es[0].a.y), 0, 1e-9);
  EXPECT_NEAR(std::abs(twice / 2), r.area(), 1e-12 * r.area());
}

TEST(ExportRoundTrip, WktAndGeoJsonWithinTheirTolerance) {
  for (const auto& r : samples()) {
    double previous_error = 1e300;
    for (double rel : {1e-3, 1e-5, 1e-7}) {
      io::ExportOptions o;
      o.tolerance = rel * std::hypot(r.bbox().width(), r.bbox().height());
      // WKT: parse every ring.
      const std::string wkt = io::to_wkt(r, o);
      // Rings are the innermost parenthesised lists "x y, x y, ...".
      std::vector<std::vector<Point>> rings;
      for (std::size_t open = wkt.find('('); open != std::string::npos; open = wkt.find('(', open + 1)) {
        const std::size_t close = wkt.find(')', open);
        const std::string body = wkt.substr(open + 1, close - open - 1);
        if (body.find('(') != std::string::npos) continue;
        std::vector<Point> ring;
        std::istringstream pts(body);
        std::string pair;
        while (std::getline(pts, pair, ',')) {
          std::istringstream xy(pair);
          Point p;
          xy >> p.x >> p.y;
          ring.push_back(p);
        }
        EXPECT_EQ(ring.front(), ring.back());
        rings.push_back(ring);
      }
      const double wkt_area = shoelace_rings(rings);
      const double error = std::abs(wkt_area - r.area());
      EXPECT_LE(error, perimeter(r) * o.tolerance);
      EXPECT_LE(error, previous_error);
      previous_error = error;
      // GeoJSON: same rings, RFC 7946 orientation (exterior ccw, holes cw).
      const auto gj = nlohmann::json::parse(io::to_geojson(r, o));
      std::vector<std::vector<Point>> grings;
      for (const auto& poly : gj["features"][0]["geometry"]["coordinates"]) {
        for (std::size_t k = 0; k < poly.size(); ++k) {
          std::vector<Point> ring;
          for (const auto& p : poly[k]) ring.push_back({p[0].get<double>(), p[1].get<double>()});
          const double a = shoelace_rings({ring});
          EXPECT_EQ(a > 0, k == 0);
          grings.push_back(ring);
        }
      }
      EXPECT_DOUBLE_EQ(shoelace_rings(grings), wkt_area);
      EXPECT_DOUBLE_EQ(gj["features"][0]["properties"]["area"].get<double>(), r.area());
    }
  }
}

TEST(ExportRoundTrip, CsvHasOneRowPerCurve) {
  for (const auto& r : samples()) {
    std::istringstream in(io::to_csv(r));
    std::string line;
    std::size_t rows = 0;
    std::getline(in, line);
    EXPECT_EQ(line, "component,loop,hole,kind,x0,y0,x1,y1,cx,cy,r,sweep_deg");
    while (std::getline(in, line)) ++rows;
    std::size_t curves = 0;
    for (const auto& l : r.loops()) curves += l.curves.size();
    EXPECT_EQ(rows, curves);
  }
}

TEST(ExportRoundTrip, AtomicWriteLeavesNothingOnFailure) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("pkmws-atomic-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path good = dir / "a.txt";
  io::write_file_atomic(good, "one");
  io::write_file_atomic(good, "two");
  std::ifstream in(good);
  std::string text;
  in >> text;
  EXPECT_EQ(text, "two");
  EXPECT_THROW(io::write_file_atomic(dir / "missing" / "b.txt", "x"), io::InputError);
  std::size_t files = 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    (void)e;
    ++files;
  }
  EXPECT_EQ(files, 1u);
  EXPECT_THROW(io::parse_export_format("png"), io::InputError);
  fs::remove_all(dir);
}
