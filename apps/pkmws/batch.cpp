// pkmws batch FILES... --out DIR: the main job of `make demo`. For every
// mechanism file: what `pkmws area` reports (the same computation: criteria
// files give their certified limited area, files with bodies add the real
// workspace), the figure `pkmws export -f svg` draws, and one row of a summary
// table (DIR/summary.md, DIR/summary.json). Files without a planar workspace
// (a lone Pi-joint) are listed with the reason instead.
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "cli.hpp"
#include "pkmws/criteria/fields.hpp"
#include "pkmws/io/export.hpp"
#include "pkmws/report/figure.hpp"

namespace pkmws::cli {

namespace {

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

}  // namespace

void add_batch(CLI::App& app, std::vector<Command>& commands) {
  auto* sub = app.add_subcommand("batch", "Areas and figures of many mechanism files, with a summary table");
  struct Args {
    std::vector<std::string> files;
    std::string out;
    bool json = false;
  };
  auto a = std::make_shared<Args>();
  sub->add_option("FILES", a->files, "Mechanism files (JSON)")->required();
  sub->add_option("--out,-o", a->out, "Output directory (created if missing)")->required();
  sub->add_flag("--json", a->json, "Print one JSON object: the summary rows (docs/schema/batch.output.schema.json)");
  commands.push_back({sub, [a] {
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::create_directories(a->out, ec);
    if (ec) throw io::InputError(a->out + ": cannot create directory: " + ec.message());
    // Load everything first: one bad file stops the run before anything is written.
    std::vector<io::MechanismFile> mechs;
    for (const auto& f : a->files) mechs.push_back(io::load_mechanism(f));
    Json rows = Json::array();
    std::string md =
        "| file | name | mechanism | area | certified bounds | unit | method | components | compute time (ms) | figure "
        "| limits / real workspace |\n"
        "|---|---|---|---:|---|---|---|---:|---:|---|---|\n";
    for (const auto& mech : mechs) {
      const std::string stem = fs::path(mech.path).stem().string();
      Json row{{"file", mech.path}, {"name", mech.name}, {"mechanism", mech.mechanism}};
      report::AreaReport result;
      try {
        result = report::area(mech);
      } catch (const std::exception& e) {
        row["note"] = e.what();
        std::string links;
        if (mech.model->dof() == 1) {  // its curves instead of a region
          const auto charts = write_curve_figures(mech, a->out);
          row["charts"] = charts;
          for (const auto& c : charts) links += " [" + c + "](" + c + ")";
        }
        rows.push_back(row);
        md += "| " + stem + " | " + mech.name + " | " + mech.mechanism + " | – | | | | | | " + std::string(e.what()) +
              links + " | |\n";
        continue;
      }
      // The numbers of `pkmws area --json`, under the same names.
      const Json rep = Json::parse(report::to_json_text(result));
      const double area = rep["area"], lo = rep["area_lower"], hi = rep["area_upper"];
      const std::string method = rep["method"];
      for (const char* key : {"area", "area_lower", "area_upper", "method", "time_ms", "criteria", "real_area",
                              "real_area_lower", "real_area_upper", "real_method"}) {
        if (rep.contains(key)) row[key] = rep[key];
      }
      row["units"] = mech.units;
      row["components"] = rep["components"].size();
      std::string note;
      if (result.limited) {
        std::string limits;
        for (const auto& c : rep["criteria"]) {
          limits += (limits.empty() ? "" : ", ") + c["criterion"].get<std::string>() + " <= " +
                    fmt("%g", c["threshold"].get<double>());
        }
        note = "limited by " + limits + " (reachable " + fmt("%.10g", criteria::criteria_domain(mech).area()) + ")";
        row["components"] = nullptr;  // not enumerated for certified level sets
        row["components_reason"] = "not enumerated for a criteria-limited workspace (certified level sets)";
      } else if (result.real) {
        note = "real: " + io::interval_text(result.real->real.area_lower, result.real->real.area_upper, 10) + " (" +
               result.real->real.method() + ")";
      }
      const std::string svg = stem + ".svg";
      io::write_file_atomic(fs::path(a->out) / svg, report::area_figure(mech, result));
      row["figure"] = svg;
      rows.push_back(row);
      const std::string bounds = method == "exact" ? "exact" : io::interval_text(lo, hi, 10);
      const std::string comps = result.limited ? "–" : std::to_string(rep["components"].size());
      md += "| " + stem + " | " + mech.name + " | " + mech.mechanism + " | " + fmt("%.10g", area) + " | " + bounds +
            " | " + area_unit(mech) + " | " + method + " | " + comps + " | " + fmt("%.1f", rep["time_ms"].get<double>()) +
            " | [" + svg + "](" + svg + ") | " + note + " |\n";
      if (!a->json) {
        std::printf("%-34s %18.10g %s  %s\n", stem.c_str(), area, area_unit(mech).c_str(),
                    method == "exact" ? "exact" : ("certified " + io::interval_text(lo, hi, 10)).c_str());
      }
    }
    md += std::string("\ncompute time: ") + report::kComputeTimeMeaning +
          " (the `time_ms` of `pkmws area --json`, one file at a time).\n";
    io::write_file_atomic(fs::path(a->out) / "summary.md", md);
    io::write_file_atomic(fs::path(a->out) / "summary.json", rows.dump(2) + "\n");
    if (a->json) {
      print_json(Json{{"output_dir", a->out}, {"summary", "summary.json"}, {"rows", rows}});
      return 0;
    }
    std::size_t figures = 0;
    for (const auto& row : rows) figures += row.contains("figure") ? 1 : 0;
    std::printf("wrote %zu figures and summary.md to %s (%zu files without a planar workspace are listed with the reason)\n",
                figures, a->out.c_str(), rows.size() - figures);
    return 0;
  }});
}

}  // namespace pkmws::cli
