// `pkmws optimize`: the best design for an objective under constraints (NLopt,
// pkmws/design/optimize.hpp), its report, every evaluation as a sweep row and
// the optimum as a mechanism file (docs/design_space.md,
// docs/schema/optimize.output.schema.json).
#pragma once

#include <filesystem>
#include <string>

#include "pkmws/design/optimize.hpp"

namespace pkmws::report {

struct OptimizeReport {
  design::OptimizeSpec spec;
  design::OptimizeResult result;
  /// Times in the report and the history (false: outputs compare byte for byte).
  bool timing = true;
};

/// Reads the optimisation file and runs the search. Throws InputError naming the field.
OptimizeReport optimize(const std::filesystem::path& spec_file, bool timing = true);

/// `pkmws optimize --json` (indented by 2, no bare null, no trailing newline).
std::string to_json_text(const OptimizeReport& report);
/// `-o FILE`: the report as design::optimize_report writes it (indented by 1, a trailing newline).
std::string report_file_text(const OptimizeReport& report);
/// `--history FILE`: every evaluation as a row of the sweep's CSV columns.
std::string history_csv(const OptimizeReport& report);
/// `--design FILE`: the optimum as a mechanism file.
std::string design_file_text(const OptimizeReport& report);
/// `pkmws optimize` without --json (lines ending in a newline).
std::string to_text(const OptimizeReport& report);

}  // namespace pkmws::report
