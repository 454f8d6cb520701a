// Shared pieces of the pkmws command line: one file per subcommand registers
// itself here; main() turns every error into one line on stderr and exit 2.
#pragma once

#include <CLI/CLI.hpp>

#include <chrono>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pkmws/geometry/region.hpp"
#include "pkmws/io/mechanism_file.hpp"

namespace pkmws::criteria {
struct LimitedWorkspace;  // pkmws/criteria/fields.hpp
}

namespace pkmws::cli {

using Json = nlohmann::json;

/// Each subcommand registers itself and sets `run` when it is selected.
struct Command {
  CLI::App* app = nullptr;
  std::function<int()> run;
};

void add_area(CLI::App& app, std::vector<Command>& commands);
void add_export(CLI::App& app, std::vector<Command>& commands);
void add_kinematics(CLI::App& app, std::vector<Command>& commands);  // ik, dk, eval
void add_info(CLI::App& app, std::vector<Command>& commands);
void add_batch(CLI::App& app, std::vector<Command>& commands);
void add_plot(CLI::App& app, std::vector<Command>& commands);
void add_grid(CLI::App& app, std::vector<Command>& commands);     // grid baseline
void add_compare(CLI::App& app, std::vector<Command>& commands);  // exact vs grid
void add_levels(CLI::App& app, std::vector<Command>& commands);   // criterion bands (levels.cpp)
/// `pkmws area` for a file with `criteria` limits: certified area bounds of the
/// limited workspace (levels.cpp); `tolerance` relative to the area. The
/// certified pieces behind it go to `*limited` when given (for figures).
Json criteria_area_report(const io::MechanismFile& mech, double tolerance,
                          criteria::LimitedWorkspace* limited = nullptr);
/// What `pkmws levels` writes for a criterion at increasing levels "a,b,c":
/// the band figure (svg) or the traced level curves (csv: level, piece, x, y).
std::string bands_export(const io::MechanismFile& mech, const std::string& criterion, const std::string& levels,
                         bool svg, double tolerance);
/// Writes the curve charts of a 1-DOF file into `dir`; returns the file names.
std::vector<std::string> write_curve_figures(const io::MechanismFile& mech, const std::string& dir);

/// Milliseconds since `start`.
double elapsed_ms(std::chrono::steady_clock::time_point start);
/// Prints JSON (indented) to stdout.
void print_json(const Json& j);
/// Parses a number argument ("X", "Q1", ...) or throws io::InputError.
double parse_number(const std::string& text, const std::string& what);

/// The file's exact workspace, or throws io::InputError when the mechanism has
/// none (e.g. a lone Pi-joint) with the mechanism's reason.
geometry::Region workspace_of(const io::MechanismFile& file);
/// The workspace as an enclosure (exact, or certified where the boundary is
/// not made of arcs and segments); errors become InputError with the path.
certified::CertifiedRegion workspace_enclosure_of(const io::MechanismFile& file);
/// A pose inside the workspace for drawing the mechanism (largest component's
/// centroid when inside, else the centre of its largest inscribed circle).
mechanisms::Pose sample_pose(const io::MechanismFile& file, const geometry::Region& region);
/// Area, components and their figures, as in `pkmws area --json`.
Json region_report(const geometry::Region& region, double min_area);
/// Length unit squared, e.g. "mm²".
std::string area_unit(const io::MechanismFile& file);

}  // namespace pkmws::cli
