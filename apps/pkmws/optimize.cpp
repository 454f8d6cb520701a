// pkmws optimize SPEC.json: design synthesis with NLopt (the best design for
// an objective under constraints); pkmws feasible SWEEP.csv --where ...: the
// feasible boxes of parameters of a grid sweep (docs/design_space.md).
// Option parsing and printing only: the work is in lib/src/design.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "cli.hpp"
#include "pkmws/design/feasible.hpp"
#include "pkmws/design/optimize.hpp"

namespace pkmws::cli {

namespace {


void print_summary(const design::OptimizeSpec& spec, const design::OptimizeResult& r) {
  std::string phases;
  for (const auto& p : r.phases) {
    phases += (phases.empty() ? "" : "; ") + p.method + " " + std::to_string(p.evaluations) + " evaluations (" +
              p.result + ")";
  }
  std::printf("optimize: %s over %zu parameter(s): %s\n", spec.objective.text.c_str(), spec.sweep.parameters.size(),
              phases.c_str());
  std::printf("status: %s; %zu evaluations (%zu feasible) in %.3f s, seed %u\n", r.status.c_str(), r.evaluations,
              r.feasible_evaluations, r.time_ms / 1000.0, spec.seed);
  if (!r.feasible) std::printf("no evaluated design satisfies every constraint; the least infeasible one:\n");
  std::printf("%s: %s\n", r.feasible ? "optimum" : "design",
              r.objective ? format_g(*r.objective).c_str() : ("none (" + r.best.status + ": " + r.best.reason + ")").c_str());
  for (std::size_t k = 0; k < spec.sweep.parameters.size() && k < r.best.values.size(); ++k) {
    std::printf("  %s = %s\n", spec.sweep.parameters[k].name.c_str(), format_g(r.best.values[k]).c_str());
  }
  for (const auto& c : r.constraints) {
    std::printf("  %s: %s\n", c.text.c_str(),
                c.value ? (format_g(*c.value) + " (margin " + format_g(*c.margin) + (c.satisfied ? ", holds)" : ", violated)")).c_str()
                        : "no value (the design is not ok)");
  }
}

}  // namespace

void add_optimize(CLI::App& app, std::vector<Command>& commands) {
  auto* sub = app.add_subcommand("optimize", "The best design for an objective under constraints (NLopt)");
  struct Args {
    std::string spec, out, history, design;
    bool json = false, no_timing = false;
  };
  auto a = std::make_shared<Args>();
  sub->add_option("SPEC", a->spec, "Optimisation file (JSON; docs/design_space.md)")->required();
  sub->add_flag("--json", a->json, "Print one JSON object (docs/schema/optimize.output.schema.json)");
  sub->add_option("-o,--out", a->out, "Also write the JSON report to this file");
  sub->add_option("--history", a->history, "Write every evaluation as a row (the sweep's CSV columns)");
  sub->add_option("--design", a->design, "Write the optimum as a mechanism file");
  sub->add_flag("--no-timing", a->no_timing, "Leave out times (outputs compare byte for byte)");
  commands.push_back({sub, [a] {
    check_outputs({a->out, a->history, a->design});
    const design::OptimizeSpec spec = design::load_optimize(a->spec);
    const design::OptimizeResult r = design::optimize(spec);
    const std::string report = design::optimize_report(spec, r, !a->no_timing);
    std::vector<std::pair<std::string, std::string>> files;
    if (!a->out.empty()) files.emplace_back(a->out, report + "\n");
    if (!a->history.empty()) {
      std::string csv = design::csv_header(spec.sweep, !a->no_timing) + "\n";
      for (const auto& row : r.history) csv += design::csv_line(row, !a->no_timing) + "\n";
      files.emplace_back(a->history, csv);
    }
    if (!a->design.empty()) files.emplace_back(a->design, design::design_text(spec, r.best.values));
    write_outputs(files);
    if (a->json) {
      print_json(Json::parse(report));
    } else {
      print_summary(spec, r);
    }
    return 0;
  }});
}

void add_feasible(CLI::App& app, std::vector<Command>& commands) {
  auto* sub = app.add_subcommand("feasible", "The feasible boxes of parameters of a grid sweep (sampled at corners)");
  struct Args {
    std::string csv, out, boxes, svg;
    std::vector<std::string> where;
    bool json = false;
  };
  auto a = std::make_shared<Args>();
  sub->add_option("CSV", a->csv, "Output of pkmws sweep (a grid)")->required();
  sub->add_option("--where", a->where, "A condition COLUMN >= NUMBER or COLUMN <= NUMBER (repeatable)")->required();
  sub->add_flag("--json", a->json, "Print one JSON object (docs/schema/feasible.output.schema.json)");
  sub->add_option("-o,--out", a->out, "Also write the JSON report to this file");
  sub->add_option("--csv", a->boxes, "Write the boxes as CSV");
  sub->add_option("--svg", a->svg, "Draw the boxes over the designs (two parameters)");
  commands.push_back({sub, [a] {
    check_outputs({a->out, a->boxes, a->svg});
    const design::FeasibleSet set = design::feasible_set(a->csv, a->where);
    const std::string report = design::feasible_report(set, a->csv);
    std::vector<std::pair<std::string, std::string>> files;
    if (!a->out.empty()) files.emplace_back(a->out, report + "\n");
    if (!a->boxes.empty()) files.emplace_back(a->boxes, design::feasible_csv(set));
    if (!a->svg.empty()) {
      if (set.parameters.size() != 2) {
        throw io::InputError("--svg: draws a sweep over two parameters (" + a->csv + " has " +
                             std::to_string(set.parameters.size()) + ")");
      }
      files.emplace_back(a->svg, design::feasible_figure(set));
    }
    write_outputs(files);
    if (a->json) {
      print_json(Json::parse(report));
      return 0;
    }
    std::printf("feasible: %zu of %zu designs, %zu of %zu cells (every corner feasible), %zu box(es)\n",
                set.feasible_designs, set.designs, set.feasible_cells, set.cells, set.boxes.size());
    for (std::size_t b = 0; b < set.boxes.size(); ++b) {
      std::string line;
      for (std::size_t k = 0; k < set.parameters.size(); ++k) {
        line += (k ? ", " : "") + set.parameters[k] + " in [" + format_g(set.boxes[b].min[k]) + ", " +
                format_g(set.boxes[b].max[k]) + "]";
      }
      std::printf("  box %zu (%zu cells): %s\n", b, set.boxes[b].cells, line.c_str());
    }
    std::printf("sampled at the grid's designs, not certified between them\n");
    return 0;
  }});
}

}  // namespace pkmws::cli
