// The certified-region quadtree and enclosure algebra (see cell_region.hpp).
#include "pkmws/certified/cell_region.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>

#include "detail/parallel.hpp"
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

Box cell_box(const Box& window, int base, const Cell& c) {
  const double n = static_cast<double>(base) * std::ldexp(1.0, c.level);
  const double w = window.width(), h = window.height();
  Box b;
  b.min = {window.min.x + w * (static_cast<double>(c.i) / n), window.min.y + h * (static_cast<double>(c.j) / n)};
  b.max = {window.min.x + w * (static_cast<double>(c.i + 1) / n), window.min.y + h * (static_cast<double>(c.j + 1) / n)};
  // The last column/row ends exactly on the window.
  if (static_cast<double>(c.i + 1) == n) b.max.x = window.max.x;
  if (static_cast<double>(c.j + 1) == n) b.max.y = window.max.y;
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

// Then vertical: runs with identical columns that touch become one box.
std::vector<Box> merge_columns(std::vector<Box> boxes) {
  std::sort(boxes.begin(), boxes.end(), [](const Box& a, const Box& b) {
    return std::tie(a.min.x, a.max.x, a.min.y) < std::tie(b.min.x, b.max.x, b.min.y);
  });
  std::vector<Box> out;
  for (const Box& b : boxes) {
    if (!out.empty()) {
      Box& last = out.back();
      if (last.min.x == b.min.x && last.max.x == b.max.x && last.max.y == b.min.y) {
        last.max.y = b.max.y;
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
  if (options.max_depth < 0 || options.max_depth > 24)
    throw std::invalid_argument("certified::cover: max_depth must be in [0, 24]");
  if (!test) throw std::invalid_argument("certified::cover: no cell test");

  detail::ParallelPolicy policy;
  policy.threads = options.threads;
  policy.serial_threshold = 256;  // cell tests are expensive compared to point tests

  CellCover result;
  std::vector<Cell> level;
  level.reserve(static_cast<std::size_t>(options.base) * static_cast<std::size_t>(options.base));
  for (int j = 0; j < options.base; ++j)
    for (int i = 0; i < options.base; ++i) level.push_back({i, j, 0});

  std::vector<Box> inside;
  constexpr std::size_t block = 64;
  for (int depth = 0; !level.empty(); ++depth) {
    result.depth = depth;
    std::vector<CellState> state(level.size());
    const std::size_t blocks = detail::block_count(level.size(), block);
    detail::for_each_block(policy, blocks, level.size(), [&](std::size_t b) {
      const std::size_t end = std::min(level.size(), (b + 1) * block);
      for (std::size_t k = b * block; k < end; ++k) state[k] = test(cell_box(options.window, options.base, level[k]));
    });
    result.tests += level.size();
    std::vector<Cell> next;
    for (std::size_t k = 0; k < level.size(); ++k) {
      const Cell& c = level[k];
      switch (state[k]) {
        case CellState::inside: inside.push_back(cell_box(options.window, options.base, c)); break;
        case CellState::outside: break;
        case CellState::undecided:
          if (depth == options.max_depth) {
            result.undecided.push_back(cell_box(options.window, options.base, c));
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

Region boxes_region(const std::vector<Box>& boxes) {
  std::vector<Region> parts;
  parts.reserve(boxes.size());
  for (const Box& b : merge_columns(merge_runs(boxes)))
    if (b.width() > 0.0 && b.height() > 0.0) parts.push_back(geometry::rectangle(b));
  if (parts.empty()) return Region{};
  return Region::unite_all(parts);
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
