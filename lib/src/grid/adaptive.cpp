// Adaptive quadtree: a root grid of base_cells^2 cells, every cell that
// straddles the boundary split into four, down to `depth` levels. Only the
// boundary band is refined, so the work grows like 2^depth instead of 4^depth.
//
// Straddle rules:
//  - certified (MOMA): the kernel's 1-Lipschitz bound decides a cell when
//    |F(centre)| exceeds its half-diagonal; an undecided cell is never claimed
//    inside or outside, so [area_lower, area_upper] contains the true area.
//    Cost: cells within a half-diagonal of the boundary are refined even if
//    the boundary does not cross them (about 1.4x the crossed cells).
//  - sampled (any mechanism): centre and four corners tested; the cell is
//    decided when all five agree. Failure modes: a feature thinner than a cell
//    (a sliver, a small hole, a thin spike) that misses all five points is
//    lost, and then the bracket is wrong; use it when the workspace has no
//    feature smaller than a root cell.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "grid/common.hpp"
#include "pkmws/grid/sampler.hpp"

namespace pkmws::grid {

namespace {

struct Cell {
  std::uint32_t i, j;  // column and row at the cell's level
};

struct Geometry {
  Box box;
  std::size_t base = 0;  // root cells per side
  int depth = 0;
  double hx(int level) const { return box.width() / (double(base) * std::ldexp(1.0, level)); }
  double hy(int level) const { return box.height() / (double(base) * std::ldexp(1.0, level)); }
};

// Per root-cell task: counts per level (integers, summed in task order).
struct TaskCounts {
  std::vector<std::uint64_t> inside;     // per level
  std::vector<std::uint64_t> evaluated;  // cells evaluated per level
  std::uint64_t outside = 0;             // leaves decided outside (all levels)
  std::uint64_t undecided = 0;           // leaves left at the finest level
  std::uint64_t undecided_centre_in = 0; // of those, centre inside
  std::uint64_t points = 0;              // membership tests
};

class Classifier {
 public:
  Classifier(const MembershipKernel& kernel, bool certified, const Geometry& g)
      : kernel_(kernel), certified_(certified), g_(g) {}

  // state[k] for the cells at `level`.
  void classify(const std::vector<Cell>& cells, int level, std::vector<std::int8_t>& state,
                TaskCounts& counts) {
    const std::size_t n = cells.size();
    state.resize(n);
    const double hx = g_.hx(level), hy = g_.hy(level);
    if (certified_) {
      xs_.resize(n);
      ys_.resize(n);
      for (std::size_t k = 0; k < n; ++k) {
        xs_[k] = g_.box.min.x + (double(cells[k].i) + 0.5) * hx;
        ys_[k] = g_.box.min.y + (double(cells[k].j) + 0.5) * hy;
      }
      const double radius = 0.5 * std::hypot(hx, hy) * (1.0 + 1e-12);
      kernel_.classify(xs_.data(), ys_.data(), n, radius, state.data());
      counts.points += n;
      return;
    }
    // Centre and four corners per cell.
    xs_.resize(5 * n);
    ys_.resize(5 * n);
    mask_.resize(5 * n);
    for (std::size_t k = 0; k < n; ++k) {
      const double x0 = g_.box.min.x + double(cells[k].i) * hx, y0 = g_.box.min.y + double(cells[k].j) * hy;
      const double x1 = g_.box.min.x + double(cells[k].i + 1) * hx, y1 = g_.box.min.y + double(cells[k].j + 1) * hy;
      const double xc = g_.box.min.x + (double(cells[k].i) + 0.5) * hx;
      const double yc = g_.box.min.y + (double(cells[k].j) + 0.5) * hy;
      const double px[5] = {xc, x0, x1, x0, x1}, py[5] = {yc, y0, y0, y1, y1};
      for (int c = 0; c < 5; ++c) {
        xs_[5 * k + c] = px[c];
        ys_[5 * k + c] = py[c];
      }
    }
    kernel_.points(xs_.data(), ys_.data(), 5 * n, mask_.data());
    counts.points += 5 * n;
    for (std::size_t k = 0; k < n; ++k) {
      int in = 0;
      for (int c = 0; c < 5; ++c) in += mask_[5 * k + c];
      state[k] = in == 5 ? cell_inside : (in == 0 ? cell_outside : cell_undecided);
    }
  }

  // Centre test of leaves (the sampled rule already has it in its first point).
  std::uint64_t centres_inside(const std::vector<Cell>& cells, int level, TaskCounts& counts) {
    const std::size_t n = cells.size();
    const double hx = g_.hx(level), hy = g_.hy(level);
    xs_.resize(n);
    ys_.resize(n);
    mask_.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
      xs_[k] = g_.box.min.x + (double(cells[k].i) + 0.5) * hx;
      ys_[k] = g_.box.min.y + (double(cells[k].j) + 0.5) * hy;
    }
    kernel_.points(xs_.data(), ys_.data(), n, mask_.data());
    counts.points += n;
    std::uint64_t in = 0;
    for (std::size_t k = 0; k < n; ++k) in += mask_[k];
    return in;
  }

