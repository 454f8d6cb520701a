// The certified-region quadtree and enclosure algebra (see cell_region.hpp).
#include "pkmws/certified/cell_region.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <limits>
#include <tuple>
#include <unordered_map>
#include <utility>

#include "detail/parallel.hpp"
#include "geometry/loops.hpp"
#include "pkmws/geometry/primitives.hpp"

namespace pkmws::certified {

using geometry::Box;
using geometry::Region;

namespace {

// A cell of the quadtree: integer coordinates at its level, so children and
// box corners are computed without accumulating rounding.
struct Cell {
  std::int64_t i = 0, j = 0;  // column, row at `level`
  int level = 0;
};

Box cell_box(const Box& window, int base, int rows, const Cell& c) {
  const double n = static_cast<double>(base) * std::ldexp(1.0, c.level);
  const double m = static_cast<double>(rows) * std::ldexp(1.0, c.level);
  const double w = window.width(), h = window.height();
  Box b;
  b.min = {window.min.x + w * (static_cast<double>(c.i) / n), window.min.y + h * (static_cast<double>(c.j) / m)};
  b.max = {window.min.x + w * (static_cast<double>(c.i + 1) / n), window.min.y + h * (static_cast<double>(c.j + 1) / m)};
  // The last column/row ends exactly on the window.
  if (static_cast<double>(c.i + 1) == n) b.max.x = window.max.x;
  if (static_cast<double>(c.j + 1) == m) b.max.y = window.max.y;
  return b;
}

double box_area(const Box& b) { return b.width() * b.height(); }

// Horizontal runs: boxes with identical rows and touching x ranges become one.
std::vector<Box> merge_runs(std::vector<Box> boxes) {
  std::sort(boxes.begin(), boxes.end(), [](const Box& a, const Box& b) {
    return std::tie(a.min.y, a.max.y, a.min.x) < std::tie(b.min.y, b.max.y, b.min.x);
  });
  std::vector<Box> out;
  for (const Box& b : boxes) {
    if (!out.empty()) {
      Box& last = out.back();
      if (last.min.y == b.min.y && last.max.y == b.max.y && last.max.x == b.min.x) {
        last.max.x = b.max.x;
        continue;
      }
    }
    out.push_back(b);
  }
  return out;
}

}  // namespace

CellCover cover(const CellTest& test, const CellOptions& options) {
  if (options.window.empty() || !(options.window.width() > 0.0) || !(options.window.height() > 0.0))
    throw std::invalid_argument("certified::cover: the window is empty");
  if (options.base < 1) throw std::invalid_argument("certified::cover: base must be >= 1");
  if (options.base_rows < 0) throw std::invalid_argument("certified::cover: base_rows must be >= 0");
  const int rows = options.base_rows > 0 ? options.base_rows : options.base;
  if (options.max_depth < 0 || options.max_depth > 24)
    throw std::invalid_argument("certified::cover: max_depth must be in [0, 24]");
  if (!test) throw std::invalid_argument("certified::cover: no cell test");

  detail::ParallelPolicy policy;
  policy.threads = options.threads;
  policy.serial_threshold = 256;  // cell tests are expensive compared to point tests

  CellCover result;
  std::vector<Cell> level;
  level.reserve(static_cast<std::size_t>(options.base) * static_cast<std::size_t>(rows));
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < options.base; ++i) level.push_back({i, j, 0});

  std::vector<Box> inside;
  constexpr std::size_t block = 64;
  for (int depth = 0; !level.empty(); ++depth) {
    result.depth = depth;
    std::vector<CellState> state(level.size());
    const std::size_t blocks = detail::block_count(level.size(), block);
    detail::for_each_block(policy, blocks, level.size(), [&](std::size_t b) {
      const std::size_t end = std::min(level.size(), (b + 1) * block);
      for (std::size_t k = b * block; k < end; ++k) state[k] = test(cell_box(options.window, options.base, rows, level[k]));
    });
    result.tests += level.size();
    std::vector<Cell> next;
    for (std::size_t k = 0; k < level.size(); ++k) {
      const Cell& c = level[k];
      switch (state[k]) {
        case CellState::inside: inside.push_back(cell_box(options.window, options.base, rows, c)); break;
        case CellState::outside: break;
        case CellState::undecided:
          if (depth == options.max_depth) {
            result.undecided.push_back(cell_box(options.window, options.base, rows, c));
          } else {
            for (int dj = 0; dj < 2; ++dj)
              for (int di = 0; di < 2; ++di) next.push_back({2 * c.i + di, 2 * c.j + dj, c.level + 1});
          }
          break;
      }
    }
    level = std::move(next);
  }
  for (const Box& b : inside) result.area_inside += box_area(b);
  for (const Box& b : result.undecided) result.area_undecided += box_area(b);
  result.inside = merge_runs(std::move(inside));
  result.undecided = merge_runs(std::move(result.undecided));
  return result;
}

