// pkmws explain FILE X Y [--json]: which parts collide at that platform
// position (docs/format.md (bodies); the report is the library's,
// pkmws/report/explain.hpp), and the real workspace's figure pieces of export and batch.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <numbers>

#include "bodies_cli.hpp"
#include "pkmws/geometry/primitives.hpp"
#include "pkmws/io/export.hpp"
#include "pkmws/report/explain.hpp"

namespace pkmws::cli {

namespace {

using report::pair_label;

// Four significant digits without an exponent ("10410", "880.5", "0.02342").
std::string sig4(double v) {
  const int mag = v != 0.0 ? static_cast<int>(std::floor(std::log10(std::abs(v)))) : 0;
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*f", std::max(0, 3 - mag), v);
  return buf;
}

const std::vector<std::string> kPalette = {"#1f77b4", "#ff7f0e", "#2ca02c", "#9467bd", "#8c564b",
                                           "#e377c2", "#17becf", "#bcbd22", "#7f7f7f", "#d62728"};

}  // namespace

std::vector<io::FigureOptions::Overlay> real_workspace_overlays(const bodies::RealWorkspace& real,
                                                                const std::string& area_unit) {
  // Interference regions hatched, one colour and angle per pair: where two
  // overlap, both hatchings show (translucent fills would mix into colours
  // that are not in the legend). Each is tagged with its number in the legend.
  static const double kHatch[] = {45.0, -45.0, 0.0, 90.0, 22.5, -67.5, 67.5, -22.5};
  std::vector<io::FigureOptions::Overlay> out;
  std::size_t k = 0;
  for (const auto& i : real.interference) {
    if (i.region.outer.empty()) continue;
    io::FigureOptions::Overlay ov;
    // The outer enclosure (certainly contains the region).
    ov.region = i.region.outer;
    ov.fill = kPalette[k % kPalette.size()];
    ov.hatch_deg = kHatch[k % std::size(kHatch)];
    ov.stroke = "none";
    ov.css_class = "interference";
    ov.label = std::to_string(k + 1);
    ov.legend = ov.label + " " + pair_label(i.a, i.b, i.kind) + ": " +
                (i.region.exact ? sig4(i.region.area_lower)
                                : sig4(i.region.area_lower) + "\u2013" + sig4(i.region.area_upper)) +
                " " + area_unit;
    ov.legend_rank = 2;
    out.push_back(std::move(ov));
    ++k;
  }
  io::FigureOptions::Overlay outline;
  outline.region = real.real.inner;
  outline.fill = "none";
  outline.stroke = "black";
  outline.stroke_px = 2.2;
  outline.css_class = "real";
  outline.legend_rank = 1;
  outline.legend = std::string(real.real.exact ? "real workspace" : "real workspace (inner enclosure)") + ": " +
                   io::interval_text(real.real.area_lower, real.real.area_upper, 5) + " " + area_unit;
  out.push_back(std::move(outline));
  return out;
}

std::vector<io::FigureOptions::Part> figure_parts(const io::MechanismFile& file, geometry::Point p) {
  std::vector<io::FigureOptions::Part> out;
  const auto shapes = file.bodies->shapes_at(p);
  if (!shapes) return out;
  const auto& parts = file.bodies->model().parts;
  const std::string& u = file.units;
  auto num = [](double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return std::string(buf);
  };
  // Fixed parts first, then the moving ones on top (opaque: no mixed colours).
  for (int pass = 0; pass < 2; ++pass) {
    for (std::size_t k = 0; k < shapes->size(); ++k) {
      const bodies::Part& part = parts[k];
      if (!part.solid() || part.fixed() != (pass == 0)) continue;
      io::FigureOptions::Part fp;
      fp.core = (*shapes)[k].core;
      fp.radius = (*shapes)[k].radius;
      switch (part.kind) {
        case bodies::PartKind::housing:
          fp.fill = "#9e9e9e";
          fp.stroke = "#424242";
          fp.css_class = "part housing";
          fp.legend = "housing (" + num(part.width) + " " + u + " wide)";
          break;
        case bodies::PartKind::obstacle:
          fp.fill = "#a1887f";
          fp.stroke = "#4e342e";
          fp.css_class = "part obstacle";
          fp.legend = "obstacle";
          break;
        case bodies::PartKind::slider_block:
          fp.fill = "#b0bec5";
          fp.stroke = "#37474f";
          fp.css_class = "part slider-block";
          fp.legend = "slider block (" + num(part.length) + " \u00d7 " + num(part.width) + " " + u + ")";
          break;
        case bodies::PartKind::link:
          fp.fill = "#dfe6ea";
          fp.stroke = "#607d8b";
          fp.css_class = "part link-body";
          fp.legend = std::string(part.proximal ? "proximal link" : file.bodies->link_noun()) +
                      " body (\u2300 " + num(2 * part.radius) + " " + u + ")";
          break;
        case bodies::PartKind::platform_joint:
          fp.fill = "#ffe0b2";
          fp.stroke = "#e65100";
          fp.css_class = "part platform-joint";
          fp.legend = "platform joint (\u2300 " + num(2 * part.radius) + " " + u + ")";
          break;
      }
      out.push_back(std::move(fp));
    }
  }
  return out;
}

void add_explain(CLI::App& app, std::vector<Command>& commands) {
  auto* sub = app.add_subcommand("explain", "Which parts collide at a platform position (needs `bodies`)");
  struct Args {
    std::string file, x, y;
    bool json = false;
  };
  auto a = std::make_shared<Args>();
  sub->add_option("FILE", a->file, "Mechanism file (JSON) with bodies")->required();
  sub->add_option("X", a->x, "Platform x")->required();
  sub->add_option("Y", a->y, "Platform y")->required();
  sub->add_flag("--json", a->json, "Print one JSON object");
  commands.push_back({sub, [a] {
    const double x = parse_length(a->x, "X"), y = parse_length(a->y, "Y");
    const report::ExplainReport r = report::explain(io::load_mechanism(a->file), {x, y});
    std::cout << (a->json ? report::to_json_text(r) + "\n" : report::to_text(r));
    return 0;
  }});
}

}  // namespace pkmws::cli
