// pkmws atlas SWEEP.csv --x COL --y COL --metric COL -o OUT.svg: a metric of
// a two-parameter grid sweep as a filled contour map (docs/design_space.md).
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <set>

#include "cli.hpp"
#include "pkmws/design/sweep.hpp"
#include "pkmws/io/atlas.hpp"
#include "pkmws/io/export.hpp"

namespace pkmws::cli {

void add_atlas(CLI::App& app, std::vector<Command>& commands) {
  auto* sub = app.add_subcommand("atlas", "A metric over two swept parameters as a contour map (from a sweep CSV)");
  struct Args {
    std::string csv, x, y, metric, out, title, x_label, y_label, metric_label;
    bool minimize = false;
    bool json = false;
  };
  auto a = std::make_shared<Args>();
  sub->add_option("CSV", a->csv, "Output of pkmws sweep (a grid over at least two parameters)")->required();
  sub->add_option("--x", a->x, "Parameter column on the horizontal axis")->required();
  sub->add_option("--y", a->y, "Parameter column on the vertical axis")->required();
  sub->add_option("--metric", a->metric, "Metric column to map")->required();
  sub->add_option("-o,--out", a->out, "Output SVG")->required();
  sub->add_option("--title", a->title, "Figure title (default: metric over the two parameters)");
  sub->add_option("--x-label", a->x_label, "Horizontal axis title with unit (default: the column name)");
  sub->add_option("--y-label", a->y_label, "Vertical axis title with unit (default: the column name)");
  sub->add_option("--metric-label", a->metric_label, "Colour bar title with unit (default: the column name)");
  sub->add_flag("--minimize", a->minimize, "Mark the smallest value instead of the largest");
  sub->add_flag("--json", a->json, "Print one JSON object (docs/schema/atlas.output.schema.json)");
  commands.push_back({sub, [a] {
    std::ifstream in(a->csv);
    if (!in) throw io::InputError(a->csv + ": cannot open");
    std::string line;
    if (!std::getline(in, line)) throw io::InputError(a->csv + ": empty file");
    const std::vector<std::string> header = design::split_csv(line);
    const auto column = [&](const std::string& name, const char* option) {
      for (std::size_t k = 0; k < header.size(); ++k) {
        if (header[k] == name) return k;
      }
      std::string names;
      for (const auto& h : header) names += (names.empty() ? "" : ", ") + h;
      throw io::InputError(std::string(option) + ": no column '" + name + "' in " + a->csv + " (columns: " + names + ")");
    };
    const std::size_t cx = column(a->x, "--x"), cy = column(a->y, "--y"), cm = column(a->metric, "--metric"),
                      cs = column("status", "status");
    std::map<std::pair<double, double>, std::optional<double>> values;
    std::set<double> xs, ys;
    std::size_t number = 1;
    while (std::getline(in, line)) {
      ++number;
      if (line.empty()) continue;
      const auto f = design::split_csv(line);
      if (f.size() != header.size()) throw io::InputError(a->csv + ":" + std::to_string(number) + ": malformed row");
      const double x = parse_number(f[cx], a->x), y = parse_number(f[cy], a->y);
      std::optional<double> v;
      if (f[cs] == "ok" && !f[cm].empty()) v = parse_number(f[cm], a->metric);
      if (!values.emplace(std::pair{x, y}, v).second) {
        throw io::InputError(a->csv + ":" + std::to_string(number) + ": a second design at (" + f[cx] + ", " + f[cy] +
                             "): the other parameters vary too (sweep two parameters, or filter the rows)");
      }
      xs.insert(x);
      ys.insert(y);
    }
    io::AtlasData d;
    d.xs.assign(xs.begin(), xs.end());
    d.ys.assign(ys.begin(), ys.end());
    for (double y : d.ys) {
      for (double x : d.xs) {
        const auto it = values.find({x, y});
        d.z.push_back(it == values.end() ? std::nullopt : it->second);
      }
    }
    d.x_label = a->x_label.empty() ? a->x : a->x_label;
    d.y_label = a->y_label.empty() ? a->y : a->y_label;
    d.metric_label = a->metric_label.empty() ? a->metric : a->metric_label;
    d.title = a->title.empty() ? a->metric + " over " + a->x + " \u00d7 " + a->y : a->title;
    d.maximize = !a->minimize;
    std::string svg;
    try {
      svg = io::atlas_figure(d);
    } catch (const std::invalid_argument& e) {
      throw io::InputError(a->csv + ": " + e.what());
    }
    io::write_file_atomic(a->out, svg);
    if (a->json) {
      std::size_t missing = 0;
      for (const auto& z : d.z) missing += z ? 0 : 1;
      print_json(Json{{"csv", a->csv}, {"x", a->x}, {"y", a->y}, {"metric", a->metric}, {"output", a->out},
                      {"columns", d.xs.size()}, {"rows", d.ys.size()}, {"cells_without_value", missing},
                      {"marked", a->minimize ? "smallest" : "largest"}});
      return 0;
    }
    std::printf("atlas of %s over %zu x %zu designs -> %s\n", a->metric.c_str(), d.xs.size(), d.ys.size(),
                a->out.c_str());
    return 0;
  }});
}

}  // namespace pkmws::cli
