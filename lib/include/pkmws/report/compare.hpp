// `pkmws compare`: a file's exact (or, with criteria, certified) area against
// the grid baseline along a ladder of resolutions, with the time each needs
// for an accuracy (docs/format.md (command line), docs/benchmarks.md,
// docs/schema/compare.output.schema.json).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "pkmws/grid/compare.hpp"
#include "pkmws/io/mechanism_file.hpp"

namespace pkmws::report {

struct CompareOptions {
  /// A ladder stops after the first step slower than this (seconds).
  double budget_s = 20.0;
  int threads = 0;
  /// Cells per side of the uniform grids and quadtree depths (empty: grid::CompareOptions' defaults).
  std::vector<std::size_t> ladder;
  std::vector<int> depths;
};

struct CompareReport {
  std::string name, mechanism, units;
  std::string area_units;  // e.g. "mm²"
  /// The file's criteria limit the workspace: the grids sample the limited
  /// region and the reference is its certified area (one run).
  bool limited = false;
  int exact_runs = 0;  // runs of the reference computation (median reported)
  grid::CompareResult result;
};

/// The comparison for `file`. Throws InputError naming the file where a
/// sampler cannot run; a mechanism without a planar workspace throws its own
/// reason (as Mechanism::workspace() gives it).
CompareReport compare(const io::MechanismFile& file, const CompareOptions& options = {});

/// `pkmws compare --json` (indented, no trailing newline).
std::string to_json_text(const CompareReport& report);
/// `pkmws compare` without --json (lines ending in a newline).
std::string to_text(const CompareReport& report);
/// `--csv OUT`: one line per row (method, cells_per_side, depth, points, area, ...).
std::string to_csv(const CompareReport& report);

}  // namespace pkmws::report
