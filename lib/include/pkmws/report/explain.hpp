// `pkmws explain`: which parts collide at a platform position (docs/format.md
// (bodies), docs/schema/explain.output.schema.json); `pkmws eval` adds the same
// test for files with bodies.
#pragma once

#include <string>

#include "pkmws/bodies/bodies.hpp"
#include "pkmws/geometry/types.hpp"
#include "pkmws/io/mechanism_file.hpp"

namespace pkmws::report {

struct ExplainReport {
  std::string name, mechanism, units;
  geometry::Point point;
  /// Reachable, and per checked pair its clearance (link angle: its margin) and whether it collides.
  bodies::PoseCheck check;
};

/// The pose-level collision test of a file with bodies at platform point p.
/// Throws InputError naming the file when it lists no bodies.
ExplainReport explain(const io::MechanismFile& file, geometry::Point p);

/// `pkmws explain --json` (indented, no trailing newline).
std::string to_json_text(const ExplainReport& report);
/// `pkmws explain` without --json (lines ending in a newline).
std::string to_text(const ExplainReport& report);

}  // namespace pkmws::report
