// `pkmws area` (pkmws/report/area.hpp): moved from the command line's area.cpp,
// common.cpp (region_report), levels.cpp (criteria_area_report) and explain.cpp
// (the real workspace), numbers and JSON unchanged.
#include "pkmws/report/area.hpp"

#include <algorithm>
#include <chrono>
#include <numbers>
#include <cstdio>

#include "pkmws/io/export.hpp"
#include "pkmws/pkmws.hpp"
#include "report/figure_pieces.hpp"
#include "report/json.hpp"
#include "report/text.hpp"

namespace pkmws::report {

using detail::Json;

namespace {

double elapsed_ms(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// Area, components and their figures; the inscribed rectangle to a relative
// width of `rectangle_precision`. With `inside` (a certified enclosure's inner
// region), each component's rectangle is searched there, so that it fits the
// true workspace.
void region_report(AreaReport& out, const geometry::Region& region, double min_area, double rectangle_precision,
                   bool any_angle, const geometry::Region* inside) {
  const auto rectangle = [&](const geometry::Component& c, const geometry::Region* in) {
    return any_angle ? geometry::largest_inscribed_rectangle_any_angle(c, rectangle_precision, {}, in)
                     : geometry::largest_inscribed_rectangle(c, rectangle_precision, {}, in);
  };
  double area = 0.0;
  // Rectangles must fit the true workspace: for a certified enclosure they are
  // searched in the inner region's components within this component.
  std::vector<geometry::Component> inner;
  if (inside) inner = inside->components(io::effective_min_area(*inside, {}));
  for (const auto& c : region.components(min_area)) {
    const auto circle = geometry::largest_inscribed_circle(c, inscribed_circle_precision(c.bbox));
    geometry::InscribedRectangle rect;
    if (!inside) {
      rect = rectangle(c, &region);
    } else {
      for (const auto& k : inner) {
        if (k.outer.curves.empty() || !geometry::inside(c, k.outer.curves.front().source)) continue;
        const auto r = rectangle(k, inside);
        if (r.area > rect.area) rect = r;
        rect.area_upper = std::max(rect.area_upper, r.area_upper);
      }
    }
    out.components.push_back({c.area, c.perimeter, c.holes.size(), c.bbox, c.centroid, circle, rect});
    area += c.area;
  }
  out.area = area;
  out.bbox = region.bbox();
  out.boundary_curves = region.curve_count();
}

// The level sets' options of a limited workspace (without the budget).
certified::LevelSetOptions level_set_options(const LimitedOptions& options) {
  certified::LevelSetOptions o;
  o.relative_tolerance = options.tolerance;
  o.build_regions = options.build_regions;
  o.regions = options.regions;
  o.charts = options.charts;
  o.threads = options.threads;
  if (options.refine_depth) o.refine_depth = *options.refine_depth;
  o.retries = options.retries;
  return o;
}

// For a file with `criteria` limits: certified area bounds of the limited
// workspace (docs/theory/level_sets.md).
void criteria_area_report(AreaReport& out, const io::MechanismFile& mech, const AreaOptions& options) {
  LimitedOptions o;
  o.tolerance = options.criteria_tolerance;
  o.budget = options.budget;
  criteria::LimitedWorkspace lw = limited_workspace(mech, o);
  if (options.figure_pieces && lw.charted && !lw.detail.stopped) {
    plane_figure_pieces(mech, criteria::file_limits(mech), o.budget.apply(level_set_options(o)), lw.detail);
  }
  out.method = "certified";
  out.area = lw.region.area_estimate();
  out.area_lower = lw.region.area_lower;
  out.area_upper = lw.region.area_upper;
  for (const auto& l : criteria::file_limits(mech)) {
    if (l.name == "singularity_distance") {  // a distance, not a field's level set
      out.criteria.push_back({l.name, l.threshold, 0.0});
      continue;
    }
    const auto fields = criteria::fields_for(mech, l.name);
    out.criteria.push_back({l.name, l.threshold, fields.empty() ? 0.0 : fields.front().characteristic_length});
  }
  if (lw.detail.stopped && options.budget.bound) out.stopped = options.budget.stopped_note;
  out.note = lw.note;
  out.enclosure = lw.region;
  out.limited = std::move(lw);
}

}  // namespace

Json detail::criterion_limit_json(const CriterionLimit& limit) {
  Json out{{"criterion", limit.criterion}, {"threshold", limit.threshold}};
  if (limit.characteristic_length > 0.0) out["characteristic_length"] = limit.characteristic_length;
  return out;
}

std::string criterion_limit_text(const CriterionLimit& limit, const std::string& units) {
  // min_singularity_distance limits from below.
  const char* relation = limit.criterion == "singularity_distance" ? " >= " : " <= ";
  std::string t = limit.criterion + relation + detail::format("%g", limit.threshold);
  if (limit.criterion == "singularity_distance") t += " " + units;  // a length
  if (limit.characteristic_length > 0.0) {
    t += detail::format(" (characteristic length L = %.6g %s)", limit.characteristic_length, units.c_str());
  }
  return t;
}

namespace {

Json rectangle_json(const geometry::InscribedRectangle& r) {
  Json out{{"box", detail::box_json(r.box)},
           {"width", r.box.width()},
           {"height", r.box.height()},
           {"area", r.area},
           {"area_upper", r.area_upper},
           {"verified", r.verified}};
  if (r.angle != 0.0 || r.orientations > 0) {  // asked at any orientation: `box` is in the turned frame
    out["angle_deg"] = r.angle * 180.0 / std::numbers::pi;
    Json corners = Json::array();
    for (const geometry::Point& p : r.corners()) corners.push_back({p.x, p.y});
    out["corners"] = corners;
  }
  return out;
}

// `real_area`, `real_area_lower`, `real_area_upper`, `real_method`, `interference` [...].
Json real_workspace_json(const bodies::RealWorkspace& real) {
  Json out;
  out["reachable_area"] = real.reachable.area_lower;
  out["real_area"] = real.real.area_estimate();
  out["real_area_lower"] = real.real.area_lower;
  out["real_area_upper"] = real.real.area_upper;
  out["real_method"] = real.real.method();
  Json list = Json::array();
  for (const auto& i : real.interference) {
    list.push_back({{"parts", {i.a, i.b}},
                    {"kind", i.kind},
                    {"method", i.region.method()},
                    {"area_lower", i.region.area_lower},
                    {"area_upper", i.region.area_upper}});
  }
  out["interference"] = list;
  return out;
}

// The text lines of `pkmws area` for the real workspace (unit: e.g. "mm²").
std::string real_workspace_text(const bodies::RealWorkspace& real, const std::string& unit) {
  using detail::format;
  const auto& r = real.real;
  std::string t = format("reachable  %.15g %s  (exact)\n", real.reachable.area_lower, unit.c_str());
  if (r.exact) {
    t += format("real       %.15g %s  (exact: reachable minus interference)\n", r.area_lower, unit.c_str());
  } else {
    t += format("real       %.10g %s  (certified: %.10g <= area <= %.10g)\n", r.area_estimate(), unit.c_str(),
                r.area_lower, r.area_upper);
  }
  t += format("interference (per pair, %s):\n", unit.c_str());
  for (const auto& i : real.interference) {
    const std::string label = pair_label(i.a, i.b, i.kind);
    if (i.region.exact) {
      t += format("  %-28s %.10g  (exact)\n", label.c_str(), i.region.area_lower);
    } else {
      t += format("  %-28s %.10g .. %.10g  (certified)\n", label.c_str(), i.region.area_lower, i.region.area_upper);
    }
  }
  return t;
}

}  // namespace

double inscribed_circle_precision(const geometry::Box& b) { return 1e-5 * std::max(b.width(), b.height()); }

std::string pair_label(const std::string& a, const std::string& b, const std::string& kind) {
  return kind == "link_angle" ? a + " ∠ " + b : a + " / " + b;
}

void plane_figure_pieces(const mechanisms::Design& file, const std::vector<criteria::Limit>& limits,
                         certified::LevelSetOptions o, certified::LevelSetResult& detail) {
  o.charts = false;
  o.relative_tolerance = std::max(o.relative_tolerance, 1e-4);
  o.refine_depth = 3;
  o.retries = false;
  criteria::LimitedWorkspace plane = criteria::limited_workspace(file, limits, o);
  detail.inside_boxes = std::move(plane.detail.inside_boxes);
  detail.inner_polygons = std::move(plane.detail.inner_polygons);
  detail.undecided_boxes = std::move(plane.detail.undecided_boxes);
}

criteria::LimitedWorkspace limited_workspace(const io::MechanismFile& file, const LimitedOptions& options) {
  if (!(options.tolerance > 0.0 && options.tolerance < 1.0)) throw io::InputError("tolerance: must be in (0, 1)");
  if (!file.criteria.any()) throw io::InputError(file.path + ": the file has no criteria limits");
  return criteria::limited_workspace(file, criteria::file_limits(file), options.budget.apply(level_set_options(options)));
}

bodies::RealWorkspace real_workspace(const io::MechanismFile& file, const geometry::Region& reachable, int depth) {
  bodies::InterferenceOptions options;
  options.max_depth = depth;
  return bodies::real_workspace(*file.bodies, reachable, options);
}

AreaReport area(const io::MechanismFile& mech, const AreaOptions& options) {
  AreaReport out;
  out.name = mech.name;
  out.mechanism = mech.mechanism;
  out.units = mech.units;
  const auto start = std::chrono::steady_clock::now();
  if (mech.criteria.any()) {
    // Criteria limits: certified level sets (docs/theory/level_sets.md).
    criteria_area_report(out, mech, options);
    out.time_ms = elapsed_ms(start);
    return out;
  }
  out.enclosure = pkmws::workspace(mech);
  // Exact: the region itself. Certified: the outer enclosure's components
  // (every point of the true workspace is in one of them).
  const geometry::Region& region = out.enclosure.exact ? out.enclosure.inner : out.enclosure.outer;
  if (region.empty()) {
    throw io::InputError(mech.path + ": the workspace is empty (impossible geometry: the legs cannot meet)");
  }
  region_report(out, region, io::effective_min_area(region, {}), options.rectangle_precision,
                options.rectangle_any_angle, out.enclosure.exact ? nullptr : &out.enclosure.inner);
  out.method = out.enclosure.method();
  if (out.enclosure.exact) {
    // Exact boundary: the bounds are the double rounding of Green's theorem.
    const AreaBounds b = exact_area_bounds(out.area);
    out.area_lower = b.lower;
    out.area_upper = b.upper;
  } else {
    out.area = out.enclosure.area_estimate();
    out.area_lower = out.enclosure.area_lower;
    out.area_upper = out.enclosure.area_upper;
    out.components_of_outer_enclosure = true;
  }
  // docs/format.md (bodies): with bodies, the real workspace = reachable − ∪ interference.
  if (mech.bodies) out.real = real_workspace(mech, region, options.interference_depth);
  out.time_ms = elapsed_ms(start);
  return out;
}

std::string to_json_text(const AreaReport& r) {
  Json report;
  report["name"] = r.name;
  report["mechanism"] = r.mechanism;
  report["units"] = r.units;
  report["method"] = r.method;
  report["area"] = r.area;
  report["area_lower"] = r.area_lower;
  report["area_upper"] = r.area_upper;
  Json comps = Json::array();
  for (const auto& c : r.components) {
    comps.push_back(Json{{"area", c.area},
                         {"perimeter", c.perimeter},
                         {"holes", c.holes},
                         {"bbox", detail::box_json(c.bbox)},
                         {"centroid", detail::point_json(c.centroid)},
                         {"inscribed_circle",
                          {{"center", detail::point_json(c.inscribed_circle.center)},
                           {"radius", c.inscribed_circle.radius},
                           {"radius_upper", c.inscribed_circle.radius_upper}}},
                         {"inscribed_rectangle", rectangle_json(c.inscribed_rectangle)}});
  }
  // Criteria files: not enumerated for certified level sets (see docs/theory/level_sets.md).
  report["components"] = comps;
  if (r.bbox) {
    report["bbox"] = detail::box_json(*r.bbox);
    report["boundary_curves"] = r.boundary_curves;
  }
  if (r.components_of_outer_enclosure) report["components_of"] = "outer enclosure";
  if (r.limited) {
    Json lim = Json::array();
    for (const auto& l : r.criteria) lim.push_back(detail::criterion_limit_json(l));
    report["criteria"] = lim;
    report["traced_cells"] = r.limited->detail.traced_cells;
    report["undecided_cells"] = r.limited->detail.undecided_cells;
    report["curve_points"] = r.limited->detail.curve_points;
    if (r.limited->singular_error > 0.0 || !r.limited->singular_undecided.empty()) {
      // min_singularity_distance: the traced type-2 singular set and its bound.
      std::size_t segments = 0;
      for (const auto& c : r.limited->singular_curves) segments += c.size() > 1 ? c.size() - 1 : 0;
      report["singular_segments"] = segments;
      report["singular_error"] = r.limited->singular_error;
      report["singular_undecided"] = r.limited->singular_undecided.size();
    }
    if (!r.stopped.empty()) report["stopped"] = r.stopped;
    if (!r.note.empty()) report["note"] = r.note;
  }
  if (r.real) report.update(real_workspace_json(*r.real));
  report["time_ms"] = r.time_ms;
  return detail::json_text(std::move(report));
}

std::string to_text(const AreaReport& r) {
  using detail::format;
  const std::string unit = r.units + "²";
  std::string t = format("%s (%s)\n", r.name.c_str(), r.mechanism.c_str());
  const double area = r.area, lo = r.area_lower, hi = r.area_upper;
  if (r.limited) {
    if (hi > 0.0) {
      t += format("area       %.10g %s  (certified: %.12g <= area <= %.12g, width %.2g of the area)\n", area,
                  unit.c_str(), lo, hi, (hi - lo) / hi);
    } else {  // certified empty: no relative width (0 / 0)
      t += format("area       0 %s  (certified: the limited workspace is empty)\n", unit.c_str());
    }
    for (const auto& c : r.criteria) t += "           limited by " + criterion_limit_text(c, r.units) + "\n";
    if (r.limited->singular_error > 0.0 || !r.limited->singular_undecided.empty()) {
      std::size_t segments = 0;
      for (const auto& c : r.limited->singular_curves) segments += c.size() > 1 ? c.size() - 1 : 0;
      t += format("           type-2 singular curve: %zu chords within %.3g of it, %zu boxes not traced\n", segments,
                  r.limited->singular_error, r.limited->singular_undecided.size());
    }
    if (!r.stopped.empty()) t += format("STOPPED    %s\n", r.stopped.c_str());
    if (!r.note.empty()) t += format("note       %s\n", r.note.c_str());
  } else if (r.enclosure.exact) {
    t += format("area       %.15g %s  (exact, %zu component%s)\n", area, unit.c_str(), r.components.size(),
                r.components.size() == 1 ? "" : "s");
  } else {
    t += format("area       %.10g %s  (certified: %.10g <= area <= %.10g, width %.2g of the area)\n", area,
                unit.c_str(), lo, hi, (hi - lo) / area);
    t += format("           components of the outer enclosure: %zu\n", r.components.size());
  }
  int k = 0;
  for (const auto& c : r.components) {
    const auto& rect = c.inscribed_rectangle;
    t += format("  [%d] area %.15g, perimeter %.10g, centroid (%.6g, %.6g), "
                "inscribed circle r = %.6g, inscribed rectangle %.6g x %.6g = %.10g %s\n",
                k++, c.area, c.perimeter, c.centroid.x, c.centroid.y, c.inscribed_circle.radius, rect.box.width(),
                rect.box.height(), rect.area, unit.c_str());
    if (rect.orientations > 0) {
      t.pop_back();  // the newline
      t += format(", turned by %.6g deg (bounds [%.10g, %.10g])\n", rect.angle * 180.0 / std::numbers::pi, rect.area,
                  rect.area_upper);
    }
  }
  if (r.real) t += real_workspace_text(*r.real, unit);
  t += format("time       %.3f ms  (%s)\n", r.time_ms, kComputeTimeMeaning);
  return t;
}

}  // namespace pkmws::report