namespace {

// The union of boxes as rectilinear loops, without a general Boolean sweep:
// the boxes' coordinates are compressed to a lattice, each lattice row holds
// the merged x-intervals it is covered by, and the boundary is the set of
// directed lattice edges with the union on their left: vertical edges at the
// ends of every row interval, horizontal edges where a row line separates
// covered from uncovered. Edges are chained turning left first (diagonally
// touching cells stay apart), loops that still revisit a vertex are split
// there, and the union is the even-odd combination of the loops.
struct LatticeEdge {
  int x0, y0, x1, y1;
};

using Interval = std::pair<int, int>;

std::vector<Interval> merge_intervals(std::vector<Interval> v) {
  std::sort(v.begin(), v.end());
  std::vector<Interval> out;
  for (const Interval& i : v) {
    if (!out.empty() && i.first <= out.back().second) {
      out.back().second = std::max(out.back().second, i.second);
    } else {
      out.push_back(i);
    }
  }
  return out;
}

bool covered(const std::vector<Interval>& row, int a, int b) {
  // Is the lattice segment [a, b] (inside one elementary piece) covered?
  auto it = std::upper_bound(row.begin(), row.end(), Interval{a, std::numeric_limits<int>::max()});
  if (it == row.begin()) return false;
  --it;
  return it->first <= a && b <= it->second;
}

std::vector<std::vector<std::pair<int, int>>> lattice_loops(const std::vector<std::vector<Interval>>& rows) {
  const int n_rows = static_cast<int>(rows.size());
  std::vector<LatticeEdge> edges;
  for (int j = 0; j < n_rows; ++j) {
    for (const Interval& i : rows[static_cast<std::size_t>(j)]) {
      edges.push_back({i.first, j + 1, i.first, j});    // left side, downwards
      edges.push_back({i.second, j, i.second, j + 1});  // right side, upwards
    }
  }
  const std::vector<Interval> none;
  for (int j = 0; j <= n_rows; ++j) {
    const auto& below = j > 0 ? rows[static_cast<std::size_t>(j - 1)] : none;
    const auto& above = j < n_rows ? rows[static_cast<std::size_t>(j)] : none;
    std::vector<int> cuts;
    for (const Interval& i : below) { cuts.push_back(i.first); cuts.push_back(i.second); }
    for (const Interval& i : above) { cuts.push_back(i.first); cuts.push_back(i.second); }
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
      const int a = cuts[k], b = cuts[k + 1];
      const bool up = covered(above, a, b), down = covered(below, a, b);
      if (up && !down) edges.push_back({a, j, b, j});   // bottom of the union, +x
      if (down && !up) edges.push_back({b, j, a, j});   // top of the union, -x
    }
  }
  std::vector<std::pair<geometry::Point, geometry::Point>> chain;  // small integers: exact as doubles
  chain.reserve(edges.size());
  for (const LatticeEdge& e : edges) {
    chain.push_back({{static_cast<double>(e.x0), static_cast<double>(e.y0)},
                     {static_cast<double>(e.x1), static_cast<double>(e.y1)}});
  }
  std::vector<std::vector<std::pair<int, int>>> loops;
  for (const auto& loop : geometry::left_turn_loops(chain)) {
    // Drop collinear vertices.
    std::vector<std::pair<int, int>> out;
    const std::size_t n = loop.size();
    for (std::size_t k = 0; k < n; ++k) {
      const LatticeEdge& in = edges[loop[(k + n - 1) % n]];
      const LatticeEdge& at = edges[loop[k]];
      const long cross = static_cast<long>(in.x1 - in.x0) * (at.y1 - at.y0) - static_cast<long>(in.y1 - in.y0) * (at.x1 - at.x0);
      if (cross != 0) out.push_back({at.x0, at.y0});
    }
    if (out.size() >= 4) loops.push_back(std::move(out));
  }
  return loops;
}

}  // namespace

