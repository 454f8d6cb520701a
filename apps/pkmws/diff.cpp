// pkmws diff A.json B.json [-o FIG.svg] [--json]: two designs compared
// (docs/design_space.md, "Comparing designs"): the areas of A ∩ B, A − B,
// B − A and A ∪ B, the change of every sweep metric, and both workspaces in
// one figure; the report is the library's (pkmws/report/diff.hpp).
#include <iostream>

#include "cli.hpp"
#include "pkmws/report/diff.hpp"

namespace pkmws::cli {

void add_diff(CLI::App& app, std::vector<Command>& commands) {
  auto* sub = app.add_subcommand("diff", "Compare two designs: A ∩ B, A − B, B − A and every metric's change");
  struct Args {
    std::string a, b;
    report::DiffOptions options;
    bool json = false;
  };
  auto args = std::make_shared<Args>();
  sub->add_option("A", args->a, "First mechanism file (JSON)")->required();
  sub->add_option("B", args->b, "Second mechanism file (JSON), in the same length unit")->required();
  sub->add_option("-o,--output", args->options.figure, "Write the figure (SVG): A only, B only, A ∩ B");
  sub->add_flag("--json", args->json, "Print one JSON object");
  sub->add_option("--rectangle-precision", args->options.rectangle_precision,
                  "Relative width of the inscribed rectangle's bounds (default 1e-6)")
      ->check(CLI::Range(1e-12, 0.5));
  sub->add_option("--criteria-tolerance", args->options.criteria_tolerance,
                  "Files with criteria: relative width of the certified limited area (default 1e-4)")
      ->check(CLI::Range(1e-9, 0.5));
  sub->add_option("--gci-cells", args->options.gci_cells, "Fine-grid cells across a workspace for the GCI (default 128)")
      ->check(CLI::Range(2, 4096));
  commands.push_back({sub, [args] {
    check_outputs({args->options.figure});
    const io::MechanismFile a = io::load_mechanism(args->a);
    const io::MechanismFile b = io::load_mechanism(args->b);
    const report::DiffReport r = report::diff(a, b, args->options);
    if (!r.svg.empty()) write_outputs({{r.figure, r.svg}});
    std::cout << (args->json ? report::to_json_text(r) + "\n" : report::to_text(r));
    return 0;
  }});
}

}  // namespace pkmws::cli
