// Design-space sweeps: a base mechanism file, parameters addressed by their
// file paths (`legs[1].rod_length`, `orientation_deg`; several paths tied to
// one value), designs on a grid or a Sobol sequence, and metrics per design.
// A design that is invalid or has an empty workspace is a row with a status
// and the reason, never an aborted sweep. Rows are independent of the thread
// count and of how designs are split across processes (docs/design_space.md).
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "pkmws/geometry/types.hpp"

namespace pkmws::design {

/// One swept parameter: every path in `paths` takes the same value.
struct SweepParameter {
  std::string name;                 // column name (default: the first path)
  std::vector<std::string> paths;   // file paths, e.g. "legs[0].rod_length"
  std::vector<double> values;       // grid sampling: the values, in order
  double from = 0.0, to = 0.0;      // Sobol sampling: the range
};

struct SweepSpec {
  std::filesystem::path base_file;
  std::string base_document;        // the base file's JSON text
  std::vector<SweepParameter> parameters;
  enum class Sampling { grid, sobol };
  Sampling sampling = Sampling::grid;
  std::size_t samples = 0;          // Sobol: number of designs
  std::vector<std::string> metrics; // see metric_names()
  std::vector<geometry::Point> task;  // task polygon for "task_fit" (empty: none)
  double rectangle_precision = 1e-6;  // relative width of the inscribed rectangle
  double criteria_tolerance = 1e-6;   // relative width of certified limited areas
  int interference_depth = 7;         // quadtree depth of real workspaces
  int gci_cells = 128;                // fine-grid cells across the workspace for "gci"
};

/// The metrics a sweep can compute, in column order.
const std::vector<std::string>& metric_names();

/// The metric that gives a column ("rectangle_area" -> "inscribed_rectangle"),
/// "" for a column no metric gives; every metric column, in order.
std::string metric_of_column(const std::string& column);
const std::vector<std::string>& all_metric_columns();

/// Reads and validates a sweep file; throws io::InputError naming the field.
SweepSpec load_sweep(const std::filesystem::path& file);

/// Number of designs, and the parameter values of design `index` (grid:
/// the first parameter varies slowest; Sobol: the index-th point).
std::size_t design_count(const SweepSpec& spec);
std::vector<double> design_values(const SweepSpec& spec, std::size_t index);

/// One row of the result.
struct DesignRow {
  std::size_t index = 0;
  std::vector<double> values;       // one per parameter
  std::string status;               // "ok", "invalid", "empty", "failed"
  std::string reason;               // why not "ok"
  std::vector<std::optional<double>> metrics;  // one per metric column
  double time_ms = 0.0;
};

/// Metric columns of the spec (a metric may give several columns).
std::vector<std::string> metric_columns(const SweepSpec& spec);

/// Evaluates one design (never throws for a bad design: the row says why).
DesignRow evaluate_design(const SweepSpec& spec, std::size_t index);
/// The same for any parameter values (one per parameter, in order), e.g. a
/// point an optimiser asks for; `index` only labels the row.
DesignRow evaluate_design(const SweepSpec& spec, std::size_t index, const std::vector<double>& values);

/// Evaluates the designs `indices` on `threads` threads (0: all, 1: serial),
/// calling `done(row)` from the calling thread's side in completion order,
/// serialised; returns the rows ordered by index.
std::vector<DesignRow> run_sweep(const SweepSpec& spec, const std::vector<std::size_t>& indices, int threads,
                                 const std::function<void(const DesignRow&)>& done = {});

/// CSV: header and one line per row (numbers round-trip: %.17g; no time
/// column when `timing` is false, so that outputs compare byte for byte).
std::string csv_header(const SweepSpec& spec, bool timing);
std::string csv_line(const DesignRow& row, bool timing);
/// The fields of one CSV line (RFC 4180 quoting).
std::vector<std::string> split_csv(const std::string& line);
/// Parses a line written by csv_line (for --resume and --merge); nullopt if
/// it is incomplete or malformed.
std::optional<DesignRow> parse_csv_line(const std::string& line, std::size_t parameters, std::size_t metrics,
                                        bool timing);

}  // namespace pkmws::design
