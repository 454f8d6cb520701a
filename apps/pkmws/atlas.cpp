// pkmws atlas SWEEP.csv --x COL --y COL --metric COL -o OUT.svg: a metric of
// a two-parameter grid sweep as a filled contour map (docs/design_space.md);
// the report is the library's (pkmws/report/atlas.hpp).
#include <iostream>

#include "cli.hpp"
#include "pkmws/io/export.hpp"
#include "pkmws/report/atlas.hpp"

namespace pkmws::cli {

void add_atlas(CLI::App& app, std::vector<Command>& commands) {
  auto* sub = app.add_subcommand("atlas", "A metric over two swept parameters as a contour map (from a sweep CSV)");
  struct Args {
    report::AtlasOptions options;
    bool json = false;
  };
  auto a = std::make_shared<Args>();
  report::AtlasOptions& o = a->options;
  sub->add_option("CSV", o.csv, "Output of pkmws sweep (a grid over at least two parameters)")->required();
  sub->add_option("--x", o.x, "Parameter column on the horizontal axis")->required();
  sub->add_option("--y", o.y, "Parameter column on the vertical axis")->required();
  sub->add_option("--metric", o.metric, "Metric column to map")->required();
  sub->add_option("-o,--out", o.output, "Output SVG")->required();
  sub->add_option("--title", o.title, "Figure title (default: metric over the two parameters)");
  sub->add_option("--x-label", o.x_label, "Horizontal axis title with unit (default: the column name)");
  sub->add_option("--y-label", o.y_label, "Vertical axis title with unit (default: the column name)");
  sub->add_option("--metric-label", o.metric_label, "Colour bar title with unit (default: the column name)");
  sub->add_flag("--minimize", o.minimize, "Mark the smallest value instead of the largest");
  sub->add_flag("--json", a->json, "Print one JSON object (docs/schema/atlas.output.schema.json)");
  commands.push_back({sub, [a] {
    const report::AtlasReport r = report::atlas(a->options);
    io::write_file_atomic(a->options.output, r.svg);
    std::cout << (a->json ? report::to_json_text(r) + "\n" : report::to_text(r));
    return 0;
  }});
}

}  // namespace pkmws::cli
