#include "pkmws/design/optimize.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <nlopt.hpp>
#include <sstream>

#include <nlohmann/json.hpp>

#include "design/spec_reading.hpp"
#include "io/json_reader.hpp"
#include "pkmws/io/mechanism_file.hpp"
#include "pkmws/io/parameters.hpp"

namespace pkmws::design {

namespace {

using nlohmann::json;
using io::InputError;
using io::detail::JsonReader;

double elapsed_ms(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

std::string join(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& i : items) out += (out.empty() ? "" : ", ") + i;
  return out;
}

std::string format_weight(double w) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.12g", w);
  return buf;
}

// Which columns need what from the base file.
std::string requirement(const std::string& column) {
  if (column.rfind("limited_", 0) == 0) return "criteria";
  if (column.rfind("real_", 0) == 0) return "bodies";
  return "";
}

// An objective or constraint column: a parameter name or a metric column.
// Returns the parameter index, or adds the column's metric to the spec.
std::optional<std::size_t> resolve_column(OptimizeSpec& spec, const std::string& column, const std::string& where,
                                          const io::MechanismFile& base) {
  for (std::size_t k = 0; k < spec.sweep.parameters.size(); ++k) {
    if (spec.sweep.parameters[k].name == column) return k;
  }
  const std::string metric = metric_of_column(column);
  if (metric.empty()) {
    std::vector<std::string> names;
    for (const auto& p : spec.sweep.parameters) names.push_back(p.name);
    throw InputError(where + ": '" + column + "' is neither a parameter (" + join(names) +
                     ") nor a metric column (" + join(all_metric_columns()) + ")");
  }
  const std::string needs = requirement(column);
  if (needs == "criteria" && !base.criteria.any()) {
    throw InputError(where + ": '" + column + "' needs a base file with criteria limits");
  }
  if (needs == "bodies" && !base.bodies) throw InputError(where + ": '" + column + "' needs a base file with bodies");
  if (std::find(spec.sweep.metrics.begin(), spec.sweep.metrics.end(), metric) == spec.sweep.metrics.end()) {
    spec.sweep.metrics.push_back(metric);
  }
  return std::nullopt;
}

OptimizeSpec parse_document(const json& doc, const std::filesystem::path& dir) {
  JsonReader r(doc, "");
  r.declare_fields({"base", "parameters", "objective", "constraints", "task", "global", "local", "max_evaluations",
                    "global_evaluations", "seed", "xtol_rel", "ftol_rel", "max_time", "penalty",
                    "rectangle_precision", "criteria_tolerance", "interference_depth", "gci_cells"});
  OptimizeSpec spec;
  spec.sweep.sampling = SweepSpec::Sampling::sobol;  // continuous ranges; designs come from the optimiser
  json base_doc = reading::read_base(r, dir, spec.sweep);
  const io::MechanismFile base = io::load_mechanism(spec.sweep.base_file);

  const json& params = r.raw("parameters");
  if (!params.is_array() || params.empty()) r.fail("parameters", "must be a non-empty array");
  const auto& columns = all_metric_columns();
  for (std::size_t i = 0; i < params.size(); ++i) {
    const std::string where = io::detail::item("parameters", i);
    if (!params[i].is_object()) throw InputError(where + ": must be an object");
    JsonReader p(params[i], where);
    p.declare_fields({"name", "path", "from", "to", "start"});
    SweepParameter sp;
    reading::read_paths(p, base_doc, sp);
    if (std::find(columns.begin(), columns.end(), sp.name) != columns.end() || sp.name == "index" ||
        sp.name == "status" || sp.name == "reason" || sp.name == "time_ms") {
      p.fail("name", "'" + sp.name + "' is a column of the results; choose another name");
    }
    for (const auto& other : spec.sweep.parameters) {
      if (other.name == sp.name) p.fail("name", "'" + sp.name + "' names two parameters");
    }
    sp.from = p.number("from");
    sp.to = p.number("to");
    if (!(sp.to > sp.from)) p.fail("to", "must be greater than from");
    std::optional<double> start = p.optional_number("start");
    if (start && (*start < sp.from || *start > sp.to)) p.fail("start", "must lie within [from, to]");
    p.finish();
    spec.sweep.parameters.push_back(std::move(sp));
    spec.start.push_back(start);
  }

  // The objective: {"maximize": X} or {"minimize": X}, X a column, a
  // parameter, or {"parameter": weight, ...} (a weighted sum: machine size).
  {
    JsonReader o = r.object("objective");
    o.declare_fields({"maximize", "minimize"});
    if (o.has("maximize") == o.has("minimize")) {
      o.fail("maximize", "give exactly one of objective.maximize and objective.minimize");
    }
    const std::string key = o.has("maximize") ? "maximize" : "minimize";
    spec.objective.maximize = key == "maximize";
    const json& target = o.raw(key);
    const std::string where = o.field(key);
    if (target.is_string()) {
      spec.objective.column = target.get<std::string>();
      if (auto k = resolve_column(spec, spec.objective.column, where, base)) spec.objective.weights = {{*k, 1.0}};
      spec.objective.text = key + " " + spec.objective.column;
    } else if (target.is_object() && !target.empty()) {
      std::string text;
      for (auto it = target.begin(); it != target.end(); ++it) {
        const std::string term = where + "." + it.key();
        std::optional<std::size_t> k;
        for (std::size_t j = 0; j < spec.sweep.parameters.size(); ++j) {
          if (spec.sweep.parameters[j].name == it.key()) k = j;
        }
        if (!k) {
          std::vector<std::string> names;
          for (const auto& p : spec.sweep.parameters) names.push_back(p.name);
          throw InputError(term + ": not a parameter (a weighted sum takes parameters: " + join(names) + ")");
        }
        const double w = JsonReader::as_number(it.value(), term);
        if (w == 0) throw InputError(term + ": the weight must not be zero");
        spec.objective.weights.emplace_back(*k, w);
        text += (text.empty() ? "" : " + ") + format_weight(w) + " " + it.key();
      }
      spec.objective.text = key + " " + text;
    } else {
      throw InputError(where + ": must be a metric column, a parameter, or an object {parameter: weight}");
    }
  }

  if (r.has("constraints")) {
    const json& c = r.raw("constraints");
    if (!c.is_array()) r.fail("constraints", "must be an array of strings like \"task_margin >= 5\"");
    for (std::size_t k = 0; k < c.size(); ++k) {
      const std::string where = io::detail::item("constraints", k);
      if (!c[k].is_string()) throw InputError(where + ": must be a string like \"task_margin >= 5\"");
      Constraint con = parse_constraint(c[k].get<std::string>(), where);
      resolve_column(spec, con.column, where, base);
      spec.constraints.push_back(std::move(con));
    }
  }
  // Metrics in the sweep's column order.
  std::vector<std::string> ordered;
  for (const auto& m : metric_names()) {
    if (std::find(spec.sweep.metrics.begin(), spec.sweep.metrics.end(), m) != spec.sweep.metrics.end()) {
      ordered.push_back(m);
    }
  }
  spec.sweep.metrics = ordered;

  reading::read_task(r, spec.sweep);
  for (const char* m : {"task_fit", "task_fit_limited", "task_fit_real"}) {
    const bool wants = std::find(spec.sweep.metrics.begin(), spec.sweep.metrics.end(), m) != spec.sweep.metrics.end();
    if (wants && spec.sweep.task.empty()) r.fail("task", std::string("is required by the metric ") + m + "'s columns");
  }
  if (r.has("global")) spec.global = r.one_of("global", {"direct_l", "crs2_lm", "none"});
  if (r.has("local")) spec.local = r.one_of("local", {"cobyla", "bobyqa", "none"});
  if (spec.global == "none" && spec.local == "none") r.fail("local", "global and local are both none: nothing searches");
  if (spec.local == "bobyqa" && spec.sweep.parameters.size() < 2) {
    r.fail("local", "bobyqa needs at least 2 parameters (use cobyla)");
  }
  if (r.has("max_evaluations")) {
    spec.max_evaluations = r.integer("max_evaluations");
    if (spec.max_evaluations < 1 || spec.max_evaluations > 1000000) r.fail("max_evaluations", "must be 1 to 1000000");
  }
  if (r.has("global_evaluations")) {
    spec.global_evaluations = r.integer("global_evaluations");
    if (spec.global_evaluations < 0 || spec.global_evaluations > spec.max_evaluations) {
      r.fail("global_evaluations", "must be 0 to max_evaluations");
    }
  }
  if (r.has("seed")) {
    const int s = r.integer("seed");
    if (s < 0) r.fail("seed", "must be a non-negative integer");
    spec.seed = static_cast<unsigned>(s);
  }
  if (auto v = r.optional_positive("xtol_rel")) spec.xtol_rel = *v;
  if (auto v = r.optional_positive("ftol_rel")) spec.ftol_rel = *v;
  if (auto v = r.optional_positive("max_time")) spec.max_time = *v;
  if (auto v = r.optional_positive("penalty")) spec.penalty = *v;
  reading::read_accuracy(r, spec.sweep);
  r.finish();
  return spec;
}

// ------------------------------------------------------------------ search

const char* result_name(nlopt::result r) {
  switch (r) {
    case nlopt::FAILURE: return "FAILURE";
    case nlopt::INVALID_ARGS: return "INVALID_ARGS";
    case nlopt::OUT_OF_MEMORY: return "OUT_OF_MEMORY";
    case nlopt::ROUNDOFF_LIMITED: return "ROUNDOFF_LIMITED";
    case nlopt::FORCED_STOP: return "FORCED_STOP";
    case nlopt::SUCCESS: return "SUCCESS";
    case nlopt::STOPVAL_REACHED: return "STOPVAL_REACHED";
    case nlopt::FTOL_REACHED: return "FTOL_REACHED";
    case nlopt::XTOL_REACHED: return "XTOL_REACHED";
    case nlopt::MAXEVAL_REACHED: return "MAXEVAL_REACHED";
    case nlopt::MAXTIME_REACHED: return "MAXTIME_REACHED";
    default: return "UNKNOWN";
  }
}

// The penalised objective's values for designs that are not ok (invalid,
// empty, failed) and the cap of the violation term: a design that is not ok
// is worse than any design that is.
constexpr double violation_cap = 1e3;

class Search {
 public:
  Search(const OptimizeSpec& spec, const std::function<void(const DesignRow&)>& evaluated)
      : spec_(spec), evaluated_(evaluated), gscale_(spec.constraints.size(), 0.0) {}

