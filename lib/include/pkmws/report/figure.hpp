// The figures of a file as `pkmws export -f svg` and `pkmws batch` draw them
// (docs/format.md (figures)): the workspace with the numbers of its area
// report, and the real workspace of a machine with its parts.
#pragma once

#include <string>

#include "pkmws/geometry/region.hpp"
#include "pkmws/io/mechanism_file.hpp"
#include "pkmws/report/area.hpp"

namespace pkmws::report {

/// The figure of a file with the numbers of `report` (report::area) in its
/// caption: the workspace (criteria files: the certified limited region, filled
/// with its traced inner bound, over the reachable workspace; certified
/// workspaces: the inner enclosure and the undecided band; files with bodies:
/// interference hatched by pair, the real workspace outlined, the parts at the pose).
std::string area_figure(const io::MechanismFile& file, const AreaReport& report);

/// `export --real -f svg`: the real workspace's inner enclosure `region` with
/// its area in the caption and the machine's parts at a pose inside it.
std::string real_workspace_figure(const io::MechanismFile& file, const geometry::Region& region);

}  // namespace pkmws::report
