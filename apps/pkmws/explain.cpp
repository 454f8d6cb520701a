// pkmws explain FILE X Y [--json]: which parts collide at that platform
// position (docs/format.md (bodies)), and the real-workspace helpers of area / export / eval.
#include <cmath>
#include <cstdio>
#include <numbers>

#include "bodies_cli.hpp"
#include "pkmws/geometry/primitives.hpp"
#include "pkmws/io/export.hpp"

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

Json collisions_json(const io::MechanismFile& file, geometry::Point p) {
  const auto check = bodies::check_pose(*file.bodies, p);
  Json out{{"reachable", check.reachable}, {"collides", check.collides()}};
  Json hits = Json::array(), pairs = Json::array();
  for (const auto& c : check.contacts) {
    Json j{{"parts", {c.a, c.b}}, {"kind", c.kind}, {"collides", c.collides}};
    if (c.kind == "link_angle") {
      j["angle_margin_deg"] = c.clearance * 180.0 / std::numbers::pi;
    } else {
      j["clearance"] = c.clearance;
    }
    pairs.push_back(j);
    if (c.collides) hits.push_back(pair_label(c.a, c.b, c.kind));
  }
  out["collisions"] = hits;
  out["pairs"] = pairs;
  if (!check.reachable) out["reason"] = "not in the reachable workspace (inverse kinematics or a stroke fails)";
  return out;
}

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
    const io::MechanismFile mech = io::load_mechanism(a->file);
    if (!mech.bodies) throw io::InputError(a->file + ": the file lists no `bodies` (docs/format.md (bodies)): nothing can collide");
    Json out = collisions_json(mech, {x, y});
    out["name"] = mech.name;
    out["mechanism"] = mech.mechanism;
    out["point"] = {x, y};
    out["units"] = mech.units;
    if (a->json) {
      print_json(out);
      return 0;
    }
    std::printf("%s at (%.6g, %.6g) %s\n", mech.name.c_str(), x, y, mech.units.c_str());
    if (!out["reachable"].get<bool>()) {
      std::printf("not reachable: %s\n", out["reason"].get<std::string>().c_str());
      return 0;
    }
    std::printf("%s\n", out["collides"].get<bool>() ? "COLLISION" : "no collision");
    for (const auto& p : out["pairs"]) {
      const std::string label = pair_label(p["parts"][0], p["parts"][1], p["kind"]);
      if (p["kind"] == "link_angle") {
        std::printf("  %-28s %s  angle %+.4g deg from the minimum\n", label.c_str(),
                    p["collides"].get<bool>() ? "collide" : "clear  ", p["angle_margin_deg"].get<double>());
      } else {
        std::printf("  %-28s %s  clearance %+.6g %s\n", label.c_str(), p["collides"].get<bool>() ? "collide" : "clear  ",
                    p["clearance"].get<double>(), mech.units.c_str());
      }
    }
    return 0;
  }});
}

}  // namespace pkmws::cli
