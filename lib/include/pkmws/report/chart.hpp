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
  /// Which outputs to draw: the SVG figure, the Markdown tables.
  bool figure = true;
  bool markdown = true;
};

struct ChartReport {
  std::string svg;       // the panels (when asked)
  std::string markdown;  // the tables (when asked)
};

/// Reads the sweeps and draws the panels and tables. Throws InputError naming
/// the option (--y-label count, --x / --y: no such column, --mark) or the file
/// and line (a malformed row, a second design at one x).
ChartReport chart(const ChartOptions& options);

}  // namespace pkmws::report
