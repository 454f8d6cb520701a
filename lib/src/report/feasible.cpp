// `pkmws feasible` (pkmws/report/feasible.hpp): moved from the command line's
// optimize.cpp, report, files and text unchanged. The report's JSON is the
// design layer's (design::feasible_report).
#include "pkmws/report/feasible.hpp"

#include "pkmws/report/common.hpp"
#include "report/text.hpp"

namespace pkmws::report {

FeasibleReport feasible(const std::string& csv, const std::vector<std::string>& conditions) {
  return FeasibleReport{csv, design::feasible_set(csv, conditions)};
}

std::string to_json_text(const FeasibleReport& r) {
  return json_with_null_reasons(design::feasible_report(r.set, r.csv));
}

std::string report_file_text(const FeasibleReport& r) { return design::feasible_report(r.set, r.csv) + "\n"; }

std::string boxes_csv(const FeasibleReport& r) { return design::feasible_csv(r.set); }

std::string figure(const FeasibleReport& r) {
  if (r.set.parameters.size() != 2) {
    throw io::InputError("--svg: draws a sweep over two parameters (" + r.csv + " has " +
                         std::to_string(r.set.parameters.size()) + ")");
  }
  return design::feasible_figure(r.set);
}

std::string to_text(const FeasibleReport& report) {
  using detail::format;
  const design::FeasibleSet& set = report.set;
  const auto g = [](double v) { return format("%.10g", v); };
  std::string t = format("feasible: %zu of %zu designs, %zu of %zu cells (every corner feasible), %zu box(es)\n",
                         set.feasible_designs, set.designs, set.feasible_cells, set.cells, set.boxes.size());
  for (std::size_t b = 0; b < set.boxes.size(); ++b) {
    std::string line;
    for (std::size_t k = 0; k < set.parameters.size(); ++k) {
      line += (k ? ", " : "") + set.parameters[k] + " in [" + g(set.boxes[b].min[k]) + ", " + g(set.boxes[b].max[k]) +
              "]";
    }
    t += format("  box %zu (%zu cells): %s\n", b, set.boxes[b].cells, line.c_str());
  }
  t += "sampled at the grid's designs, not certified between them\n";
  return t;
}

}  // namespace pkmws::report
