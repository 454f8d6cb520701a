// `pkmws diff`: two designs compared (docs/design_space.md, "Comparing
// designs"; docs/schema/diff.output.schema.json): the areas of A ∩ B, A − B,
// B − A and A ∪ B (CGAL Booleans of the exact regions, certified bounds from
// the enclosure algebra otherwise), the change of every sweep metric, and both
// workspaces in one figure.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "pkmws/certified/cell_region.hpp"
#include "pkmws/io/mechanism_file.hpp"

namespace pkmws::report {

struct DiffOptions {
  double rectangle_precision = 1e-6;  // relative width of the inscribed rectangle's bounds
  double criteria_tolerance = 1e-4;   // files with criteria: relative width of the limited area
  int gci_cells = 128;                // fine-grid cells across a workspace for the GCI
  /// The figure's path ("": no figure), named in the report (the caller writes it).
  std::string figure;
};

/// One file compared: its path, name, mechanism and how its workspace is known ("exact", "certified").
struct DiffSide {
  std::string file, name, mechanism, method;
};

/// A Boolean piece: the region (inner/outer enclosures) and its area with bounds.
struct DiffRegion {
  certified::CertifiedRegion region;
  double area = 0.0, area_lower = 0.0, area_upper = 0.0;
};

/// One metric of both designs: the values of A and B (with certified bounds or
/// an error where the metric has them), the change B − A, or none with the reason.
struct DiffMetric {
  std::string metric, unit;
  std::optional<double> a, b, change, relative_change;
  std::string a_reason, b_reason, change_reason, relative_change_reason;  // why a value is missing
  std::optional<std::pair<double, double>> a_bounds, b_bounds, change_bounds;
  std::optional<double> a_error, b_error, change_error;
};

struct DiffReport {
  DiffSide a, b;
  std::string units, area_units;
  bool exact = false;  // both regions exact: exact Booleans
  DiffRegion a_and_b, a_minus_b, b_minus_a, a_or_b;
  /// area, components, inscribed_circle, rectangle_width, rectangle_height,
  /// rectangle_area, limited_area, real_area, gci.
  std::vector<DiffMetric> metrics;
  std::string figure;  // its path, or "" (no figure asked)
  std::string svg;     // the figure: A only, B only, A ∩ B (and the undecided band)
  double time_ms = 0.0;
};

/// Compares `a` and `b`. Throws InputError when their length units differ and
/// naming the file whose metrics cannot be computed.
DiffReport diff(const io::MechanismFile& a, const io::MechanismFile& b, const DiffOptions& options = {});

/// `pkmws diff --json` (indented, no trailing newline).
std::string to_json_text(const DiffReport& report);
/// `pkmws diff` without --json (lines ending in a newline).
std::string to_text(const DiffReport& report);

}  // namespace pkmws::report
