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

struct Geometry {
  Box box;
  std::size_t base = 0;  // root cells per side
  int depth = 0;
  double hx(int level) const { return box.width() / (double(base) * std::ldexp(1.0, level)); }
  double hy(int level) const { return box.height() / (double(base) * std::ldexp(1.0, level)); }
};

// Cells of one level as their centres (structure of arrays, so the kernel and
// the child generation vectorise). A child's centre is its parent's plus or
// minus a quarter cell: exact in binary floating point up to the last bits,
// and the certified radius carries a relative margin for that.
struct Cells {
  std::vector<double> x, y;
  std::size_t size() const { return x.size(); }
  void resize(std::size_t n) {
    x.resize(n);
    y.resize(n);
  }
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

// Buffers reused across levels, tasks and calls (one set per thread): a
// fresh multi-megabyte vector per task costs page faults that cost more than
// the membership tests.
struct Scratch {
  std::vector<double> xs, ys;
  std::vector<std::uint8_t> mask;
  std::vector<std::int8_t> state;
  Cells cells, children;
};

Scratch& thread_scratch() {
  thread_local Scratch scratch;
  return scratch;
}

class Classifier {
 public:
  Classifier(const MembershipKernel& kernel, bool certified, const Geometry& g, Scratch& scratch)
      : kernel_(kernel), certified_(certified), g_(g), xs_(scratch.xs), ys_(scratch.ys), mask_(scratch.mask) {}

  // state[k] for the cells (centres) at `level`.
  void classify(const Cells& cells, int level, std::vector<std::int8_t>& state, TaskCounts& counts) {
    const std::size_t n = cells.size();
    state.resize(n);
    const double hx = g_.hx(level), hy = g_.hy(level);
    if (certified_) {
      const double radius = 0.5 * std::hypot(hx, hy) * (1.0 + 1e-12);
      kernel_.classify(cells.x.data(), cells.y.data(), n, radius, state.data());
      counts.points += n;
      return;
    }
    // Centre and four corners per cell.
    xs_.resize(5 * n);
    ys_.resize(5 * n);
    mask_.resize(5 * n);
    const double ax = 0.5 * hx, ay = 0.5 * hy;
    for (std::size_t k = 0; k < n; ++k) {
      const double xc = cells.x[k], yc = cells.y[k];
      const double px[5] = {xc, xc - ax, xc + ax, xc - ax, xc + ax};
      const double py[5] = {yc, yc - ay, yc - ay, yc + ay, yc + ay};
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

  // Centre test of leaves.
  std::uint64_t centres_inside(const Cells& cells, TaskCounts& counts) {
    const std::size_t n = cells.size();
    mask_.resize(n);
    kernel_.points(cells.x.data(), cells.y.data(), n, mask_.data());
    counts.points += n;
    std::uint64_t in = 0;
    for (std::size_t k = 0; k < n; ++k) in += mask_[k];
    return in;
  }

 private:
  const MembershipKernel& kernel_;
  bool certified_;
  const Geometry& g_;
  std::vector<double>& xs_;
  std::vector<double>& ys_;
  std::vector<std::uint8_t>& mask_;
};

// Refines one straddling root cell (centre x, y) down to g.depth.
void refine(Classifier& classifier, Scratch& scratch, double root_x, double root_y, const Geometry& g,
            TaskCounts& counts) {
  std::vector<std::int8_t>& state = scratch.state;
  Cells& cells = scratch.cells;
  Cells& children = scratch.children;
  cells.x.assign(1, root_x);
  cells.y.assign(1, root_y);
  int level = 0;
  while (level < g.depth && cells.size() > 0) {
    const std::size_t n = cells.size();
    ++level;
    const double qx = 0.5 * g.hx(level), qy = 0.5 * g.hy(level);  // parent centre to child centre
    children.resize(4 * n);
    for (std::size_t k = 0; k < n; ++k) {
      const double x = cells.x[k], y = cells.y[k];
      children.x[4 * k + 0] = x - qx;
      children.x[4 * k + 1] = x + qx;
      children.x[4 * k + 2] = x - qx;
      children.x[4 * k + 3] = x + qx;
      children.y[4 * k + 0] = y - qy;
      children.y[4 * k + 1] = y - qy;
      children.y[4 * k + 2] = y + qy;
      children.y[4 * k + 3] = y + qy;
    }
    classifier.classify(children, level, state, counts);
    counts.evaluated[level] += 4 * n;
    // Branch-free compaction of the undecided children into `cells`.
    cells.resize(4 * n);
    std::size_t kept = 0;
    std::uint64_t in = 0, out = 0;
    for (std::size_t k = 0; k < 4 * n; ++k) {
      cells.x[kept] = children.x[k];
      cells.y[kept] = children.y[k];
      kept += std::size_t(state[k] == cell_undecided);
      in += std::uint64_t(state[k] == cell_inside);
      out += std::uint64_t(state[k] == cell_outside);
    }
    cells.resize(kept);
    counts.inside[std::size_t(level)] += in;
    counts.outside += out;
  }
  counts.undecided += cells.size();
  if (cells.size() > 0) counts.undecided_centre_in += classifier.centres_inside(cells, counts);
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
  Cells roots;
  roots.resize(g.base * g.base);
  for (std::size_t j = 0; j < g.base; ++j) {
    for (std::size_t i = 0; i < g.base; ++i) {
      roots.x[j * g.base + i] = g.box.min.x + (double(i) + 0.5) * g.hx(0);
      roots.y[j * g.base + i] = g.box.min.y + (double(j) + 0.5) * g.hy(0);
    }
  }
  Scratch root_scratch;
  std::vector<std::int8_t> state;
  Classifier root_classifier(kernel, certified, g, root_scratch);
  root_classifier.classify(roots, 0, state, root);
  root.evaluated[0] = roots.size();
  Cells straddling;
  for (std::size_t k = 0; k < roots.size(); ++k) {
    if (state[k] == cell_inside) {
      ++root.inside[0];
    } else if (state[k] == cell_outside) {
      ++root.outside;
    } else {
      straddling.x.push_back(roots.x[k]);
      straddling.y.push_back(roots.y[k]);
    }
  }
  if (options.depth == 0) {
    root.undecided = straddling.size();
    if (straddling.size() > 0) root.undecided_centre_in = root_classifier.centres_inside(straddling, root);
    straddling.resize(0);
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
    Scratch& scratch = thread_scratch();
    Classifier classifier(kernel, certified, g, scratch);
    refine(classifier, scratch, straddling.x[t], straddling.y[t], g, c);
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
