// pkmws export FILE --format svg|dxf|wkt|geojson|csv -o OUT (docs/format.md (command line));
// what the file holds is the library's (pkmws/report/export.hpp).
#include <cstdio>
#include <iostream>

#include "cli.hpp"
#include "pkmws/io/export.hpp"
#include "pkmws/report/export.hpp"

namespace pkmws::cli {

void add_export(CLI::App& app, std::vector<Command>& commands) {
  auto* sub = app.add_subcommand("export", "Write the workspace boundary (svg, dxf, wkt, geojson, csv)");
  struct Args {
    std::string file, format, out;
    double tolerance = 0.0;
    report::ExportOptions options;
    std::string levels;
    double max_time = 0.0;
    bool json = false;
  };
  auto a = std::make_shared<Args>();
  sub->add_option("FILE", a->file, "Mechanism file (JSON)")->required();
  sub->add_option("--format,-f", a->format, "svg | dxf | wkt | geojson | csv")->required();
  sub->add_flag("--json", a->json, "Print one JSON object about the file written (docs/schema/export.output.schema.json)");
  sub->add_option("-o,--output", a->out, "Output file")->required();
  auto* tolerance_option = sub->add_option(
      "--tolerance", a->tolerance,
      "Max deviation of polylines (wkt, geojson) in the file's unit; default 1e-6 of the bounding-box "
      "diagonal; refused below 1e-12 of the region's size (double precision), above a tenth of its "
      "diagonal, or when the polygons would exceed 2e6 vertices");
  sub->add_flag("--bare", a->options.bare, "svg: the boundary only, without axes and mechanism");
  sub->add_flag("--real", a->options.real,
                "Files with bodies: export the real workspace's inner enclosure (certainly reachable "
                "without collision) instead of the computed workspace");
  sub->add_option("--bound", a->options.bound,
                  "Certified workspaces (boundary not made of arcs and segments, e.g. the real-scheme "
                  "biglide, files with criteria limits, --real): export the outer enclosure (every point "
                  "of the region; default, --real: inner) or the inner one (only points of the region); "
                  "wkt and csv, which carry no metadata, need it explicitly. WKT/GeoJSON polygons lie "
                  "inside (inner) or around (outer) the enclosure")
      ->check(CLI::IsMember({"inner", "outer"}));
  sub->add_option("--criterion", a->options.criterion,
                  "With --levels: export the bands of a criterion (pressure_angle, reaction, velocity_ratio, condition_number) "
                  "instead of the workspace: svg = band figure, csv = traced level curves");
  sub->add_option("--levels", a->levels, "Increasing thresholds of --criterion, e.g. 20,40,60,80");
  add_max_time_option(sub, a->max_time);
  commands.push_back({sub, [a, tolerance_option] {
    report::ExportOptions& options = a->options;
    options.format = io::parse_export_format(a->format);
    options.output = a->out;
    if (tolerance_option->count() > 0) options.tolerance = a->tolerance;
    check_outputs({a->out});
    // Certified regions (criteria limits, bands): a bound stops the work with
    // exit 2 and no file (an export does not carry a `stopped` label).
    const CertifiedWork work("export", a->max_time);
    options.budget = work.budget();
    char limit[160];
    std::snprintf(limit, sizeof limit, "--max-time: stopped at %g s before the export was complete; nothing written (give more time)",
                  a->max_time);
    const std::string refusal = limit;
    if (a->levels.empty() != options.criterion.empty()) throw io::InputError("--criterion and --levels go together");
    report::check_export_options(options);
    const io::MechanismFile mech = io::load_mechanism(a->file);
    if (!a->levels.empty()) options.levels = parse_levels(a->levels);
    report::ExportReport result;
    const std::string content = work.finish_by_deadline(
        [&] {
          result = report::export_file(mech, options);
          if (result.stopped) throw io::InputError(refusal);
          return result.text;
        },
        refusal);
    io::write_file_atomic(a->out, content);
    if (a->json) std::cout << report::to_json_text(result) << "\n";
    return 0;
  }});
}

}  // namespace pkmws::cli
