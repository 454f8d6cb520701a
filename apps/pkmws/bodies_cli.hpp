// The real workspace on the command line (docs/format.md (bodies)): `pkmws explain`, and the
// figure pieces `export` and `batch` draw when a file lists `bodies` (the numbers: pkmws/report).
#pragma once

#include <optional>

#include "cli.hpp"
#include "pkmws/bodies/bodies.hpp"
#include "pkmws/criteria/fields.hpp"
#include "pkmws/io/export.hpp"
#include "pkmws/report/area.hpp"

namespace pkmws::cli {

void add_explain(CLI::App& app, std::vector<Command>& commands);

/// The figure overlays: interference regions hatched and tagged by pair (legend: the pair and its
/// certified area in `area_unit`), the real workspace outlined in black.
std::vector<io::FigureOptions::Overlay> real_workspace_overlays(const bodies::RealWorkspace& real,
                                                                const std::string& area_unit);

/// The parts at platform point p as figure parts (housings, slider blocks, rods/links, platform
/// joint, obstacles), one legend entry per kind with its size in `units`; empty when p is unreachable.
std::vector<io::FigureOptions::Part> figure_parts(const io::MechanismFile& file, geometry::Point p);

/// The figure `export -f svg` and `batch` draw for a file: the workspace (criteria files: the
/// certified limited region, filled with its traced inner bound, over the reachable workspace;
/// files with bodies: interference and the real workspace, the parts at the pose), with the
/// numbers of `result` in the caption.
std::string file_figure(const io::MechanismFile& mech, const report::AreaReport& result);

}  // namespace pkmws::cli
