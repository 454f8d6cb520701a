// pkmws compare FILE [--json] [--csv OUT]: exact area against the grid
// baseline along a ladder of resolutions (docs/format.md (command line), docs/benchmarks.md);
// the report is the library's (pkmws/report/compare.hpp).
#include <iostream>

#include "cli.hpp"
#include "pkmws/io/export.hpp"
#include "pkmws/report/compare.hpp"

namespace pkmws::cli {

void add_compare(CLI::App& app, std::vector<Command>& commands) {
  auto* sub = app.add_subcommand("compare", "Exact area against grid estimates at several resolutions");
  struct Options {
    std::string file;
    bool json = false;
    std::string csv;
    report::CompareOptions compare;
  };
  auto o = std::make_shared<Options>();
  sub->add_option("FILE", o->file, "Mechanism file (JSON)")->required();
  sub->add_flag("--json", o->json, "Print one JSON object");
  sub->add_option("--csv", o->csv, "Also write the rows as CSV to this file");
  sub->add_option("--budget", o->compare.budget_s, "Stop a ladder after the first step slower than this (seconds)")
      ->check(CLI::PositiveNumber);
  sub->add_option("--threads", o->compare.threads, "Threads (0 = all)")->check(CLI::Range(0, 1024));
  sub->add_option("--ladder", o->compare.ladder, "Cells per side of the uniform grids (default 100 ... 16000)")
      ->check(CLI::Range(std::size_t{1}, std::size_t{1} << 14));  // as pkmws grid --cells
  sub->add_option("--depths", o->compare.depths, "Quadtree depths (default 2 4 ... 20, at most 20)")
      ->check(CLI::Range(0, 20));
  commands.push_back({sub, [o] {
    check_outputs({o->csv});  // before minutes of work, not after
    const report::CompareReport r = report::compare(io::load_mechanism(o->file), o->compare);
    if (!o->csv.empty()) io::write_file_atomic(o->csv, report::to_csv(r));
    std::cout << (o->json ? report::to_json_text(r) + "\n" : report::to_text(r));
    return 0;
  }});
}

}  // namespace pkmws::cli
