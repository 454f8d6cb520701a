// The real workspace on the command line (docs/format.md (bodies)): `pkmws explain`, and the
// pieces `area`, `export` and `eval` use when a file lists `bodies`.
#pragma once

#include "cli.hpp"
#include "pkmws/bodies/bodies.hpp"
#include "pkmws/io/export.hpp"

namespace pkmws::cli {

void add_explain(CLI::App& app, std::vector<Command>& commands);

/// Which parts collide at platform point p (the pose-level test), as JSON:
/// reachable, collides, collisions ["a / b", ...], pairs [{parts, kind, clearance, collides}].
Json collisions_json(const io::MechanismFile& file, geometry::Point p);

/// The real workspace of a file with bodies (quadtree depth `depth`).
bodies::RealWorkspace real_workspace_of(const io::MechanismFile& file, const geometry::Region& reachable, int depth);

/// `real_area`, `real_area_lower`, `real_area_upper`, `real_method`, `interference` [...] for `area --json`.
Json real_workspace_json(const bodies::RealWorkspace& real);

/// The text lines of `pkmws area` for the real workspace (unit: e.g. "mm²").
void print_real_workspace(const bodies::RealWorkspace& real, const std::string& unit);

/// The parts at platform point p as figure overlays (grey, semi-transparent); empty when p is unreachable.
std::vector<io::FigureOptions::Overlay> part_overlays(const io::MechanismFile& file, geometry::Point p);

/// The figure overlays: interference regions shaded and labelled by pair, the real workspace outlined in black.
std::vector<io::FigureOptions::Overlay> real_workspace_overlays(const bodies::RealWorkspace& real);

}  // namespace pkmws::cli
