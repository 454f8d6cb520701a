// pkmws plot FILE --out DIR: the curves of a 1-DOF mechanism as SVG line
// charts (the active Pi-joint: [Milutinovic] figures 8-12 and 15-17); the
// report is the library's (pkmws/report/plot.hpp).
#include <filesystem>
#include <iostream>

#include "cli.hpp"
#include "pkmws/io/export.hpp"
#include "pkmws/report/plot.hpp"

namespace pkmws::cli {

void add_plot(CLI::App& app, std::vector<Command>& commands) {
  auto* sub = app.add_subcommand("plot", "Curves of a 1-DOF mechanism (Pi-joint figures) as SVG charts");
  struct Args {
    std::string file, out;
    bool json = false;
  };
  auto a = std::make_shared<Args>();
  sub->add_option("FILE", a->file, "Mechanism file (JSON)")->required();
  sub->add_option("--out,-o", a->out, "Output directory (must exist)")->required();
  sub->add_flag("--json", a->json, "Print one JSON object (docs/schema/plot.output.schema.json)");
  commands.push_back({sub, [a] {
    const auto mech = io::load_mechanism(a->file);
    if (!std::filesystem::is_directory(a->out)) throw io::InputError(a->out + ": no such directory");
    const report::PlotReport r = report::plot(mech, a->out);
    for (const auto& f : r.figures) io::write_file_atomic(std::filesystem::path(a->out) / f.file, f.svg);
    std::cout << (a->json ? report::to_json_text(r) + "\n" : report::to_text(r));
    return 0;
  }});
}

}  // namespace pkmws::cli
