// `pkmws batch` (pkmws/report/batch.hpp): moved from the command line's
// batch.cpp, rows, summaries, JSON and text unchanged; the rows come from the
// area report's struct (not its JSON text parsed back).
#include "pkmws/report/batch.hpp"

#include <filesystem>

#include "pkmws/criteria/fields.hpp"
#include "pkmws/io/figure.hpp"
#include "pkmws/report/common.hpp"
#include "pkmws/report/figure.hpp"
#include "pkmws/report/plot.hpp"
#include "report/json.hpp"
#include "report/text.hpp"

namespace pkmws::report {

using detail::Json;
using detail::format;

namespace {

Json row_json(const BatchRow& r) {
  Json row{{"file", r.file}, {"name", r.name}, {"mechanism", r.mechanism}};
  if (!r.has_area) {
    row["note"] = r.note;
    if (r.charts) row["charts"] = *r.charts;
    return row;
  }
  row["area"] = r.area;
  row["area_lower"] = r.area_lower;
  row["area_upper"] = r.area_upper;
  row["method"] = r.method;
  row["time_ms"] = r.time_ms;
  if (!r.criteria.empty()) {
    Json lim = Json::array();
    for (const auto& l : r.criteria) lim.push_back(detail::criterion_limit_json(l));
    row["criteria"] = lim;
  }
  if (r.real) {
    row["real_area"] = r.real->area;
    row["real_area_lower"] = r.real->lower;
    row["real_area_upper"] = r.real->upper;
    row["real_method"] = r.real->method;
  }
  row["units"] = r.units;
  if (r.components) {
    row["components"] = *r.components;
  } else {
    row["components"] = nullptr;  // not enumerated for certified level sets
    row["components_reason"] = "not enumerated for a criteria-limited workspace (certified level sets)";
  }
  row["figure"] = r.figure;
  return row;
}

Json rows_json(const BatchReport& report) {
  Json rows = Json::array();
  for (const auto& r : report.rows) rows.push_back(row_json(r));
  return rows;
}

}  // namespace

BatchRow batch_row(const io::MechanismFile& mech) {
  BatchRow row;
  row.file = mech.path;
  row.stem = std::filesystem::path(mech.path).stem().string();
  row.name = mech.name;
  row.mechanism = mech.mechanism;
  row.units = mech.units;
  row.area_units = area_unit(mech);
  AreaReport result;
  try {
    AreaOptions options;
    options.figure_pieces = true;  // the row's figure draws the limited workspace's pieces
    result = area(mech, options);
  } catch (const std::exception& e) {
    row.note = e.what();
    if (mech.model->dof() == 1) {  // its curves instead of a region
      row.charts.emplace();
      for (auto& f : plot(mech, "").figures) {
        row.charts->push_back(f.file);
        row.files.push_back({f.file, std::move(f.svg)});
      }
    }
    return row;
  }
  row.has_area = true;
  row.area = result.area;
  row.area_lower = result.area_lower;
  row.area_upper = result.area_upper;
  row.method = result.method;
  row.time_ms = result.time_ms;
  if (result.limited) {
    row.criteria = result.criteria;
    row.reachable_area = criteria::criteria_domain(mech).area();
    row.reachable_exact = criteria::criteria_domain_exact(mech);
  } else {
    row.components = result.components.size();
  }
  if (result.real) {
    const auto& real = result.real->real;
    row.real = BatchRow::Real{real.area_estimate(), real.area_lower, real.area_upper, real.method()};
  }
  row.figure = row.stem + ".svg";
  row.files.push_back({row.figure, area_figure(mech, result)});
  return row;
}

std::string to_json_text(const BatchReport& report) {
  return detail::json_text(Json{{"output_dir", report.output_dir}, {"summary", "summary.json"}, {"rows", rows_json(report)}});
}

std::string summary_json(const BatchReport& report) { return rows_json(report).dump(2) + "\n"; }

std::string summary_markdown(const BatchReport& report) {
  std::string md =
      "| file | name | mechanism | area | certified bounds | unit | method | components | compute time (ms) | figure "
      "| limits / real workspace |\n"
      "|---|---|---|---:|---|---|---|---:|---:|---|---|\n";
  for (const auto& r : report.rows) {
    if (!r.has_area) {
      std::string links;
      if (r.charts) {
        for (const auto& c : *r.charts) links += " [" + c + "](" + c + ")";
      }
      md += "| " + r.stem + " | " + r.name + " | " + r.mechanism + " | – | | | | | | " + r.note + links + " | |\n";
      continue;
    }
    std::string note;
    if (!r.criteria.empty()) {
      std::string limits;
      for (const auto& c : r.criteria) {
        limits += (limits.empty() ? "" : ", ") + criterion_limit_text(c, r.units);
      }
      note = "limited by " + limits + " (reachable " + (r.reachable_exact ? "" : "≤ ") +
             format("%.10g", r.reachable_area) + ")";
    } else if (r.real) {
      note = "real: " + io::interval_text(r.real->lower, r.real->upper, 10) + " (" + r.real->method + ")";
    }
    const std::string bounds = r.method == "exact" ? "exact" : io::interval_text(r.area_lower, r.area_upper, 10);
    const std::string comps = r.components ? std::to_string(*r.components) : "–";
    md += "| " + r.stem + " | " + r.name + " | " + r.mechanism + " | " + format("%.10g", r.area) + " | " + bounds +
          " | " + r.area_units + " | " + r.method + " | " + comps + " | " + format("%.1f", r.time_ms) + " | [" +
          r.figure + "](" + r.figure + ") | " + note + " |\n";
  }
  md += std::string("\ncompute time: ") + kComputeTimeMeaning +
        " (the `time_ms` of `pkmws area --json`, one file at a time).\n";
  return md;
}

std::string to_text(const BatchRow& r) {
  if (!r.has_area) return "";
  return format("%-34s %18.10g %s  %s\n", r.stem.c_str(), r.area, r.area_units.c_str(),
                r.method == "exact" ? "exact" : ("certified " + io::interval_text(r.area_lower, r.area_upper, 10)).c_str());
}

std::string to_text(const BatchReport& report) {
  std::size_t figures = 0;
  for (const auto& r : report.rows) figures += r.has_area ? 1 : 0;
  return format("wrote %zu figures and summary.md to %s (%zu files without a planar workspace are listed with the reason)\n",
                figures, report.output_dir.c_str(), report.rows.size() - figures);
}

}  // namespace pkmws::report