  // The design at x, evaluated once (NLopt asks for the objective and the
  // constraints of one point separately).
  const DesignRow& at(const double* x) {
    const std::size_t n = spec_.sweep.parameters.size();
    std::vector<double> v(x, x + n);
    for (std::size_t k = 0; k < n; ++k) {
      v[k] = std::clamp(v[k], spec_.sweep.parameters[k].from, spec_.sweep.parameters[k].to);
    }
    if (!history_.empty() && history_.back().values == v) return history_.back();
    history_.push_back(evaluate_design(spec_.sweep, history_.size(), v));
    const DesignRow& row = history_.back();
    if (row.status == "ok" && !scaled_) set_scales(row);
    if (evaluated_) evaluated_(row);
    return row;
  }

  // Scaled objective (minimised) and scaled constraint violations.
  std::optional<double> scaled_objective(const DesignRow& row) const {
    const auto f = objective_value(spec_, row);
    if (!f) return std::nullopt;
    return (spec_.objective.maximize ? -*f : *f) / fscale_;
  }
  // c_j <= 0 where the constraint holds.
  std::vector<double> scaled_constraints(const DesignRow& row) const {
    const auto values = constraint_values(spec_, row);
    std::vector<double> c(values.size());
    for (std::size_t j = 0; j < values.size(); ++j) {
      c[j] = values[j].margin ? std::min(-*values[j].margin / gscale_[j], violation_cap) : violation_cap;
    }
    return c;
  }
  double wall() const { return spec_.penalty * violation_cap * 10.0; }
  double penalised(const DesignRow& row) const {
    const auto f = scaled_objective(row);
    if (row.status != "ok" || !f) return wall();
    double v = 0.0;
    for (double c : scaled_constraints(row)) v += std::max(0.0, c);
    return *f + spec_.penalty * std::min(v, violation_cap);
  }

