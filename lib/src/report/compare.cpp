// `pkmws compare` (pkmws/report/compare.hpp): moved from the command line's
// compare.cpp, numbers, JSON, CSV and text unchanged.
#include "pkmws/report/compare.hpp"

#include <sstream>
#include <stdexcept>

#include "pkmws/criteria/fields.hpp"
#include "pkmws/report/common.hpp"
#include "report/json.hpp"
#include "report/text.hpp"

namespace pkmws::report {

using detail::Json;

namespace {

std::string resolution(const grid::CompareRow& row) {
  if (row.method == "exact" || row.method == "certified") return "-";
  std::ostringstream s;
  if (row.method == "adaptive") {
    s << "depth " << row.depth << " (" << row.cells_per_side << "/side)";
  } else {
    s << row.cells_per_side << "^2";
  }
  return s.str();
}

std::string number(std::optional<double> v, const char* fmt) {
  if (!v) return "";
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, *v);
  return buf;
}

Json compare_json(const CompareReport& report) {
  const grid::CompareResult& r = report.result;
  Json rows = Json::array();
  for (const auto& row : r.rows) {
    Json j{{"method", row.method},     {"cells_per_side", row.cells_per_side}, {"points", row.points},
           {"area", row.area},         {"rel_error", row.rel_error},           {"time_ms", row.time_ms},
           {"ratio_to_exact", row.ratio_to_exact}, {"points_per_second", row.points_per_second}};
    if (row.depth >= 0) j["depth"] = row.depth;
    if (row.guaranteed_rel_error) j["guaranteed_rel_error"] = *row.guaranteed_rel_error;
    if (row.time_certified_ms) j["time_certified_ms"] = *row.time_certified_ms;
    rows.push_back(j);
  }
  Json at = Json::array();
  for (const auto& t : r.at_accuracy) {
    Json j{{"method", t.method}, {"accuracy", t.accuracy}, {"target", t.target}, {"extrapolated", t.extrapolated}};
    if (t.time_ms) j["time_ms"] = *t.time_ms;
    if (t.ratio_to_exact) j["ratio_to_exact"] = *t.ratio_to_exact;
    at.push_back(j);
  }
  Json cross = Json::array();
  for (const auto& c : r.crossovers) {
    Json j{{"method", c.method}, {"accuracy", c.accuracy}, {"note", c.note}};
    if (c.rel_error) j["rel_error"] = *c.rel_error;
    cross.push_back(j);
  }
  return Json{{"name", report.name},
              {"mechanism", report.mechanism},
              {"units", report.units},
              {"exact_area", r.exact_area},
              {"exact_time_ms", r.exact_time_ms},
              {"exact_time_min_ms", r.exact_time_min_ms},
              {"exact_time_max_ms", r.exact_time_max_ms},
              {"threads", r.threads},
              {"isa", r.isa},
              {"rows", rows},
              {"time_at_accuracy", at},
              {"crossovers", cross},
              {"notes", r.notes}};
}

}  // namespace

CompareReport compare(const io::MechanismFile& mech, const CompareOptions& options) {
  grid::CompareOptions co;
  co.time_budget_ms = 1000.0 * options.budget_s;
  co.execution.threads = options.threads;
  if (!options.ladder.empty()) co.ladder = options.ladder;
  if (!options.depths.empty()) co.depths = options.depths;
  // With criteria limits the grids sample the limited region and the
  // reference is its certified area (one run: seconds, not microseconds).
  std::shared_ptr<const mechanisms::Mechanism> model = mech.model;
  if (mech.criteria.any()) {
    model = criteria::limited_mechanism(mech);
    co.exact_runs = 1;
    co.reference = [&mech] {
      certified::LevelSetOptions lo;
      lo.relative_tolerance = 1e-6;
      const auto lw = criteria::limited_workspace(mech, criteria::file_limits(mech), lo);
      return grid::CompareOptions::Reference{lw.region.area_estimate(),
                                             0.5 * lw.region.width() / lw.region.area_estimate(), "certified"};
    };
  }
  CompareReport report;
  report.name = mech.name;
  report.mechanism = mech.mechanism;
  report.units = mech.units;
  report.area_units = area_unit(mech);
  report.limited = mech.criteria.any();
  report.exact_runs = co.exact_runs;
  try {
    report.result = grid::compare(*model, co);
  } catch (const std::invalid_argument& e) {
    throw io::InputError(mech.path + ": " + e.what());
  } catch (const std::logic_error& e) {
    throw io::InputError(mech.path + ": " + e.what());
  }
  return report;
}

