// `pkmws sweep`: metrics over a design space (pkmws/design/sweep.hpp;
// docs/design_space.md): the sweep's CSV (one row per design, ordered by
// index), read back for --resume and --merge, its rows as JSON (--json FILE)
// and the summary line.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "pkmws/design/sweep.hpp"

namespace pkmws::report {

/// A sweep CSV read back: its header line and its rows.
struct SweepCsv {
  std::string header;
  std::vector<design::DesignRow> rows;
  bool timing = false;  // a time_ms column before `reason`
};

/// Reads a sweep CSV. A last line without its line break was cut short by a
/// kill: it is left out (and so evaluated again on --resume). Throws
/// InputError naming the file (not a sweep CSV) or the line (a malformed row).
SweepCsv read_sweep_csv(const std::filesystem::path& path);
/// Joins shard CSVs, ordered by design index. Throws InputError naming the
/// file holding a design twice or whose columns differ from the first's.
SweepCsv merge_sweep_csvs(const std::vector<std::string>& parts);
/// The CSV text: the header, then one line per row.
std::string csv_text(const SweepCsv& csv);

struct SweepReport {
  design::SweepSpec spec;
  std::vector<design::DesignRow> rows;  // every design of the sweep (or shard), by index
  std::size_t evaluated = 0;            // designs evaluated by this run (not resumed)
  double seconds = 0.0;                 // the run's wall time
  std::string output;                   // the CSV written
};

/// `--json FILE`: base, parameters, metrics, columns and the rows, one object
/// per design (indented by 1, a trailing newline; a metric not computed is null).
std::string rows_json_text(const SweepReport& report);
/// `pkmws sweep`: "N designs (counts by status) -> OUT; K evaluated in S s (R designs/s)".
std::string to_text(const SweepReport& report);
/// `pkmws sweep --merge`: "merged N designs from K files into OUT".
std::string merge_text(const SweepCsv& merged, std::size_t files, const std::string& output);

}  // namespace pkmws::report
