// Boundary exports re-read by small independent parsers: the area recomputed
// from each file (Green's theorem on the SVG/DXF/CSV curves, shoelace on the
// WKT/GeoJSON rings) is compared with the exact Region::area().
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

namespace {

namespace fs = std::filesystem;
using pkmws::geometry::Box;
using pkmws::geometry::Point;
using pkmws::geometry::Region;
namespace geo = pkmws::geometry;
namespace io = pkmws::io;

constexpr double pi = std::numbers::pi;

double cross2(Point a, Point b) { return a.x * b.y - a.y * b.x; }

// ---------------------------------------------------------------- regions

struct Case {
  std::string name;
  Region region;
  double closed_form;  // exact area, or NaN if none
};

std::vector<Case> cases() {
  const double nan = std::nan("");
  std::vector<Case> out;
  out.push_back({"disk", geo::disk({1.5, -2.0}, 3.0), pi * 9.0});
  out.push_back({"annulus", geo::annulus({0.25, 0.5}, 1.0, 2.5), pi * (2.5 * 2.5 - 1.0)});
  out.push_back({"rectangle", geo::rectangle(Box{{-1.0, -2.0}, {3.0, 1.0}}), 12.0});
  // Half circles: arcs of exactly pi (the worst case for SVG's endpoint form).
  out.push_back({"stadium", geo::stadium({0.0, 0.0}, {4.0, 0.0}, 0.7), pi * 0.49 + 2 * 0.7 * 4.0});
  out.push_back({"band", geo::band({10.0, 5.0}, 0.3, 2.0, 1.25, 1), 2.0 * 1.25 * 2.0});
  // Half circles at irrational directions: their endpoints are rounded, and a
  // single SVG arc of sweep pi would put the centre off by ~1e-8 r.
  std::vector<Region> tilted;
  for (int k = 0; k < 6; ++k) {
    const double a = 0.1 + 0.37 * k;
    const Point s{10.0 * k, 0.7};
    tilted.push_back(geo::stadium(s, {s.x + 3.0 * std::cos(a), s.y + 3.0 * std::sin(a)}, 0.9));
  }
  out.push_back({"tilted_stadiums", Region::unite_all(tilted), nan});
  // Three quarters of a disk: one arc of 3pi/2 (large-arc flag) and two segments.
  out.push_back({"three_quarter_disk",
                 geo::disk({0.0, 0.0}, 1.0) - geo::rectangle(Box{{0.0, 0.0}, {2.0, 2.0}}),
                 0.75 * pi});
  // Two components, one with two holes; arcs of many sweeps.
  out.push_back({"mixed",
                 ((geo::disk({0.0, 0.0}, 2.0) | geo::rectangle(Box{{-1.0, -3.0}, {4.0, 0.5}})) -
                  geo::disk({0.5, -0.4}, 0.4) - geo::stadium({2.0, -2.0}, {3.0, -1.5}, 0.3)) |
                     geo::annulus({9.0, 1.0}, 0.5, 1.5),
                 nan});
  // Far from the origin: the local origins must keep the relative accuracy.
  out.push_back({"far", geo::disk({1000.0, -2000.0}, 0.5) - geo::disk({1000.2, -2000.0}, 0.1),
                 pi * (0.25 - 0.01)});
  return out;
}

std::size_t curve_total(const Region& r, double min_area = 0.0) {
  std::size_t n = 0;
  for (const auto& c : r.components(min_area)) {
    n += c.outer.curves.size();
    for (const auto& h : c.holes) n += h.curves.size();
  }
  return n;
}

// ------------------------------------------------------------- SVG parser

std::string attribute(const std::string& text, const std::string& element, const std::string& name) {
  const auto e = text.find("<" + element);
  if (e == std::string::npos) return {};
  const auto a = text.find(" " + name + "=\"", e);
  if (a == std::string::npos) return {};
  const auto begin = a + name.size() + 3;
  return text.substr(begin, text.find('"', begin) - begin);
}

struct SvgStats {
  double area = 0.0;
  int subpaths = 0;
  int arcs = 0;
  int large_arcs = 0;
  int lines = 0;
};

// Area of path data made of M, L, A (rx == ry, no rotation) and Z, by Green's
// theorem per subpath relative to its first point. The arc's centre is
// recomputed from its endpoints as an SVG renderer does (SVG 1.1 F.6.5).
SvgStats svg_area(const std::string& d) {
  std::istringstream in(d);
  SvgStats st;
  Point o, cur;
  double twice = 0.0;
  char cmd = 0;
  auto flush = [&] { st.area += 0.5 * twice; twice = 0.0; };
  while (in >> std::ws && in.peek() != EOF) {
    if (std::isalpha(in.peek())) in >> cmd;
    if (cmd == 'M') {
      flush();
      in >> o.x >> o.y;
      cur = o;
      ++st.subpaths;
    } else if (cmd == 'L') {
      Point q;
      in >> q.x >> q.y;
      twice += cross2(cur - o, q - o);
      cur = q;
      ++st.lines;
    } else if (cmd == 'A') {
      double rx = 0, ry = 0, rot = 0;
      int large = 0, sweep = 0;
      Point q;
      in >> rx >> ry >> rot >> large >> sweep >> q.x >> q.y;
      EXPECT_EQ(rx, ry);
      EXPECT_EQ(rot, 0.0);
      const Point p = cur;
      const Point v = q - p;
      const double half = 0.5 * std::hypot(v.x, v.y);
      const double r = std::max(rx, half);
      const double dist = std::sqrt(std::max(0.0, r * r - half * half));
      const Point left{-v.y / (2 * half), v.x / (2 * half)};
      const double side = (sweep != large) ? 1.0 : -1.0;
      const Point c = 0.5 * (p + q) + (side * dist) * left;
      double t = std::atan2(cross2(p - c, q - c), geo::dot(p - c, q - c));
      if (sweep == 1 && t < 0) t += 2 * pi;
      if (sweep == 0 && t > 0) t -= 2 * pi;
      twice += cross2(c - o, q - p) + r * r * t;
      cur = q;
      ++st.arcs;
      st.large_arcs += large;
    } else if (cmd == 'Z') {
      twice += cross2(cur - o, o - o);
      cur = o;
      cmd = 0;
    } else {
      ADD_FAILURE() << "unexpected path command " << cmd;
      break;
    }
  }
  flush();
  return st;
}

// ------------------------------------------------------------- DXF parser

struct DxfEntity {
  std::string type;
  std::map<int, std::string> codes;
  double num(int code) const { return std::strtod(codes.at(code).c_str(), nullptr); }
};

struct Dxf {
  std::map<std::string, std::string> header;  // $VAR -> first value
  std::vector<std::string> layers;
  std::vector<DxfEntity> entities;
};

Dxf parse_dxf(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::pair<int, std::string>> pairs;
  std::string code, value;
  while (std::getline(in, code) && std::getline(in, value)) pairs.emplace_back(std::stoi(code), value);
  Dxf dxf;
  std::string section;
  std::string var;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const auto& [c, v] = pairs[i];
    if (c == 0 && v == "SECTION") { section = pairs.at(i + 1).second; ++i; continue; }
    if (c == 0 && v == "ENDSEC") { section.clear(); continue; }
    if (section == "HEADER") {
      if (c == 9) var = v;
      else if (!var.empty()) { dxf.header.emplace(var, v); var.clear(); }
    } else if (section == "TABLES") {
      if (c == 0 && v == "LAYER") dxf.layers.push_back(pairs.at(i + 1).second);
    } else if (section == "ENTITIES") {
      if (c == 0) dxf.entities.push_back({v, {}});
      else dxf.entities.back().codes[c] = v;
    }
  }
  EXPECT_EQ(pairs.back().second, "EOF");
  return dxf;
}