  std::vector<DesignRow>& history() { return history_; }

 private:
  // Scales fixed at the first ok design: the objective's magnitude there,
  // each constraint's bound (or its value there when the bound is 0).
  void set_scales(const DesignRow& row) {
    scaled_ = true;
    const auto f = objective_value(spec_, row);
    fscale_ = f && std::abs(*f) > 0 ? std::abs(*f) : 1.0;
    const auto values = constraint_values(spec_, row);
    for (std::size_t j = 0; j < gscale_.size(); ++j) {
      const double b = std::abs(spec_.constraints[j].bound);
      const double v = values[j].value ? std::abs(*values[j].value) : 0.0;
      gscale_[j] = b > 0 ? b : v > 0 ? v : 1.0;
    }
  }

  const OptimizeSpec& spec_;
  const std::function<void(const DesignRow&)>& evaluated_;
  std::vector<DesignRow> history_;
  bool scaled_ = false;
  double fscale_ = 1.0;
  std::vector<double> gscale_;
};

// Runs `opt`, turning NLopt's exceptions for "stopped early" into results.
nlopt::result run(nlopt::opt& opt, std::vector<double>& x) {
  double f = 0.0;
  try {
    return opt.optimize(x, f);
  } catch (const nlopt::roundoff_limited&) {
    return nlopt::ROUNDOFF_LIMITED;
  } catch (const nlopt::forced_stop&) {
    return nlopt::FORCED_STOP;
  }
}

bool feasible(const OptimizeSpec& spec, const DesignRow& row) {
  if (row.status != "ok" || !objective_value(spec, row)) return false;
  for (const auto& c : constraint_values(spec, row)) {
    if (!c.satisfied) return false;
  }
  return true;
}

}  // namespace

