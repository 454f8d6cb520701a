// `pkmws atlas`: a metric of a two-parameter grid sweep as a filled contour
// map (docs/design_space.md, docs/schema/atlas.output.schema.json).
#pragma once

#include <cstddef>
#include <string>

#include "pkmws/io/atlas.hpp"

namespace pkmws::report {

struct AtlasOptions {
  /// The sweep CSV (pkmws sweep) and its columns: parameters on the axes, the metric mapped.
  std::string csv, x, y, metric;
  /// The SVG's path, named in the report (the caller writes the file).
  std::string output;
  /// Titles (empty: the metric over the two parameters, the column names).
  std::string title, x_label, y_label, metric_label;
  /// Mark the smallest value instead of the largest.
  bool minimize = false;
};

struct AtlasReport {
  AtlasOptions options;
  io::AtlasData data;         // the grid of values read (nullopt where a design is not ok or missing)
  std::size_t missing = 0;    // cells without a value
  std::string svg;            // the figure
};

/// Reads the sweep and draws its atlas. Throws InputError naming the file and
/// line (a malformed row, a second design at one grid point), the option
/// (--x, --y, --metric: no such column) or the file (fewer than 2 x 2 designs).
AtlasReport atlas(const AtlasOptions& options);

/// `pkmws atlas --json` (indented, no trailing newline).
std::string to_json_text(const AtlasReport& report);
/// `pkmws atlas` without --json: one line naming the figure.
std::string to_text(const AtlasReport& report);

}  // namespace pkmws::report
