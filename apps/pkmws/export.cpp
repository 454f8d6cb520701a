// pkmws export FILE --format svg|dxf|wkt|geojson|csv -o OUT (docs/format.md (command line)).
#include <cmath>
#include <cstdio>

#include "cli.hpp"
#include "pkmws/criteria/fields.hpp"
#include "pkmws/io/export.hpp"
#include "pkmws/pkmws.hpp"
#include "pkmws/report/figure.hpp"
#include "pkmws/report/levels.hpp"

namespace pkmws::cli {

namespace {
// Relative bound width of the criteria-limited regions exported (their
// enclosures are built at cell resolution, so a finer width buys little).
constexpr double kLimitedTolerance = 1e-4;
}  // namespace

void add_export(CLI::App& app, std::vector<Command>& commands) {
  auto* sub = app.add_subcommand("export", "Write the workspace boundary (svg, dxf, wkt, geojson, csv)");
  struct Args {
    std::string file, format, out;
    double tolerance = 0.0;
    bool bare = false;
    bool real = false;
    std::string bound;
    std::string criterion, levels;
    double max_time = 0.0;
    bool json = false;
  };
  auto a = std::make_shared<Args>();
  sub->add_option("FILE", a->file, "Mechanism file (JSON)")->required();
  sub->add_option("--format,-f", a->format, "svg | dxf | wkt | geojson | csv")->required();
  sub->add_flag("--json", a->json, "Print one JSON object about the file written (docs/schema/export.output.schema.json)");
  sub->add_option("-o,--output", a->out, "Output file")->required();
  auto* tolerance_option = sub->add_option(
      "--tolerance", a->tolerance,
      "Max deviation of polylines (wkt, geojson) in the file's unit; default 1e-6 of the bounding-box "
      "diagonal; refused below 1e-12 of the region's size (double precision), above a tenth of its "
      "diagonal, or when the polygons would exceed 2e6 vertices");
  sub->add_flag("--bare", a->bare, "svg: the boundary only, without axes and mechanism");
  sub->add_flag("--real", a->real,
                "Files with bodies: export the real workspace's inner enclosure (certainly reachable "
                "without collision) instead of the computed workspace");
  sub->add_option("--bound", a->bound,
                  "Certified workspaces (boundary not made of arcs and segments, e.g. the real-scheme "
                  "biglide, files with criteria limits, --real): export the outer enclosure (every point "
                  "of the region; default, --real: inner) or the inner one (only points of the region); "
                  "wkt and csv, which carry no metadata, need it explicitly. WKT/GeoJSON polygons lie "
                  "inside (inner) or around (outer) the enclosure")
      ->check(CLI::IsMember({"inner", "outer"}));
  sub->add_option("--criterion", a->criterion,
                  "With --levels: export the bands of a criterion (pressure_angle, reaction, velocity_ratio, condition_number) "
                  "instead of the workspace: svg = band figure, csv = traced level curves");
  sub->add_option("--levels", a->levels, "Increasing thresholds of --criterion, e.g. 20,40,60,80");
  add_max_time_option(sub, a->max_time);
  commands.push_back({sub, [a, tolerance_option] {
    const io::ExportFormat format = io::parse_export_format(a->format);
    check_outputs({a->out});
    // Certified regions (criteria limits, bands): a bound stops the work with
    // exit 2 and no file (an export does not carry a `stopped` label).
    const CertifiedWork work("export", a->max_time);
    // --json: what was written (the file itself is the output).
    auto done = [&a](const io::MechanismFile& mech, const std::string& content, const std::string& bound) {
      if (!a->json) return 0;
      Json j{{"name", mech.name}, {"mechanism", mech.mechanism}, {"units", mech.units}, {"format", a->format},
             {"output", a->out}, {"content", content}};
      if (bound.empty()) {
        j["bound"] = nullptr;
        j["bound_reason"] = "the region is exact (or a figure), not one of two enclosures";
      } else {
        j["bound"] = bound;
      }
      print_json(j);
      return 0;
    };
    char limit[160];
    std::snprintf(limit, sizeof limit, "--max-time: stopped at %g s before the export was complete; nothing written (give more time)",
                  a->max_time);
    const std::string refusal = limit;
    auto refuse_stopped = [&refusal] { throw io::InputError(refusal); };
    if (a->criterion.empty() != a->levels.empty()) throw io::InputError("--criterion and --levels go together");
    if (!a->criterion.empty()) {
      if (format != io::ExportFormat::svg && format != io::ExportFormat::csv) {
        throw io::InputError("--criterion: the bands export as svg (figure) or csv (traced level curves)");
      }
      const io::MechanismFile mech = io::load_mechanism(a->file);
      const std::string content = work.finish_by_deadline(
          [&] {
            report::LevelsOptions options;
            options.criterion = a->criterion;
            options.levels = parse_levels(a->levels);
            options.tolerance = 1e-4;
            options.budget = work.budget();
            const report::LevelsReport run = report::levels(mech, options);
            if (run.stopped) refuse_stopped();
            return format == io::ExportFormat::svg ? report::band_figure(mech, run) : report::level_curves_csv(run);
          },
          refusal);
      io::write_file_atomic(a->out, content);
      return done(mech, "bands of " + a->criterion, "");
    }
    const bool tolerance_given = tolerance_option->count() > 0;
    if (tolerance_given && !(a->tolerance > 0.0 && std::isfinite(a->tolerance))) {
      throw io::InputError("--tolerance: must be a positive finite length");
    }
    const io::MechanismFile mech = io::load_mechanism(a->file);
    if (format == io::ExportFormat::svg && !a->bare && !a->real) {
      // The figure: what `pkmws area` computes, drawn as `pkmws batch` draws it
      // (criteria files: the certified limited region; bodies: the real workspace).
      const std::string content = work.finish_by_deadline(
          [&] {
            report::AreaOptions options;
            options.budget = work.budget();
            const report::AreaReport result = report::area(mech, options);
            if (!result.stopped.empty()) refuse_stopped();
            return report::area_figure(mech, result);
          },
          refusal);
      io::write_file_atomic(a->out, content);
      return done(mech, "figure", "");
    }
    // With criteria limits ([Briot] figs. 10, 13): the certified limited
    // region, its enclosures built at cell resolution.
    const bool limited = mech.criteria.any() && !a->real;
    // Which enclosure: stated in GeoJSON, DXF and SVG; WKT and CSV carry no
    // metadata, so a certified region needs --bound there (checked before the
    // region is built where that is known from the file).
    const bool boundary_only = format != io::ExportFormat::svg || a->bare;
    auto require_bound = [&](bool certified_region) {
      if (certified_region && boundary_only && a->bound.empty() &&
          (format == io::ExportFormat::wkt || format == io::ExportFormat::csv)) {
        throw io::InputError(std::string("--bound: ") + (a->real ? "the real workspace" : "this workspace") +
                             " is certified, not exact, and " + std::string(io::format_name(format)) +
                             " has no metadata to say which enclosure it holds: give --bound inner or --bound outer");
      }
    };
    if (a->real && !mech.bodies) {
      throw io::InputError(a->file + ": --real needs `bodies` in the file (docs/format.md (bodies))");
    }
    require_bound(limited || a->real);
    std::string bound_written;  // the enclosure written ("" for an exact region), for --json
    const std::string content = work.finish_by_deadline(
        [&]() -> std::string {
          certified::CertifiedRegion enclosure;
          if (limited) {
            certified::LevelSetOptions lo;
            lo.relative_tolerance = kLimitedTolerance;
            lo.build_regions = true;
            const auto lw = criteria::limited_workspace(mech, criteria::file_limits(mech), work.options(lo));
            if (lw.detail.stopped) refuse_stopped();
            enclosure = lw.region;
          } else {
            enclosure = pkmws::workspace(mech);
          }
          require_bound(a->real || !enclosure.exact);
          const std::string bound = !a->bound.empty() ? a->bound : a->real ? "inner" : "outer";
          geometry::Region region = enclosure.exact || bound == "outer" ? enclosure.outer : enclosure.inner;
          if (enclosure.outer.empty()) {
            throw io::InputError(a->file + ": the workspace is empty (impossible geometry): nothing to export");
          }
          io::ExportOptions options;
          options.units = mech.units;
          options.tolerance = tolerance_given ? a->tolerance : 0.0;
          if (!enclosure.exact) {
            options.bound = bound == "inner" ? io::Bound::inner : io::Bound::outer;
            options.area_lower = enclosure.area_lower;
            options.area_upper = enclosure.area_upper;
          }
          if (a->real) {
            // Real = reachable − interference: an enclosure even when reachable is exact.
            const auto real = report::real_workspace(mech, region, 7).real;
            region = bound == "inner" ? real.inner : real.outer;
            options.bound = bound == "inner" ? io::Bound::inner : io::Bound::outer;
            options.area_lower = real.area_lower;
            options.area_upper = real.area_upper;
            if (real.outer.empty()) throw io::InputError(a->file + ": the real workspace is empty: nothing to export");
          }
          std::string text;
          if (format == io::ExportFormat::svg && !a->bare) {
            // --real: the real workspace's inner enclosure (the figure without --real draws it outlined).
            text = report::real_workspace_figure(mech, region);
          } else {
            text = io::to_format(region, format, options);
          }
          bound_written = enclosure.exact && !a->real ? "" : bound;
          return text;
        },
        refusal);
    io::write_file_atomic(a->out, content);
    return done(mech, format == io::ExportFormat::svg && !a->bare ? "figure" : "boundary", bound_written);
  }});
}

}  // namespace pkmws::cli