Region boxes_region(const std::vector<Box>& boxes) {
  std::vector<double> xs, ys;
  std::vector<Box> kept;
  for (const Box& b : boxes) {
    if (!(b.width() > 0.0 && b.height() > 0.0)) continue;
    kept.push_back(b);
    xs.push_back(b.min.x);
    xs.push_back(b.max.x);
    ys.push_back(b.min.y);
    ys.push_back(b.max.y);
  }
  if (kept.empty()) return Region{};
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  std::sort(ys.begin(), ys.end());
  ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
  auto index = [](const std::vector<double>& v, double x) {
    return static_cast<int>(std::lower_bound(v.begin(), v.end(), x) - v.begin());
  };
  std::vector<std::vector<Interval>> rows(ys.size() - 1);
  for (const Box& b : kept) {
    const int i0 = index(xs, b.min.x), i1 = index(xs, b.max.x);
    const int j0 = index(ys, b.min.y), j1 = index(ys, b.max.y);
    for (int j = j0; j < j1; ++j) rows[static_cast<std::size_t>(j)].push_back({i0, i1});
  }
  for (auto& r : rows) r = merge_intervals(std::move(r));
  std::vector<Region> polygons;
  for (const auto& loop : lattice_loops(rows)) {
    std::vector<geometry::Point> pts;
    pts.reserve(loop.size());
    for (const auto& [i, j] : loop) pts.push_back({xs[static_cast<std::size_t>(i)], ys[static_cast<std::size_t>(j)]});
    polygons.push_back(geometry::polygon(pts));
  }
  if (polygons.size() == 1) return polygons.front();
  return Region::symmetric_difference_all(polygons);
}

Region polygons_region(const std::vector<std::vector<geometry::Point>>& pieces) {
  using geometry::Point;
  struct Span {
    double lo, hi;
    int dir;  // +1: the edge runs towards increasing coordinate
  };
  std::vector<std::pair<Point, Point>> edges;  // the pieces' edges, region on the left
  std::unordered_map<double, std::vector<Span>> rows, columns;  // axis-aligned edges by y / by x
  std::vector<Point> p;
  for (const auto& piece : pieces) {
    p.clear();
    for (const Point& v : piece) {
      if (p.empty() || !(p.back() == v)) p.push_back(v);
    }
    while (p.size() > 1 && p.front() == p.back()) p.pop_back();
    if (p.size() < 3) continue;
    double twice_area = 0.0;  // about the first vertex: no cancellation of large coordinates
    for (std::size_t k = 1; k + 1 < p.size(); ++k) {
      const Point a = p[k] - p[0], b = p[k + 1] - p[0];
      twice_area += a.x * b.y - a.y * b.x;
    }
    if (twice_area == 0.0) continue;
    if (twice_area < 0.0) std::reverse(p.begin(), p.end());  // counter-clockwise: the piece on each edge's left
    for (std::size_t k = 0; k < p.size(); ++k) {
      const Point& a = p[k];
      const Point& b = p[(k + 1) % p.size()];
      if (a.y == b.y) rows[a.y].push_back({std::min(a.x, b.x), std::max(a.x, b.x), a.x < b.x ? 1 : -1});
      else if (a.x == b.x) columns[a.x].push_back({std::min(a.y, b.y), std::max(a.y, b.y), a.y < b.y ? 1 : -1});
      else edges.push_back({a, b});
    }
  }
  // A vertex on another piece's axis-aligned edge (a piece touching a
  // neighbour's side at a point) splits that edge: the loops then meet at
  // the vertex, where they are split, instead of touching an edge.
  for (const auto& piece : pieces) {
    for (const Point& v : piece) {
      if (auto row = rows.find(v.y); row != rows.end()) row->second.push_back({v.x, v.x, 0});
      if (auto column = columns.find(v.x); column != columns.end()) column->second.push_back({v.y, v.y, 0});
    }
  }
  // Shared edges cancel: on each axis line, the net direction of the edges
  // over each interval between their ends (two pieces on either side of an
  // edge run it in opposite directions; interior-disjoint pieces never in the same).
  const auto cancel = [&](std::unordered_map<double, std::vector<Span>>& lines, bool horizontal) {
    std::vector<std::pair<double, int>> events;
    for (auto& [c, spans] : lines) {
      events.clear();
      for (const Span& s : spans) {
        events.push_back({s.lo, s.dir});
        events.push_back({s.hi, -s.dir});
      }
      std::sort(events.begin(), events.end());
      int sum = 0;
      for (std::size_t k = 0; k + 1 < events.size(); ++k) {
        sum += events[k].second;
        const double t0 = events[k].first, t1 = events[k + 1].first;
        if (sum == 0 || !(t1 > t0)) continue;
        const Point a = horizontal ? Point{t0, c} : Point{c, t0}, b = horizontal ? Point{t1, c} : Point{c, t1};
        edges.push_back(sum > 0 ? std::pair{a, b} : std::pair{b, a});
      }
    }
  };
  cancel(rows, true);
  cancel(columns, false);

  // The loops, each simple; the vertices inside straight axis-aligned runs dropped.
  std::vector<Region> polygons;
  for (const auto& loop : geometry::left_turn_loops(edges)) {
    std::vector<Point> out;
    const std::size_t n = loop.size();
    for (std::size_t k = 0; k < n; ++k) {
      const Point& a = edges[loop[(k + n - 1) % n]].first;
      const Point& v = edges[loop[k]].first;
      const Point& b = edges[loop[(k + 1) % n]].first;
      if ((a.x == v.x && v.x == b.x) || (a.y == v.y && v.y == b.y)) continue;
      out.push_back(v);
    }
    if (out.size() >= 3) polygons.push_back(geometry::polygon(out));
  }
  if (polygons.empty()) return Region{};
  if (polygons.size() == 1) return polygons.front();
  return Region::symmetric_difference_all(polygons);
}

