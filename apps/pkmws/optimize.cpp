// pkmws optimize SPEC.json: design synthesis with NLopt (the best design for
// an objective under constraints); pkmws feasible SWEEP.csv --where ...: the
// feasible boxes of parameters of a grid sweep (docs/design_space.md).
// Option parsing and printing only: the reports are the library's
// (pkmws/report/optimize.hpp, pkmws/report/feasible.hpp).
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cli.hpp"
#include "pkmws/report/feasible.hpp"
#include "pkmws/report/optimize.hpp"

namespace pkmws::cli {

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
    const report::OptimizeReport r = report::optimize(a->spec, !a->no_timing);
    std::vector<std::pair<std::string, std::string>> files;
    if (!a->out.empty()) files.emplace_back(a->out, report::report_file_text(r));
    if (!a->history.empty()) files.emplace_back(a->history, report::history_csv(r));
    if (!a->design.empty()) files.emplace_back(a->design, report::design_file_text(r));
    write_outputs(files);
    std::cout << (a->json ? report::to_json_text(r) + "\n" : report::to_text(r));
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
    const report::FeasibleReport r = report::feasible(a->csv, a->where);
    std::vector<std::pair<std::string, std::string>> files;
    if (!a->out.empty()) files.emplace_back(a->out, report::report_file_text(r));
    if (!a->boxes.empty()) files.emplace_back(a->boxes, report::boxes_csv(r));
    if (!a->svg.empty()) files.emplace_back(a->svg, report::figure(r));
    write_outputs(files);
    std::cout << (a->json ? report::to_json_text(r) + "\n" : report::to_text(r));
    return 0;
  }});
}

}  // namespace pkmws::cli
