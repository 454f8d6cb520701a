// pkmws area FILE [--json]: the exact workspace area (docs/format.md (command line)).
#include <cstdio>
#include <iostream>
#include <optional>

#include "bodies_cli.hpp"
#include "pkmws/io/export.hpp"

namespace pkmws::cli {

AreaResult compute_area(const io::MechanismFile& mech, int interference_depth, const CertifiedWork* work,
                        double rectangle_precision) {
  AreaResult out;
  const auto start = std::chrono::steady_clock::now();
  if (mech.criteria.any()) {
    // Criteria limits: certified level sets (levels.cpp, docs/theory/level_sets.md).
    criteria::LimitedWorkspace lw;
    out.report = criteria_area_report(mech, 1e-6, work, &lw);
    out.enclosure = lw.region;
    out.limited = std::move(lw);
    out.report["time_ms"] = elapsed_ms(start);
    return out;
  }
  out.enclosure = workspace_enclosure_of(mech);
  // Exact: the region itself. Certified: the outer enclosure's components
  // (every point of the true workspace is in one of them).
  const geometry::Region& region = out.enclosure.exact ? out.enclosure.inner : out.enclosure.outer;
  if (region.empty()) {
    throw io::InputError(mech.path + ": the workspace is empty (impossible geometry: the legs cannot meet)");
  }
  Json& report = out.report;
  report = region_report(region, io::effective_min_area(region, {}), rectangle_precision,
                         out.enclosure.exact ? nullptr : &out.enclosure.inner);
  double area = report["area"];
  report["name"] = mech.name;
  report["mechanism"] = mech.mechanism;
  report["units"] = mech.units;
  report["method"] = out.enclosure.method();
  if (out.enclosure.exact) {
    // Exact boundary: the bounds are the double rounding of Green's theorem.
    const double rounding = 64 * std::numeric_limits<double>::epsilon() * area;
    report["area_lower"] = area - rounding;
    report["area_upper"] = area + rounding;
  } else {
    area = out.enclosure.area_estimate();
    report["area"] = area;
    report["area_lower"] = out.enclosure.area_lower;
    report["area_upper"] = out.enclosure.area_upper;
    report["components_of"] = "outer enclosure";
  }
  // docs/format.md (bodies): with bodies, the real workspace = reachable − ∪ interference.
  if (mech.bodies) {
    out.real = real_workspace_of(mech, region, interference_depth);
    report.update(real_workspace_json(*out.real));
  }
  report["time_ms"] = elapsed_ms(start);
  return out;
}

void add_area(CLI::App& app, std::vector<Command>& commands) {
  auto* sub = app.add_subcommand("area", "Exact workspace area with the file's criteria");
  auto file = std::make_shared<std::string>();
  auto json = std::make_shared<bool>(false);
  sub->add_option("FILE", *file, "Mechanism file (JSON)")->required();
  sub->add_flag("--json", *json, "Print one JSON object");
  auto depth = std::make_shared<int>(7);
  sub->add_option("--interference-depth", *depth,
                  "Files with bodies: quadtree depth of the certified interference regions "
                  "(each level about halves the real area's bound width; default 7)")
      ->check(CLI::Range(0, 12));
  auto rectangle_precision = std::make_shared<double>(1e-6);
  sub->add_option("--rectangle-precision", *rectangle_precision,
                  "Relative width of the inscribed rectangle's certified area bounds (default 1e-6; "
                  "1e-9 takes about a second per component)")
      ->check(CLI::Range(1e-12, 0.5));
  auto max_time = std::make_shared<double>(0.0);
  add_max_time_option(sub, *max_time);
  commands.push_back({sub, [file, json, depth, max_time, rectangle_precision] {
    const io::MechanismFile mech = io::load_mechanism(*file);
    // Criteria limits are certified level sets: bounded by --max-time, with progress.
    const CertifiedWork work("area", *max_time);
    const AreaResult result = compute_area(mech, *depth, &work, *rectangle_precision);
    const Json& report = result.report;
    if (*json) {
      print_json(report);
      return 0;
    }
    std::printf("%s (%s)\n", mech.name.c_str(), mech.mechanism.c_str());
    const double area = report["area"], lo = report["area_lower"], hi = report["area_upper"];
    if (result.limited) {
      std::printf("area       %.10g %s  (certified: %.12g <= area <= %.12g, width %.2g of the area)\n", area,
                  area_unit(mech).c_str(), lo, hi, (hi - lo) / hi);
      for (const auto& c : report["criteria"]) {
        std::printf("           limited by %s <= %g\n", c["criterion"].get<std::string>().c_str(),
                    c["threshold"].get<double>());
      }
      if (report.contains("stopped")) std::printf("STOPPED    %s\n", report["stopped"].get<std::string>().c_str());
      if (report.contains("note")) std::printf("note       %s\n", report["note"].get<std::string>().c_str());
    } else if (result.enclosure.exact) {
      std::printf("area       %.15g %s  (exact, %zu component%s)\n", area, area_unit(mech).c_str(),
                  report["components"].size(), report["components"].size() == 1 ? "" : "s");
    } else {
      std::printf("area       %.10g %s  (certified: %.10g <= area <= %.10g, width %.2g of the area)\n", area,
                  area_unit(mech).c_str(), lo, hi, (hi - lo) / area);
      std::printf("           components of the outer enclosure: %zu\n", report["components"].size());
    }
    int k = 0;
    for (const auto& c : report["components"]) {
      const auto& rect = c["inscribed_rectangle"];
      std::printf("  [%d] area %.15g, perimeter %.10g, centroid (%.6g, %.6g), "
                  "inscribed circle r = %.6g, inscribed rectangle %.6g x %.6g = %.10g %s\n",
                  k++, c["area"].get<double>(), c["perimeter"].get<double>(), c["centroid"][0].get<double>(),
                  c["centroid"][1].get<double>(), c["inscribed_circle"]["radius"].get<double>(),
                  rect["width"].get<double>(), rect["height"].get<double>(), rect["area"].get<double>(),
                  area_unit(mech).c_str());
    }
    if (result.real) print_real_workspace(*result.real, area_unit(mech));
    std::printf("time       %.3f ms  (%s)\n", report["time_ms"].get<double>(), kComputeTimeMeaning);
    return 0;
  }});
}

}  // namespace pkmws::cli