Constraint parse_constraint(const std::string& text, const std::string& where) {
  const auto ge = text.find(">="), le = text.find("<=");
  const auto bad = [&]() {
    return InputError(where + ": expected 'COLUMN >= NUMBER' or 'COLUMN <= NUMBER', got '" + text + "'");
  };
  if ((ge == std::string::npos) == (le == std::string::npos)) throw bad();
  const auto op = ge != std::string::npos ? ge : le;
  Constraint c;
  c.text = text;
  c.at_least = ge != std::string::npos;
  c.column = trim(text.substr(0, op));
  const std::string rhs = trim(text.substr(op + 2));
  if (c.column.empty() || rhs.empty() || c.column.find_first_of("<>= \t") != std::string::npos) throw bad();
  char* end = nullptr;
  c.bound = std::strtod(rhs.c_str(), &end);
  if (end != rhs.c_str() + rhs.size() || !std::isfinite(c.bound) || rhs.find_first_of("xXnN") != std::string::npos) {
    throw bad();
  }
  return c;
}

OptimizeSpec load_optimize(const std::filesystem::path& file) {
  return parse_document(reading::read_spec_file(file, "optimisation"), file.parent_path());
}

OptimizeSpec parse_optimize(const std::string& text, const std::filesystem::path& dir, const std::string& name) {
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::exception& e) {
    throw InputError(name + ": not valid JSON (" + std::string(e.what()) + ")");
  }
  if (!doc.is_object()) throw InputError(name + ": an optimisation file is a JSON object");
  return parse_document(doc, dir);
}

namespace {

// The value of a column at a row: a parameter's value or a metric column.
std::optional<double> column_value(const OptimizeSpec& spec, const DesignRow& row, const std::string& column) {
  for (std::size_t k = 0; k < spec.sweep.parameters.size(); ++k) {
    if (spec.sweep.parameters[k].name == column) return row.values[k];
  }
  if (row.status != "ok") return std::nullopt;
  const auto cols = metric_columns(spec.sweep);
  for (std::size_t k = 0; k < cols.size(); ++k) {
    if (cols[k] == column) return row.metrics[k];
  }
  return std::nullopt;
}

}  // namespace

std::optional<double> objective_value(const OptimizeSpec& spec, const DesignRow& row) {
  if (row.status != "ok") return std::nullopt;
  if (spec.objective.weights.empty()) return column_value(spec, row, spec.objective.column);
  double f = 0.0;
  for (const auto& [k, w] : spec.objective.weights) f += w * row.values[k];
  return f;
}

std::vector<ConstraintValue> constraint_values(const OptimizeSpec& spec, const DesignRow& row) {
  std::vector<ConstraintValue> out;
  for (const Constraint& c : spec.constraints) {
    ConstraintValue v;
    v.text = c.text;
    // A parameter's constraint needs a design that is ok too: it is part of a feasible design.
    if (row.status == "ok") v.value = column_value(spec, row, c.column);
    if (v.value) {
      v.margin = c.at_least ? *v.value - c.bound : c.bound - *v.value;
      v.satisfied = *v.margin >= 0;
    }
    out.push_back(std::move(v));
  }
  return out;
}

