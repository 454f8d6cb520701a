// The figures of a file (pkmws/report/figure.hpp): moved from the command
// line's figures.cpp and explain.cpp (the real workspace's overlays and the
// machine's parts), unchanged.
#include "pkmws/report/figure.hpp"

#include <cmath>
#include <cstdio>

#include "pkmws/criteria/fields.hpp"
#include "pkmws/io/export.hpp"
#include "report/text.hpp"

namespace pkmws::report {

namespace {

// A number for captions: printf's %g with 10 significant digits.
std::string format_g10(double v) { return detail::format("%.10g", v); }

// Four significant digits without an exponent ("10410", "880.5", "0.02342").
std::string sig4(double v) {
  const int mag = v != 0.0 ? static_cast<int>(std::floor(std::log10(std::abs(v)))) : 0;
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*f", std::max(0, 3 - mag), v);
  return buf;
}

const std::vector<std::string> kPalette = {"#1f77b4", "#ff7f0e", "#2ca02c", "#9467bd", "#8c564b",
                                           "#e377c2", "#17becf", "#bcbd22", "#7f7f7f", "#d62728"};

// "pressure angle ≤ 40°, reaction ≤ 200 N" from the report's `criteria`.
std::string limits_text(const std::vector<CriterionLimit>& criteria) {
  std::string out;
  for (const auto& c : criteria) {
    const std::string& name = c.criterion;
    char buf[96];
    const double t = c.threshold;
    if (name == "pressure_angle") std::snprintf(buf, sizeof buf, "pressure angle \u2264 %g\u00b0", t);
    else if (name == "reaction") std::snprintf(buf, sizeof buf, "reaction \u2264 %g N", t);
    else if (name == "velocity_ratio") std::snprintf(buf, sizeof buf, "velocity ratio \u2264 %g", t);
    else if (name == "condition_number") std::snprintf(buf, sizeof buf, "condition number \u2264 %g", t);
    else std::snprintf(buf, sizeof buf, "%s \u2264 %g", name.c_str(), t);
    out += (out.empty() ? "" : ", ") + std::string(buf);
  }
  return out;
}

// The figure overlays: interference regions hatched and tagged by pair (legend: the pair and its
// certified area in `area_unit`), the real workspace outlined in black.
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

// The parts at platform point p as figure parts (housings, slider blocks, rods/links, platform
// joint, obstacles), one legend entry per kind with its size in `units`; empty when p is unreachable.
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

}  // namespace

std::string area_figure(const io::MechanismFile& mech, const AreaReport& result) {
  const std::string unit = area_unit(mech);
  const double lo = result.area_lower, hi = result.area_upper;
  io::FigureOptions f;
  f.title = mech.name;
  std::string caption;
  geometry::Region region, pose_region;
  if (result.limited) {
    // [Briot] figs. 10, 13: the certified limited region over the reachable workspace.
    const geometry::Region reachable = criteria::criteria_domain(mech);
    region = reachable;
    f.region_fill = "#e6e6e6";
    f.region_stroke = "#8a8a8a";
    // A 3-RPR without leg limits ([Briot]'s PAMINSA) has the plane as its workspace: the file's analysis window.
    const std::string domain = mech.model->workspace_label();
    f.region_legend = domain + (criteria::criteria_domain_exact(mech) ? " (" : " (outer enclosure, ") +
                      format_g10(reachable.area()) + " " + unit + ")";
    io::FigureOptions::Overlay limited;
    limited.rings = io::traced_inner_rings(result.limited->detail);
    limited.fill = "#f4a3a3";
    limited.stroke = "#8b1a1a";
    limited.stroke_px = 1.6;
    limited.css_class = "limited";
    const std::string limits = limits_text(result.criteria);
    limited.legend = limits + ": inner bound drawn";
    f.overlays.push_back(limited);
    pose_region = io::largest_ring_region(limited.rings, reachable);
    caption = "Workspace with " + limits + ": certified area in " + io::interval_text(lo, hi, 10) + " " + unit +
              ". Filled: its inner bound (certified cells and the inner side of the traced level curves, every "
              "point within the limits); grey: the rest of the " + domain + ".";
  } else if (!result.enclosure.exact) {
    // Certain part filled, the undecided band between the enclosures grey.
    region = result.enclosure.inner;
    f.region_legend = "workspace (inner enclosure)";
    io::FigureOptions::Overlay band;
    band.region = result.enclosure.outer.subtract(result.enclosure.inner);
    band.fill = "#7a7a7a";
    band.stroke = "none";
    band.css_class = "undecided";
    band.legend = "undecided cells (between the enclosures)";
    f.overlays.push_back(band);
    caption = "Certified workspace area in " + io::interval_text(lo, hi, 10) + " " + unit +
              " (filled: the inner enclosure, certainly reachable; grey: undecided cells, outer minus inner).";
  } else {
    region = result.enclosure.inner;
    const std::size_t n = result.components.size();
    caption = "Exact workspace area = " + format_g10(result.area) + " " + unit + " (" + std::to_string(n) +
              " component" + (n == 1 ? "" : "s") + ").";
  }
  if (pose_region.empty()) pose_region = region;
  if (result.real) {
    const auto& real = *result.real;
    f.region_legend = "reachable workspace";
    auto overlays = real_workspace_overlays(real, unit);
    f.overlays.insert(f.overlays.end(), overlays.begin(), overlays.end());
    caption = "Reachable workspace " + format_g10(real.reachable.area_lower) + " " + unit + " (exact, filled); real workspace " +
              io::interval_text(real.real.area_lower, real.real.area_upper, 10) + " " + unit + " (" + real.real.method() +
              ", black outline): reachable minus the interference of the numbered pairs (hatched). Parts drawn at "
              "the pose P.";
    if (!real.real.inner.empty()) pose_region = real.real.inner;  // a collision-free pose
  }
  const std::string cite = io::source_citation(mech);
  f.caption = (cite.empty() ? "" : cite + ". ") + caption;
  const mechanisms::Pose pose = sample_pose(mech, pose_region);
  if (mech.bodies) f.parts = figure_parts(mech, {pose.x, pose.y});
  return io::workspace_figure(mech, region, pose, f);
}

std::string real_workspace_figure(const io::MechanismFile& mech, const geometry::Region& region) {
  // The real workspace's inner enclosure (the figure of area_figure draws it outlined).
  io::FigureOptions figure;
  figure.title = mech.name;
  figure.region_legend = "real workspace (inner enclosure)";
  figure.caption = "Inner enclosure of the real workspace (certainly reachable without collision): area " +
                   format_g10(region.area()) + " " + area_unit(mech) + ".";
  const mechanisms::Pose pose = sample_pose(mech, region);
  figure.parts = figure_parts(mech, {pose.x, pose.y});
  return io::workspace_figure(mech, region, pose, figure);
}

}  // namespace pkmws::report