namespace {
CertifiedRegion make(Region inner, Region outer, bool exact) {
  CertifiedRegion r;
  r.area_lower = inner.area();
  r.area_upper = exact ? r.area_lower : outer.area();
  r.inner = std::move(inner);
  r.outer = std::move(outer);
  r.exact = exact;
  // Rounding of the two area evaluations can invert nearly equal bounds.
  if (r.area_upper < r.area_lower) r.area_upper = r.area_lower;
  return r;
}
}  // namespace

CertifiedRegion from_exact(const Region& region) { return make(region, region, true); }

CertifiedRegion certify(const CellTest& test, const Region& within, CellOptions options) {
  if (within.empty()) return from_exact(within);
  if (options.window.empty()) options.window = within.bbox();
  const CellCover c = cover(test, options);
  const Region in_cells = boxes_region(c.inside);
  const Region inner = within.intersect(in_cells);
  if (c.undecided.empty()) return make(inner, inner, true);
  std::vector<Box> all = c.inside;
  all.insert(all.end(), c.undecided.begin(), c.undecided.end());
  const Region outer = within.intersect(boxes_region(all));
  return make(inner, outer, false);
}

CertifiedRegion intersect(const CertifiedRegion& a, const CertifiedRegion& b) {
  const bool exact = a.exact && b.exact;
  Region inner = a.inner.intersect(b.inner);
  Region outer = exact ? inner : a.outer.intersect(b.outer);
  return make(std::move(inner), std::move(outer), exact);
}

CertifiedRegion unite(const CertifiedRegion& a, const CertifiedRegion& b) {
  const bool exact = a.exact && b.exact;
  Region inner = a.inner.unite(b.inner);
  Region outer = exact ? inner : a.outer.unite(b.outer);
  return make(std::move(inner), std::move(outer), exact);
}

CertifiedRegion subtract(const CertifiedRegion& a, const CertifiedRegion& b) {
  const bool exact = a.exact && b.exact;
  Region inner = a.inner.subtract(b.outer);
  Region outer = exact ? inner : a.outer.subtract(b.inner);
  return make(std::move(inner), std::move(outer), exact);
}

}  // namespace pkmws::certified
