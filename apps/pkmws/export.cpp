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
    double max_time = 0.0;
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
  add_max_time_option(sub, a->max_time);
  commands.push_back({sub, [a] {
    const io::ExportFormat format = io::parse_export_format(a->format);
    check_outputs({a->out});
    // Certified regions (criteria limits, bands): a bound stops the work with
    // exit 2 and no file (an export does not carry a `stopped` label).
    const CertifiedWork work("export", a->max_time);
    auto refuse_stopped = [&work] {
      throw io::InputError("--max-time: " + work.stopped_note() + "; nothing written (give more time)");
    };
    if (a->criterion.empty() != a->levels.empty()) throw io::InputError("--criterion and --levels go together");
    if (!a->criterion.empty()) {
      if (format != io::ExportFormat::svg && format != io::ExportFormat::csv) {
        throw io::InputError("--criterion: the bands export as svg (figure) or csv (traced level curves)");
      }
      const io::MechanismFile mech = io::load_mechanism(a->file);
      bool stopped = false;
      const std::string content =
          bands_export(mech, a->criterion, a->levels, format == io::ExportFormat::svg, 1e-4, &work, &stopped);
      if (stopped) refuse_stopped();
      io::write_file_atomic(a->out, content);
      return 0;
    }
    if (a->tolerance < 0.0 || !std::isfinite(a->tolerance)) {
      throw io::InputError("--tolerance: must be a positive length");
    }
    const io::MechanismFile mech = io::load_mechanism(a->file);
    // With criteria limits ([Briot] figs. 10, 13): the certified limited
    // region, its enclosures built at cell resolution.
    const bool limited = mech.criteria.any() && !a->real;
    std::string limited_caption;
    certified::CertifiedRegion enclosure;
    if (limited) {
      certified::LevelSetOptions lo;
      lo.relative_tolerance = 1e-4;
      lo.build_regions = true;
      const auto lw = criteria::limited_workspace(mech, criteria::file_limits(mech), work.options(lo));
      if (lw.detail.stopped) refuse_stopped();
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
          io::FigureOptions figure;
          figure.title = mech.name;
          char caption[512];
          std::snprintf(caption, sizeof caption, "exact workspace area = %.10g %s", region.area(),
                        area_unit(mech).c_str());
          if (!enclosure.exact) {
            // Certain part filled, the undecided band between the enclosures hatched grey.
            std::snprintf(caption, sizeof caption,
                          "certified %s%s%s: %.10g <= area <= %.10g %s (filled: certainly inside; grey: "
                          "undecided cells)",
                          limited ? "workspace with " : "workspace", limited ? limited_caption.c_str() : "", "",
                          enclosure.area_lower, enclosure.area_upper, area_unit(mech).c_str());
            region = enclosure.inner;
            io::FigureOptions::Overlay band;
            band.region = enclosure.outer.subtract(enclosure.inner);
            band.fill = "#7a7a7a";
            band.fill_opacity = 0.8;
            band.stroke = "none";
            band.legend = "undecided (certified bounds)";
            figure.overlays.push_back(band);
          }
          figure.caption = caption;
          mechanisms::Pose pose = sample_pose(mech, region);
          if (mech.bodies && !a->real) {
            // docs/format.md (bodies): computed workspace (filled), interference regions shaded and
            // labelled by pair, the real workspace outlined in black ([Vasilic] figs. 5-11).
            const auto real = real_workspace_of(mech, region, 7);
            figure.overlays = real_workspace_overlays(real);
            std::snprintf(caption, sizeof caption,
                          "computed workspace %.8g %s (filled); real workspace %.8g %s (%s, %.8g..%.8g; black outline)",
                          region.area(), area_unit(mech).c_str(), real.real.area_estimate(), area_unit(mech).c_str(),
                          real.real.method().c_str(), real.real.area_lower, real.real.area_upper);
            figure.caption = caption;
            // Draw the mechanism at a collision-free pose.
            if (!real.real.inner.empty()) pose = sample_pose(mech, real.real.inner);
            // The parts themselves at that pose, under the labels.
            auto parts = part_overlays(mech, {pose.x, pose.y});
            figure.overlays.insert(figure.overlays.begin(), parts.begin(), parts.end());
          }
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
