// `pkmws chart`: metrics of one-parameter sweeps, one line per sweep (a
// configuration), one panel per metric, and the same numbers as Markdown
// tables (docs/design_space.md, "The MOMA program of building").
#pragma once

#include <string>
#include <vector>

namespace pkmws::report {

struct ChartOptions {
  /// Sweep CSVs (pkmws sweep), each PATH or PATH=LABEL (default label: the file's stem).
  std::vector<std::string> csvs;
  /// The parameter column on the horizontal axis; the metric columns, one
  /// panel / table each (NAME or the midpoint of NAME_lower and NAME_upper).
  std::string x;
  std::vector<std::string> ys;
  /// Titles with units (empty: the column names; y_labels: one per y or none).
  std::string title, x_label, caption;
  std::vector<std::string> y_labels;
  /// x values to highlight, comma-separated, and their legend text.
  std::string marks;
  std::string marks_label = "marked values";
  /// The outputs' paths, named in the report (the caller writes them); "": not drawn.
  std::string output;           // the SVG figure
  std::string markdown_output;  // the Markdown tables
};

struct ChartReport {
  /// Each sweep read: its path and label, and the metrics it has values of.
  struct Sweep {
    std::string csv, label;
    std::vector<std::string> metrics;
  };
  std::string x;
  std::vector<std::string> metrics;  // the --y columns, one panel / table each
  std::vector<Sweep> sweeps;
  std::string output, markdown_output;  // as asked ("": not drawn)
  std::string svg;       // the panels (when asked)
  std::string markdown;  // the tables (when asked)
};

/// Reads the sweeps and draws the panels and tables. Throws InputError naming
/// the option (--y-label count, --x / --y: no such column, --mark) or the file
/// and line (a malformed row, a second design at one x).
ChartReport chart(const ChartOptions& options);

/// `pkmws chart --json` (indented, no trailing newline; docs/schema/chart.output.schema.json):
/// the sweeps with their labels and metrics, and the files written.
std::string to_json_text(const ChartReport& report);
/// `pkmws chart` without --json: the files written, one per line.
std::string to_text(const ChartReport& report);

}  // namespace pkmws::report