// Chains LINE and ARC entities into closed loops (fails if an end is left
// open) and returns the area: outer loops (layer BOUNDARY) minus holes.
double dxf_area(const Dxf& dxf, double scale, int* loops_out = nullptr) {
  struct Piece {
    Point a, b;          // ends, ARC: counter-clockwise from a to b
    Point c;             // ARC centre
    double r = 0, sweep = 0;
    bool arc = false;
    bool hole = false;
  };
  std::vector<Piece> pieces;
  double area = 0.0;
  int loops = 0;
  for (const auto& e : dxf.entities) {
    const bool hole = e.codes.at(8) == "HOLES";
    if (e.type == "CIRCLE") {
      const double r = e.num(40);
      area += (hole ? -1 : 1) * pi * r * r;
      ++loops;
    } else if (e.type == "LINE") {
      pieces.push_back({{e.num(10), e.num(20)}, {e.num(11), e.num(21)}, {}, 0, 0, false, hole});
    } else if (e.type == "ARC") {
      const Point c{e.num(10), e.num(20)};
      const double r = e.num(40), a0 = e.num(50) * pi / 180, a1 = e.num(51) * pi / 180;
      double s = a1 - a0;
      while (s <= 0) s += 2 * pi;
      while (s > 2 * pi) s -= 2 * pi;
      pieces.push_back({{c.x + r * std::cos(a0), c.y + r * std::sin(a0)},
                        {c.x + r * std::cos(a1), c.y + r * std::sin(a1)}, c, r, s, true, hole});
    } else {
      ADD_FAILURE() << "unexpected entity " << e.type;
    }
  }
  const double eps = 1e-9 * scale;
  auto near = [eps](Point p, Point q) { return std::hypot(p.x - q.x, p.y - q.y) <= eps; };
  std::vector<bool> used(pieces.size(), false);
  for (std::size_t s = 0; s < pieces.size(); ++s) {
    if (used[s]) continue;
    // Walk from piece s until back at its start.
    const Point o = pieces[s].a;
    double twice = 0.0;
    std::size_t i = s;
    bool forward = true;
    for (;;) {
      used[i] = true;
      const Piece& p = pieces[i];
      EXPECT_EQ(p.hole, pieces[s].hole) << "a loop mixes layers";
      const Point from = forward ? p.a : p.b, to = forward ? p.b : p.a;
      if (p.arc) {
        const double sign = forward ? 1.0 : -1.0;
        twice += cross2(p.c - o, to - from) + sign * p.r * p.r * p.sweep;
      } else {
        twice += cross2(from - o, to - o);
      }
      if (near(to, o)) break;
      std::size_t next = pieces.size();
      for (std::size_t j = 0; j < pieces.size(); ++j) {
        if (used[j]) continue;
        if (near(pieces[j].a, to)) { next = j; forward = true; break; }
        if (near(pieces[j].b, to)) { next = j; forward = false; break; }
      }
      if (next == pieces.size()) {
        ADD_FAILURE() << "open chain at (" << to.x << ", " << to.y << ")";
        return std::nan("");
      }
      i = next;
    }
    area += (pieces[s].hole ? -1 : 1) * std::abs(0.5 * twice);
    ++loops;
  }
  if (loops_out) *loops_out = loops;
  return area;
}

