// The figure of a mechanism file as `pkmws export -f svg` and `pkmws batch`
// draw it, with the numbers of `pkmws area` in its caption.
#include <cstdio>

#include "bodies_cli.hpp"
#include "pkmws/criteria/fields.hpp"
#include "pkmws/io/figure.hpp"

namespace pkmws::cli {

namespace {

// "pressure angle ≤ 40°, reaction ≤ 200 N" from the report's `criteria`.
std::string limits_text(const std::vector<report::CriterionLimit>& criteria) {
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

}  // namespace

std::string file_figure(const io::MechanismFile& mech, const report::AreaReport& result) {
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
    f.region_legend = domain + " (" + format_g(reachable.area()) + " " + unit + ")";
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
    caption = "Exact workspace area = " + format_g(result.area) + " " + unit + " (" + std::to_string(n) +
              " component" + (n == 1 ? "" : "s") + ").";
  }
  if (pose_region.empty()) pose_region = region;
  if (result.real) {
    const auto& real = *result.real;
    f.region_legend = "reachable workspace";
    auto overlays = real_workspace_overlays(real, unit);
    f.overlays.insert(f.overlays.end(), overlays.begin(), overlays.end());
    caption = "Reachable workspace " + format_g(real.reachable.area_lower) + " " + unit + " (exact, filled); real workspace " +
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

}  // namespace pkmws::cli