std::string to_json_text(const CompareReport& report) { return detail::json_text(compare_json(report)); }

std::string to_text(const CompareReport& report) {
  using detail::format;
  const grid::CompareResult& r = report.result;
  std::string t = format("%s (%s)\n", report.name.c_str(), report.mechanism.c_str());
  t += format("%s area %.15g %s, %.3f ms median of %d runs (%s)\n", r.rows.front().method.c_str(), r.exact_area,
              report.area_units.c_str(), r.exact_time_ms, report.exact_runs,
              report.limited ? "certified level sets of the file's criteria, 1e-6" : "build + area");
  t += format("grid: %d thread%s, %s kernel\n\n", r.threads, r.threads == 1 ? "" : "s", r.isa.c_str());
  t += format("%-10s %-22s %13s %20s %10s %10s %11s %9s\n", "method", "resolution", "points", "area", "error",
              "guaranteed", "time ms", "x exact");
  for (const auto& row : r.rows) {
    t += format("%-10s %-22s %13llu %20.12f %10.2e %10s %11.3f %9.3g\n", row.method.c_str(), resolution(row).c_str(),
                static_cast<unsigned long long>(row.points), row.area, row.rel_error,
                number(row.guaranteed_rel_error, "%.2e").c_str(), row.time_ms, row.ratio_to_exact);
  }
  t += "\nerror = |area - exact| / exact (needs the exact area); guaranteed = certified half-width of the\n"
       "bracket / exact (what a grid user can state; uniform grid: its time adds the certified pass)\n\n";
  t += "time to reach a relative accuracy (log-log interpolation; * = extrapolated):\n";
  for (const auto& a : r.at_accuracy) {
    if (!a.time_ms) continue;
    t += format("  %-9s %-10s %.0e: %12.3f ms = %10.3g x exact%s\n", a.method.c_str(), a.accuracy.c_str(), a.target,
                *a.time_ms, *a.ratio_to_exact, a.extrapolated ? " *" : "");
  }
  t += "accuracy reached in the exact computation's time:\n";
  for (const auto& c : r.crossovers) {
    t += format("  %-9s %-10s %s (%s)\n", c.method.c_str(), c.accuracy.c_str(), number(c.rel_error, "%.2e").c_str(),
                c.note.c_str());
  }
  for (const auto& note : r.notes) t += format("note: %s\n", note.c_str());
  return t;
}

std::string to_csv(const CompareReport& report) {
  std::ostringstream s;
  s << "method,cells_per_side,depth,points,area,rel_error,guaranteed_rel_error,time_ms,time_certified_ms,"
       "ratio_to_exact,points_per_second\n";
  for (const auto& row : report.result.rows) {
    s << row.method << ',' << row.cells_per_side << ',' << (row.depth >= 0 ? std::to_string(row.depth) : "")
      << ',' << row.points << ',' << number(row.area, "%.17g") << ',' << number(row.rel_error, "%.6e") << ','
      << number(row.guaranteed_rel_error, "%.6e") << ',' << number(row.time_ms, "%.6g") << ','
      << number(row.time_certified_ms, "%.6g") << ',' << number(row.ratio_to_exact, "%.6g") << ','
      << number(row.points_per_second, "%.6g") << '\n';
  }
  return s.str();
}

}  // namespace pkmws::report