OptimizeResult optimize(const OptimizeSpec& spec, const std::function<void(const DesignRow&)>& evaluated) {
  const auto start = std::chrono::steady_clock::now();
  const std::size_t n = spec.sweep.parameters.size();
  Search search(spec, evaluated);
  OptimizeResult result;
  std::vector<double> lower(n), upper(n), x(n);
  for (std::size_t k = 0; k < n; ++k) {
    const auto& p = spec.sweep.parameters[k];
    lower[k] = p.from;
    upper[k] = p.to;
    x[k] = spec.start[k].value_or(0.5 * (p.from + p.to));
  }
  const std::size_t budget = static_cast<std::size_t>(spec.max_evaluations);
  std::size_t global_budget = 0;
  if (spec.global != "none") {
    global_budget = spec.local == "none" ? budget
                    : spec.global_evaluations >= 0 ? static_cast<std::size_t>(spec.global_evaluations)
                                                   : budget / 2;
  }
  const auto remaining_time = [&]() {
    return spec.max_time > 0 ? std::max(1e-3, spec.max_time - elapsed_ms(start) / 1000.0) : 0.0;
  };
  nlopt::srand(spec.seed);

  nlopt::result last = nlopt::FAILURE;
  bool out_of_time = false;
  // Global phase: the penalised objective over the box.
  if (global_budget > 0) {
    const auto t0 = std::chrono::steady_clock::now();
    const std::size_t before = search.history().size();
    nlopt::opt opt(spec.global == "crs2_lm" ? nlopt::GN_CRS2_LM : nlopt::GN_DIRECT_L, static_cast<unsigned>(n));
    opt.set_lower_bounds(lower);
    opt.set_upper_bounds(upper);
    opt.set_maxeval(static_cast<int>(global_budget));
    if (spec.max_time > 0) opt.set_maxtime(remaining_time());
    auto f = [](unsigned, const double* xs, double*, void* data) -> double {
      auto* s = static_cast<Search*>(data);
      return s->penalised(s->at(xs));
    };
    opt.set_min_objective(f, &search);
    std::vector<double> xg = x;
    last = run(opt, xg);
    out_of_time = last == nlopt::MAXTIME_REACHED;
    result.phases.push_back({spec.global == "crs2_lm" ? "GN_CRS2_LM" : "GN_DIRECT_L", search.history().size() - before,
                             result_name(last), elapsed_ms(t0)});
    // The local phase starts at the best design of the penalised objective.
    std::size_t best = before;
    for (std::size_t i = before; i < search.history().size(); ++i) {
      if (search.penalised(search.history()[i]) < search.penalised(search.history()[best])) best = i;
    }
    if (best < search.history().size()) x = search.history()[best].values;
  }
  // Local phase.
  const std::size_t used = search.history().size();
  if (spec.local != "none" && used < budget && !out_of_time) {
    const auto t0 = std::chrono::steady_clock::now();
    const std::size_t before = used;
    const bool cobyla = spec.local == "cobyla";
    nlopt::opt opt(cobyla ? nlopt::LN_COBYLA : nlopt::LN_BOBYQA, static_cast<unsigned>(n));
    opt.set_lower_bounds(lower);
    opt.set_upper_bounds(upper);
    opt.set_maxeval(static_cast<int>(budget - used));
    opt.set_xtol_rel(spec.xtol_rel);
    opt.set_ftol_rel(spec.ftol_rel);
    if (spec.max_time > 0) opt.set_maxtime(remaining_time());
    // The first step: a tenth of each range from a given start, less after a
    // global phase (about the spacing of its samples).
    const double fraction =
        global_budget > 0
            ? std::clamp(0.5 / std::pow(static_cast<double>(global_budget), 1.0 / static_cast<double>(n)), 0.01, 0.1)
            : 0.1;
    std::vector<double> step(n);
    for (std::size_t k = 0; k < n; ++k) step[k] = fraction * (upper[k] - lower[k]);
    opt.set_initial_step(step);
    if (cobyla) {
      auto f = [](unsigned, const double* xs, double*, void* data) -> double {
        auto* s = static_cast<Search*>(data);
        const DesignRow& row = s->at(xs);
        const auto v = s->scaled_objective(row);
        return row.status == "ok" && v ? *v : s->wall();
      };
      opt.set_min_objective(f, &search);
      if (!spec.constraints.empty()) {
        auto c = [](unsigned m, double* out, unsigned, const double* xs, double*, void* data) {
          auto* s = static_cast<Search*>(data);
          const auto cs = s->scaled_constraints(s->at(xs));
          for (unsigned j = 0; j < m; ++j) out[j] = cs[j];
        };
        opt.add_inequality_mconstraint(c, &search, std::vector<double>(spec.constraints.size(), 0.0));
      }
    } else {
      auto f = [](unsigned, const double* xs, double*, void* data) -> double {
        auto* s = static_cast<Search*>(data);
        return s->penalised(s->at(xs));
      };
      opt.set_min_objective(f, &search);
    }
    last = run(opt, x);
    result.phases.push_back({cobyla ? "LN_COBYLA" : "LN_BOBYQA", search.history().size() - before, result_name(last),
                             elapsed_ms(t0)});
  }

  // The optimum: the best feasible design evaluated; without one, the design
  // closest to feasibility (the least scaled violation; then the earliest).
  const auto& h = search.history();
  std::optional<std::size_t> best;
  for (std::size_t i = 0; i < h.size(); ++i) {
    if (!feasible(spec, h[i])) continue;
    ++result.feasible_evaluations;
    const double f = *objective_value(spec, h[i]);
    if (!best || (spec.objective.maximize ? f > *objective_value(spec, h[*best]) : f < *objective_value(spec, h[*best]))) {
      best = i;
    }
  }
  result.feasible = best.has_value();
  if (!best && !h.empty()) {
    best = 0;
    for (std::size_t i = 1; i < h.size(); ++i) {
      if (search.penalised(h[i]) < search.penalised(h[*best])) best = i;
    }
  }
  if (best) {
    result.best = h[*best];
    result.objective = objective_value(spec, result.best);
    result.constraints = constraint_values(spec, result.best);
  }
  const bool converged = last == nlopt::SUCCESS || last == nlopt::XTOL_REACHED || last == nlopt::FTOL_REACHED ||
                         last == nlopt::STOPVAL_REACHED || last == nlopt::ROUNDOFF_LIMITED;
  result.status = !result.feasible ? "infeasible" : converged ? "converged" : "budget_exhausted";
  result.evaluations = h.size();
  result.history = std::move(search.history());
  result.time_ms = elapsed_ms(start);
  return result;
}