// ------------------------------------------------------- WKT / GeoJSON / CSV

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

double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

// ------------------------------------------------------------------ tests

TEST(ExportOptions, EffectiveToleranceAndMinArea) {
  const Region r = geo::rectangle(Box{{0.0, 0.0}, {3.0, 4.0}});
  EXPECT_DOUBLE_EQ(io::effective_tolerance(r, {}), 5e-6);  // 1e-6 of the diagonal 5
  EXPECT_DOUBLE_EQ(io::effective_min_area(r, {}), 12e-12);
  io::ExportOptions o;
  o.tolerance = 0.25;
  o.min_area = 1e-3;
  EXPECT_EQ(io::effective_tolerance(r, o), 0.25);
  EXPECT_EQ(io::effective_min_area(r, o), 1e-3);
}

TEST(ExportFormat, ParsesNamesAndRejectsOthers) {
  for (auto f : {io::ExportFormat::svg, io::ExportFormat::dxf, io::ExportFormat::wkt,
                 io::ExportFormat::geojson, io::ExportFormat::csv}) {
    EXPECT_EQ(io::parse_export_format(io::format_name(f)), f);
  }
  EXPECT_THROW(io::parse_export_format("pdf"), io::InputError);
}

TEST(ExportSvg, PathAreaMatchesExactArea) {
  double worst = 0.0;
  for (const auto& c : cases()) {
    SCOPED_TRACE(c.name);
    const std::string svg = io::to_svg(c.region);
    EXPECT_NE(svg.find("transform=\"scale(1,-1)\""), std::string::npos);
    EXPECT_EQ(attribute(svg, "path", "fill-rule"), "evenodd");
    const SvgStats st = svg_area(attribute(svg, "path", "d"));
    const double exact = c.region.area();
    if (!std::isnan(c.closed_form)) {
      EXPECT_LT(rel(exact, c.closed_form), 1e-13);
    }
    EXPECT_LT(rel(st.area, exact), 1e-12) << st.area << " vs " << exact;
    worst = std::max(worst, rel(st.area, exact));
    std::size_t loops = 0;
    for (const auto& comp : c.region.components()) loops += 1 + comp.holes.size();
    EXPECT_EQ(static_cast<std::size_t>(st.subpaths), loops);

    // The viewBox (y flipped) holds the bounding box with a margin.
    std::istringstream vb(attribute(svg, "svg", "viewBox"));
    double x = 0, y = 0, w = 0, h = 0;
    vb >> x >> y >> w >> h;
    const Box b = c.region.bbox();
    EXPECT_LT(x, b.min.x);
    EXPECT_LT(y, -b.max.y);
    EXPECT_GT(x + w, b.max.x);
    EXPECT_GT(y + h, -b.min.y);
  }
  std::printf("  SVG round trip: worst relative area error %.3g\n", worst);
}

