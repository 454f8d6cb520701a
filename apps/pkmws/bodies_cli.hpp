// The real workspace on the command line (docs/format.md (bodies)): `pkmws explain`, and the
// pieces `area`, `export` and `eval` use when a file lists `bodies`.
#pragma once

#include <optional>

#include "cli.hpp"
#include "pkmws/bodies/bodies.hpp"
#include "pkmws/criteria/fields.hpp"
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

/// The figure overlays: interference regions hatched and tagged by pair (legend: the pair and its
/// certified area in `area_unit`), the real workspace outlined in black.
std::vector<io::FigureOptions::Overlay> real_workspace_overlays(const bodies::RealWorkspace& real,
                                                                const std::string& area_unit);

/// The parts at platform point p as figure parts (housings, slider blocks, rods/links, platform
/// joint, obstacles), one legend entry per kind with its size in `units`; empty when p is unreachable.
std::vector<io::FigureOptions::Part> figure_parts(const io::MechanismFile& file, geometry::Point p);

/// What `pkmws area` computes for a file, and the regions behind the numbers.
struct AreaResult {
  Json report;                                       // `pkmws area --json`
  certified::CertifiedRegion enclosure;              // the workspace (criteria files: the limited one)
  std::optional<bodies::RealWorkspace> real;         // files with bodies
  std::optional<criteria::LimitedWorkspace> limited; // files with criteria (traced pieces for figures)
};
/// What `time_ms` (area --json, summary.json) and the summary's time column cover.
inline constexpr const char* kComputeTimeMeaning =
    "computation: workspace, area, components with inscribed circles, criteria limits or real workspace; "
    "loading and figures excluded";
/// `pkmws area`: the area report of a file (time_ms: see kComputeTimeMeaning).
/// With `work`, criteria limits are bounded by its deadline (the report then has `stopped`).
AreaResult compute_area(const io::MechanismFile& mech, int interference_depth, const CertifiedWork* work = nullptr,
                        double rectangle_precision = 1e-6);
/// The figure `export -f svg` and `batch` draw for a file: the workspace (criteria files: the
/// certified limited region, filled with its traced inner bound, over the reachable workspace;
/// files with bodies: interference and the real workspace, the parts at the pose), with the
/// numbers of `result` in the caption.
std::string file_figure(const io::MechanismFile& mech, const AreaResult& result);

}  // namespace pkmws::cli
