// pkmws grid FILE --cells N [--polar] [--adaptive DEPTH] [--sweep] [--threads K] [--json]:
// the grid baseline (docs/format.md (command line); [Vasilic] §4.1-4.2, figs. 4 and 8);
// the report is the library's (pkmws/report/grid.hpp).
#include <iostream>

#include "cli.hpp"
#include "pkmws/report/grid.hpp"

namespace pkmws::cli {

void add_grid(CLI::App& app, std::vector<Command>& commands) {
  // 16384^2 = 2.7e8 point tests: seconds with the MOMA kernel, minutes with the
  // slowest membership tests; finer resolution is what --adaptive is for.
  constexpr std::size_t max_grid_cells = std::size_t{1} << 14;
  auto* sub = app.add_subcommand("grid", "Grid estimate of the workspace area (the papers' sampling baseline)");
  struct Options {
    std::string file;
    report::GridOptions grid;
    bool json = false;
  };
  auto o = std::make_shared<Options>();
  sub->add_option("FILE", o->file, "Mechanism file (JSON)")->required();
  sub->add_option("--cells", o->grid.cells,
                  "Cells per side: N x N Cartesian cells over the bounding box; with --polar N rings x ~pi N "
                  "sectors; with --adaptive the root grid; with --sweep the raster")
      ->required()
      ->check(CLI::Range(std::size_t{1}, max_grid_cells));
  sub->add_flag("--polar", o->grid.polar, "Polar grid about the centre of the bounding box ([Vasilic] figs. 9-11a)");
  sub->add_option("--adaptive", o->grid.adaptive, "Quadtree refined DEPTH levels below the root grid")
      ->check(CLI::Range(0, 30));
  sub->add_flag("--sweep", o->grid.sweep, "Joint-space sweep through the direct kinematics ([Vasilic] fig. 4)");
  sub->add_option("--samples", o->grid.samples, "Joint samples per joint for --sweep (default 5 N)")
      ->check(CLI::Range(std::size_t{2}, std::size_t{1} << 16));
  sub->add_option("--threads", o->grid.threads, "Threads (0 = all)")->check(CLI::Range(0, 1024));
  sub->add_option("--isa", o->grid.isa, "Kernel instruction set: scalar, baseline, avx2, avx512, best");
  sub->add_flag("--json", o->json, "Print one JSON object");
  commands.push_back({sub, [o] {
    const report::GridReport r = report::grid(io::load_mechanism(o->file), o->grid);
    std::cout << (o->json ? report::to_json_text(r) + "\n" : report::to_text(r));
    return 0;
  }});
}

}  // namespace pkmws::cli
