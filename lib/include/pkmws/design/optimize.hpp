// Design synthesis: the best design of a base mechanism file over continuous
// parameters (field paths, tied paths allowed, each within [from, to]) for an
// objective (a sweep metric column to maximise or minimise, or a weighted sum
// of parameters: the machine's size) subject to constraints on metric columns
// and parameters ("task_margin >= 5"). A global derivative-free method
// (NLopt's DIRECT-L or CRS2, seeded) on a penalised objective, then a local
// one (COBYLA with the constraints, or BOBYQA on the penalised objective).
// Every design is evaluated by the sweep's evaluate_design, so a design the
// loader rejects, or with an empty workspace, is an infeasible point, never
// an error (docs/design_space.md). No NLopt in this header.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "pkmws/design/sweep.hpp"

namespace pkmws::design {

/// What is optimised: a metric column (or a parameter) or a weighted sum of
/// parameters, to maximise or to minimise.
struct Objective {
  bool maximize = true;
  std::string column;                              // a metric column or a parameter name; "" for a sum
  std::vector<std::pair<std::size_t, double>> weights;  // parameter index, weight (the sum's terms)
  std::string text;                                // e.g. "maximize rectangle_area", "minimize 2 rod + 1 stroke"
};

/// A constraint `column >= bound` or `column <= bound` on a metric column or a parameter.
struct Constraint {
  std::string text;      // as written, e.g. "task_margin >= 5"
  std::string column;
  bool at_least = true;  // >= (else <=)
  double bound = 0.0;
};

/// Parses "column >= number" / "column <= number" (spaces optional); throws
/// io::InputError naming `where` otherwise. The column is not checked here.
Constraint parse_constraint(const std::string& text, const std::string& where);

struct OptimizeSpec {
  /// The base file, the parameters (`from`, `to`), the metrics the objective
  /// and the constraints need, the task and the metrics' accuracy.
  SweepSpec sweep;
  std::vector<std::optional<double>> start;  // per parameter (default: the middle of [from, to])
  Objective objective;
  std::vector<Constraint> constraints;
  std::string global = "direct_l";  // "direct_l", "crs2_lm" or "none"
  std::string local = "cobyla";     // "cobyla", "bobyqa" or "none"
  int max_evaluations = 200;        // both phases together
  int global_evaluations = -1;      // the global phase's share (-1: half of max_evaluations)
  unsigned seed = 1;                // NLopt's random numbers (CRS2), so that runs repeat
  double xtol_rel = 1e-6;           // local phase: relative change of the parameters
  double ftol_rel = 1e-10;          // local phase: relative change of the objective
  double max_time = 0.0;            // seconds for both phases (0: no bound)
  double penalty = 100.0;           // weight of the scaled constraint violations
};

/// Reads and validates an optimisation file; throws io::InputError naming the field.
OptimizeSpec load_optimize(const std::filesystem::path& file);
/// The same from a JSON text (`name` in messages; `dir`: where `base` is relative to).
OptimizeSpec parse_optimize(const std::string& text, const std::filesystem::path& dir, const std::string& name);

/// A constraint at a design: its value and margin (>= 0: it holds; the
/// distance to the bound in the column's units).
struct ConstraintValue {
  std::string text;
  std::optional<double> value;   // none: the design is not ok (invalid, empty, failed)
  std::optional<double> margin;
  bool satisfied = false;
};

/// One phase of the search (global or local).
struct PhaseResult {
  std::string method;       // NLopt's name, e.g. "GN_DIRECT_L"
  std::size_t evaluations = 0;
  std::string result;       // NLopt's return code, e.g. "MAXEVAL_REACHED", "XTOL_REACHED"
  double time_ms = 0.0;
};

struct OptimizeResult {
  /// "optimal" (a feasible design; the local phase converged), "stopped" (a
  /// feasible design, but the budget or the time ran out first),
  /// "infeasible" (no evaluated design satisfies every constraint).
  std::string status;
  bool feasible = false;
  DesignRow best;                  // the optimum (or the least infeasible design)
  std::optional<double> objective; // its objective value (none when it is not ok)
  std::vector<ConstraintValue> constraints;  // at the optimum
  std::vector<PhaseResult> phases;
  std::size_t evaluations = 0;
  std::size_t feasible_evaluations = 0;
  double time_ms = 0.0;
  std::vector<DesignRow> history;  // every evaluation, in order (index = evaluation number)
};

/// Runs the search; `evaluated(row)` is called after every evaluation.
OptimizeResult optimize(const OptimizeSpec& spec, const std::function<void(const DesignRow&)>& evaluated = {});

/// The objective value and the constraint values of an evaluated design.
std::optional<double> objective_value(const OptimizeSpec& spec, const DesignRow& row);
std::vector<ConstraintValue> constraint_values(const OptimizeSpec& spec, const DesignRow& row);

/// The mechanism file of a design: the base with the parameters set to `values`.
std::string design_text(const OptimizeSpec& spec, const std::vector<double>& values);

/// The report of `pkmws optimize --json` (docs/schema/optimize.output.schema.json), as JSON text.
std::string optimize_report(const OptimizeSpec& spec, const OptimizeResult& result, bool timing = true);

}  // namespace pkmws::design
