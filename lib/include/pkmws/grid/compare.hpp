// Exact workspace against the grid baseline (`pkmws compare`, docs/benchmarks.md):
// the exact area (Region, Green's theorem) and its median time, then the
// uniform Cartesian grid along a ladder of resolutions and the adaptive
// quadtree at several depths, each with its relative error and time.
//
// Two notions of accuracy are reported, because they differ by orders of
// magnitude:
//  - observed error |estimate - exact| / exact: known only because the exact
//    area is known; it is what the grid delivers, by luck of cancellation;
//  - guaranteed error: what a grid user can state without the exact answer,
//    from the certified cell test (MOMA): max(area - lower, upper - area) / exact.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "pkmws/grid/sampler.hpp"

namespace pkmws::grid {

struct CompareOptions {
  /// Cells per side of the uniform grid (N x N cells over Mechanism::bounds()).
  std::vector<std::size_t> ladder{100, 200, 400, 1000, 2000, 4000, 8000, 16000};
  /// Quadtree depths below a root grid of `adaptive_base` cells per side.
  std::vector<int> depths{2, 4, 6, 8, 10, 12, 14, 16, 18, 20};
  std::size_t adaptive_base = 32;
  /// A sequence (ladder or depths) stops after the first step slower than this.
  double time_budget_ms = 20000.0;
  /// Runs of the exact computation (build + area); the median is reported.
  int exact_runs = 21;
  /// Also run the certified bounds pass on the uniform grid (its own time column).
  bool certified_bounds = true;
  Execution execution;
  /// The reference computation, when it is not Mechanism::workspace() (e.g. a
  /// criteria-limited region: certified level sets). Returns the area and its
  /// guaranteed relative half-width; timed like the exact one.
  struct Reference {
    double area = 0.0;
    double relative_half_width = 0.0;
    std::string method = "certified";
  };
  std::function<Reference()> reference;
};

struct CompareRow {
  std::string method;               // "exact", "cartesian", "adaptive"
  std::size_t cells_per_side = 0;   // cartesian N; adaptive: base * 2^depth
  int depth = -1;                   // adaptive only
  std::uint64_t points = 0;         // membership tests
  double area = 0.0;
  double rel_error = 0.0;           // observed
  std::optional<double> guaranteed_rel_error;  // from certified bounds
  double time_ms = 0.0;             // the estimate
  std::optional<double> time_certified_ms;     // estimate + certified bounds
  double ratio_to_exact = 0.0;      // time_ms / exact median time
  double points_per_second = 0.0;
};

/// Time a method needs for a given accuracy, interpolated log-log between the
/// two runs that bracket it. Each run counts with the worst error of itself
/// and every slower run (a lucky coarse grid does not count as reaching an
/// accuracy that finer grids lose again), so the curve is monotone;
/// `extrapolated` when no run reached it.
struct TimeAtAccuracy {
  std::string method;
  std::string accuracy;             // "observed" or "guaranteed"
  double target = 0.0;              // relative accuracy
  std::optional<double> time_ms;    // nullopt: fewer than two runs
  bool extrapolated = false;
  std::optional<double> ratio_to_exact;  // time_ms / exact time
};

/// Relative error a method reaches in the exact computation's time.
struct Crossover {
  std::string method;
  std::string accuracy;             // "observed" or "guaranteed"
  std::optional<double> rel_error;  // nullopt: not determinable
  std::string note;                 // how it was found ("interpolated", "extrapolated", ...)
};

struct CompareResult {
  std::string kind;                 // mechanism keyword
  double exact_area = 0.0;
  double exact_time_ms = 0.0;       // median
  double exact_time_min_ms = 0.0;
  double exact_time_max_ms = 0.0;
  int threads = 1;
  std::string isa;
  std::vector<CompareRow> rows;
  std::vector<std::string> notes;   // e.g. "cartesian ladder stopped after 8000^2: 23 s > budget"
  std::vector<TimeAtAccuracy> at_accuracy;  // for 1e-3, 1e-4, 1e-5, 1e-6
  std::vector<Crossover> crossovers;
};

CompareResult compare(const mechanisms::Mechanism& mechanism, const CompareOptions& options = {});

/// Interpolation helpers (exposed for tests): points (time_ms, rel_error).
TimeAtAccuracy time_at_accuracy(const std::vector<std::pair<double, double>>& runs, double target);
Crossover accuracy_at_time(const std::vector<std::pair<double, double>>& runs, double time_ms);

}  // namespace pkmws::grid
