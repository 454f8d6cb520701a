// `pkmws levels` (pkmws/report/levels.hpp): moved from the command line's
// levels.cpp, numbers, JSON, figure and curves unchanged.
#include "pkmws/report/levels.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <sstream>

#include "pkmws/io/export.hpp"
#include "pkmws/io/figure.hpp"
#include "report/figure_pieces.hpp"
#include "report/json.hpp"
#include "report/text.hpp"

namespace pkmws::report {

using detail::Json;

namespace {

// Band colours from good to bad: small criterion values blue-green, large
// ones yellow to orange (a sequential palette readable in grey scale); the
// band above the highest level light grey.
std::string band_colour(std::size_t k, std::size_t n) {
  static const char* kRamp[] = {"#2a788e", "#22a884", "#7ad151", "#bddf26", "#fde725", "#fdae61", "#f46d43"};
  constexpr std::size_t m = std::size(kRamp);
  const std::size_t at = n <= 1 ? 1 : (k * (m - 1) + (n - 1) / 2) / (n - 1);
  return kRamp[std::min(at, m - 1)];
}
const char* kAboveColour = "#d9d9d9";

std::string num(double v) { return detail::format("%g", v); }

}  // namespace

void check_levels(const std::vector<double>& levels) {
  if (levels.empty()) throw io::InputError("--levels: expected a comma-separated list of numbers");
  for (std::size_t k = 1; k < levels.size(); ++k) {
    if (!(levels[k] > levels[k - 1])) throw io::InputError("--levels: values must increase");
  }
}

LevelsReport levels(const io::MechanismFile& mech, const LevelsOptions& options) {
  LevelsReport run;
  run.name = mech.name;
  run.mechanism = mech.mechanism;
  run.units = mech.units;
  run.criterion = options.criterion;
  const std::string& name = options.criterion;
  const std::vector<double>& levels = options.levels;
  check_levels(levels);
  const auto start = std::chrono::steady_clock::now();
  const auto fields = criteria::fields_for(mech, name);
  run.field = fields.front();
  run.criterion_units = run.field.unit;
  for (double t : levels) {
    // Outside the criterion's range the sub-level set is empty or everything,
    // and at its ends it degenerates to a curve: refused, not computed.
    if (!(t > run.field.threshold_min && t < run.field.threshold_max)) {
      char text[160];
      std::snprintf(text, sizeof text, "--levels: %g is outside the range of %s, (%g, %g) %s", t, name.c_str(),
                    run.field.threshold_min, run.field.threshold_max, run.field.unit.c_str());
      throw io::InputError(text);
    }
  }
  // A criterion infinite everywhere has empty sub-level sets: nothing to refine.
  run.note = fields.front().nowhere;
  // W exact, or an exact region cut by level sets traced with the criterion's.
  const auto sets = criteria::workspace_sets(mech);
  const geometry::Region ws =
      !run.note.empty() ? geometry::Region{} : sets ? sets->within : mech.model->workspace();
  const certified::WithinTest within_test = sets ? sets->within_test : fields.front().within_test;
  std::vector<certified::Constraint> cuts;
  if (sets) {
    for (const auto& cut : sets->cuts) cuts.push_back({cut.field.get(), cut.level});
  }
  certified::LevelSetOptions o;
  o.relative_tolerance = options.tolerance;
  if (sets && run.note.empty()) {
    const auto w = certified::sublevel_set(cuts, ws, within_test, options.budget.apply(o, "workspace"));
    run.workspace_area_lower = w.region.area_lower;
    run.workspace_area_upper = w.region.area_upper;
    run.stopped = w.stopped;
  } else {
    run.workspace_area_lower = run.workspace_area_upper = ws.area();
  }
  // Each sub-level set is the criteria-limited workspace of its level, the
  // one `pkmws area` certifies for a file with that limit (charts included:
  // DexTAR (+1, -1) at 20, 40, 60, 80 deg took 2.4 s in (x, y) alone).
  for (std::size_t k = 0; k < levels.size(); ++k) {
    const std::string stage = "level " + std::to_string(k + 1) + " of " + std::to_string(levels.size());
    const std::vector<criteria::Limit> limit{{name, levels[k]}};
    criteria::LimitedWorkspace lw = criteria::limited_workspace(mech, limit, options.budget.apply(o, stage));
    certified::LevelSetResult r = std::move(lw.detail);
    r.region = std::move(lw.region);
    r.curves = std::move(lw.curves);
    if (options.figure_pieces && lw.charted && !r.stopped) {
      plane_figure_pieces(mech, limit, options.budget.apply(o, stage), r);
    }
    run.stopped = run.stopped || r.stopped;
    run.sublevel_sets.push_back(std::move(r));
  }
  if (run.stopped) run.stopped_note = options.budget.stopped_note;
  run.levels = levels;
  run.bands = certified::bands_from_sublevels(levels, run.sublevel_sets);
  run.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return run;
}

std::string to_json_text(const LevelsReport& run) {
  Json j;
  j["name"] = run.name;
  j["mechanism"] = run.mechanism;
  j["units"] = run.units;  // lengths; areas in units² (docs/format.md (output vocabulary))
  j["criterion"] = run.criterion;
  j["criterion_units"] = run.criterion_units;  // of the levels `from` and `to`
  if (run.field.characteristic_length > 0.0) j["characteristic_length"] = run.field.characteristic_length;
  Json bands = Json::array();
  for (std::size_t k = 0; k < run.bands.size(); ++k) {
    const auto& b = run.bands[k];
    Json band{{"from", k == 0 ? Json(nullptr) : Json(b.lower_level)},
              {"to", b.upper_level},
              {"area_lower", b.area_lower},
              {"area_upper", b.area_upper},
              {"sublevel_area_lower", run.sublevel_sets[k].region.area_lower},
              {"sublevel_area_upper", run.sublevel_sets[k].region.area_upper}};
    if (k == 0) band["from_reason"] = "the first band has no lower level (everything up to `to`)";
    bands.push_back(band);
  }
  j["bands"] = bands;
  j["method"] = "certified";
  j["time_ms"] = run.time_ms;
  if (run.stopped) j["stopped"] = run.stopped_note;
  if (!run.note.empty()) j["note"] = run.note;
  return detail::json_text(std::move(j));
}

std::string to_text(const LevelsReport& run) {
  using detail::format;
  std::string t = format("%s: %s bands (%s), areas in %s, certified\n", run.name.c_str(), run.criterion.c_str(),
                         run.criterion_units.c_str(), (run.units + "²").c_str());
  if (run.field.characteristic_length > 0.0) {
    t += format("characteristic length L = %.6g %s (x' = (x, y, L phi))\n", run.field.characteristic_length,
                run.units.c_str());
  }
  t += format("%-18s %-20s %-20s %-20s %-20s\n", "band", "area_lower", "area_upper", "sublevel_lower", "sublevel_upper");
  for (std::size_t k = 0; k < run.bands.size(); ++k) {
    const std::string band = k == 0 ? format("<= %g", run.levels[k])
                                    : format("%g .. %g", run.levels[k - 1], run.levels[k]);
    t += format("%-18s %-20.12g %-20.12g %-20.12g %-20.12g\n", band.c_str(), run.bands[k].area_lower,
                run.bands[k].area_upper, run.sublevel_sets[k].region.area_lower, run.sublevel_sets[k].region.area_upper);
  }
  if (run.stopped) t += format("STOPPED    %s\n", run.stopped_note.c_str());
  if (!run.note.empty()) t += format("note       %s\n", run.note.c_str());
  t += format("time       %.1f ms\n", run.time_ms);
  return t;
}

// The band figure: the workspace in the colour of the band above the highest
// level, each sub-level set's traced inner region on top (largest first), with
// the axes, scale bar, legend (every band with its certified area bounds) and
// caption of the workspace figures.
std::string band_figure(const io::MechanismFile& mech, const LevelsReport& run) {
  const geometry::Region ws = criteria::criteria_domain(mech);  // drawn: W, or its outer enclosure
  const std::string unit = area_unit(mech);
  const std::string crit_unit = run.field.unit == "deg" ? "\u00b0" : (run.field.unit.empty() ? "" : " " + run.field.unit);
  const std::size_t n = run.levels.size();
  io::FigureOptions f;
  f.title = mech.name;
  f.region_fill = kAboveColour;
  f.region_stroke = "#555555";
  // The band above the highest level: the workspace minus the highest sub-level set.
  const double above_lo = std::max(0.0, run.workspace_area_lower - run.sublevel_sets[n - 1].region.area_upper);
  const double above_hi = std::max(0.0, run.workspace_area_upper - run.sublevel_sets[n - 1].region.area_lower);
  f.region_legend = "> " + num(run.levels[n - 1]) + crit_unit + ": " + io::interval_text(above_lo, above_hi) + " " + unit;
  // Legend: the bands in increasing order of the criterion, then the mechanism.
  f.region_legend_rank = -100 + static_cast<int>(n);
  for (std::size_t kk = n; kk-- > 0;) {  // painter's order: the largest sub-level set first
    io::FigureOptions::Overlay ov;
    ov.rings = io::traced_inner_rings(run.sublevel_sets[kk]);
    ov.fill = band_colour(kk, n);
    ov.stroke = "#303030";
    ov.stroke_px = 0.8;
    ov.css_class = "band";
    const auto& b = run.bands[kk];
    const std::string range = kk == 0 ? "\u2264 " + num(run.levels[0]) + crit_unit
                                      : num(run.levels[kk - 1]) + "\u2013" + num(run.levels[kk]) + crit_unit;
    ov.legend = range + ": " + io::interval_text(b.area_lower, b.area_upper) + " " + unit;
    ov.legend_rank = -100 + static_cast<int>(kk);
    f.overlays.push_back(std::move(ov));
  }
  const std::string cite = io::source_citation(mech);
  std::string what = run.field.name;
  std::replace(what.begin(), what.end(), '_', ' ');
  f.caption = (cite.empty() ? "" : cite + ". ") + "Bands of the " + what +
              (run.field.unit.empty() ? "" : " (" + run.field.unit + ")") + " with certified area bounds in " + unit +
              " (legend). Each band is drawn from the traced level curves (the inner bound of its sub-level set).";
  // The mechanism at a pose of the lowest band (the best transmission).
  const geometry::Region best = io::largest_ring_region(f.overlays.back().rings, ws);
  const mechanisms::Pose pose = sample_pose(mech, best.empty() ? ws : best);
  return io::workspace_figure(mech, ws, pose, f);
}

std::string level_curves_csv(const LevelsReport& run) {
  std::ostringstream c;
  c.precision(17);
  c << "level,piece,x,y\n";
  for (std::size_t k = 0; k < run.sublevel_sets.size(); ++k) {
    int piece = 0;
    for (const auto& p : run.sublevel_sets[k].curves) {
      for (const auto& q : p) c << run.levels[k] << "," << piece << "," << q.x << "," << q.y << "\n";
      ++piece;
    }
  }
  return c.str();
}

}  // namespace pkmws::report
