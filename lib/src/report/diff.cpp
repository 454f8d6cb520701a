// `pkmws diff` (pkmws/report/diff.hpp): moved from the command line's diff.cpp,
// numbers, figure, JSON and text unchanged.
#include "pkmws/report/diff.hpp"

#include <chrono>
#include <cmath>
#include <limits>

#include "pkmws/design/sweep.hpp"
#include "pkmws/io/figure.hpp"
#include "pkmws/pkmws.hpp"
#include "pkmws/report/common.hpp"
#include "report/json.hpp"
#include "report/text.hpp"

namespace pkmws::report {

using detail::Json;

namespace {

// Okabe-Ito colours (colour-blind safe): A only, B only, both.
constexpr const char* kFillA = "#E69F00";
constexpr const char* kFillB = "#56B4E9";
constexpr const char* kFillBoth = "#009E73";

struct Side {
  const io::MechanismFile* file = nullptr;
  certified::CertifiedRegion enclosure;
  design::SweepSpec spec;
  design::DesignRow row;
};

// The metrics of one file, computed as a sweep computes them (one design, no parameters).
void evaluate(Side& s, const DiffOptions& o) {
  s.spec.base_file = s.file->path;
  s.spec.base_document = io::document_text(*s.file);
  s.spec.metrics = {"area", "components", "inscribed_circle", "inscribed_rectangle", "limited_area", "real_area",
                    "gci"};
  s.spec.rectangle_precision = o.rectangle_precision;
  s.spec.criteria_tolerance = o.criteria_tolerance;
  s.spec.gci_cells = o.gci_cells;
  s.row = design::evaluate_design(s.spec, 0);
  if (s.row.status != "ok") throw io::InputError(s.file->path + ": " + s.row.reason);
}

std::optional<double> column(const Side& s, const std::string& name) {
  const auto cols = design::metric_columns(s.spec);
  for (std::size_t k = 0; k < cols.size(); ++k) {
    if (cols[k] == name) return s.row.metrics[k];
  }
  return std::nullopt;
}

DiffRegion piece(const certified::CertifiedRegion& r) {
  if (r.exact) {
    const double a = r.inner.area();
    const double rounding = 64 * std::numeric_limits<double>::epsilon() * a;
    return {r, a, a - rounding, a + rounding};
  }
  return {r, r.area_estimate(), r.area_lower, r.area_upper};
}

// One row of the metric table: kind "value", "bounds" (NAME_lower/_upper
// columns) or "error" (a column with its error).
struct MetricRow {
  std::string metric, unit, kind;
  std::string lower_col, upper_col, error_col;
};

DiffMetric metric_of(const MetricRow& m, const Side& a, const Side& b) {
  DiffMetric d;
  d.metric = m.metric;
  d.unit = m.unit;
  const auto why_missing = [&](const Side& s) -> std::string {
    if (m.metric == "limited_area") return s.file->path + " has no criteria";
    if (m.metric == "real_area") return s.file->path + " has no bodies";
    if (m.metric == "gci") {
      const std::string r = s.row.reason;
      return r.rfind("gci: ", 0) == 0 ? r.substr(5) : "no condition number";
    }
    return "not computed";
  };
  std::optional<double> la, ua, lb, ub;
  if (m.kind == "bounds") {
    la = column(a, m.lower_col), ua = column(a, m.upper_col), lb = column(b, m.lower_col), ub = column(b, m.upper_col);
    if (la && ua) d.a = 0.5 * (*la + *ua);
    if (lb && ub) d.b = 0.5 * (*lb + *ub);
  } else {
    d.a = column(a, m.metric == "inscribed_circle" ? "inscribed_circle_radius" : m.metric);
    d.b = column(b, m.metric == "inscribed_circle" ? "inscribed_circle_radius" : m.metric);
    if (m.kind == "error") d.a_error = column(a, m.error_col), d.b_error = column(b, m.error_col);
  }
  if (!d.a) d.a_reason = why_missing(a);
  if (!d.b) d.b_reason = why_missing(b);
  if (d.a && d.b) d.change = *d.b - *d.a;
  if (d.change && *d.a != 0.0) d.relative_change = *d.change / *d.a;
  if (!d.change) d.change_reason = "the metric is missing for " + std::string(!d.a ? "A" : "B");
  if (!d.relative_change) d.relative_change_reason = !d.change ? "no change (a value is missing)" : "A's value is 0";
  if (m.kind == "bounds") {
    if (la && ua) d.a_bounds = std::pair{*la, *ua};
    if (lb && ub) d.b_bounds = std::pair{*lb, *ub};
    if (la && ua && lb && ub) d.change_bounds = std::pair{*lb - *ua, *ub - *la};
  }
  if (m.kind == "error" && d.a_error && d.b_error) d.change_error = *d.a_error + *d.b_error;
  return d;
}

Json metric_json(const DiffMetric& m) {
  Json j{{"metric", m.metric}, {"unit", m.unit}};
  const auto put = [&](const std::string& key, const std::optional<double>& v, const std::string& reason) {
    j[key] = v ? Json(*v) : Json(nullptr);
    if (!reason.empty()) j[key + "_reason"] = reason;
  };
  put("a", m.a, m.a_reason);
  put("b", m.b, m.b_reason);
  put("change", m.change, m.change_reason);
  put("relative_change", m.relative_change, m.relative_change_reason);
  if (m.a_bounds) j["a_bounds"] = {m.a_bounds->first, m.a_bounds->second};
  if (m.b_bounds) j["b_bounds"] = {m.b_bounds->first, m.b_bounds->second};
  if (m.change_bounds) j["change_bounds"] = {m.change_bounds->first, m.change_bounds->second};
  if (m.a_error) j["a_error"] = *m.a_error;
  if (m.b_error) j["b_error"] = *m.b_error;
  if (m.change_error) j["change_error"] = *m.change_error;
  return j;
}

std::string g(double v, int digits) { return detail::format("%.*g", digits, v); }

// `s` padded with spaces to `width` characters (UTF-8 code points).
std::string pad(const std::string& s, std::size_t width) {
  std::size_t n = 0;
  for (unsigned char c : s) n += (c & 0xC0) != 0x80;
  return s + std::string(n < width ? width - n : 1, ' ');
}

// A value of A or B in the table: bounds where they are wide, value ± error, or the value.
std::string text_value(const DiffMetric& m, bool side_a) {
  const std::optional<double>& v = side_a ? m.a : m.b;
  const auto& bounds = side_a ? m.a_bounds : m.b_bounds;
  const auto& error = side_a ? m.a_error : m.b_error;
  if (!v) return "n/a";
  if (bounds && bounds->second - bounds->first > 1e-12 * std::abs(*v)) {
    return io::interval_text(bounds->first, bounds->second, 8);
  }
  if (error) return g(*v, 6) + " ± " + g(*error, 2);
  return g(*v, 12);
}

std::string figure_of(const DiffReport& r, const io::MechanismFile& a) {
  io::FigureOptions f;
  f.title = "Workspaces of A and B compared";
  f.draw_mechanism = false;
  f.region_fill = "none";
  f.region_stroke = "#222222";
  f.region_legend = "";
  const auto overlay = [&](const geometry::Region& region, const char* fill, const std::string& legend,
                           const std::string& css) {
    io::FigureOptions::Overlay o;
    o.region = region;
    o.fill = fill;
    o.stroke = "#333333";
    o.stroke_px = 0.8;
    o.legend = legend;
    o.css_class = css;
    return o;
  };
  const auto area_text = [&](const certified::CertifiedRegion& c) {
    return (c.exact ? g(c.area_lower, 7) : io::interval_text(c.area_lower, c.area_upper, 8)) + " " + r.area_units;
  };
  const auto& a_only = r.a_minus_b.region;
  const auto& b_only = r.b_minus_a.region;
  const auto& both = r.a_and_b.region;
  const auto& either = r.a_or_b.region;
  f.overlays.push_back(overlay(a_only.inner, kFillA, "A only: " + area_text(a_only), "a-only"));
  f.overlays.push_back(overlay(b_only.inner, kFillB, "B only: " + area_text(b_only), "b-only"));
  f.overlays.push_back(overlay(both.inner, kFillBoth, "A \u2229 B: " + area_text(both), "a-and-b"));
  if (!r.exact) {
    io::FigureOptions::Overlay band;
    band.region = either.outer.subtract(a_only.inner.unite(b_only.inner).unite(both.inner));
    band.fill = "#9a9a9a";
    band.stroke = "none";
    band.css_class = "undecided";
    band.legend = "undecided (between the enclosures)";
    f.overlays.push_back(band);
  }
  f.caption = "A = " + r.a.name + "; B = " + r.b.name + ". " +
              (r.exact ? "Exact areas (CGAL Booleans of the exact regions)"
                       : "Certified area bounds (enclosure algebra; certainly-in parts filled)") +
              ": |A| = " + text_value(r.metrics[0], true) + " " + r.area_units + ", |B| = " +
              text_value(r.metrics[0], false) + " " + r.area_units + ", |A \u222a B| = " + area_text(either) + ".";
  return io::workspace_figure(a, r.exact ? either.inner : either.outer, mechanisms::Pose{}, f);
}

}  // namespace

DiffReport diff(const io::MechanismFile& file_a, const io::MechanismFile& file_b, const DiffOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  // One length unit: areas and changes are only comparable then.
  if (file_a.units != file_b.units) {
    throw io::InputError(file_b.path + ": units: \"" + file_b.units + "\" differs from \"" + file_a.units + "\" of " +
                         file_a.path + " (diff compares files in one length unit; convert one)");
  }
  Side a, b;
  a.file = &file_a;
  b.file = &file_b;
  a.enclosure = pkmws::workspace(file_a);
  b.enclosure = pkmws::workspace(file_b);
  evaluate(a, options);
  evaluate(b, options);

  DiffReport r;
  r.a = {file_a.path, file_a.name, file_a.mechanism, a.enclosure.method()};
  r.b = {file_b.path, file_b.name, file_b.mechanism, b.enclosure.method()};
  r.units = file_a.units;
  r.area_units = area_unit(file_a);
  // The Boolean pieces: exact regions, or the enclosure algebra.
  r.exact = a.enclosure.exact && b.enclosure.exact;
  const auto exact_piece = [](const geometry::Region& region) {
    certified::CertifiedRegion c;
    c.inner = region;
    c.outer = region;
    c.exact = true;
    c.area_lower = c.area_upper = region.area();
    return piece(c);
  };
  if (r.exact) {
    const geometry::Region& ra = a.enclosure.inner;
    const geometry::Region& rb = b.enclosure.inner;
    r.a_and_b = exact_piece(ra.intersect(rb));
    r.a_minus_b = exact_piece(ra.subtract(rb));
    r.b_minus_a = exact_piece(rb.subtract(ra));
    r.a_or_b = exact_piece(ra.unite(rb));
  } else {
    r.a_and_b = piece(certified::intersect(a.enclosure, b.enclosure));
    r.a_minus_b = piece(certified::subtract(a.enclosure, b.enclosure));
    r.b_minus_a = piece(certified::subtract(b.enclosure, a.enclosure));
    r.a_or_b = piece(certified::unite(a.enclosure, b.enclosure));
  }

  const std::string unit = r.units, aunit = r.area_units;
  const std::vector<MetricRow> table = {
      {"area", aunit, "bounds", "area_lower", "area_upper", ""},
      {"components", "", "value", "", "", ""},
      {"inscribed_circle", unit, "value", "", "", ""},
      {"rectangle_width", unit, "value", "", "", ""},
      {"rectangle_height", unit, "value", "", "", ""},
      {"rectangle_area", aunit, "value", "", "", ""},
      {"limited_area", aunit, "bounds", "limited_area_lower", "limited_area_upper", ""},
      {"real_area", aunit, "bounds", "real_area_lower", "real_area_upper", ""},
      {"gci", "", "error", "", "", "gci_error"},
  };
  for (const MetricRow& m : table) r.metrics.push_back(metric_of(m, a, b));
  // Exact area: the exact value, not the midpoint of its rounding bounds.
  if (r.exact) {
    DiffMetric& area = r.metrics[0];
    area.a = a.enclosure.inner.area();
    area.b = b.enclosure.inner.area();
    area.change = *area.b - *area.a;
    area.relative_change = *area.change / *area.a;
  }
  if (!options.figure.empty()) {
    r.figure = options.figure;
    r.svg = figure_of(r, file_a);
  }
  r.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return r;
}

std::string to_json_text(const DiffReport& r) {
  const auto side = [](const DiffSide& s) {
    return Json{{"file", s.file}, {"name", s.name}, {"mechanism", s.mechanism}, {"method", s.method}};
  };
  const auto region = [](const DiffRegion& p) {
    return Json{{"area", p.area}, {"area_lower", p.area_lower}, {"area_upper", p.area_upper}};
  };
  Json metrics = Json::array();
  for (const auto& m : r.metrics) metrics.push_back(metric_json(m));
  Json j;
  j["a"] = side(r.a);
  j["b"] = side(r.b);
  j["units"] = r.units;
  j["area_units"] = r.area_units;
  j["method"] = r.exact ? "exact" : "certified";
  j["regions"] = Json{{"a_and_b", region(r.a_and_b)},
                      {"a_minus_b", region(r.a_minus_b)},
                      {"b_minus_a", region(r.b_minus_a)},
                      {"a_or_b", region(r.a_or_b)}};
  j["metrics"] = metrics;
  if (!r.figure.empty()) {
    j["figure"] = r.figure;
  } else {
    j["figure"] = nullptr;
    j["figure_reason"] = "no -o FIG.svg given";
  }
  j["time_ms"] = r.time_ms;
  return detail::json_text(std::move(j));
}

std::string to_text(const DiffReport& r) {
  using detail::format;
  const std::string& aunit = r.area_units;
  std::string t = format("A  %s (%s, %s)\nB  %s (%s, %s)\n", r.a.name.c_str(), r.a.file.c_str(), r.a.method.c_str(),
                         r.b.name.c_str(), r.b.file.c_str(), r.b.method.c_str());
  t += format("\nregions (%s)\n", r.exact ? "exact: CGAL Booleans of the exact regions"
                                         : "certified: [area of the inner, area of the outer enclosure]");
  const auto region_line = [&](const char* label, const DiffRegion& p) {
    const std::string v = r.exact ? g(p.area, 15) : io::interval_text(p.area_lower, p.area_upper, 8);
    t += format("  %s%s %s\n", pad(label, 8).c_str(), v.c_str(), aunit.c_str());
  };
  region_line("A \u2229 B", r.a_and_b);
  region_line("A \u2212 B", r.a_minus_b);
  region_line("B \u2212 A", r.b_minus_a);
  region_line("A \u222a B", r.a_or_b);
  t += format("\n%s%s%s%s%s\n", pad("metric", 22).c_str(), pad("A", 24).c_str(), pad("B", 24).c_str(),
              pad("B \u2212 A", 18).c_str(), "relative");
  for (const auto& m : r.metrics) {
    std::string name = m.metric;
    if (!m.unit.empty()) name += " (" + m.unit + ")";
    const std::string change = m.change ? g(*m.change, 8) : "n/a";
    const std::string rel = m.relative_change ? g(100.0 * *m.relative_change, 4) + " %" : "n/a";
    t += format("%s%s%s%s%s\n", pad(name, 22).c_str(), pad(text_value(m, true), 24).c_str(),
                pad(text_value(m, false), 24).c_str(), pad(change, 18).c_str(), rel.c_str());
  }
  for (const auto& m : r.metrics) {
    if (!m.a) t += format("  %s n/a for A: %s\n", m.metric.c_str(), m.a_reason.c_str());
    if (!m.b) t += format("  %s n/a for B: %s\n", m.metric.c_str(), m.b_reason.c_str());
  }
  if (!r.figure.empty()) t += format("\nfigure  %s\n", r.figure.c_str());
  return t;
}

}  // namespace pkmws::report