std::string optimize_report(const OptimizeSpec& spec, const OptimizeResult& result, bool timing) {
  const std::string not_ok = "the design is " + result.best.status + (result.best.reason.empty() ? "" : ": " + result.best.reason);
  json params = json::array();
  for (std::size_t k = 0; k < spec.sweep.parameters.size(); ++k) {
    const auto& p = spec.sweep.parameters[k];
    params.push_back({{"name", p.name}, {"paths", p.paths}, {"from", p.from}, {"to", p.to},
                      {"value", k < result.best.values.size() ? result.best.values[k] : p.from}});
  }
  json constraints = json::array();
  for (std::size_t j = 0; j < spec.constraints.size(); ++j) {
    const auto& c = spec.constraints[j];
    const ConstraintValue* v = j < result.constraints.size() ? &result.constraints[j] : nullptr;
    json cj = {{"text", c.text},
               {"column", c.column},
               {"sense", c.at_least ? ">=" : "<="},
               {"bound", c.bound},
               {"value", v && v->value ? json(*v->value) : json(nullptr)},
               {"margin", v && v->margin ? json(*v->margin) : json(nullptr)},
               {"satisfied", v && v->satisfied}};
    if (!(v && v->value)) cj["reason"] = not_ok;
    constraints.push_back(cj);
  }
  json metrics = json::object();
  const auto cols = metric_columns(spec.sweep);
  for (std::size_t k = 0; k < cols.size(); ++k) {
    if (k < result.best.metrics.size() && result.best.metrics[k]) metrics[cols[k]] = *result.best.metrics[k];
  }
  json phases = json::array();
  for (const auto& p : result.phases) {
    json ph = {{"method", p.method}, {"evaluations", p.evaluations}, {"result", p.result}};
    if (timing) ph["time_ms"] = p.time_ms;
    phases.push_back(ph);
  }
  json objective = {{"sense", spec.objective.maximize ? "maximize" : "minimize"},
                    {"text", spec.objective.text},
                    {"value", result.objective ? json(*result.objective) : json(nullptr)}};
  if (!result.objective) objective["value_reason"] = not_ok;
  json j = {{"base", spec.sweep.base_file.string()},
            {"status", result.status},
            {"feasible", result.feasible},
            {"objective", objective},
            {"parameters", params},
            {"constraints", constraints},
            {"design", {{"status", result.best.status}, {"reason", result.best.reason}}},
            {"metrics", metrics},
            {"evaluations", result.evaluations},
            {"feasible_evaluations", result.feasible_evaluations},
            {"phases", phases},
            {"seed", spec.seed},
            {"document", reading::design_document(spec.sweep, result.best.values)}};
  if (timing) j["time_ms"] = result.time_ms;
  return j.dump(1);
}

std::string design_text(const OptimizeSpec& spec, const std::vector<double>& values) {
  return reading::design_document(spec.sweep, values).dump(2) + "\n";
}

}  // namespace pkmws::design
