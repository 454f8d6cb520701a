// `pkmws optimize` (pkmws/report/optimize.hpp): moved from the command line's
// optimize.cpp, report, files and text unchanged. The report's JSON is the
// design layer's (design::optimize_report, also the Python module's).
#include "pkmws/report/optimize.hpp"

#include "pkmws/design/sweep.hpp"
#include "pkmws/report/common.hpp"
#include "report/text.hpp"

namespace pkmws::report {

namespace {

std::string g(double v) { return detail::format("%.10g", v); }

}  // namespace

OptimizeReport optimize(const std::filesystem::path& spec_file, bool timing) {
  OptimizeReport r;
  r.spec = design::load_optimize(spec_file);
  r.result = design::optimize(r.spec);
  r.timing = timing;
  return r;
}

std::string to_json_text(const OptimizeReport& r) {
  return json_with_null_reasons(design::optimize_report(r.spec, r.result, r.timing));
}

std::string report_file_text(const OptimizeReport& r) {
  return design::optimize_report(r.spec, r.result, r.timing) + "\n";
}

std::string history_csv(const OptimizeReport& r) {
  std::string csv = design::csv_header(r.spec.sweep, r.timing) + "\n";
  for (const auto& row : r.result.history) csv += design::csv_line(row, r.timing) + "\n";
  return csv;
}

std::string design_file_text(const OptimizeReport& r) { return design::design_text(r.spec, r.result.best.values); }

std::string to_text(const OptimizeReport& report) {
  using detail::format;
  const design::OptimizeSpec& spec = report.spec;
  const design::OptimizeResult& r = report.result;
  std::string phases;
  for (const auto& p : r.phases) {
    phases += (phases.empty() ? "" : "; ") + p.method + " " + std::to_string(p.evaluations) + " evaluations (" +
              p.result + ")";
  }
  std::string t = format("optimize: %s over %zu parameter(s): %s\n", spec.objective.text.c_str(),
                         spec.sweep.parameters.size(), phases.c_str());
  t += format("status: %s; %zu evaluations (%zu feasible) in %.3f s, seed %u\n", r.status.c_str(), r.evaluations,
              r.feasible_evaluations, r.time_ms / 1000.0, spec.seed);
  if (!r.feasible) t += "no evaluated design satisfies every constraint; the least infeasible one:\n";
  t += format("%s: %s\n", r.feasible ? "optimum" : "design",
              r.objective ? g(*r.objective).c_str() : ("none (" + r.best.status + ": " + r.best.reason + ")").c_str());
  for (std::size_t k = 0; k < spec.sweep.parameters.size() && k < r.best.values.size(); ++k) {
    t += format("  %s = %s\n", spec.sweep.parameters[k].name.c_str(), g(r.best.values[k]).c_str());
  }
  for (const auto& c : r.constraints) {
    t += format("  %s: %s\n", c.text.c_str(),
                c.value ? (g(*c.value) + " (margin " + g(*c.margin) + (c.satisfied ? ", holds)" : ", violated)")).c_str()
                        : "no value (the design is not ok)");
  }
  return t;
}

}  // namespace pkmws::report
