// SVG and DXF export: path areas against the exact areas (SVG read back as a
// renderer does, DXF entities chained into loops), arc flags and directions,
// numbers that read back exactly, slivers, the empty region.
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

using pkmws::geometry::Box;
using pkmws::geometry::Point;
using pkmws::geometry::Region;
namespace geo = pkmws::geometry;
namespace io = pkmws::io;
using pkmws::test::attribute;
using pkmws::test::cases;
using pkmws::test::cross2;
using pkmws::test::curve_total;
using pkmws::test::rel;

constexpr double pi = std::numbers::pi;

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

}  // namespace
