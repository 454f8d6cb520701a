#include "mechanisms/contour.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>

namespace pkmws::mechanisms {

using geometry::Point;

namespace {

// Bisection on the sign of f between a (f(a) = fa) and b (opposite sign).
Point refine(const std::function<double(Point)>& f, Point a, double fa, Point b) {
  for (int it = 0; it < 48; ++it) {
    const Point m{0.5 * (a.x + b.x), 0.5 * (a.y + b.y)};
    const double fm = f(m);
    if (!std::isfinite(fm)) break;
    if ((fm < 0.0) == (fa < 0.0)) {
      a = m;
      fa = fm;
    } else {
      b = m;
    }
  }
  return {0.5 * (a.x + b.x), 0.5 * (a.y + b.y)};
}

}  // namespace

std::vector<std::vector<Point>> zero_contours(const std::function<double(Point)>& f, const geometry::Box& box, int n) {
  std::vector<std::vector<Point>> out;
  if (n < 2 || box.empty() || !(box.width() > 0.0) || !(box.height() > 0.0)) return out;
  const auto N = static_cast<std::size_t>(n);
  const double dx = box.width() / n, dy = box.height() / n;
  auto node = [&](std::size_t i, std::size_t j) {
    return Point{box.min.x + static_cast<double>(i) * dx, box.min.y + static_cast<double>(j) * dy};
  };
  std::vector<double> v((N + 1) * (N + 1));
  for (std::size_t j = 0; j <= N; ++j)
    for (std::size_t i = 0; i <= N; ++i) v[j * (N + 1) + i] = f(node(i, j));
  auto val = [&](std::size_t i, std::size_t j) { return v[j * (N + 1) + i]; };

  // Edge ids: horizontal edge (i, j)-(i+1, j) = 2 * (j * (N + 1) + i), vertical (i, j)-(i, j+1) = that + 1.
  std::map<std::uint64_t, Point> crossing;
  auto edge_point = [&](std::size_t i0, std::size_t j0, std::size_t i1, std::size_t j1) -> std::uint64_t {
    const bool vertical = i0 == i1;
    const std::uint64_t id = 2 * (j0 * (N + 1) + i0) + (vertical ? 1 : 0);
    if (!crossing.count(id)) crossing[id] = refine(f, node(i0, j0), val(i0, j0), node(i1, j1));
    return id;
  };
  auto sign = [](double x) { return x < 0.0; };
  std::vector<std::pair<std::uint64_t, std::uint64_t>> segments;
  for (std::size_t j = 0; j < N; ++j) {
    for (std::size_t i = 0; i < N; ++i) {
      const double c[4] = {val(i, j), val(i + 1, j), val(i + 1, j + 1), val(i, j + 1)};
      bool finite = true;
      for (double x : c) finite = finite && std::isfinite(x);
      if (!finite) continue;
      std::vector<std::uint64_t> pts;  // crossings in the order bottom, right, top, left
      if (sign(c[0]) != sign(c[1])) pts.push_back(edge_point(i, j, i + 1, j));
      if (sign(c[1]) != sign(c[2])) pts.push_back(edge_point(i + 1, j, i + 1, j + 1));
      if (sign(c[3]) != sign(c[2])) pts.push_back(edge_point(i, j + 1, i + 1, j + 1));
      if (sign(c[0]) != sign(c[3])) pts.push_back(edge_point(i, j, i, j + 1));
      if (pts.size() == 2) {
        segments.push_back({pts[0], pts[1]});
      } else if (pts.size() == 4) {
        // Saddle: the centre's sign decides which corners connect.
        const double centre = f({box.min.x + (static_cast<double>(i) + 0.5) * dx, box.min.y + (static_cast<double>(j) + 0.5) * dy});
        if (sign(centre) == sign(c[0])) {
          segments.push_back({pts[0], pts[1]});
          segments.push_back({pts[2], pts[3]});
        } else {
          segments.push_back({pts[0], pts[3]});
          segments.push_back({pts[1], pts[2]});
        }
      }
    }
  }
  // Chain segments through their shared crossings.
  std::multimap<std::uint64_t, std::size_t> at;
  for (std::size_t k = 0; k < segments.size(); ++k) {
    at.insert({segments[k].first, k});
    at.insert({segments[k].second, k});
  }
  std::vector<bool> used(segments.size(), false);
  auto next_segment = [&](std::uint64_t p) -> std::ptrdiff_t {
    auto [lo, hi] = at.equal_range(p);
    for (auto it = lo; it != hi; ++it)
      if (!used[it->second]) return static_cast<std::ptrdiff_t>(it->second);
    return -1;
  };
  for (std::size_t k = 0; k < segments.size(); ++k) {
    if (used[k]) continue;
    used[k] = true;
    std::vector<std::uint64_t> chain{segments[k].first, segments[k].second};
    for (int dir = 0; dir < 2; ++dir) {
      for (;;) {
        const std::uint64_t end = chain.back();
        const std::ptrdiff_t s = next_segment(end);
        if (s < 0) break;
        used[static_cast<std::size_t>(s)] = true;
        const auto& seg = segments[static_cast<std::size_t>(s)];
        chain.push_back(seg.first == end ? seg.second : seg.first);
      }
      std::reverse(chain.begin(), chain.end());
    }
    std::vector<Point> line;
    for (std::uint64_t id : chain) line.push_back(crossing[id]);
    out.push_back(std::move(line));
  }
  return out;
}

}  // namespace pkmws::mechanisms
