// Exact against grid (see grid/compare.hpp).
#include "pkmws/grid/compare.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "grid/common.hpp"
#include "pkmws/geometry/region.hpp"

namespace pkmws::grid {

namespace {

// Conservative envelope of (time, error) runs sorted by time: each run's
// error is replaced by the worst error of it and every slower run, so a
// lucky coarse run (cell-centre errors fluctuate) does not count as reaching
// an accuracy the finer runs lose again. Of equal neighbours the slower one is
// kept. Errors of 0 are clamped to 1e-300 so that logs stay finite.
std::vector<std::pair<double, double>> envelope(std::vector<std::pair<double, double>> runs) {
  std::sort(runs.begin(), runs.end());
  std::vector<std::pair<double, double>> valid;
  for (auto [t, e] : runs) {
    if (t > 0.0 && std::isfinite(t) && std::isfinite(e)) valid.push_back({t, std::max(e, 1e-300)});
  }
  for (std::size_t i = valid.size(); i-- > 1;) {
    valid[i - 1].second = std::max(valid[i - 1].second, valid[i].second);
  }
  std::vector<std::pair<double, double>> out;
  for (std::size_t i = 0; i < valid.size(); ++i) {
    if (i + 1 < valid.size() && valid[i].second == valid[i + 1].second) continue;
    out.push_back(valid[i]);
  }
  return out;
}

// log-log line through a and b evaluated at log-coordinate of the other axis.
double loglog(double x0, double y0, double x1, double y1, double x) {
  const double lx0 = std::log(x0), lx1 = std::log(x1), ly0 = std::log(y0), ly1 = std::log(y1);
  return std::exp(ly0 + (std::log(x) - lx0) * (ly1 - ly0) / (lx1 - lx0));
}

std::string format_ms(double ms) {
  char buf[64];
  if (ms >= 1000.0) {
    std::snprintf(buf, sizeof buf, "%.1f s", ms / 1000.0);
  } else {
    std::snprintf(buf, sizeof buf, "%.3g ms", ms);
  }
  return buf;
}

}  // namespace

TimeAtAccuracy time_at_accuracy(const std::vector<std::pair<double, double>>& runs, double target) {
  TimeAtAccuracy r;
  r.target = target;
  const auto env = envelope(runs);
  if (env.empty()) return r;
  for (std::size_t i = 0; i < env.size(); ++i) {
    if (env[i].second <= target) {
      // Reached at run i; between runs i-1 and i the error falls along a power law.
      r.time_ms = i == 0 ? env[0].first
                         : loglog(env[i - 1].second, env[i - 1].first, env[i].second, env[i].first, target);
      return r;
    }
  }
  if (env.size() < 2) return r;
  const auto& a = env[env.size() - 2];
  const auto& b = env.back();
  r.time_ms = loglog(a.second, a.first, b.second, b.first, target);
  r.extrapolated = true;
  return r;
}

Crossover accuracy_at_time(const std::vector<std::pair<double, double>>& runs, double time_ms) {
  Crossover c;
  const auto env = envelope(runs);
  if (env.size() < 2) {
    c.note = "fewer than two runs";
    return c;
  }
  if (time_ms < env.front().first) {
    c.rel_error = loglog(env[0].first, env[0].second, env[1].first, env[1].second, time_ms);
    c.note = "extrapolated: even the coarsest run is slower than the exact computation";
    return c;
  }
  for (std::size_t i = 1; i < env.size(); ++i) {
    if (time_ms <= env[i].first) {
      c.rel_error = loglog(env[i - 1].first, env[i - 1].second, env[i].first, env[i].second, time_ms);
      c.note = "interpolated";
      return c;
    }
  }
  const auto& a = env[env.size() - 2];
  const auto& b = env.back();
  c.rel_error = loglog(a.first, a.second, b.first, b.second, time_ms);
  c.note = "extrapolated beyond the slowest run";
  return c;
}

CompareResult compare(const mechanisms::Mechanism& mechanism, const CompareOptions& options) {
  if (options.exact_runs < 1) throw std::invalid_argument("compare: exact_runs must be >= 1");
  CompareResult result;
  result.kind = std::string(mechanism.kind());

  // Exact: build the region and integrate its boundary, from scratch each run.
  std::vector<double> times;
  CompareOptions::Reference reference{0.0, 64 * std::numeric_limits<double>::epsilon(), "exact"};
  for (int k = 0; k < options.exact_runs; ++k) {
    const auto start = detail::Clock::now();
    if (options.reference) {
      reference = options.reference();
    } else {
      const geometry::Region region = mechanism.workspace();
      reference.area = region.area();
    }
    times.push_back(detail::ms_since(start));
    result.exact_area = reference.area;
  }
  if (!(result.exact_area > 0.0)) throw std::invalid_argument("compare: the exact workspace is empty");
  std::sort(times.begin(), times.end());
  result.exact_time_ms = times[times.size() / 2];
  result.exact_time_min_ms = times.front();
  result.exact_time_max_ms = times.back();
  {
    CompareRow row;
    row.method = reference.method;  // "exact", or "certified" for a criteria-limited region
    row.area = result.exact_area;
    row.rel_error = 0.0;
    // Exact: the double rounding (as `pkmws area`); certified: its bounds.
    row.guaranteed_rel_error = reference.relative_half_width;
    row.time_ms = result.exact_time_ms;
    row.ratio_to_exact = 1.0;
    result.rows.push_back(row);
  }
  const double exact = result.exact_area;

  // Warm-up, not recorded: the first parallel call starts TBB's worker threads.
  {
    CartesianOptions warm;
    warm.cells_x = warm.cells_y = 600;
    (void)cartesian(mechanism, warm, options.execution);
  }

  // Uniform Cartesian grid along the ladder.
  for (const std::size_t n : options.ladder) {
    CartesianOptions co;
    co.cells_x = co.cells_y = n;
    co.certified_bounds = options.certified_bounds;
    const CartesianResult r = cartesian(mechanism, co, options.execution);
    result.threads = std::max(result.threads, r.threads);
    result.isa = r.isa;
    CompareRow row;
    row.method = "cartesian";
    row.cells_per_side = n;
    row.points = r.points_tested;
    row.area = r.area;
    row.rel_error = std::abs(r.area - exact) / exact;
    row.time_ms = r.time_ms - r.bounds_time_ms;
    row.points_per_second = r.points_per_second;
    if (r.area_lower && r.area_upper && r.bounds_certified) {
      row.guaranteed_rel_error = std::max(r.area - *r.area_lower, *r.area_upper - r.area) / exact;
      row.time_certified_ms = r.time_ms;
    }
    row.ratio_to_exact = row.time_ms / result.exact_time_ms;
    result.rows.push_back(row);
    if (r.time_ms > options.time_budget_ms && n != options.ladder.back()) {
      result.notes.push_back("cartesian ladder stopped after " + std::to_string(n) + "^2 cells: that step took " +
                             format_ms(r.time_ms) + " > the " + format_ms(options.time_budget_ms) + " budget");
      break;
    }
  }

  // Adaptive quadtree.
  for (const int depth : options.depths) {
    AdaptiveOptions ao;
    ao.base_cells = options.adaptive_base;
    ao.depth = depth;
    const AdaptiveResult r = adaptive(mechanism, ao, options.execution);
    CompareRow row;
    row.method = "adaptive";
    row.depth = depth;
    row.cells_per_side = r.effective_cells;
    row.points = r.points_tested;
    row.area = r.area;
    row.rel_error = std::abs(r.area - exact) / exact;
    row.time_ms = r.time_ms;
    row.points_per_second = r.points_per_second;
    if (r.bounds_certified) {
      row.guaranteed_rel_error = 0.5 * (*r.area_upper - *r.area_lower) / exact;
      row.time_certified_ms = r.time_ms;
    }
    row.ratio_to_exact = row.time_ms / result.exact_time_ms;
    result.rows.push_back(row);
    if (r.time_ms > options.time_budget_ms && depth != options.depths.back()) {
      result.notes.push_back("adaptive depths stopped after depth " + std::to_string(depth) + ": that step took " +
                             format_ms(r.time_ms) + " > the " + format_ms(options.time_budget_ms) + " budget");
      break;
    }
  }

  // Time to reach given accuracies, and accuracy reached in the exact time.
  for (const std::string method : {"cartesian", "adaptive"}) {
    for (const std::string accuracy : {"observed", "guaranteed"}) {
      std::vector<std::pair<double, double>> runs;
      for (const CompareRow& row : result.rows) {
        if (row.method != method) continue;
        if (accuracy == "observed") {
          runs.push_back({row.time_ms, row.rel_error});
        } else if (row.guaranteed_rel_error && row.time_certified_ms) {
          runs.push_back({*row.time_certified_ms, *row.guaranteed_rel_error});
        }
      }
      if (runs.empty()) continue;
      for (const double target : {1e-3, 1e-4, 1e-5, 1e-6}) {
        TimeAtAccuracy t = time_at_accuracy(runs, target);
        t.method = method;
        t.accuracy = accuracy;
        if (t.time_ms) t.ratio_to_exact = *t.time_ms / result.exact_time_ms;
        result.at_accuracy.push_back(t);
      }
      Crossover c = accuracy_at_time(runs, result.exact_time_ms);
      c.method = method;
      c.accuracy = accuracy;
      result.crossovers.push_back(c);
    }
  }
  return result;
}

}  // namespace pkmws::grid
