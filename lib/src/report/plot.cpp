// `pkmws plot` (pkmws/report/plot.hpp): moved from the command line's plot.cpp,
// figures, JSON and text unchanged.
#include "pkmws/report/plot.hpp"

#include "pkmws/io/plot.hpp"
#include "report/json.hpp"

namespace pkmws::report {

using detail::Json;

PlotReport plot(const io::MechanismFile& mech, const std::string& output_dir) {
  const auto charts = mech.model->capability<io::Charts>();
  if (!charts) {
    throw io::InputError(mech.path + ": `plot` draws the curves of a pi_joint file (" + charts.reason() +
                         "); use `export` for the workspace of a " + mech.mechanism);
  }
  PlotReport r{mech.name, mech.mechanism, mech.units, output_dir, {}};
  for (const auto& figure : charts->charts()) r.figures.push_back({figure.stem + ".svg", io::line_chart_svg(figure.chart)});
  return r;
}

std::string to_json_text(const PlotReport& r) {
  Json files = Json::array();
  for (const auto& f : r.figures) files.push_back(f.file);
  return detail::json_text(Json{{"name", r.name}, {"mechanism", r.mechanism}, {"units", r.units},
                                {"output_dir", r.output_dir}, {"figures", files}});
}

std::string to_text(const PlotReport& r) {
  std::string t;
  for (const auto& f : r.figures) t += r.output_dir + "/" + f.file + "\n";
  return t;
}

}  // namespace pkmws::report
