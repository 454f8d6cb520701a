#include "export_cases.hpp"

#include <cmath>
#include <numbers>

#include "pkmws/geometry/primitives.hpp"

namespace pkmws::test {

namespace {

using geometry::Box;
using geometry::Point;
using geometry::Region;
namespace geo = pkmws::geometry;

constexpr double pi = std::numbers::pi;

}  // namespace

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

std::size_t curve_total(const Region& r, double min_area) {
  std::size_t n = 0;
  for (const auto& c : r.components(min_area)) {
    n += c.outer.curves.size();
    for (const auto& h : c.holes) n += h.curves.size();
  }
  return n;
}

std::string attribute(const std::string& text, const std::string& element, const std::string& name) {
  const auto e = text.find("<" + element);
  if (e == std::string::npos) return {};
  const auto a = text.find(" " + name + "=\"", e);
  if (a == std::string::npos) return {};
  const auto begin = a + name.size() + 3;
  return text.substr(begin, text.find('"', begin) - begin);
}

double cross2(Point a, Point b) { return a.x * b.y - a.y * b.x; }

double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

}  // namespace pkmws::test