TEST(ExportSvg, ArcFlagsFollowTheSweep) {
  // 3/4 disk: one ccw arc of 3pi/2 written as a single large arc.
  const Region r = geo::disk({0.0, 0.0}, 1.0) - geo::rectangle(Box{{0.0, 0.0}, {2.0, 2.0}});
  const SvgStats st = svg_area(io::svg_path(r));
  EXPECT_EQ(st.arcs, 1);
  EXPECT_EQ(st.large_arcs, 1);
  EXPECT_EQ(st.lines, 2);
  EXPECT_NEAR(st.area, 0.75 * pi, 1e-14);
  // A hole (clockwise circle) is written with sweep flag 0 and subtracts.
  const Region a = geo::annulus({0.0, 0.0}, 1.0, 2.0);
  const std::string d = io::svg_path(a);
  EXPECT_NE(d.find(" 0 0 1 "), std::string::npos);  // ccw outer pieces
  EXPECT_NE(d.find(" 0 0 0 "), std::string::npos);  // cw hole pieces
  EXPECT_NEAR(svg_area(d).area, 3 * pi, 1e-14);
}

TEST(ExportSvg, NumbersReadBackExactly) {
  // Endpoints with many digits: the path holds them exactly.
  const Region r = geo::rectangle(Box{{0.1, 1.0 / 3.0}, {std::sqrt(2.0), pi}});
  const std::string d = io::svg_path(r);
  std::istringstream in(d);
  char m = 0;
  double x = 0, y = 0;
  in >> m >> x >> y;
  bool found = false;
  const auto loops = r.loops();
  for (const auto& cv : loops.front().curves) found |= cv.source == Point{x, y};
  EXPECT_TRUE(found) << d;
  EXPECT_NE(d.find("3.141592653589793"), std::string::npos);
}

TEST(ExportSvg, SliversBelowMinAreaAreDropped) {
  const Region r = geo::disk({0.0, 0.0}, 10.0) | geo::disk({100.0, 0.0}, 1e-6);
  EXPECT_EQ(r.components().size(), 2u);
  EXPECT_EQ(svg_area(io::svg_path(r)).subpaths, 1);
  io::ExportOptions keep;
  keep.min_area = 1e-20;
  EXPECT_EQ(svg_area(io::svg_path(r, keep)).subpaths, 2);
  // CSV rows follow the same rule.
  const std::string csv = io::to_csv(r);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 2);
}

TEST(ExportSvg, EmptyRegionIsAValidDocument) {
  const std::string svg = io::to_svg(Region{});
  EXPECT_EQ(attribute(svg, "path", "d"), "");
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_EQ(io::to_wkt(Region{}), "MULTIPOLYGON EMPTY\n");
}

