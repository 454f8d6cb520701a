// `pkmws grid` (pkmws/report/grid.hpp): moved from the command line's grid.cpp,
// numbers, JSON and text unchanged.
#include "pkmws/report/grid.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "pkmws/criteria/fields.hpp"
#include "pkmws/report/common.hpp"
#include "report/json.hpp"
#include "report/text.hpp"

namespace pkmws::report {

using detail::Json;

namespace {

grid::Isa parse_isa(const std::string& s) {
  for (const grid::Isa isa : {grid::Isa::scalar, grid::Isa::baseline, grid::Isa::avx2, grid::Isa::avx512,
                              grid::Isa::best}) {
    if (s == grid::to_string(isa)) return isa;
  }
  throw io::InputError("--isa: expected scalar, baseline, avx2, avx512 or best, got \"" + s + "\"");
}

Json grid_json(const GridReport& r) {
  const grid::SampleResult& s = r.result;
  Json j{{"name", r.name}, {"mechanism", r.mechanism}, {"units", r.units}, {"method", "grid"}};
  if (r.polar) {
    j["rings"] = r.polar->rings;
    j["sectors"] = r.polar->sectors;
    j["centre"] = {r.polar->centre.x, r.polar->centre.y};
    j["radius"] = r.polar->radius;
  }
  if (r.adaptive) {
    j["depth"] = r.adaptive->depth;
    j["root_cells"] = r.adaptive->root_cells;
    j["effective_cells_per_side"] = r.adaptive->effective_cells;
    j["straddle_rule"] = r.adaptive->rule;
    j["undecided_cells"] = r.adaptive->undecided;
    j["area_centre_test"] = r.adaptive->area_centre;
    j["cells_per_level"] = r.adaptive->cells_per_level;
  }
  if (r.sweep) {
    j["joint_samples"] = r.sweep->samples;
    j["valid_poses"] = r.sweep->valid_poses;
    j["raster_boundary_cells"] = r.sweep->boundary_cells;
  }
  j["sampler"] = s.method;
  j["area"] = s.area;
  if (r.certified()) {
    j["area_lower"] = *s.area_lower;
    j["area_upper"] = *s.area_upper;
  } else if (s.area_lower && s.area_upper) {
    // Not a guarantee: kept under other names so scripts reading
    // area_lower/area_upper never mistake it for one.
    j["area_lower_if_resolved"] = *s.area_lower;
    j["area_upper_if_resolved"] = *s.area_upper;
  }
  j["bounds"] = r.bounds;
  j["cells"] = s.cells;
  j["points_tested"] = s.points_tested;
  j["inside"] = s.inside;
  j["points_per_second"] = s.points_per_second;
  j["time_ms"] = s.time_ms;
  j["bounds_time_ms"] = s.bounds_time_ms;
  j["threads"] = s.threads;
  j["kernel"] = s.kernel;
  j["isa"] = s.isa;
  return j;
}

}  // namespace

GridReport grid(const io::MechanismFile& mech, const GridOptions& o) {
  // With criteria limits, a grid point counts when it is reachable and
  // within every limit (the same fields as the certified level sets).
  const std::shared_ptr<const mechanisms::Mechanism> model =
      mech.criteria.any() ? criteria::limited_mechanism(mech) : mech.model;
  if (int(o.polar) + int(o.adaptive >= 0) + int(o.sweep) > 1) {
    throw io::InputError("grid: give at most one of --polar, --adaptive, --sweep");
  }
  // Bounds on the work (minutes at the slowest membership tests, ~5e5 per second).
  if (o.adaptive >= 0 && std::ldexp(static_cast<double>(o.cells), o.adaptive) > 0x1p24) {
    throw io::InputError("--adaptive: --cells x 2^DEPTH must not exceed 2^24 cells per side (got " +
                         std::to_string(o.cells) + " x 2^" + std::to_string(o.adaptive) + ")");
  }
  if (o.sweep && std::pow(static_cast<double>(o.samples ? o.samples : 5 * o.cells), mech.model->dof()) > 0x1p28) {
    throw io::InputError("--samples: at most 2^28 direct-kinematics samples in all (samples^" +
                         std::to_string(mech.model->dof()) + "); give fewer --samples or --cells");
  }
  grid::Execution exec;
  exec.threads = o.threads;
  exec.isa = parse_isa(o.isa);
  const std::size_t n = o.cells;
  GridReport report;
  report.name = mech.name;
  report.mechanism = mech.mechanism;
  report.units = mech.units;
  report.area_units = area_unit(mech);
  grid::SampleResult& r = report.result;
  try {
    if (o.polar) {
      grid::PolarOptions po;
      po.rings = n;
      // ~square cells at half the radius: 2 pi (R/2) / sectors = R / rings; a multiple of 4.
      po.sectors = std::max<std::size_t>(4, 4 * std::size_t(std::llround(std::numbers::pi * double(n) / 4.0)));
      po.certified_bounds = true;
      const auto p = grid::polar(*model, po, exec);
      r = p;
      report.polar = GridReport::Polar{po.rings, po.sectors, p.centre, p.radius};
      report.description = "polar " + std::to_string(po.rings) + " rings x " + std::to_string(po.sectors) + " sectors";
    } else if (o.adaptive >= 0) {
      grid::AdaptiveOptions ao;
      ao.base_cells = n;
      ao.depth = o.adaptive;
      const auto a = grid::adaptive(*model, ao, exec);
      r = a;
      report.adaptive = GridReport::Adaptive{a.cells_per_level.size() - 1, n,           a.effective_cells, a.rule,
                                             a.undecided,                  a.area_centre, a.cells_per_level};
      report.description = "adaptive quadtree, " + std::to_string(n) + "^2 root cells, depth " +
                           std::to_string(o.adaptive) + " (" + std::to_string(a.effective_cells) +
                           " cells per side), " + a.rule + " straddle rule";
    } else if (o.sweep) {
      grid::JointSweepOptions jo;
      jo.raster_cells = n;
      jo.samples = o.samples ? o.samples : 5 * n;
      const auto s = grid::joint_sweep(*model, jo, exec);
      r = s;
      report.sweep = GridReport::JointSweep{jo.samples, s.poses, s.boundary_cells};
      report.description = "joint-space sweep, " + std::to_string(jo.samples) + "^2 DK samples rasterised on " +
                           std::to_string(n) + "^2 cells";
    } else {
      grid::CartesianOptions co;
      co.cells_x = co.cells_y = n;
      co.certified_bounds = true;
      r = grid::cartesian(*model, co, exec);
      report.description = "Cartesian " + std::to_string(n) + " x " + std::to_string(n) + " cells, cell-centre IK test";
    }
  } catch (const std::invalid_argument& e) {
    throw io::InputError(mech.path + ": " + e.what());
  }
  if (report.certified()) {
    report.bounds = "certified: cells decided by a 1-Lipschitz bound of the membership test";
  } else if (r.area_lower && r.area_upper) {
    report.bounds = std::string("none certified: ") +
                    (r.method == "joint_sweep" ? "the raster bracket misses cells where the DK spreads samples apart"
                                               : "no certified cell test for " + mech.mechanism +
                                                     "; the bracket holds only if every feature is wider than a cell");
  } else {
    report.bounds = "none: no certified cell test for " + mech.mechanism;
  }
  return report;
}

std::string to_json_text(const GridReport& r) { return detail::json_text(grid_json(r)); }

std::string to_text(const GridReport& report) {
  using detail::format;
  const grid::SampleResult& r = report.result;
  std::string t = format("%s (%s)\n", report.name.c_str(), report.mechanism.c_str());
  t += format("area       %.10g %s  (grid: %s)\n", r.area, report.area_units.c_str(), report.description.c_str());
  if (report.certified()) {
    t += format("bounds     [%.10g, %.10g] (certified)\n", *r.area_lower, *r.area_upper);
  } else if (r.area_lower && r.area_upper) {
    t += format("bounds     [%.10g, %.10g] (%s)\n", *r.area_lower, *r.area_upper, report.bounds.c_str());
  } else {
    t += format("bounds     %s\n", report.bounds.c_str());
  }
  t += format("cells      %llu, %llu %s, %.3g per second (%d thread%s, %s kernel, %s)\n",
              static_cast<unsigned long long>(r.cells), static_cast<unsigned long long>(r.points_tested),
              r.method == "joint_sweep" ? "DK evaluations" : "point tests", r.points_per_second, r.threads,
              r.threads == 1 ? "" : "s", r.kernel.c_str(), r.isa.c_str());
  t += format("time       %.3f ms", r.time_ms);
  if (r.bounds_time_ms > 0.0) t += format(" (of which bounds %.3f ms)", r.bounds_time_ms);
  t += "\n";
  return t;
}

}  // namespace pkmws::report