 private:
  const MembershipKernel& kernel_;
  bool certified_;
  const Geometry& g_;
  std::vector<double> xs_, ys_;
  std::vector<std::uint8_t> mask_;
};

// Refines the undecided cells `cells` (at `level`) down to g.depth.
void refine(Classifier& classifier, std::vector<Cell> cells, int level, const Geometry& g, TaskCounts& counts) {
  std::vector<std::int8_t> state;
  std::vector<Cell> children;
  while (level < g.depth && !cells.empty()) {
    children.clear();
    children.reserve(4 * cells.size());
    for (const Cell c : cells) {
      for (std::uint32_t dj = 0; dj < 2; ++dj) {
        for (std::uint32_t di = 0; di < 2; ++di) children.push_back({2 * c.i + di, 2 * c.j + dj});
      }
    }
    ++level;
    classifier.classify(children, level, state, counts);
    counts.evaluated[level] += children.size();
    cells.clear();
    for (std::size_t k = 0; k < children.size(); ++k) {
      if (state[k] == cell_inside) {
        ++counts.inside[level];
      } else if (state[k] == cell_outside) {
        ++counts.outside;
      } else {
        cells.push_back(children[k]);
      }
    }
  }
  counts.undecided += cells.size();
  if (!cells.empty()) counts.undecided_centre_in += classifier.centres_inside(cells, level, counts);
}

}  // namespace

AdaptiveResult adaptive(const mechanisms::Mechanism& mechanism, const AdaptiveOptions& options,
                        const Execution& execution) {
  const auto start = detail::Clock::now();
  if (options.base_cells == 0) throw std::invalid_argument("grid: base_cells must be positive");
  if (options.depth < 0 || options.depth > 40) throw std::invalid_argument("grid: adaptive depth must be in [0, 40]");
  if (double(options.base_cells) * std::ldexp(1.0, options.depth) > 2147483648.0) {
    throw std::invalid_argument("grid: base_cells * 2^depth must be at most 2^31");
  }
  const MembershipKernel kernel(mechanism, {execution.isa, execution.phi});
  bool certified = false;
  switch (options.rule) {
    case StraddleRule::automatic: certified = kernel.certified(); break;
    case StraddleRule::sampled: certified = false; break;
    case StraddleRule::certified:
      if (!kernel.certified()) {
        throw std::invalid_argument("grid: no certified straddle test for " + std::string(mechanism.kind()));
      }
      certified = true;
      break;
  }
  const auto policy = detail::policy_of(execution);
  AdaptiveResult r;
  detail::fill_common(r, kernel, "adaptive");
  r.rule = certified ? "certified" : "sampled";
  Geometry g;
  g.box = detail::sample_box(mechanism, options.box);
  r.box = g.box;
  g.base = options.base_cells;
  g.depth = options.depth;
  r.effective_cells = options.base_cells << options.depth;
  const std::size_t levels = std::size_t(options.depth) + 1;

  // Level 0: the root grid, classified serially in one batch.
  TaskCounts root;
  root.inside.assign(levels, 0);
  root.evaluated.assign(levels, 0);
  std::vector<Cell> roots;
  roots.reserve(g.base * g.base);
  for (std::uint32_t j = 0; j < g.base; ++j) {
    for (std::uint32_t i = 0; i < g.base; ++i) roots.push_back({i, j});
  }
  std::vector<std::int8_t> state;
  Classifier root_classifier(kernel, certified, g);
  root_classifier.classify(roots, 0, state, root);
  root.evaluated[0] = roots.size();
  std::vector<Cell> straddling;
  for (std::size_t k = 0; k < roots.size(); ++k) {
    if (state[k] == cell_inside) {
      ++root.inside[0];
    } else if (state[k] == cell_outside) {
      ++root.outside;
    } else {
      straddling.push_back(roots[k]);
    }
  }
  if (options.depth == 0) {
    root.undecided = straddling.size();
    if (!straddling.empty()) root.undecided_centre_in = root_classifier.centres_inside(straddling, 0, root);
    straddling.clear();
  }

  // One task per straddling root cell; results summed in task order.
  std::vector<TaskCounts> tasks(straddling.size());
  // Each straddling root cell refines a boundary band of ~2^level cells per
  // level, four children each: ~8 2^depth cell tests per task.
  const std::size_t work = straddling.size() * (std::size_t{8} << std::min(options.depth, 20));
  r.threads = pkmws::detail::threads_for(detail::policy_of(execution), straddling.size(), work);
  pkmws::detail::for_each_block(policy, straddling.size(), work, [&](std::size_t t) {
    TaskCounts& c = tasks[t];
    c.inside.assign(levels, 0);
    c.evaluated.assign(levels, 0);
    Classifier classifier(kernel, certified, g);
    refine(classifier, {straddling[t]}, 0, g, c);
  });
  TaskCounts total = root;
  for (const TaskCounts& c : tasks) {
    for (std::size_t l = 0; l < levels; ++l) {
      total.inside[l] += c.inside[l];
      total.evaluated[l] += c.evaluated[l];
    }
    total.outside += c.outside;
    total.undecided += c.undecided;
    total.undecided_centre_in += c.undecided_centre_in;
    total.points += c.points;
  }

  double lower = 0.0;
  std::uint64_t leaves = total.outside + total.undecided;
  for (std::size_t l = 0; l < levels; ++l) {
    lower += double(total.inside[l]) * (g.hx(int(l)) * g.hy(int(l)));
    leaves += total.inside[l];
    r.inside += total.inside[l];
  }
  const double leaf_area = g.hx(options.depth) * g.hy(options.depth);
  r.area_lower = lower;
  r.area_upper = lower + double(total.undecided) * leaf_area;
  r.area = lower + 0.5 * double(total.undecided) * leaf_area;
  r.area_centre = lower + double(total.undecided_centre_in) * leaf_area;
  r.bounds_certified = certified;
  r.undecided = total.undecided;
  r.cells_per_level = total.evaluated;
  r.cells = leaves;
  r.points_tested = total.points;
  r.time_ms = detail::ms_since(start);
  detail::set_rate(r);
  return r;
}

}  // namespace pkmws::grid