TEST(ExportDxf, EntitiesChainIntoLoopsWithTheExactArea) {
  double worst = 0.0;
  for (const auto& c : cases()) {
    SCOPED_TRACE(c.name);
    io::ExportOptions o;
    o.units = "mm";
    const Dxf dxf = parse_dxf(io::to_dxf(c.region, o));
    EXPECT_EQ(dxf.header.at("$ACADVER"), "AC1009");
    EXPECT_EQ(dxf.header.at("$MEASUREMENT"), "1");
    EXPECT_EQ(dxf.layers, (std::vector<std::string>{"BOUNDARY", "HOLES"}));
    EXPECT_EQ(dxf.entities.size(), curve_total(c.region));
    std::size_t holes = 0, loops = 0;
    for (const auto& comp : c.region.components()) {
      holes += comp.holes.size();
      loops += 1 + comp.holes.size();
    }
    std::size_t on_holes = 0;
    for (const auto& e : dxf.entities) on_holes += e.codes.at(8) == "HOLES";
    EXPECT_EQ(holes == 0, on_holes == 0);
    const Box b = c.region.bbox();
    int chained = 0;
    const double area = dxf_area(dxf, std::max(b.width(), b.height()), &chained);
    EXPECT_EQ(static_cast<std::size_t>(chained), loops);
    EXPECT_LT(rel(area, c.region.area()), 1e-12) << area << " vs " << c.region.area();
    worst = std::max(worst, rel(area, c.region.area()));
  }
  std::printf("  DXF round trip: worst relative area error %.3g\n", worst);
}

TEST(ExportDxf, ClockwiseArcIsWrittenCounterClockwise) {
  // A square with a half-disk notch cut from its right side: on the outer
  // (counter-clockwise) loop the notch is a clockwise half circle about
  // (4, 0) from (4, -1) through (3, 0) to (4, 1).
  const Region r = geo::rectangle(Box{{0.0, -2.0}, {4.0, 2.0}}) - geo::disk({4.0, 0.0}, 1.0);
  const Dxf dxf = parse_dxf(io::to_dxf(r));
  int arcs = 0;
  for (const auto& e : dxf.entities) {
    if (e.type != "ARC") continue;
    ++arcs;
    EXPECT_DOUBLE_EQ(e.num(40), 1.0);
    EXPECT_DOUBLE_EQ(e.num(50), 90.0);   // ccw from (4, 1) ...
    EXPECT_DOUBLE_EQ(e.num(51), 270.0);  // ... to (4, -1), through (3, 0)
  }
  EXPECT_EQ(arcs, 1);
  EXPECT_NEAR(dxf_area(dxf, 4.0), 16.0 - 0.5 * pi, 1e-13);
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

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() /
                     ("pkmws_export_test_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(ExportWriteFile, OverwritesAtomicallyAndLeavesNoTemporary) {
  const fs::path d = fresh_dir("overwrite");
  const fs::path f = d / "out.svg";
  io::write_file_atomic(f, "first version, longer than the second\n");
  EXPECT_EQ(slurp(f), "first version, longer than the second\n");
  io::write_file_atomic(f, "second\n");
  EXPECT_EQ(slurp(f), "second\n");
  io::write_file_atomic(f, "");
  EXPECT_EQ(slurp(f), "");
  std::size_t entries = 0;
  for (const auto& e : fs::directory_iterator(d)) {
    ++entries;
    EXPECT_EQ(e.path().filename(), "out.svg");
  }
  EXPECT_EQ(entries, 1u);
  fs::remove_all(d);
}

TEST(ExportWriteFile, MissingDirectoryThrowsAndWritesNothing) {
  const fs::path d = fresh_dir("missing");
  const fs::path f = d / "no" / "such" / "dir" / "out.dxf";
  try {
    io::write_file_atomic(f, "content");
    ADD_FAILURE() << "no exception";
  } catch (const io::InputError& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.rfind(f.string() + ": cannot write: ", 0), 0u) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos);
  }
  EXPECT_FALSE(fs::exists(d / "no"));
  EXPECT_TRUE(fs::is_empty(d));
  // A directory in the way is refused too, and left as it was.
  fs::create_directory(d / "taken");
  EXPECT_THROW(io::write_file_atomic(d / "taken", "x"), io::InputError);
  EXPECT_TRUE(fs::is_directory(d / "taken"));
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(d)) ++entries;
  EXPECT_EQ(entries, 1u);
  fs::remove_all(d);
}

