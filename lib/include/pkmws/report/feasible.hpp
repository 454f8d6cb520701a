// `pkmws feasible`: the grid cells of a sweep whose corners all satisfy the
// conditions, merged into boxes of parameters (pkmws/design/feasible.hpp;
// docs/design_space.md, docs/schema/feasible.output.schema.json). Sampled at
// the grid's designs, not certified between them.
#pragma once

#include <string>
#include <vector>

#include "pkmws/design/feasible.hpp"

namespace pkmws::report {

struct FeasibleReport {
  std::string csv;  // the sweep read
  design::FeasibleSet set;
};

/// Reads the sweep CSV and applies the conditions ("COLUMN >= NUMBER").
/// Throws InputError naming the file, the line or the condition.
FeasibleReport feasible(const std::string& csv, const std::vector<std::string>& conditions);

/// `pkmws feasible --json` (indented by 2, no bare null, no trailing newline).
std::string to_json_text(const FeasibleReport& report);
/// `-o FILE`: the report as design::feasible_report writes it (indented by 1, a trailing newline).
std::string report_file_text(const FeasibleReport& report);
/// `--csv FILE`: the boxes (box, cells, then <parameter>_min, <parameter>_max per parameter).
std::string boxes_csv(const FeasibleReport& report);
/// `--svg FILE`: the boxes over the designs; throws InputError ("--svg: ...")
/// unless the sweep has two parameters.
std::string figure(const FeasibleReport& report);
/// `pkmws feasible` without --json (lines ending in a newline).
std::string to_text(const FeasibleReport& report);

}  // namespace pkmws::report
