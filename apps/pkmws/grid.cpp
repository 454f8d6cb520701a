// pkmws grid FILE --cells N [--polar] [--adaptive DEPTH] [--sweep] [--threads K] [--json]:
// the grid baseline (docs/format.md (command line); [Vasilic] §4.1-4.2, figs. 4 and 8).
#include <cmath>
#include <cstdio>
#include <numbers>

#include "cli.hpp"
#include "pkmws/criteria/fields.hpp"
#include "pkmws/grid/sampler.hpp"

namespace pkmws::cli {

namespace {

grid::Isa parse_isa(const std::string& s) {
  for (const grid::Isa isa : {grid::Isa::scalar, grid::Isa::baseline, grid::Isa::avx2, grid::Isa::avx512,
                              grid::Isa::best}) {
    if (s == grid::to_string(isa)) return isa;
  }
  throw io::InputError("--isa: expected scalar, baseline, avx2, avx512 or best, got \"" + s + "\"");
}

}  // namespace

void add_grid(CLI::App& app, std::vector<Command>& commands) {
  // 16384^2 = 2.7e8 point tests: seconds with the MOMA kernel, minutes with the
  // slowest membership tests; finer resolution is what --adaptive is for.
  constexpr std::size_t max_grid_cells = std::size_t{1} << 14;
  auto* sub = app.add_subcommand("grid", "Grid estimate of the workspace area (the papers' sampling baseline)");
  struct Options {
    std::string file;
    std::size_t cells = 0;
    bool polar = false;
    int adaptive = -1;
    bool sweep = false;
    std::size_t samples = 0;
    int threads = 0;
    std::string isa = "best";
    bool json = false;
  };
  auto o = std::make_shared<Options>();
  sub->add_option("FILE", o->file, "Mechanism file (JSON)")->required();
  sub->add_option("--cells", o->cells,
                  "Cells per side: N x N Cartesian cells over the bounding box; with --polar N rings x ~pi N "
                  "sectors; with --adaptive the root grid; with --sweep the raster")
      ->required()
      ->check(CLI::Range(std::size_t{1}, max_grid_cells));
  sub->add_flag("--polar", o->polar, "Polar grid about the centre of the bounding box ([Vasilic] figs. 9-11a)");
  sub->add_option("--adaptive", o->adaptive, "Quadtree refined DEPTH levels below the root grid")
      ->check(CLI::Range(0, 30));
  sub->add_flag("--sweep", o->sweep, "Joint-space sweep through the direct kinematics ([Vasilic] fig. 4)");
  sub->add_option("--samples", o->samples, "Joint samples per joint for --sweep (default 5 N)")
      ->check(CLI::Range(std::size_t{2}, std::size_t{1} << 16));
  sub->add_option("--threads", o->threads, "Threads (0 = all)")->check(CLI::Range(0, 1024));
  sub->add_option("--isa", o->isa, "Kernel instruction set: scalar, baseline, avx2, avx512, best");
  sub->add_flag("--json", o->json, "Print one JSON object");
  commands.push_back({sub, [o] {
    const io::MechanismFile mech = io::load_mechanism(o->file);
    // With criteria limits, a grid point counts when it is reachable and
    // within every limit (the same fields as the certified level sets).
    const std::shared_ptr<const mechanisms::Mechanism> model =
        mech.criteria.any() ? criteria::limited_mechanism(mech) : mech.model;
    if (int(o->polar) + int(o->adaptive >= 0) + int(o->sweep) > 1) {
      throw io::InputError("grid: give at most one of --polar, --adaptive, --sweep");
    }
    // Bounds on the work (minutes at the slowest membership tests, ~5e5 per second).
    if (o->adaptive >= 0 && std::ldexp(static_cast<double>(o->cells), o->adaptive) > 0x1p24) {
      throw io::InputError("--adaptive: --cells x 2^DEPTH must not exceed 2^24 cells per side (got " +
                           std::to_string(o->cells) + " x 2^" + std::to_string(o->adaptive) + ")");
    }
    if (o->sweep && std::pow(static_cast<double>(o->samples ? o->samples : 5 * o->cells), mech.model->dof()) > 0x1p28) {
      throw io::InputError("--samples: at most 2^28 direct-kinematics samples in all (samples^" +
                           std::to_string(mech.model->dof()) + "); give fewer --samples or --cells");
    }
    grid::Execution exec;
    exec.threads = o->threads;
    exec.isa = parse_isa(o->isa);
    const std::size_t n = o->cells;
    Json report{{"name", mech.name}, {"mechanism", mech.mechanism}, {"units", mech.units}, {"method", "grid"}};
    grid::SampleResult r;
    std::string description;
    try {
      if (o->polar) {
        grid::PolarOptions po;
        po.rings = n;
        // ~square cells at half the radius: 2 pi (R/2) / sectors = R / rings; a multiple of 4.
        po.sectors = std::max<std::size_t>(4, 4 * std::size_t(std::llround(std::numbers::pi * double(n) / 4.0)));
        po.certified_bounds = true;
        const auto p = grid::polar(*model, po, exec);
        r = p;
        report["rings"] = po.rings;
        report["sectors"] = po.sectors;
        report["centre"] = {p.centre.x, p.centre.y};
        report["radius"] = p.radius;
        description = "polar " + std::to_string(po.rings) + " rings x " + std::to_string(po.sectors) + " sectors";
      } else if (o->adaptive >= 0) {
        grid::AdaptiveOptions ao;
        ao.base_cells = n;
        ao.depth = o->adaptive;
        const auto a = grid::adaptive(*model, ao, exec);
        r = a;
        report["depth"] = a.cells_per_level.size() - 1;
        report["root_cells"] = n;
        report["effective_cells_per_side"] = a.effective_cells;
        report["straddle_rule"] = a.rule;
        report["undecided_cells"] = a.undecided;
        report["area_centre_test"] = a.area_centre;
        report["cells_per_level"] = a.cells_per_level;
        description = "adaptive quadtree, " + std::to_string(n) + "^2 root cells, depth " +
                      std::to_string(o->adaptive) + " (" + std::to_string(a.effective_cells) + " cells per side), " +
                      a.rule + " straddle rule";
      } else if (o->sweep) {
        grid::JointSweepOptions jo;
        jo.raster_cells = n;
        jo.samples = o->samples ? o->samples : 5 * n;
        const auto s = grid::joint_sweep(*model, jo, exec);
        r = s;
        report["joint_samples"] = jo.samples;
        report["valid_poses"] = s.poses;
        report["raster_boundary_cells"] = s.boundary_cells;
        description = "joint-space sweep, " + std::to_string(jo.samples) + "^2 DK samples rasterised on " +
                      std::to_string(n) + "^2 cells";
      } else {
        grid::CartesianOptions co;
        co.cells_x = co.cells_y = n;
        co.certified_bounds = true;
        r = grid::cartesian(*model, co, exec);
        description = "Cartesian " + std::to_string(n) + " x " + std::to_string(n) + " cells, cell-centre IK test";
      }
    } catch (const std::invalid_argument& e) {
      throw io::InputError(o->file + ": " + e.what());
    }
    report["sampler"] = r.method;
    report["area"] = r.area;
    if (r.area_lower && r.area_upper && r.bounds_certified) {
      report["area_lower"] = *r.area_lower;
      report["area_upper"] = *r.area_upper;
      report["bounds"] = "certified: cells decided by a 1-Lipschitz bound of the membership test";
    } else if (r.area_lower && r.area_upper) {
      // Not a guarantee: kept under other names so scripts reading
      // area_lower/area_upper never mistake it for one.
      report["area_lower_if_resolved"] = *r.area_lower;
      report["area_upper_if_resolved"] = *r.area_upper;
      report["bounds"] = std::string("none certified: ") +
                         (r.method == "joint_sweep"
                              ? "the raster bracket misses cells where the DK spreads samples apart"
                              : "no certified cell test for " + mech.mechanism +
                                    "; the bracket holds only if every feature is wider than a cell");
    } else {
      report["bounds"] = "none: no certified cell test for " + mech.mechanism;
    }
    report["cells"] = r.cells;
    report["points_tested"] = r.points_tested;
    report["inside"] = r.inside;
    report["points_per_second"] = r.points_per_second;
    report["time_ms"] = r.time_ms;
    report["bounds_time_ms"] = r.bounds_time_ms;
    report["threads"] = r.threads;
    report["kernel"] = r.kernel;
    report["isa"] = r.isa;
    if (o->json) {
      print_json(report);
      return 0;
    }
    std::printf("%s (%s)\n", mech.name.c_str(), mech.mechanism.c_str());
    std::printf("area       %.10g %s  (grid: %s)\n", r.area, area_unit(mech).c_str(), description.c_str());
    if (report.contains("area_lower")) {
      std::printf("bounds     [%.10g, %.10g] (certified)\n", *r.area_lower, *r.area_upper);
    } else if (report.contains("area_lower_if_resolved")) {
      std::printf("bounds     [%.10g, %.10g] (%s)\n", *r.area_lower, *r.area_upper,
                  report["bounds"].get<std::string>().c_str());
    } else {
      std::printf("bounds     %s\n", report["bounds"].get<std::string>().c_str());
    }
    std::printf("cells      %llu, %llu %s, %.3g per second (%d thread%s, %s kernel, %s)\n",
                static_cast<unsigned long long>(r.cells), static_cast<unsigned long long>(r.points_tested),
                r.method == "joint_sweep" ? "DK evaluations" : "point tests", r.points_per_second, r.threads,
                r.threads == 1 ? "" : "s", r.kernel.c_str(), r.isa.c_str());
    std::printf("time       %.3f ms", r.time_ms);
    if (r.bounds_time_ms > 0.0) std::printf(" (of which bounds %.3f ms)", r.bounds_time_ms);
    std::printf("\n");
    return 0;
  }});
}

}  // namespace pkmws::cli
