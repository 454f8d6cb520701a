// pkmws plot FILE --out DIR: the curves of a 1-DOF mechanism as SVG line
// charts (the active Pi-joint: [Milutinovic] figures 8-12 and 15-17).
#include <cstdio>
#include <filesystem>

#include "cli.hpp"
#include "pkmws/io/export.hpp"
#include "pkmws/io/plot.hpp"

namespace pkmws::cli {

std::vector<std::string> write_curve_figures(const io::MechanismFile& mech, const std::string& dir) {
  const auto charts = mech.model->capability<io::Charts>();
  if (!charts) {
    throw io::InputError(mech.path + ": `plot` draws the curves of a pi_joint file (" + charts.reason() +
                         "); use `export` for the workspace of a " + mech.mechanism);
  }
  std::vector<std::string> files;
  for (const auto& figure : charts->charts()) {
    const std::string name = figure.stem + ".svg";
    io::write_file_atomic(std::filesystem::path(dir) / name, io::line_chart_svg(figure.chart));
    files.push_back(name);
  }
  return files;
}

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
    const auto files = write_curve_figures(mech, a->out);
    if (a->json) {
      print_json(Json{{"name", mech.name}, {"mechanism", mech.mechanism}, {"units", mech.units},
                      {"output_dir", a->out}, {"figures", files}});
      return 0;
    }
    for (const auto& f : files) std::printf("%s/%s\n", a->out.c_str(), f.c_str());
    return 0;
  }});
}

}  // namespace pkmws::cli
