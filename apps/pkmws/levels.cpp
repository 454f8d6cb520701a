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

// Colours from good (green) to bad (red), one per band.
std::string band_colour(std::size_t k, std::size_t n) {
  const double t = n <= 1 ? 0.0 : static_cast<double>(k) / static_cast<double>(n - 1);
  const int r = static_cast<int>(60 + 190 * t), g = static_cast<int>(190 - 130 * t), b = 90;
  char buf[16];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", r, g, b);
  return buf;
}

std::string svg_figure(const io::MechanismFile& mech, const BandRun& run) {
  const geometry::Region ws = mech.model->workspace();
  geometry::Box box = ws.bbox();
  const double w = box.width(), h = box.height();
  const double pad = 0.08 * std::max(w, h);
  box.min = {box.min.x - pad, box.min.y - pad};
  box.max = {box.max.x + pad, box.max.y + pad};
  const double scale = 700.0 / std::max(box.width(), box.height());
  auto X = [&](double x) { return (x - box.min.x) * scale; };
  auto Y = [&](double y) { return (box.max.y - y) * scale; };
  std::ostringstream s;
  s.precision(5);
  const double width = box.width() * scale, height = box.height() * scale;
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width + 220 << "\" height=\"" << height + 40
    << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
   s << "<text x=\"8\" y=\"16\">" << io::xml_escape(mech.name) << ": " << run.field.name << " (" << run.field.unit << ")</text>\n";
  s << "<g transform=\"translate(0,24)\">\n";
  // Bands: the sub-level pieces of the largest level first, then smaller ones
  // on top, clipped to the workspace (cells across its boundary overhang it).
  s << "<clipPath id=\"ws\">\n";
  for (const auto& loop : ws.loops()) {
    if (loop.hole) continue;
    s << "<polygon points=\"";
    for (const auto& p : loop.polyline(1e-4 * std::max(w, h))) s << X(p.x) << "," << Y(p.y) << " ";
    s << "\"/>\n";
  }
  s << "</clipPath>\n<g clip-path=\"url(#ws)\">\n";
  const std::size_t n = run.levels.size();
  for (std::size_t kk = n; kk-- > 0;) {
    const auto& r = run.sub[kk];
    const std::string c = band_colour(kk, n);
    s << "<g fill=\"" << c << "\" stroke=\"none\">\n";
    for (const auto& b : r.inside_boxes) {
      if (b.width() * scale < 0.25 || b.height() * scale < 0.25) continue;  // below a pixel: invisible
      s << "<rect x=\"" << X(b.min.x) << "\" y=\"" << Y(b.max.y) << "\" width=\"" << b.width() * scale
        << "\" height=\"" << b.height() * scale << "\"/>\n";
    }
    for (const auto& poly : r.inner_polygons) {
      geometry::Box pb;
      for (const auto& p : poly) pb.expand(p);
      if (pb.width() * scale < 0.25 && pb.height() * scale < 0.25) continue;
      s << "<polygon points=\"";
      for (const auto& p : poly) s << X(p.x) << "," << Y(p.y) << " ";
      s << "\"/>\n";
    }
    s << "</g>\n";
  }
  s << "</g>\n";
  // Mask outside the workspace: its boundary drawn over the cells.
  s << "<g fill=\"none\" stroke=\"black\" stroke-width=\"1.5\">\n";
  for (const auto& loop : ws.loops()) {
    const auto pts = loop.polyline(1e-4 * std::max(w, h));
    s << "<polygon points=\"";
    for (const auto& p : pts) s << X(p.x) << "," << Y(p.y) << " ";
    s << "\"/>\n";
  }
  s << "</g>\n";
  // Level curves (traced points).
  s << "<g fill=\"none\" stroke=\"#202020\" stroke-width=\"0.7\">\n";
  for (const auto& r : run.sub) {
    for (const auto& piece : r.curves) {
      geometry::Box pb;
      for (const auto& p : piece) pb.expand(p);
      if (pb.width() * scale < 0.25 && pb.height() * scale < 0.25) continue;
      s << "<polyline points=\"";
      for (const auto& p : piece) s << X(p.x) << "," << Y(p.y) << " ";
      s << "\"/>\n";
    }
  }
  s << "</g>\n";
  // The mechanism at a sample pose, with its type-2 singular curves dashed.
  mechanisms::Pose pose = sample_pose(mech, ws);
  if (const auto* rpr = dynamic_cast<const mechanisms::ThreeRpr*>(mech.model.get())) pose.phi = rpr->orientation();
  const mechanisms::Drawing d = mech.model->draw(pose);
  s << "<g fill=\"none\" stroke=\"#303080\" stroke-width=\"1.2\" stroke-dasharray=\"6,4\">\n";
  for (const auto& c : d.singular_curves) {
    s << "<polyline points=\"";
    for (const auto& p : c) s << X(p.x) << "," << Y(p.y) << " ";
    s << "\"/>\n";
  }
  s << "</g>\n<g stroke=\"#1040a0\" stroke-width=\"2.5\">\n";
  for (const auto& l : d.links) {
    s << "<line x1=\"" << X(l.a.x) << "\" y1=\"" << Y(l.a.y) << "\" x2=\"" << X(l.b.x) << "\" y2=\"" << Y(l.b.y) << "\"/>\n";
  }
  s << "</g>\n<g fill=\"white\" stroke=\"#1040a0\" stroke-width=\"1.5\">\n";
  for (const auto& j : d.joints) s << "<circle cx=\"" << X(j.x) << "\" cy=\"" << Y(j.y) << "\" r=\"3.5\"/>\n";
  s << "</g>\n";
  // Legend.
  for (std::size_t k = 0; k < n; ++k) {
    const double y = 20.0 + 22.0 * static_cast<double>(k);
    char label[160];
    if (k == 0) {
      std::snprintf(label, sizeof label, "&#8804; %g: [%.6g, %.6g]", run.levels[k], run.bands[k].area_lower, run.bands[k].area_upper);
    } else {
      std::snprintf(label, sizeof label, "%g..%g: [%.6g, %.6g]", run.levels[k - 1], run.levels[k], run.bands[k].area_lower,
                    run.bands[k].area_upper);
    }
    s << "<rect x=\"" << width + 8 << "\" y=\"" << y - 11 << "\" width=\"14\" height=\"14\" fill=\"" << band_colour(k, n)
      << "\"/><text x=\"" << width + 26 << "\" y=\"" << y << "\" font-size=\"10\">" << label << "</text>\n";
  }
  s << "<text x=\"" << width + 8 << "\" y=\"" << 20.0 + 22.0 * static_cast<double>(n) << "\" font-size=\"10\">areas in "
    << area_unit(mech) << " (certified)</text>\n";
  s << "<text x=\"" << width + 8 << "\" y=\"" << 36.0 + 22.0 * static_cast<double>(n)
    << "\" font-size=\"10\">dashed: type-2 singularity</text>\n";
  s << "</g>\n</svg>\n";
  return s.str();
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

Json criteria_area_report(const io::MechanismFile& mech, double tolerance, const CertifiedWork* work) {
  const auto limits = criteria::file_limits(mech);
  certified::LevelSetOptions o;
  o.relative_tolerance = tolerance;
  const criteria::LimitedWorkspace lw = criteria::limited_workspace(mech, limits, work ? work->options(o) : o);
  Json report;
  report["name"] = mech.name;
  report["mechanism"] = mech.mechanism;
  report["units"] = mech.units;
  report["method"] = "certified";
  report["area"] = lw.region.area_estimate();
  report["area_lower"] = lw.region.area_lower;
  report["area_upper"] = lw.region.area_upper;
  Json lim = Json::array();
  for (const auto& l : limits) lim.push_back({{"criterion", l.name}, {"threshold", l.threshold}});
  report["criteria"] = lim;
  report["components"] = Json::array();  // not enumerated for certified level sets (see docs/theory/level_sets.md)
  report["traced_cells"] = lw.detail.traced_cells;
  report["undecided_cells"] = lw.detail.undecided_cells;
  report["curve_points"] = lw.detail.curve_points;
  report["time_ms"] = lw.time_ms;
  if (lw.detail.stopped && work) report["stopped"] = work->stopped_note();
  if (!lw.note.empty()) report["note"] = lw.note;
  return report;
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
  sub->add_option("--criterion", a->criterion, "pressure_angle (deg) | reaction (N) | velocity_ratio (biglide, V_i/V_y)")->required();
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
    j["criterion"] = a->criterion;
    j["unit"] = run.field.unit;
    j["area_unit"] = area_unit(mech);
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
