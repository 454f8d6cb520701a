// pkmws levels FILE --criterion NAME --levels a,b,c: the workspace cut into
// bands of a criterion with certified area bounds per band ([Briot] figs. 9,
// 10, 12, 13), optional SVG figure and CSV of the traced level curves; the
// report, figure and curves are the library's (pkmws/report/levels.hpp).
#include <iostream>
#include <sstream>

#include "cli.hpp"
#include "pkmws/report/levels.hpp"

namespace pkmws::cli {

std::vector<double> parse_levels(const std::string& text) {
  std::vector<double> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) out.push_back(parse_number(item, "--levels"));
  report::check_levels(out);
  return out;
}

void add_levels(CLI::App& app, std::vector<Command>& commands) {
  auto* sub = app.add_subcommand("levels", "Bands of a criterion with certified areas ([Briot] figs. 9-13)");
  struct Args {
    std::string file, criterion, levels, svg, csv;
    double tolerance = 1e-6;
    double max_time = 0.0;
    bool json = false;
  };
  auto a = std::make_shared<Args>();
  sub->add_option("FILE", a->file, "Mechanism file (JSON)")->required();
  sub->add_option("--criterion", a->criterion, "pressure_angle (deg) | reaction (N) | velocity_ratio (biglide V_i/V_y; moma, five_bar |dq|/|dP|; 3-DOF |dq|/|dx'|) | condition_number")->required();
  sub->add_option("--levels", a->levels, "Increasing thresholds, e.g. 20,40,60,80")->required();
  sub->add_option("--tolerance", a->tolerance, "Target bound width relative to each area (default 1e-6)");
  sub->add_option("--svg", a->svg, "Write the band figure (SVG)");
  sub->add_option("--csv", a->csv, "Write the traced level curves (CSV: level, piece, x, y)");
  sub->add_flag("--json", a->json, "Print one JSON object");
  add_max_time_option(sub, a->max_time);
  commands.push_back({sub, [a] {
    check_tolerance(a->tolerance);
    const io::MechanismFile mech = io::load_mechanism(a->file);
    report::LevelsOptions options;
    options.criterion = a->criterion;
    options.levels = parse_levels(a->levels);
    options.tolerance = a->tolerance;
    options.figure_pieces = !a->svg.empty();
    check_outputs({a->svg, a->csv});
    const CertifiedWork work("levels", a->max_time);
    options.budget = work.budget();
    const report::LevelsReport run = report::levels(mech, options);
    std::vector<std::pair<std::string, std::string>> outputs;  // all or nothing
    if (!a->svg.empty()) outputs.emplace_back(a->svg, report::band_figure(mech, run));
    if (!a->csv.empty()) outputs.emplace_back(a->csv, report::level_curves_csv(run));
    write_outputs(outputs);
    if (a->json) {
      std::cout << report::to_json_text(run) << "\n";
    } else {
      std::cout << report::to_text(run);
    }
    return 0;
  }});
}

}  // namespace pkmws::cli
