// pkmws explain FILE X Y [--json]: which parts collide at that platform
// position (docs/format.md (bodies)); the report is the library's
// (pkmws/report/explain.hpp).
#include <iostream>

#include "cli.hpp"
#include "pkmws/report/explain.hpp"

namespace pkmws::cli {

void add_explain(CLI::App& app, std::vector<Command>& commands) {
  auto* sub = app.add_subcommand("explain", "Which parts collide at a platform position (needs `bodies`)");
  struct Args {
    std::string file, x, y;
    bool json = false;
  };
  auto a = std::make_shared<Args>();
  sub->add_option("FILE", a->file, "Mechanism file (JSON) with bodies")->required();
  sub->add_option("X", a->x, "Platform x")->required();
  sub->add_option("Y", a->y, "Platform y")->required();
  sub->add_flag("--json", a->json, "Print one JSON object");
  commands.push_back({sub, [a] {
    const double x = parse_length(a->x, "X"), y = parse_length(a->y, "Y");
    const report::ExplainReport r = report::explain(io::load_mechanism(a->file), {x, y});
    std::cout << (a->json ? report::to_json_text(r) + "\n" : report::to_text(r));
    return 0;
  }});
}

}  // namespace pkmws::cli
