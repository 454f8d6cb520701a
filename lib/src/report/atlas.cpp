// `pkmws atlas` (pkmws/report/atlas.hpp): moved from the command line's
// atlas.cpp, figure, JSON and text unchanged.
#include "pkmws/report/atlas.hpp"

#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>

#include "pkmws/design/sweep.hpp"
#include "pkmws/report/common.hpp"
#include "report/json.hpp"
#include "report/text.hpp"

namespace pkmws::report {

using detail::Json;

AtlasReport atlas(const AtlasOptions& a) {
  std::ifstream in(a.csv);
  if (!in) throw io::InputError(a.csv + ": cannot open");
  std::string line;
  if (!std::getline(in, line)) throw io::InputError(a.csv + ": empty file");
  const std::vector<std::string> header = design::split_csv(line);
  const auto column = [&](const std::string& name, const char* option) {
    for (std::size_t k = 0; k < header.size(); ++k) {
      if (header[k] == name) return k;
    }
    std::string names;
    for (const auto& h : header) names += (names.empty() ? "" : ", ") + h;
    throw io::InputError(std::string(option) + ": no column '" + name + "' in " + a.csv + " (columns: " + names + ")");
  };
  const std::size_t cx = column(a.x, "--x"), cy = column(a.y, "--y"), cm = column(a.metric, "--metric"),
                    cs = column("status", "status");
  std::map<std::pair<double, double>, std::optional<double>> values;
  std::set<double> xs, ys;
  std::size_t number = 1;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty()) continue;
    const auto f = design::split_csv(line);
    if (f.size() != header.size()) throw io::InputError(a.csv + ":" + std::to_string(number) + ": malformed row");
    const double x = parse_number(f[cx], a.x), y = parse_number(f[cy], a.y);
    std::optional<double> v;
    if (f[cs] == "ok" && !f[cm].empty()) v = parse_number(f[cm], a.metric);
    if (!values.emplace(std::pair{x, y}, v).second) {
      throw io::InputError(a.csv + ":" + std::to_string(number) + ": a second design at (" + f[cx] + ", " + f[cy] +
                           "): the other parameters vary too (sweep two parameters, or filter the rows)");
    }
    xs.insert(x);
    ys.insert(y);
  }
  AtlasReport r;
  r.options = a;
  io::AtlasData& d = r.data;
  d.xs.assign(xs.begin(), xs.end());
  d.ys.assign(ys.begin(), ys.end());
  for (double y : d.ys) {
    for (double x : d.xs) {
      const auto it = values.find({x, y});
      d.z.push_back(it == values.end() ? std::nullopt : it->second);
    }
  }
  d.x_label = a.x_label.empty() ? a.x : a.x_label;
  d.y_label = a.y_label.empty() ? a.y : a.y_label;
  d.metric_label = a.metric_label.empty() ? a.metric : a.metric_label;
  d.title = a.title.empty() ? a.metric + " over " + a.x + " \u00d7 " + a.y : a.title;
  d.maximize = !a.minimize;
  try {
    r.svg = io::atlas_figure(d);
  } catch (const std::invalid_argument& e) {
    throw io::InputError(a.csv + ": " + e.what());
  }
  for (const auto& z : d.z) r.missing += z ? 0 : 1;
  return r;
}

std::string to_json_text(const AtlasReport& r) {
  const AtlasOptions& a = r.options;
  return detail::json_text(Json{{"csv", a.csv},
                                {"x", a.x},
                                {"y", a.y},
                                {"metric", a.metric},
                                {"output", a.output},
                                {"columns", r.data.xs.size()},
                                {"rows", r.data.ys.size()},
                                {"cells_without_value", r.missing},
                                {"marked", a.minimize ? "smallest" : "largest"}});
}

std::string to_text(const AtlasReport& r) {
  return detail::format("atlas of %s over %zu x %zu designs -> %s\n", r.options.metric.c_str(), r.data.xs.size(),
                        r.data.ys.size(), r.options.output.c_str());
}

}  // namespace pkmws::report
