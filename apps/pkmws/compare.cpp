// pkmws compare FILE [--json] [--csv OUT]: exact area against the grid
// baseline along a ladder of resolutions (docs/format.md (command line), docs/benchmarks.md).
#include <cmath>
#include <cstdio>
#include <sstream>

#include "cli.hpp"
#include "pkmws/criteria/fields.hpp"
#include "pkmws/grid/compare.hpp"
#include "pkmws/io/export.hpp"

namespace pkmws::cli {

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

std::string number(std::optional<double> v, const char* format) {
  if (!v) return "";
  char buf[64];
  std::snprintf(buf, sizeof buf, format, *v);
  return buf;
}

std::string csv_of(const grid::CompareResult& r) {
  std::ostringstream s;
  s << "method,cells_per_side,depth,points,area,rel_error,guaranteed_rel_error,time_ms,time_certified_ms,"
       "ratio_to_exact,points_per_second\n";
  for (const auto& row : r.rows) {
    s << row.method << ',' << row.cells_per_side << ',' << (row.depth >= 0 ? std::to_string(row.depth) : "")
      << ',' << row.points << ',' << number(row.area, "%.17g") << ',' << number(row.rel_error, "%.6e") << ','
      << number(row.guaranteed_rel_error, "%.6e") << ',' << number(row.time_ms, "%.6g") << ','
      << number(row.time_certified_ms, "%.6g") << ',' << number(row.ratio_to_exact, "%.6g") << ','
      << number(row.points_per_second, "%.6g") << '\n';
  }
  return s.str();
}

Json json_of(const grid::CompareResult& r) {
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
  return Json{{"exact_area", r.exact_area},
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

void add_compare(CLI::App& app, std::vector<Command>& commands) {
  auto* sub = app.add_subcommand("compare", "Exact area against grid estimates at several resolutions");
  struct Options {
    std::string file;
    bool json = false;
    std::string csv;
    double budget_s = 20.0;
    int threads = 0;
    std::vector<std::size_t> ladder;
    std::vector<int> depths;
  };
  auto o = std::make_shared<Options>();
  sub->add_option("FILE", o->file, "Mechanism file (JSON)")->required();
  sub->add_flag("--json", o->json, "Print one JSON object");
  sub->add_option("--csv", o->csv, "Also write the rows as CSV to this file");
  sub->add_option("--budget", o->budget_s, "Stop a ladder after the first step slower than this (seconds)")
      ->check(CLI::PositiveNumber);
  sub->add_option("--threads", o->threads, "Threads (0 = all)")->check(CLI::Range(0, 1024));
  sub->add_option("--ladder", o->ladder, "Cells per side of the uniform grids (default 100 ... 16000)")
      ->check(CLI::Range(std::size_t{1}, std::size_t{1} << 14));  // as pkmws grid --cells
  sub->add_option("--depths", o->depths, "Quadtree depths (default 2 4 ... 20, at most 20)")->check(CLI::Range(0, 20));
  commands.push_back({sub, [o] {
    check_outputs({o->csv});  // before minutes of work, not after
    const io::MechanismFile mech = io::load_mechanism(o->file);
    grid::CompareOptions co;
    co.time_budget_ms = 1000.0 * o->budget_s;
    co.execution.threads = o->threads;
    if (!o->ladder.empty()) co.ladder = o->ladder;
    if (!o->depths.empty()) co.depths = o->depths;
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
    grid::CompareResult r;
    try {
      r = grid::compare(*model, co);
    } catch (const std::invalid_argument& e) {
      throw io::InputError(o->file + ": " + e.what());
    } catch (const std::logic_error& e) {
      throw io::InputError(o->file + ": " + e.what());
    }
    if (!o->csv.empty()) io::write_file_atomic(o->csv, csv_of(r));
    if (o->json) {
      Json j = json_of(r);
      j["name"] = mech.name;
      j["mechanism"] = mech.mechanism;
      j["units"] = mech.units;
      print_json(j);
      return 0;
    }
    std::printf("%s (%s)\n", mech.name.c_str(), mech.mechanism.c_str());
    std::printf("%s area %.15g %s, %.3f ms median of %d runs (%s)\n", r.rows.front().method.c_str(), r.exact_area,
                area_unit(mech).c_str(), r.exact_time_ms, co.exact_runs,
                mech.criteria.any() ? "certified level sets of the file's criteria, 1e-6" : "build + area");
    std::printf("grid: %d thread%s, %s kernel\n\n", r.threads, r.threads == 1 ? "" : "s", r.isa.c_str());
    std::printf("%-10s %-22s %13s %20s %10s %10s %11s %9s\n", "method", "resolution", "points", "area", "error",
                "guaranteed", "time ms", "x exact");
    for (const auto& row : r.rows) {
      std::printf("%-10s %-22s %13llu %20.12f %10.2e %10s %11.3f %9.3g\n", row.method.c_str(),
                  resolution(row).c_str(), static_cast<unsigned long long>(row.points), row.area, row.rel_error,
                  number(row.guaranteed_rel_error, "%.2e").c_str(), row.time_ms, row.ratio_to_exact);
    }
    std::printf("\nerror = |area - exact| / exact (needs the exact area); guaranteed = certified half-width of the\n"
                "bracket / exact (what a grid user can state; uniform grid: its time adds the certified pass)\n\n");
    std::printf("time to reach a relative accuracy (log-log interpolation; * = extrapolated):\n");
    for (const auto& t : r.at_accuracy) {
      if (!t.time_ms) continue;
      std::printf("  %-9s %-10s %.0e: %12.3f ms = %10.3g x exact%s\n", t.method.c_str(), t.accuracy.c_str(), t.target,
                  *t.time_ms, *t.ratio_to_exact, t.extrapolated ? " *" : "");
    }
    std::printf("accuracy reached in the exact computation's time:\n");
    for (const auto& c : r.crossovers) {
      std::printf("  %-9s %-10s %s (%s)\n", c.method.c_str(), c.accuracy.c_str(),
                  number(c.rel_error, "%.2e").c_str(), c.note.c_str());
    }
    for (const auto& note : r.notes) std::printf("note: %s\n", note.c_str());
    return 0;
  }});
}

}  // namespace pkmws::cli
