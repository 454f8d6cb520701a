// Chaining directed boundary edges into simple loops (see loops.hpp).
#include "geometry/loops.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <numbers>
#include <unordered_map>

namespace pkmws::geometry {

namespace {

// A point as a hash key (-0.0 as 0.0: they are the same vertex).
struct PointKey {
  std::size_t operator()(const Point& p) const {
    const auto bits = [](double v) {
      std::uint64_t u = 0;
      const double z = v == 0.0 ? 0.0 : v;
      std::memcpy(&u, &z, sizeof u);
      return u;
    };
    return std::hash<std::uint64_t>()(bits(p.x) * 0x9e3779b97f4a7c15ULL ^ bits(p.y));
  }
};

// The clockwise angle in (0, 2π] from direction r to direction d.
double clockwise_angle(Point r, Point d) {
  double t = std::atan2(d.x * r.y - d.y * r.x, d.x * r.x + d.y * r.y);
  if (t <= 0.0) t += 2.0 * std::numbers::pi;
  return t;
}

}  // namespace

std::vector<std::vector<std::size_t>> left_turn_loops(const std::vector<std::pair<Point, Point>>& edges) {
  std::unordered_multimap<Point, std::size_t, PointKey> outgoing;
  outgoing.reserve(edges.size());
  for (std::size_t e = 0; e < edges.size(); ++e) outgoing.insert({edges[e].first, e});
  std::vector<bool> used(edges.size(), false);
  std::vector<std::vector<std::size_t>> loops;
  std::vector<std::size_t> seq, stack;
  std::unordered_map<Point, std::size_t, PointKey> at;
  for (std::size_t first = 0; first < edges.size(); ++first) {
    if (used[first]) continue;
    seq.clear();
    std::size_t cur = first;
    used[cur] = true;
    for (;;) {
      seq.push_back(cur);
      const Point back = edges[cur].first - edges[cur].second;
      std::size_t next = edges.size();
      double best = 0.0;
      auto [lo, hi] = outgoing.equal_range(edges[cur].second);
      for (auto it = lo; it != hi; ++it) {
        const std::size_t cand = it->second;
        if (used[cand] && cand != first) continue;
        const double angle = clockwise_angle(back, edges[cand].second - edges[cand].first);
        if (next == edges.size() || angle < best) {
          best = angle;
          next = cand;
        }
      }
      if (next == edges.size() || next == first) break;
      used[next] = true;
      cur = next;
    }
    // Split at repeated vertices (the edges' start points).
    stack.clear();
    at.clear();
    for (const std::size_t e : seq) {
      const Point& v = edges[e].first;
      if (auto found = at.find(v); found != at.end()) {
        const std::size_t pos = found->second;
        loops.emplace_back(stack.begin() + static_cast<std::ptrdiff_t>(pos), stack.end());
        for (std::size_t r = pos; r < stack.size(); ++r) at.erase(edges[stack[r]].first);
        stack.resize(pos);
      }
      at[v] = stack.size();
      stack.push_back(e);
    }
    if (!stack.empty()) loops.push_back(stack);
  }
  return loops;
}

}  // namespace pkmws::geometry
