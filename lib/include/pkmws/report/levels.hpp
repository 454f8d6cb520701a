// `pkmws levels`: the workspace cut into bands of a criterion with certified
// area bounds per band ([Briot] figs. 9, 10, 12, 13), the band figure and the
// traced level curves (docs/format.md (command line),
// docs/schema/levels.output.schema.json); `pkmws export --criterion` writes the
// same figure and curves.
#pragma once

#include <string>
#include <vector>

#include "pkmws/certified/level_set.hpp"
#include "pkmws/criteria/fields.hpp"
#include "pkmws/io/mechanism_file.hpp"
#include "pkmws/report/common.hpp"

namespace pkmws::report {

struct LevelsOptions {
  /// "pressure_angle", "reaction", "velocity_ratio" (biglide).
  std::string criterion;
  /// Increasing thresholds, each inside the criterion's range.
  std::vector<double> levels;
  /// Target bound width relative to each area.
  double tolerance = 1e-6;
  /// The sub-level sets' pieces in (x, y) for the band figure: where a set
  /// was traced in charts, the same set traced again in the plane to the
  /// drawing's accuracy (the numbers stay the charted ones).
  bool figure_pieces = false;
  /// Deadline and progress per level (stage "level k of n").
  Budget budget;
};

struct LevelsReport {
  std::string name, mechanism, units;
  std::string criterion;
  std::string criterion_units;  // of the levels ("deg", "N", "")
  std::vector<double> levels;
  /// Band k: levels[k-1] < criterion <= levels[k] (band 0: everything up to levels[0]).
  std::vector<certified::Band> bands;
  /// The sub-level set {criterion <= levels[k]} behind each band (area bounds, traced pieces).
  std::vector<certified::LevelSetResult> sublevel_sets;
  /// The workspace's area bounds (equal when it is exact; a workspace cut by
  /// level sets is certified at the same tolerance): the band above the
  /// highest level is the workspace minus the highest sub-level set.
  double workspace_area_lower = 0.0, workspace_area_upper = 0.0;
  /// Cut short by the budget's deadline (the bounds are valid but wider): its note.
  bool stopped = false;
  std::string stopped_note;
  /// Why every band is empty without computing, or "".
  std::string note;
  double time_ms = 0.0;
  /// The criterion's field (its unit and surrogate), for figures.
  criteria::CriterionField field;
};

/// Throws InputError ("--levels: ...") unless `levels` is a non-empty increasing list.
void check_levels(const std::vector<double>& levels);

/// The bands of `options.criterion` at `options.levels`. Throws InputError
/// ("--levels: ...") for levels that do not increase or lie outside the
/// criterion's range.
LevelsReport levels(const io::MechanismFile& file, const LevelsOptions& options);

/// `pkmws levels --json` (indented, no trailing newline).
std::string to_json_text(const LevelsReport& report);
/// `pkmws levels` without --json (lines ending in a newline).
std::string to_text(const LevelsReport& report);

/// The band figure (SVG): the workspace in the colour of the band above the
/// highest level, each sub-level set's traced inner region on top, legend with
/// every band's certified area bounds, the mechanism at a pose of the lowest band.
std::string band_figure(const io::MechanismFile& file, const LevelsReport& report);
/// The traced level curves (CSV: level, piece, x, y).
std::string level_curves_csv(const LevelsReport& report);

}  // namespace pkmws::report
