// `pkmws batch`: for every mechanism file what `pkmws area` reports (the same
// computation), the figure `pkmws export -f svg` draws, and one row of a
// summary table (summary.md, summary.json; docs/format.md (command line),
// docs/schema/batch.output.schema.json). A file without a planar workspace (a
// lone Π-joint) is a row with the reason, and its curve charts when it has them.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "pkmws/io/mechanism_file.hpp"
#include "pkmws/report/area.hpp"

namespace pkmws::report {

/// A file the batch writes into its output directory: name and content.
struct BatchFile {
  std::string name;
  std::string content;
};

/// One row of the summary: the numbers of `pkmws area --json` under the same names.
struct BatchRow {
  std::string file, stem, name, mechanism, units;
  std::string area_units;  // e.g. "mm²"
  /// No planar workspace: why (the row has no area then), and the curve charts
  /// drawn instead (1-DOF files).
  std::string note;
  std::optional<std::vector<std::string>> charts;
  /// With an area: its numbers (as report::area gives them).
  bool has_area = false;
  double area = 0.0, area_lower = 0.0, area_upper = 0.0, time_ms = 0.0;
  std::string method;
  std::vector<CriterionLimit> criteria;  // criteria-limited files
  double reachable_area = 0.0;           // criteria-limited files: the workspace without the limits
  bool reachable_exact = true;           // false: reachable_area is an outer enclosure's (an upper bound)
  /// Components; none for a criteria-limited workspace (not enumerated, with the reason).
  std::optional<std::size_t> components;
  /// Files with bodies: the real workspace's certified area.
  struct Real {
    double area = 0.0, lower = 0.0, upper = 0.0;
    std::string method;
  };
  std::optional<Real> real;
  std::string figure;  // the figure's file name ("<stem>.svg")
  /// The figure or the charts, to write into the output directory.
  std::vector<BatchFile> files;
};

/// The row of one file: its area report and figure, or the reason it has none
/// and its curve charts.
BatchRow batch_row(const io::MechanismFile& file);

struct BatchReport {
  std::string output_dir;
  std::vector<BatchRow> rows;  // their `files` may have been written and dropped
};

/// `pkmws batch --json` (indented, no trailing newline): output_dir, summary, rows.
std::string to_json_text(const BatchReport& report);
/// DIR/summary.json: the rows (indented, a trailing newline).
std::string summary_json(const BatchReport& report);
/// DIR/summary.md: the table with links to the figures, and what the time column covers.
std::string summary_markdown(const BatchReport& report);
/// The text line of one row as `pkmws batch` prints it (rows with an area), or "".
std::string to_text(const BatchRow& row);
/// The closing line of `pkmws batch` without --json.
std::string to_text(const BatchReport& report);

}  // namespace pkmws::report
