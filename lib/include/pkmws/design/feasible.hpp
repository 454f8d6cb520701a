// The feasible set of designs from a grid sweep: the grid cells whose every
// corner design is ok and satisfies every condition ("task_margin >= 5"),
// merged into boxes of parameters. Sampled, not certified: a cell is kept on
// the evidence of its corners only; between them a metric may dip below its
// bound (docs/design_space.md).
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "pkmws/design/optimize.hpp"

namespace pkmws::design {

/// A box of parameters: [min[k], max[k]] per parameter, made of `cells` grid cells.
struct FeasibleBox {
  std::vector<double> min, max;
  std::size_t cells = 0;
};

struct FeasibleSet {
  std::vector<std::string> parameters;          // the sweep's parameter columns
  std::vector<std::vector<double>> values;      // the grid's values per parameter, increasing
  std::vector<Constraint> conditions;
  std::size_t designs = 0, feasible_designs = 0;
  std::size_t cells = 0, feasible_cells = 0;
  std::vector<FeasibleBox> boxes;               // disjoint interiors, in grid order
  /// Every design: its parameter values and whether it satisfies the conditions.
  std::vector<std::vector<double>> points;
  std::vector<bool> point_feasible;
};

/// Reads a sweep CSV (pkmws sweep; a full grid: every combination of the
/// parameters' values once) and the conditions (parse_constraint's syntax,
/// on any column); throws io::InputError naming the file, the line or the
/// condition. A parameter with one value is a degenerate dimension: its
/// boxes have min = max. Cells are merged greedily in grid order: a box
/// grows along the first parameter as far as feasible cells not yet in a box
/// continue it, then along the second, and so on.
FeasibleSet feasible_set(const std::filesystem::path& csv, const std::vector<std::string>& conditions);

/// The boxes as CSV: box, cells, then <parameter>_min, <parameter>_max per parameter.
std::string feasible_csv(const FeasibleSet& set);
/// The report of `pkmws feasible --json` (docs/schema/feasible.output.schema.json), as JSON text.
std::string feasible_report(const FeasibleSet& set, const std::string& csv);
/// Two parameters: the boxes over the sampled designs as an SVG figure.
std::string feasible_figure(const FeasibleSet& set);

}  // namespace pkmws::design
