// Shared pieces of the pkmws command line: one file per subcommand registers
// itself here; main() turns every error into one line on stderr and exit 2.
#pragma once

#include <CLI/CLI.hpp>

#include <chrono>
#include <functional>
#include <string>
#include <vector>

#include "pkmws/certified/level_set.hpp"
#include "pkmws/geometry/region.hpp"
#include "pkmws/io/mechanism_file.hpp"
#include "pkmws/report/common.hpp"

namespace pkmws::cli {

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
void add_sweep(CLI::App& app, std::vector<Command>& commands);    // design-space sweeps (sweep.cpp)
void add_atlas(CLI::App& app, std::vector<Command>& commands);    // contour maps of sweeps (atlas.cpp)
void add_diff(CLI::App& app, std::vector<Command>& commands);     // two designs compared (diff.cpp)
void add_chart(CLI::App& app, std::vector<Command>& commands);    // line charts and tables of sweeps (chart.cpp)
void add_optimize(CLI::App& app, std::vector<Command>& commands); // design synthesis (optimize.cpp)
void add_feasible(CLI::App& app, std::vector<Command>& commands); // feasible boxes of a sweep (optimize.cpp)
void add_explain(CLI::App& app, std::vector<Command>& commands);  // collisions at a pose (explain.cpp)
/// The bound of a certified computation (`--max-time SECONDS`) and its progress
/// line: on stderr, when stderr is a terminal and the work has run for more
/// than a second, rewritten in place and erased at the end.
class CertifiedWork {
 public:
  /// Starts the clock; `max_seconds` 0 is no bound.
  CertifiedWork(std::string command, double max_seconds);
  ~CertifiedWork();
  CertifiedWork(const CertifiedWork&) = delete;
  CertifiedWork& operator=(const CertifiedWork&) = delete;
  /// `o` with the deadline and the progress reporter of `stage` ("level 2 of 3").
  certified::LevelSetOptions options(certified::LevelSetOptions o, const std::string& stage = "") const;
  /// What a result cut short by the deadline says about itself.
  std::string stopped_note() const;
  /// The deadline and progress line as the report layer takes them (this object must outlive its use).
  report::Budget budget() const;
  double max_seconds() const { return max_seconds_; }
  /// Runs `job`, work that cannot stop part-way (the exact Boolean operations
  /// that turn certified cells into an exported region, the file's content),
  /// and waits for it until the deadline. Past it: `pkmws: error: <refusal>` on
  /// stderr and exit status 2 at once, nothing written. No deadline: runs `job`.
  std::string finish_by_deadline(const std::function<std::string()>& job, const std::string& refusal) const;

 private:
  struct Line;
  std::shared_ptr<Line> line_;
  double max_seconds_;
  std::chrono::steady_clock::time_point start_;
};
/// Adds `--max-time SECONDS` (a positive number) to a certified command.
void add_max_time_option(CLI::App* sub, double& seconds);
/// A certified level set's --tolerance (relative bound width): InputError outside (0, 1).
void check_tolerance(double tolerance);

/// The thresholds of `--levels a,b,c`: decimal numbers, increasing (levels.cpp).
std::vector<double> parse_levels(const std::string& text);

/// Checks, before any work, that every non-empty path can be written: a file
/// name in an existing, writable directory, not a directory itself, no path
/// given twice. Throws io::InputError naming the first that cannot.
void check_outputs(const std::vector<std::string>& paths);
/// A number for text output: printf's %g with `digits` significant digits.
std::string format_g(double v, int digits = 10);
/// Writes several files all or nothing: each goes to a temporary file next to
/// it first; only when all are written are they renamed into place. On any
/// failure the temporary files are removed and nothing is changed.
void write_outputs(const std::vector<std::pair<std::string, std::string>>& files);

/// Milliseconds since `start`.
double elapsed_ms(std::chrono::steady_clock::time_point start);
/// Parses a number argument ("X", "Q1", ...) in decimal notation (no spaces,
/// hexadecimal, inf or nan) or throws io::InputError naming `what`.
using report::parse_number;
/// Largest magnitudes of positions / lengths (the file format's limit) and of
/// angles in degrees accepted on the command line: beyond them the double
/// arithmetic of the kinematics gives nothing meaningful (1e308 overflows).
inline constexpr double max_argument_length = 1e15;
inline constexpr double max_argument_degrees = 1e6;
/// parse_number within those magnitudes; errors name `what`.
double parse_length(const std::string& text, const std::string& what);
double parse_angle(const std::string& text, const std::string& what);
/// Makes every numeric option of `app` and its subcommands as strict as
/// parse_number (CLI11 alone takes "0x10", " 1" and "010" = 8).
void strict_numeric_options(CLI::App& app);

using report::area_unit;
using report::sample_pose;
}  // namespace pkmws::cli
