// pkmws levels FILE --criterion NAME --levels a,b,c: the workspace cut into
// bands of a criterion with certified area bounds per band ([Briot] figs. 9,
// 10, 12, 13), optional SVG figure and CSV of the traced level curves; and the
// criteria-limited area used by `pkmws area` (method "certified").
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "cli.hpp"
#include "pkmws/criteria/fields.hpp"
#include "pkmws/io/export.hpp"
#include "pkmws/io/figure.hpp"

namespace pkmws::cli {

namespace {

std::vector<double> parse_levels(const std::string& text) {
  std::vector<double> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) out.push_back(parse_number(item, "--levels"));
  if (out.empty()) throw io::InputError("--levels: expected a comma-separated list of numbers");
  for (std::size_t k = 1; k < out.size(); ++k) {
    if (!(out[k] > out[k - 1])) throw io::InputError("--levels: values must increase");
  }
  return out;
}

struct BandRun {
  std::vector<double> levels;
  std::vector<certified::LevelSetResult> sub;
  std::vector<certified::Band> bands;
  criteria::CriterionField field;
  double time_ms = 0.0;
  bool stopped = false;  // the deadline of --max-time was reached
  std::string note;      // why every band is empty without computing, or ""
};

BandRun run_bands(const io::MechanismFile& mech, const std::string& name, const std::vector<double>& levels,
                  double tolerance, const CertifiedWork* work = nullptr) {
  BandRun run;
  const auto start = std::chrono::steady_clock::now();
  const auto fields = criteria::fields_for(mech, name);
  run.field = fields.front();
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
  const geometry::Region ws = run.note.empty() ? mech.model->workspace() : geometry::Region{};
  certified::LevelSetOptions o;
  o.relative_tolerance = tolerance;
  for (std::size_t k = 0; k < levels.size(); ++k) {
    std::vector<certified::Constraint> cs;
    for (const auto& f : fields) cs.push_back({f.surrogate.get(), f.level(levels[k])});
    const std::string stage = "level " + std::to_string(k + 1) + " of " + std::to_string(levels.size());
    run.sub.push_back(certified::sublevel_set(cs, ws, fields.front().within_test, work ? work->options(o, stage) : o));
    run.stopped = run.stopped || run.sub.back().stopped;
  }
  run.levels = levels;
  run.bands = certified::bands_from_sublevels(levels, run.sub);
  run.time_ms = elapsed_ms(start);
  return run;
}

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

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// The band figure: the workspace in the colour of the band above the highest
// level, each sub-level set's traced inner region on top (largest first), with
// the axes, scale bar, legend (every band with its certified area bounds) and
// caption of the workspace figures.
std::string svg_figure(const io::MechanismFile& mech, const BandRun& run) {
  const geometry::Region ws = mech.model->workspace();
  const std::string unit = area_unit(mech);
  const std::string crit_unit = run.field.unit == "deg" ? "\u00b0" : (run.field.unit.empty() ? "" : " " + run.field.unit);
  const std::size_t n = run.levels.size();
  io::FigureOptions f;
  f.title = mech.name;
  f.region_fill = kAboveColour;
  f.region_stroke = "#555555";
  // The band above the highest level: the workspace minus the highest sub-level set.
  const double total = ws.area();
  const double above_lo = std::max(0.0, total - run.sub[n - 1].region.area_upper);
  const double above_hi = std::max(0.0, total - run.sub[n - 1].region.area_lower);
  f.region_legend = "> " + num(run.levels[n - 1]) + crit_unit + ": " + io::interval_text(above_lo, above_hi) + " " + unit;
  // Legend: the bands in increasing order of the criterion, then the mechanism.
  f.region_legend_rank = -100 + static_cast<int>(n);
  for (std::size_t kk = n; kk-- > 0;) {  // painter's order: the largest sub-level set first
    io::FigureOptions::Overlay ov;
    ov.rings = io::traced_inner_rings(run.sub[kk]);
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

std::string curves_csv(const BandRun& run, const std::vector<double>& levels) {
  std::ostringstream c;
  c.precision(17);
  c << "level,piece,x,y\n";
  for (std::size_t k = 0; k < run.sub.size(); ++k) {
    int piece = 0;
    for (const auto& p : run.sub[k].curves) {
      for (const auto& q : p) c << levels[k] << "," << piece << "," << q.x << "," << q.y << "\n";
      ++piece;
    }
  }
  return c.str();
}

}  // namespace

std::string bands_export(const io::MechanismFile& mech, const std::string& criterion, const std::string& levels_text,
                         bool svg, double tolerance, const CertifiedWork* work, bool* stopped) {
  const std::vector<double> levels = parse_levels(levels_text);
  const BandRun run = run_bands(mech, criterion, levels, tolerance, work);
  if (stopped) *stopped = run.stopped;
  return svg ? svg_figure(mech, run) : curves_csv(run, levels);
}

void add_levels(CLI::App& app, std::vector<Command>& commands) {
  auto* sub = app.add_subcommand("levels", "Bands of a criterion with certified areas ([Briot] figs. 9-13)");
  struct Args {
    std::string file, criterion, levels, svg, csv;
    double tolerance = 1e-6;
    double max_time = 0.0;
    bool json = false;
  };
  auto a = std::make_shared<Args>();
  sub->add_option("FILE", a->file, "Mechanism file (JSON)")->required();
  sub->add_option("--criterion", a->criterion, "pressure_angle (deg) | reaction (N) | velocity_ratio (biglide V_i/V_y; moma, five_bar |dq|/|dP|) | condition_number")->required();
  sub->add_option("--levels", a->levels, "Increasing thresholds, e.g. 20,40,60,80")->required();
  sub->add_option("--tolerance", a->tolerance, "Target bound width relative to each area (default 1e-6)");
  sub->add_option("--svg", a->svg, "Write the band figure (SVG)");
  sub->add_option("--csv", a->csv, "Write the traced level curves (CSV: level, piece, x, y)");
  sub->add_flag("--json", a->json, "Print one JSON object");
  add_max_time_option(sub, a->max_time);
  commands.push_back({sub, [a] {
    if (!(a->tolerance > 0.0 && a->tolerance < 1.0)) throw io::InputError("--tolerance: must be in (0, 1)");
    const io::MechanismFile mech = io::load_mechanism(a->file);
    const std::vector<double> levels = parse_levels(a->levels);
    check_outputs({a->svg, a->csv});
    const CertifiedWork work("levels", a->max_time);
    const BandRun run = run_bands(mech, a->criterion, levels, a->tolerance, &work);
    Json j;
    j["name"] = mech.name;
    j["mechanism"] = mech.mechanism;
    j["units"] = mech.units;  // lengths; areas in units² (docs/format.md (output vocabulary))
    j["criterion"] = a->criterion;
    j["criterion_units"] = run.field.unit;  // of the levels `from` and `to`
    Json bands = Json::array();
    for (std::size_t k = 0; k < run.bands.size(); ++k) {
      const auto& b = run.bands[k];
      Json band{{"from", k == 0 ? Json(nullptr) : Json(b.lower_level)},
                {"to", b.upper_level},
                {"area_lower", b.area_lower},
                {"area_upper", b.area_upper},
                {"sublevel_area_lower", run.sub[k].region.area_lower},
                {"sublevel_area_upper", run.sub[k].region.area_upper}};
      if (k == 0) band["from_reason"] = "the first band has no lower level (everything up to `to`)";
      bands.push_back(band);
    }
    j["bands"] = bands;
    j["method"] = "certified";
    j["time_ms"] = run.time_ms;
    if (run.stopped) j["stopped"] = work.stopped_note();
    if (!run.note.empty()) j["note"] = run.note;
    std::vector<std::pair<std::string, std::string>> outputs;  // all or nothing
    if (!a->svg.empty()) outputs.emplace_back(a->svg, svg_figure(mech, run));
    if (!a->csv.empty()) outputs.emplace_back(a->csv, curves_csv(run, levels));
    write_outputs(outputs);
    if (a->json) {
      print_json(j);
      return 0;
    }
    std::printf("%s: %s bands (%s), areas in %s, certified\n", mech.name.c_str(), a->criterion.c_str(),
                run.field.unit.c_str(), area_unit(mech).c_str());
    std::printf("%-18s %-20s %-20s %-20s %-20s\n", "band", "area_lower", "area_upper", "sublevel_lower", "sublevel_upper");
    for (std::size_t k = 0; k < run.bands.size(); ++k) {
      char band[64];
      if (k == 0) {
        std::snprintf(band, sizeof band, "<= %g", levels[k]);
      } else {
        std::snprintf(band, sizeof band, "%g .. %g", levels[k - 1], levels[k]);
      }
      std::printf("%-18s %-20.12g %-20.12g %-20.12g %-20.12g\n", band, run.bands[k].area_lower, run.bands[k].area_upper,
                  run.sub[k].region.area_lower, run.sub[k].region.area_upper);
    }
    if (run.stopped) std::printf("STOPPED    %s\n", work.stopped_note().c_str());
    if (!run.note.empty()) std::printf("note       %s\n", run.note.c_str());
    std::printf("time       %.1f ms\n", run.time_ms);
    return 0;
  }});
}

}  // namespace pkmws::cli
