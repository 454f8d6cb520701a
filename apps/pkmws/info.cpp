// pkmws info FILE [--json]: the parsed mechanism; the report is the library's (pkmws/report/info.hpp).
#include <iostream>

#include "cli.hpp"
#include "pkmws/report/info.hpp"

namespace pkmws::cli {

void add_info(CLI::App& app, std::vector<Command>& commands) {
  auto* sub = app.add_subcommand("info", "Print the parsed mechanism");
  auto file = std::make_shared<std::string>();
  auto json = std::make_shared<bool>(false);
  sub->add_option("FILE", *file, "Mechanism file (JSON)")->required();
  sub->add_flag("--json", *json, "Print the validated document with `derived` (docs/schema/info.output.schema.json)");
  commands.push_back({sub, [file, json] {
    const report::InfoReport r = report::info(io::load_mechanism(*file));
    std::cout << (*json ? report::to_json_text(r) + "\n" : report::to_text(r));
    return 0;
  }});
}

}  // namespace pkmws::cli
