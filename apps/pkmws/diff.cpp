// pkmws diff A.json B.json [-o FIG.svg] [--json]: two designs compared
// (docs/design_space.md, "Comparing designs"): the exact areas of A ∩ B,
// A − B, B − A and A ∪ B (CGAL Booleans on the exact regions; certified
// bounds from the enclosure algebra otherwise), the change of every sweep
// metric, and both workspaces in one figure.
#include <cmath>
#include <cstdio>
#include <memory>

#include "cli.hpp"
#include "pkmws/pkmws.hpp"
#include "pkmws/design/sweep.hpp"
#include "pkmws/io/export.hpp"
#include "pkmws/io/figure.hpp"

namespace pkmws::cli {

namespace {

// Okabe-Ito colours (colour-blind safe): A only, B only, both.
constexpr const char* kFillA = "#E69F00";
constexpr const char* kFillB = "#56B4E9";
constexpr const char* kFillBoth = "#009E73";

struct Side {
  io::MechanismFile file;
  certified::CertifiedRegion enclosure;
  design::SweepSpec spec;
  design::DesignRow row;
};

// The metrics of one file, computed as a sweep computes them (one design, no parameters).
void evaluate(Side& s, double rectangle_precision, double criteria_tolerance, int gci_cells) {
  s.spec.base_file = s.file.path;
  s.spec.base_document = io::document_text(s.file);
  s.spec.metrics = {"area", "components", "inscribed_circle", "inscribed_rectangle", "limited_area", "real_area",
                    "gci"};
  s.spec.rectangle_precision = rectangle_precision;
  s.spec.criteria_tolerance = criteria_tolerance;
  s.spec.gci_cells = gci_cells;
  s.row = design::evaluate_design(s.spec, 0);
  if (s.row.status != "ok") throw io::InputError(s.file.path + ": " + s.row.reason);
}

std::optional<double> column(const Side& s, const std::string& name) {
  const auto cols = design::metric_columns(s.spec);
  for (std::size_t k = 0; k < cols.size(); ++k) {
    if (cols[k] == name) return s.row.metrics[k];
  }
  return std::nullopt;
}


Json area_json(const certified::CertifiedRegion& r) {
  if (r.exact) {
    const double a = r.inner.area();
    const double rounding = 64 * std::numeric_limits<double>::epsilon() * a;
    return Json{{"area", a}, {"area_lower", a - rounding}, {"area_upper", a + rounding}};
  }
  return Json{{"area", r.area_estimate()}, {"area_lower", r.area_lower}, {"area_upper", r.area_upper}};
}

// One row of the metric table: values of A and B (with bounds or an error
// where the metric has them), the change B − A, or nulls with reasons.
struct MetricRow {
  std::string metric, unit, kind;  // kind: "value", "bounds", "error"
  std::string lower_col, upper_col, error_col;
};

Json metric_json(const MetricRow& m, const Side& a, const Side& b) {
  Json j{{"metric", m.metric}, {"unit", m.unit}};
  const auto why_missing = [&](const Side& s) -> std::string {
    if (m.metric == "limited_area") return s.file.path + " has no criteria";
    if (m.metric == "real_area") return s.file.path + " has no bodies";
    if (m.metric == "gci") {
      const std::string r = s.row.reason;
      return r.rfind("gci: ", 0) == 0 ? r.substr(5) : "no condition number";
    }
    return "not computed";
  };
  std::optional<double> va, vb, la, ua, lb, ub, ea, eb;
  if (m.kind == "bounds") {
    la = column(a, m.lower_col), ua = column(a, m.upper_col), lb = column(b, m.lower_col), ub = column(b, m.upper_col);
    if (la && ua) va = 0.5 * (*la + *ua);
    if (lb && ub) vb = 0.5 * (*lb + *ub);
  } else {
    va = column(a, m.metric == "inscribed_circle" ? "inscribed_circle_radius" : m.metric);
    vb = column(b, m.metric == "inscribed_circle" ? "inscribed_circle_radius" : m.metric);
    if (m.kind == "error") ea = column(a, m.error_col), eb = column(b, m.error_col);
  }
  const auto put = [&](const std::string& key, std::optional<double> v, const std::string& reason) {
    j[key] = v ? Json(*v) : Json(nullptr);
    if (!v) j[key + "_reason"] = reason;
  };
  put("a", va, why_missing(a));
  put("b", vb, why_missing(b));
  std::optional<double> change, relative;
  if (va && vb) change = *vb - *va;
  if (change && *va != 0.0) relative = *change / *va;
  put("change", change, va && vb ? "" : "the metric is missing for " + std::string(!va ? "A" : "B"));
  put("relative_change", relative, !change ? "no change (a value is missing)" : "A's value is 0");
  if (m.kind == "bounds") {
    if (la && ua) j["a_bounds"] = {*la, *ua};
    if (lb && ub) j["b_bounds"] = {*lb, *ub};
    if (la && ua && lb && ub) j["change_bounds"] = {*lb - *ua, *ub - *la};
  }
  if (m.kind == "error") {
    if (ea) j["a_error"] = *ea;
    if (eb) j["b_error"] = *eb;
    if (ea && eb) j["change_error"] = *ea + *eb;
  }
  return j;
}

// `s` padded with spaces to `width` characters (UTF-8 code points).
std::string pad(const std::string& s, std::size_t width) {
  std::size_t n = 0;
  for (unsigned char c : s) n += (c & 0xC0) != 0x80;
  return s + std::string(n < width ? width - n : 1, ' ');
}

std::string text_value(const Json& j, const std::string& side) {
  if (j[side].is_null()) return "n/a";
  const bool wide = j.contains(side + "_bounds") &&
                    j[side + "_bounds"][1].get<double>() - j[side + "_bounds"][0].get<double>() >
                        1e-12 * std::abs(j[side].get<double>());
  if (wide) {
    return io::interval_text(j[side + "_bounds"][0].get<double>(), j[side + "_bounds"][1].get<double>(), 8);
  }
  if (j.contains(side + "_error")) return format_g(j[side].get<double>(), 6) + " ± " + format_g(j[side + "_error"].get<double>(), 2);
  return format_g(j[side].get<double>(), 12);
}

}  // namespace

void add_diff(CLI::App& app, std::vector<Command>& commands) {
  auto* sub = app.add_subcommand("diff", "Compare two designs: A ∩ B, A − B, B − A and every metric's change");
  struct Args {
    std::string a, b, figure;
    bool json = false;
    double rectangle_precision = 1e-6, criteria_tolerance = 1e-4;
    int gci_cells = 128;
  };
  auto args = std::make_shared<Args>();
  sub->add_option("A", args->a, "First mechanism file (JSON)")->required();
  sub->add_option("B", args->b, "Second mechanism file (JSON), in the same length unit")->required();
  sub->add_option("-o,--output", args->figure, "Write the figure (SVG): A only, B only, A ∩ B");
  sub->add_flag("--json", args->json, "Print one JSON object");
  sub->add_option("--rectangle-precision", args->rectangle_precision,
                  "Relative width of the inscribed rectangle's bounds (default 1e-6)")
      ->check(CLI::Range(1e-12, 0.5));
  sub->add_option("--criteria-tolerance", args->criteria_tolerance,
                  "Files with criteria: relative width of the certified limited area (default 1e-4)")
      ->check(CLI::Range(1e-9, 0.5));
  sub->add_option("--gci-cells", args->gci_cells, "Fine-grid cells across a workspace for the GCI (default 128)")
      ->check(CLI::Range(2, 4096));
  commands.push_back({sub, [args] {
    const auto start = std::chrono::steady_clock::now();
    check_outputs({args->figure});
    Side a, b;
    a.file = io::load_mechanism(args->a);
    b.file = io::load_mechanism(args->b);
    // One length unit: areas and changes are only comparable then.
    if (a.file.units != b.file.units) {
      throw io::InputError(b.file.path + ": units: \"" + b.file.units + "\" differs from \"" + a.file.units +
                           "\" of " + a.file.path + " (diff compares files in one length unit; convert one)");
    }
    a.enclosure = pkmws::workspace(a.file);
    b.enclosure = pkmws::workspace(b.file);
    evaluate(a, args->rectangle_precision, args->criteria_tolerance, args->gci_cells);
    evaluate(b, args->rectangle_precision, args->criteria_tolerance, args->gci_cells);

    // The Boolean pieces: exact regions, or the enclosure algebra.
    const bool exact = a.enclosure.exact && b.enclosure.exact;
    const auto area_of = [](const geometry::Region& inner, const geometry::Region& outer, bool ex) {
      certified::CertifiedRegion r;
      r.inner = inner;
      r.outer = ex ? inner : outer;
      r.exact = ex;
      r.area_lower = r.inner.area();
      r.area_upper = ex ? r.area_lower : r.outer.area();
      return r;
    };
    certified::CertifiedRegion both, a_only, b_only, either;
    if (exact) {
      const geometry::Region& ra = a.enclosure.inner;
      const geometry::Region& rb = b.enclosure.inner;
      both = area_of(ra.intersect(rb), {}, true);
      a_only = area_of(ra.subtract(rb), {}, true);
      b_only = area_of(rb.subtract(ra), {}, true);
      either = area_of(ra.unite(rb), {}, true);
    } else {
      both = certified::intersect(a.enclosure, b.enclosure);
      a_only = certified::subtract(a.enclosure, b.enclosure);
      b_only = certified::subtract(b.enclosure, a.enclosure);
      either = certified::unite(a.enclosure, b.enclosure);
    }

    const std::string unit = a.file.units, aunit = area_unit(a.file);
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
    Json metrics = Json::array();
    for (const MetricRow& m : table) metrics.push_back(metric_json(m, a, b));
    // Exact area: the exact value, not the midpoint of its rounding bounds.
    if (exact) {
      metrics[0]["a"] = a.enclosure.inner.area();
      metrics[0]["b"] = b.enclosure.inner.area();
      metrics[0]["change"] = metrics[0]["b"].get<double>() - metrics[0]["a"].get<double>();
      metrics[0]["relative_change"] = metrics[0]["change"].get<double>() / metrics[0]["a"].get<double>();
    }

    Json report;
    const auto file_json = [](const Side& s) {
      return Json{{"file", s.file.path}, {"name", s.file.name}, {"mechanism", s.file.mechanism},
                  {"method", s.enclosure.method()}};
    };
    report["a"] = file_json(a);
    report["b"] = file_json(b);
    report["units"] = unit;
    report["area_units"] = aunit;
    report["method"] = exact ? "exact" : "certified";
    report["regions"] = Json{{"a_and_b", area_json(both)}, {"a_minus_b", area_json(a_only)},
                             {"b_minus_a", area_json(b_only)}, {"a_or_b", area_json(either)}};
    report["metrics"] = metrics;

    std::string svg;
    if (!args->figure.empty()) {
      io::FigureOptions f;
      f.title = "Workspaces of A and B compared";
      f.draw_mechanism = false;
      f.region_fill = "none";
      f.region_stroke = "#222222";
      f.region_legend = "";
      const auto piece = [&](const geometry::Region& r, const char* fill, const std::string& legend,
                             const std::string& css) {
        io::FigureOptions::Overlay o;
        o.region = r;
        o.fill = fill;
        o.stroke = "#333333";
        o.stroke_px = 0.8;
        o.legend = legend;
        o.css_class = css;
        return o;
      };
      const auto area_text = [&](const certified::CertifiedRegion& r) {
        return (r.exact ? format_g(r.area_lower, 7) : io::interval_text(r.area_lower, r.area_upper, 8)) + " " + aunit;
      };
      f.overlays.push_back(piece(a_only.inner, kFillA, "A only: " + area_text(a_only), "a-only"));
      f.overlays.push_back(piece(b_only.inner, kFillB, "B only: " + area_text(b_only), "b-only"));
      f.overlays.push_back(piece(both.inner, kFillBoth, "A \u2229 B: " + area_text(both), "a-and-b"));
      if (!exact) {
        io::FigureOptions::Overlay band;
        band.region = either.outer.subtract(a_only.inner.unite(b_only.inner).unite(both.inner));
        band.fill = "#9a9a9a";
        band.stroke = "none";
        band.css_class = "undecided";
        band.legend = "undecided (between the enclosures)";
        f.overlays.push_back(band);
      }
      f.caption = "A = " + a.file.name + "; B = " + b.file.name + ". " +
                  (exact ? "Exact areas (CGAL Booleans of the exact regions)"
                         : "Certified area bounds (enclosure algebra; certainly-in parts filled)") +
                  ": |A| = " + text_value(metrics[0], "a") + " " + aunit + ", |B| = " + text_value(metrics[0], "b") + " " + aunit +
                  ", |A \u222a B| = " + area_text(either) + ".";
      svg = io::workspace_figure(a.file, exact ? either.inner : either.outer, mechanisms::Pose{}, f);
      report["figure"] = args->figure;
    } else {
      report["figure"] = nullptr;
      report["figure_reason"] = "no -o FIG.svg given";
    }
    report["time_ms"] = elapsed_ms(start);
    if (!svg.empty()) write_outputs({{args->figure, svg}});

    if (args->json) {
      print_json(report);
      return 0;
    }
    std::printf("A  %s (%s, %s)\nB  %s (%s, %s)\n", a.file.name.c_str(), a.file.path.c_str(),
                a.enclosure.method().c_str(), b.file.name.c_str(), b.file.path.c_str(), b.enclosure.method().c_str());
    std::printf("\nregions (%s)\n", exact ? "exact: CGAL Booleans of the exact regions"
                                         : "certified: [area of the inner, area of the outer enclosure]");
    const auto region_line = [&](const char* label, const char* key) {
      const Json& r = report["regions"][key];
      const std::string v = exact ? format_g(r["area"].get<double>(), 15)
                                  : io::interval_text(r["area_lower"].get<double>(), r["area_upper"].get<double>(), 8);
      std::printf("  %s%s %s\n", pad(label, 8).c_str(), v.c_str(), aunit.c_str());
    };
    region_line("A \u2229 B", "a_and_b");
    region_line("A \u2212 B", "a_minus_b");
    region_line("B \u2212 A", "b_minus_a");
    region_line("A \u222a B", "a_or_b");
    std::printf("\n%s%s%s%s%s\n", pad("metric", 22).c_str(), pad("A", 24).c_str(), pad("B", 24).c_str(),
                pad("B \u2212 A", 18).c_str(), "relative");
    for (const auto& m : metrics) {
      std::string name = m["metric"].get<std::string>();
      if (!m["unit"].get<std::string>().empty()) name += " (" + m["unit"].get<std::string>() + ")";
      const std::string change = m["change"].is_null() ? "n/a" : format_g(m["change"].get<double>(), 8);
      const std::string rel =
          m["relative_change"].is_null() ? "n/a" : format_g(100.0 * m["relative_change"].get<double>(), 4) + " %";
      std::printf("%s%s%s%s%s\n", pad(name, 22).c_str(), pad(text_value(m, "a"), 24).c_str(),
                  pad(text_value(m, "b"), 24).c_str(), pad(change, 18).c_str(), rel.c_str());
    }
    for (const auto& m : metrics) {
      for (const char* side : {"a", "b"}) {
        if (m[side].is_null()) {
          std::printf("  %s n/a for %s: %s\n", m["metric"].get<std::string>().c_str(), side[0] == 'a' ? "A" : "B",
                      m[std::string(side) + "_reason"].get<std::string>().c_str());
        }
      }
    }
    if (!args->figure.empty()) std::printf("\nfigure  %s\n", args->figure.c_str());
    return 0;
  }});
}

}  // namespace pkmws::cli
