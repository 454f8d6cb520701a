// pkmws area FILE [--json]: the exact workspace area (docs/format.md (command line));
// the report is the library's (pkmws/report/area.hpp).
#include <iostream>

#include "cli.hpp"
#include "pkmws/report/area.hpp"

namespace pkmws::cli {

void add_area(CLI::App& app, std::vector<Command>& commands) {
  auto* sub = app.add_subcommand("area", "Exact workspace area with the file's criteria");
  auto file = std::make_shared<std::string>();
  auto json = std::make_shared<bool>(false);
  sub->add_option("FILE", *file, "Mechanism file (JSON)")->required();
  sub->add_flag("--json", *json, "Print one JSON object");
  auto depth = std::make_shared<int>(7);
  sub->add_option("--interference-depth", *depth,
                  "Files with bodies: quadtree depth of the certified interference regions "
                  "(each level about halves the real area's bound width; default 7)")
      ->check(CLI::Range(0, 12));
  auto rectangle_precision = std::make_shared<double>(1e-6);
  sub->add_option("--rectangle-precision", *rectangle_precision,
                  "Relative width of the inscribed rectangle's certified area bounds (default 1e-6; "
                  "1e-9 takes about a second per component)")
      ->check(CLI::Range(1e-12, 0.5));
  auto rectangle_angle = std::make_shared<std::string>("axis");
  sub->add_option("--rectangle-angle", *rectangle_angle,
                  "Inscribed rectangles axis-aligned (axis, default) or at any orientation (any: the angle "
                  "and corners are reported; docs/design_space.md)")
      ->check(CLI::IsMember({"axis", "any"}));
  auto tolerance = std::make_shared<double>(1e-6);
  sub->add_option("--tolerance", *tolerance,
                  "Files with criteria limits: target width of the certified area bounds relative to the area "
                  "(default 1e-6; 1e-9 takes about a second for the DexTAR)");
  auto max_time = std::make_shared<double>(0.0);
  add_max_time_option(sub, *max_time);
  commands.push_back({sub, [file, json, depth, max_time, rectangle_precision, rectangle_angle, tolerance] {
    check_tolerance(*tolerance);
    const io::MechanismFile mech = io::load_mechanism(*file);
    // Criteria limits are certified level sets: bounded by --max-time, with progress.
    const CertifiedWork work("area", *max_time);
    report::AreaOptions options;
    options.interference_depth = *depth;
    options.rectangle_precision = *rectangle_precision;
    options.rectangle_any_angle = *rectangle_angle == "any";
    options.criteria_tolerance = *tolerance;
    options.budget = work.budget();
    const report::AreaReport result = report::area(mech, options);
    if (*json) {
      std::cout << report::to_json_text(result) << "\n";
    } else {
      std::cout << report::to_text(result);
    }
    return 0;
  }});
}

}  // namespace pkmws::cli
