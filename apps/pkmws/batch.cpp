// pkmws batch FILES... --out DIR: the main job of `make demo`. For every
// mechanism file: exact area, the paper-style SVG figure, and one row of a
// summary table (DIR/summary.md, DIR/summary.json). Files without a planar
// workspace (a lone Pi-joint) are listed with the reason instead.
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "bodies_cli.hpp"
#include "cli.hpp"
#include "pkmws/io/export.hpp"

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
  };
  auto a = std::make_shared<Args>();
  sub->add_option("FILES", a->files, "Mechanism files (JSON)")->required();
  sub->add_option("--out,-o", a->out, "Output directory (created if missing)")->required();
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
        "| file | name | mechanism | area | unit | components | time (ms) | figure | limited / real area |\n"
        "|---|---|---|---:|---|---:|---:|---|---|\n";
    for (const auto& mech : mechs) {
      const std::string stem = fs::path(mech.path).stem().string();
      Json row{{"file", mech.path}, {"name", mech.name}, {"mechanism", mech.mechanism}};
      const auto start = std::chrono::steady_clock::now();
      geometry::Region region;
      certified::CertifiedRegion enclosure;
      try {
        enclosure = mech.model->workspace_enclosure();
        region = enclosure.exact ? enclosure.inner : enclosure.outer;
      } catch (const std::exception& e) {
        row["note"] = e.what();
        std::string links;
        if (mech.model->dof() == 1) {  // its curves instead of a region
          const auto charts = write_curve_figures(mech, a->out);
          row["charts"] = charts;
          for (const auto& c : charts) links += " [" + c + "](" + c + ")";
        }
        rows.push_back(row);
        md += "| " + stem + " | " + mech.name + " | " + mech.mechanism + " | – | | | | " +
              std::string(e.what()) + links + " | |\n";
        continue;
      }
      const double area = enclosure.exact ? region.area() : enclosure.area_estimate();
      const double time_ms = elapsed_ms(start);
      const auto comps = region.components(io::effective_min_area(region, {}));
      io::FigureOptions figure;
      figure.title = mech.name;
      figure.caption = "exact workspace area = " + fmt("%.10g", area) + " " + area_unit(mech);
      if (!enclosure.exact) {
        figure.caption = "certified workspace area in [" + fmt("%.10g", enclosure.area_lower) + ", " +
                         fmt("%.10g", enclosure.area_upper) + "] " + area_unit(mech) + " (outer enclosure drawn)";
        row["area_lower"] = enclosure.area_lower;
        row["area_upper"] = enclosure.area_upper;
      }
      row["method"] = enclosure.method();
      // What the file limits the workspace to: criteria (certified level sets,
      // 1e-5 here to keep the batch quick; `pkmws area` aims at 1e-6) or bodies
      // (the real workspace, certified). The area column stays the reachable one.
      std::string limited;
      geometry::Region pose_region = region;  // where the mechanism is drawn (a shared value, not a copy)
      if (mech.criteria.any()) {
        const Json c = criteria_area_report(mech, 1e-5);
        row["limited_area_lower"] = c["area_lower"];
        row["limited_area_upper"] = c["area_upper"];
        row["limited_method"] = "certified";
        limited = "criteria: [" + fmt("%.10g", c["area_lower"].get<double>()) + ", " +
                  fmt("%.10g", c["area_upper"].get<double>()) + "] (certified)";
        figure.caption += "; " + limited + " (pkmws export draws that region)";
      } else if (mech.bodies) {
        const auto real = real_workspace_of(mech, region, 7);
        row["real_area_lower"] = real.real.area_lower;
        row["real_area_upper"] = real.real.area_upper;
        row["real_method"] = real.real.method();
        limited = "real: [" + fmt("%.10g", real.real.area_lower) + ", " + fmt("%.10g", real.real.area_upper) + "] (" +
                  real.real.method() + ")";
        figure.overlays = real_workspace_overlays(real);
        figure.caption += "; " + limited + ", black outline";
        if (!real.real.inner.empty()) pose_region = real.real.inner;  // a collision-free pose
      }
      const std::string svg = stem + ".svg";
      io::write_file_atomic(fs::path(a->out) / svg,
                            io::workspace_figure(mech, region, sample_pose(mech, pose_region), figure));
      row["area"] = area;
      row["units"] = mech.units;
      row["components"] = comps.size();
      row["time_ms"] = time_ms;
      row["figure"] = svg;
      rows.push_back(row);
      md += "| " + stem + " | " + mech.name + " | " + mech.mechanism + " | " + fmt("%.10g", area) +
            " | " + area_unit(mech) + " | " + std::to_string(comps.size()) + " | " +
            fmt("%.2f", time_ms) + " | [" + svg + "](" + svg + ") | " + limited + " |\n";
      std::printf("%-34s %18.10g %s\n", stem.c_str(), area, area_unit(mech).c_str());
    }
    io::write_file_atomic(fs::path(a->out) / "summary.md", md);
    io::write_file_atomic(fs::path(a->out) / "summary.json", rows.dump(2) + "\n");
    std::size_t figures = 0;
    for (const auto& row : rows) figures += row.contains("figure") ? 1 : 0;
    std::printf("wrote %zu figures and summary.md to %s (%zu files without a planar workspace are listed with the reason)\n",
                figures, a->out.c_str(), rows.size() - figures);
    return 0;
  }});
}

}  // namespace pkmws::cli