// -------------------------------------------------------------- figure

std::size_t count_of(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
}

TEST(ExportFigure, MomaFigureIsWellFormed) {
  const fs::path file = fs::path(PKMWS_SOURCE_DIR) / "datasets" / "moma_m1_g0_l250.json";
  if (!fs::exists(file)) GTEST_SKIP() << file << " not there yet";
  const io::MechanismFile mech = io::load_mechanism(file);
  const Region region = mech.model->workspace();
  const auto comps = region.components();
  ASSERT_FALSE(comps.empty());
  const Point c = comps.front().centroid;
  io::FigureOptions opt;
  opt.title = mech.name;
  opt.caption = "exact workspace area = 36 202.18 mm² <M1 & l = 250>";
  const std::string svg = io::workspace_figure(mech, region, {c.x, c.y, 0.0}, opt);
  EXPECT_EQ(svg, io::workspace_figure(mech, region, {c.x, c.y, 0.0}, opt));  // deterministic
  EXPECT_EQ(count_of(svg, "<svg"), 1u);
  EXPECT_EQ(count_of(svg, "</svg>"), 1u);
  EXPECT_LT(svg.find("<svg"), svg.find("</svg>"));
  EXPECT_EQ(count_of(svg, "<g"), count_of(svg, "</g>"));
  EXPECT_NE(svg.find("exact workspace area = 36 202.18 mm² &lt;M1 &amp; l = 250&gt;"),
            std::string::npos);
  EXPECT_NE(svg.find(" A"), std::string::npos);
  // Every drawn element (lines, circles, rects, text anchors) lies on the canvas.
  double width = 0, height = 0;
  std::istringstream(attribute(svg, "svg", "width")) >> width;
  std::istringstream(attribute(svg, "svg", "height")) >> height;
  EXPECT_GE(width, 600);
  EXPECT_LE(width, 1000);
  EXPECT_GE(height, 500);
  EXPECT_LE(height, 900);
  std::size_t checked = 0;
  for (const std::string key : {" x1=\"", " x2=\"", " cx=\"", " x=\""}) {
    for (auto p = svg.find(key); p != std::string::npos; p = svg.find(key, p + 1)) {
      const double v = std::strtod(svg.c_str() + p + key.size(), nullptr);
      EXPECT_GE(v, 0.0);
      EXPECT_LE(v, width);
      ++checked;
    }
  }
  for (const std::string key : {" y1=\"", " y2=\"", " cy=\"", " y=\""}) {
    for (auto p = svg.find(key); p != std::string::npos; p = svg.find(key, p + 1)) {
      const double v = std::strtod(svg.c_str() + p + key.size(), nullptr);
      EXPECT_GE(v, 0.0);
      EXPECT_LE(v, height);
      ++checked;
    }
  }
  EXPECT_GT(checked, 20u);
  // The plot's mapping (data-transform="X0 Y0 S": px = X0 + S x, py = Y0 - S y)
  // puts the region's bounding box inside the canvas.
  const auto t = svg.find("data-transform=\"");
  ASSERT_NE(t, std::string::npos);
  double tx = 0, ty = 0, sx = 0;
  ASSERT_EQ(std::sscanf(svg.c_str() + t, "data-transform=\"%lf %lf %lf", &tx, &ty, &sx), 3);
  const double sy = -sx;
  EXPECT_GT(sx, 0.0);
  const Box b = region.bbox();
  for (const Point p : {b.min, b.max}) {
    EXPECT_GT(tx + sx * p.x, 0.0);
    EXPECT_LT(tx + sx * p.x, width);
    EXPECT_GT(ty + sy * p.y, 0.0);
    EXPECT_LT(ty + sy * p.y, height);
  }
}

}  // namespace
