// pkmws export FILE --format svg|dxf|wkt|geojson|csv -o OUT (docs/format.md (command line)).
#include <cmath>
#include <cstdio>

#include "bodies_cli.hpp"
#include "pkmws/criteria/fields.hpp"
#include "pkmws/io/export.hpp"

namespace pkmws::cli {

void add_export(CLI::App& app, std::vector<Command>& commands) {
  auto* sub = app.add_subcommand("export", "Write the workspace boundary (svg, dxf, wkt, geojson, csv)");
  struct Args {
    std::string file, format, out;
    double tolerance = 0.0;
    bool bare = false;
    bool real = false;
    std::string bound = "outer";
    std::string criterion, levels;
  };
  auto a = std::make_shared<Args>();
  sub->add_option("FILE", a->file, "Mechanism file (JSON)")->required();
  sub->add_option("--format,-f", a->format, "svg | dxf | wkt | geojson | csv")->required();
  sub->add_option("-o,--output", a->out, "Output file")->required();
  sub->add_option("--tolerance", a->tolerance,
                  "Max deviation of polylines (wkt, geojson) in the file's unit; "
                  "default 1e-6 of the bounding-box diagonal");
  sub->add_flag("--bare", a->bare, "svg: the boundary only, without axes and mechanism");
  sub->add_flag("--real", a->real,
                "Files with bodies: export the real workspace's inner enclosure (certainly reachable "
                "without collision) instead of the computed workspace");
  sub->add_option("--bound", a->bound,
                  "Certified workspaces (boundary not made of arcs and segments, e.g. the real-scheme "
                  "biglide, or files with criteria limits): export the outer enclosure (every point of "
                  "the region, default) or the inner one (only points of the region)")
      ->check(CLI::IsMember({"inner", "outer"}));
  sub->add_option("--criterion", a->criterion,
                  "With --levels: export the bands of a criterion (pressure_angle, reaction, velocity_ratio) "
                  "instead of the workspace: svg = band figure, csv = traced level curves");
  sub->add_option("--levels", a->levels, "Increasing thresholds of --criterion, e.g. 20,40,60,80");
  commands.push_back({sub, [a] {
    const io::ExportFormat format = io::parse_export_format(a->format);
    if (a->criterion.empty() != a->levels.empty()) throw io::InputError("--criterion and --levels go together");
    if (!a->criterion.empty()) {
      if (format != io::ExportFormat::svg && format != io::ExportFormat::csv) {
        throw io::InputError("--criterion: the bands export as svg (figure) or csv (traced level curves)");
      }
      const io::MechanismFile mech = io::load_mechanism(a->file);
      io::write_file_atomic(a->out, bands_export(mech, a->criterion, a->levels, format == io::ExportFormat::svg, 1e-4));
      return 0;
    }
    if (a->tolerance < 0.0 || !std::isfinite(a->tolerance)) {
      throw io::InputError("--tolerance: must be a positive length");
    }
    const io::MechanismFile mech = io::load_mechanism(a->file);
    if (format == io::ExportFormat::svg && !a->bare && !a->real) {
      // The figure: what `pkmws area` computes, drawn as `pkmws batch` draws it
      // (criteria files: the certified limited region; bodies: the real workspace).
      io::write_file_atomic(a->out, file_figure(mech, compute_area(mech, 7)));
      return 0;
    }
    // With criteria limits ([Briot] figs. 10, 13): the certified limited
    // region, its enclosures built at cell resolution.
    const bool limited = mech.criteria.any() && !a->real;
    std::string limited_caption;
    certified::CertifiedRegion enclosure;
    if (limited) {
      certified::LevelSetOptions lo;
      lo.relative_tolerance = 1e-4;
      lo.build_regions = true;
      const auto lw = criteria::limited_workspace(mech, criteria::file_limits(mech), lo);
      enclosure = lw.region;
      for (const auto& l : criteria::file_limits(mech)) {
        char buf[96];
        std::snprintf(buf, sizeof buf, "%s%s <= %g", limited_caption.empty() ? "" : ", ", l.name.c_str(), l.threshold);
        limited_caption += buf;
      }
    } else {
      enclosure = workspace_enclosure_of(mech);
    }
    geometry::Region region = enclosure.exact || a->bound == "outer" ? enclosure.outer : enclosure.inner;
    if (region.empty()) {
      throw io::InputError(a->file + ": the workspace is empty (impossible geometry): nothing to export");
    }
    if (a->real) {
      if (!mech.bodies) throw io::InputError(a->file + ": --real needs `bodies` in the file (docs/format.md (bodies))");
      region = real_workspace_of(mech, region, 7).real.inner;
      if (region.empty()) throw io::InputError(a->file + ": the real workspace is empty: nothing to export");
    }
    io::ExportOptions options;
    options.units = mech.units;
    options.tolerance = a->tolerance;
    std::string content;
    switch (format) {
      case io::ExportFormat::svg:
        if (a->bare) {
          content = io::to_svg(region, options);
        } else {
          // --real: the real workspace's inner enclosure (the figure without --real draws it outlined).
          io::FigureOptions figure;
          figure.title = mech.name;
          figure.region_legend = "real workspace (inner enclosure)";
          char area[64];
          std::snprintf(area, sizeof area, "%.10g", region.area());
          figure.caption = "Inner enclosure of the real workspace (certainly reachable without collision): area " +
                           std::string(area) + " " + area_unit(mech) + ".";
          const mechanisms::Pose pose = sample_pose(mech, region);
          figure.parts = figure_parts(mech, {pose.x, pose.y});
          content = io::workspace_figure(mech, region, pose, figure);
        }
        break;
      case io::ExportFormat::dxf: content = io::to_dxf(region, options); break;
      case io::ExportFormat::wkt: content = io::to_wkt(region, options); break;
      case io::ExportFormat::geojson: content = io::to_geojson(region, options); break;
      case io::ExportFormat::csv: content = io::to_csv(region, options); break;
    }
    io::write_file_atomic(a->out, content);
    return 0;
  }});
}

}  // namespace pkmws::cli
