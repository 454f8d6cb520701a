// `pkmws grid`: the grid baseline's estimate of a file's workspace area
// ([Vasilic] §4.1-4.2, figs. 4 and 8): a Cartesian, polar, adaptive
// (quadtree) or joint-space sampler, with certified bounds where the cell test
// allows them (docs/format.md (command line), docs/schema/grid.output.schema.json).
// Files with criteria sample their criteria-limited workspace.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "pkmws/geometry/types.hpp"
#include "pkmws/grid/sampler.hpp"
#include "pkmws/io/mechanism_file.hpp"

namespace pkmws::report {

struct GridOptions {
  /// Cells per side: Cartesian N x N; polar N rings; adaptive the root grid; joint sweep the raster.
  std::size_t cells = 0;
  /// At most one of the three (none: Cartesian).
  bool polar = false;
  int adaptive = -1;  // quadtree depth below the root grid; -1: not adaptive
  bool sweep = false;
  /// Joint samples per joint of the sweep (0: 5 x cells).
  std::size_t samples = 0;
  int threads = 0;
  /// Kernel instruction set: "scalar", "baseline", "avx2", "avx512" or "best".
  std::string isa = "best";
};

struct GridReport {
  std::string name, mechanism, units;
  std::string area_units;  // e.g. "mm²"
  grid::SampleResult result;
  /// The sampler in words ("Cartesian 40 x 40 cells, cell-centre IK test").
  std::string description;
  /// What the bounds are: certified, a bracket that holds only if resolved, or none, with why.
  std::string bounds;

  struct Polar {
    std::size_t rings = 0, sectors = 0;
    geometry::Point centre;
    double radius = 0.0;
  };
  struct Adaptive {
    std::size_t depth = 0, root_cells = 0, effective_cells = 0;
    std::string rule;  // straddle rule: "certified" or "sampled"
    std::uint64_t undecided = 0;
    double area_centre = 0.0;
    std::vector<std::uint64_t> cells_per_level;
  };
  struct JointSweep {
    std::size_t samples = 0;
    std::uint64_t valid_poses = 0, boundary_cells = 0;
  };
  std::optional<Polar> polar;
  std::optional<Adaptive> adaptive;
  std::optional<JointSweep> sweep;

  /// The certified bounds [area_lower, area_upper], or the bracket that holds
  /// only if every feature is resolved (`*_if_resolved` in the JSON).
  bool certified() const { return result.area_lower && result.area_upper && result.bounds_certified; }
};

/// The grid estimate of `file`. Throws InputError naming the option for more
/// than one sampler, work beyond the bounds (--adaptive, --samples), an
/// unknown --isa, and naming the file where the sampler cannot run.
GridReport grid(const io::MechanismFile& file, const GridOptions& options);

/// `pkmws grid --json` (indented, no trailing newline).
std::string to_json_text(const GridReport& report);
/// `pkmws grid` without --json (lines ending in a newline).
std::string to_text(const GridReport& report);

}  // namespace pkmws::report
