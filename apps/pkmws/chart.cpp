// pkmws chart CSV[=LABEL]... --x COL --y COL [--y COL ...] [-o FIG.svg]
// [--markdown TABLE.md]: metrics of one-parameter sweeps, one line per sweep
// (configuration), one panel per metric, and the same numbers as Markdown
// tables (docs/design_space.md, "The MOMA program of building"); the figure
// and tables are the library's (pkmws/report/chart.hpp).
#include <iostream>

#include "cli.hpp"
#include "pkmws/report/chart.hpp"

namespace pkmws::cli {

void add_chart(CLI::App& app, std::vector<Command>& commands) {
  auto* sub = app.add_subcommand("chart", "Metrics of one-parameter sweeps: line-chart panels and Markdown tables");
  struct Args {
    report::ChartOptions options;
    bool json = false;
  };
  auto a = std::make_shared<Args>();
  report::ChartOptions& o = a->options;
  sub->add_option("CSV", o.csvs, "Outputs of pkmws sweep, each as PATH or PATH=LABEL (one line per file)")
      ->required();
  sub->add_option("--x", o.x, "Parameter column on the horizontal axis")->required();
  sub->add_option("--y", o.ys,
                  "Metric column (repeat for more panels / tables); NAME reads NAME or the midpoint of "
                  "NAME_lower and NAME_upper")
      ->required()
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  sub->add_option("-o,--out", o.output, "Output SVG: one panel per --y");
  sub->add_option("--markdown", o.markdown_output, "Output Markdown: one table per --y (rows: files, columns: x values)");
  sub->add_option("--title", o.title, "Figure title");
  sub->add_option("--x-label", o.x_label, "Horizontal axis title with unit (default: the column name)");
  sub->add_option("--y-label", o.y_labels, "Title with unit of each --y, in order (default: the column name)")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  sub->add_option("--mark", o.marks, "x values to highlight, comma-separated (guides in the figure, bold in tables)");
  sub->add_option("--mark-label", o.marks_label, "Legend text of the highlighted x values");
  sub->add_option("--caption", o.caption, "Caption under the figure");
  sub->add_flag("--json", a->json, "Print one JSON object: the sweeps read and the files written "
                                   "(docs/schema/chart.output.schema.json)");
  commands.push_back({sub, [a] {
    const report::ChartOptions& opts = a->options;
    if (opts.output.empty() && opts.markdown_output.empty()) {
      throw io::InputError("chart: give -o FIG.svg, --markdown TABLE.md or both");
    }
    if (!opts.y_labels.empty() && opts.y_labels.size() != opts.ys.size()) {
      throw io::InputError("--y-label: give one per --y (" + std::to_string(opts.ys.size()) + ")");
    }
    check_outputs({opts.output, opts.markdown_output});
    const report::ChartReport r = report::chart(opts);
    std::vector<std::pair<std::string, std::string>> files;
    if (!opts.output.empty()) files.emplace_back(opts.output, r.svg);
    if (!opts.markdown_output.empty()) files.emplace_back(opts.markdown_output, r.markdown);
    write_outputs(files);
    std::cout << (a->json ? report::to_json_text(r) + "\n" : report::to_text(r));
    return 0;
  }});
}

}  // namespace pkmws::cli
