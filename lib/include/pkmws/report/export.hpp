// `pkmws export`: what a file's export holds — the figure (the workspace with
// the numbers of its area report), the boundary of the workspace (exact, one
// of two certified enclosures, criteria-limited, or the real workspace) in an
// exchange format, or the bands of a criterion — and the `--json` line about
// the file written (docs/format.md (command line),
// docs/schema/export.output.schema.json).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "pkmws/io/export.hpp"
#include "pkmws/io/mechanism_file.hpp"
#include "pkmws/report/common.hpp"

namespace pkmws::report {

struct ExportOptions {
  io::ExportFormat format = io::ExportFormat::svg;
  /// The output path, named in the report (the caller writes the file).
  std::string output;
  /// svg: the boundary only, without axes and mechanism.
  bool bare = false;
  /// Files with bodies: the real workspace instead of the computed one.
  bool real = false;
  /// Certified regions: "inner" or "outer" enclosure; "" the default (outer;
  /// --real: inner), refused for wkt and csv, which cannot say which they hold.
  std::string bound;
  /// Max deviation of polylines (wkt, geojson) in the file's unit; none: the default.
  std::optional<double> tolerance;
  /// With `levels`: the bands of this criterion instead of the workspace
  /// (svg: band figure, csv: traced level curves).
  std::string criterion;
  std::vector<double> levels;
  /// Certified regions (criteria limits, bands): their deadline and progress.
  Budget budget;
};

struct ExportReport {
  std::string name, mechanism, units;
  io::ExportFormat format = io::ExportFormat::svg;
  std::string output;
  /// What the file holds: "figure", "boundary" or "bands of <criterion>".
  std::string content;
  /// The enclosure written ("inner" / "outer"), "" for an exact region or a figure.
  std::string bound;
  /// The file's text.
  std::string text;
  /// Cut short by the budget's deadline: nothing to write (an export carries no `stopped` label).
  bool stopped = false;
};

/// Checks what can be checked without the file and the levels: bands only as
/// svg or csv, a positive finite --tolerance. Throws InputError naming the option.
void check_export_options(const ExportOptions& options);

/// The export of `file`: --criterion and --levels together, then
/// check_export_options. Throws InputError naming the option (--bound for
/// wkt/csv of a certified region, --real without bodies, --tolerance out of
/// range) or the file (an empty workspace).
ExportReport export_file(const io::MechanismFile& file, const ExportOptions& options);

/// `pkmws export --json` (indented, no trailing newline): the file written.
std::string to_json_text(const ExportReport& report);

}  // namespace pkmws::report
