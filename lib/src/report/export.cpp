// `pkmws export` (pkmws/report/export.hpp): moved from the command line's
// export.cpp, files and JSON unchanged.
#include "pkmws/report/export.hpp"

#include <cmath>

#include "pkmws/criteria/fields.hpp"
#include "pkmws/pkmws.hpp"
#include "pkmws/report/area.hpp"
#include "pkmws/report/figure.hpp"
#include "pkmws/report/levels.hpp"
#include "report/json.hpp"

namespace pkmws::report {

using detail::Json;

namespace {

// Relative bound width of the criteria-limited regions exported (their
// enclosures are built at cell resolution, so a finer width buys little).
constexpr double kLimitedTolerance = 1e-4;

ExportReport header(const io::MechanismFile& mech, const ExportOptions& options) {
  ExportReport r;
  r.name = mech.name;
  r.mechanism = mech.mechanism;
  r.units = mech.units;
  r.format = options.format;
  r.output = options.output;
  return r;
}

// The bands of a criterion: svg the band figure, csv the traced level curves.
ExportReport bands(const io::MechanismFile& mech, const ExportOptions& options) {
  ExportReport out = header(mech, options);
  LevelsOptions lo;
  lo.criterion = options.criterion;
  lo.levels = options.levels;
  lo.tolerance = kLimitedTolerance;
  lo.budget = options.budget;
  lo.figure_pieces = options.format == io::ExportFormat::svg;
  const LevelsReport run = levels(mech, lo);
  out.content = "bands of " + options.criterion;
  if (run.stopped) {
    out.stopped = true;
    return out;
  }
  out.text = options.format == io::ExportFormat::svg ? band_figure(mech, run) : level_curves_csv(run);
  return out;
}

}  // namespace

void check_export_options(const ExportOptions& o) {
  if (!o.criterion.empty()) {
    if (o.format != io::ExportFormat::svg && o.format != io::ExportFormat::csv) {
      throw io::InputError("--criterion: the bands export as svg (figure) or csv (traced level curves)");
    }
    return;
  }
  if (o.tolerance && !(*o.tolerance > 0.0 && std::isfinite(*o.tolerance))) {
    throw io::InputError("--tolerance: must be a positive finite length");
  }
}

ExportReport export_file(const io::MechanismFile& mech, const ExportOptions& o) {
  if (o.criterion.empty() != o.levels.empty()) throw io::InputError("--criterion and --levels go together");
  check_export_options(o);
  if (!o.criterion.empty()) return bands(mech, o);
  ExportReport out = header(mech, o);
  const io::ExportFormat format = o.format;
  if (format == io::ExportFormat::svg && !o.bare && !o.real) {
    // The figure: what `pkmws area` computes, drawn as `pkmws batch` draws it
    // (criteria files: the certified limited region; bodies: the real workspace).
    AreaOptions options;
    options.budget = o.budget;
    options.figure_pieces = true;
    const AreaReport result = area(mech, options);
    out.content = "figure";
    if (!result.stopped.empty()) {
      out.stopped = true;
      return out;
    }
    out.text = area_figure(mech, result);
    return out;
  }
  // With criteria limits ([Briot] figs. 10, 13): the certified limited
  // region, the enclosure written (only it is built) following the traced
  // level curves.
  const bool limited = mech.criteria.any() && !o.real;
  // Which enclosure: stated in GeoJSON, DXF and SVG; WKT and CSV carry no
  // metadata, so a certified region needs --bound there (checked before the
  // region is built where that is known from the file).
  const bool boundary_only = format != io::ExportFormat::svg || o.bare;
  auto require_bound = [&](bool certified_region) {
    if (certified_region && boundary_only && o.bound.empty() &&
        (format == io::ExportFormat::wkt || format == io::ExportFormat::csv)) {
      throw io::InputError(std::string("--bound: ") + (o.real ? "the real workspace" : "this workspace") +
                           " is certified, not exact, and " + std::string(io::format_name(format)) +
                           " has no metadata to say which enclosure it holds: give --bound inner or --bound outer");
    }
  };
  if (o.real && !mech.bodies) {
    throw io::InputError(mech.path + ": --real needs `bodies` in the file (docs/format.md (bodies))");
  }
  require_bound(limited || o.real);
  out.content = format == io::ExportFormat::svg && !o.bare ? "figure" : "boundary";
  const std::string bound = !o.bound.empty() ? o.bound : o.real ? "inner" : "outer";
  certified::CertifiedRegion enclosure;
  if (limited) {
    LimitedOptions lo;
    lo.tolerance = kLimitedTolerance;
    lo.build_regions = true;
    lo.regions = bound == "inner" ? certified::LevelSetOptions::Regions::inner : certified::LevelSetOptions::Regions::outer;
    lo.budget = o.budget;
    const auto lw = limited_workspace(mech, lo);
    if (lw.detail.stopped) {
      out.stopped = true;
      return out;
    }
    enclosure = lw.region;
  } else {
    enclosure = pkmws::workspace(mech);
  }
  require_bound(o.real || !enclosure.exact);
  geometry::Region region = enclosure.exact || bound == "outer" ? enclosure.outer : enclosure.inner;
  // Empty: nothing in the outer enclosure (a limited region builds only the
  // bound written; its upper bound says the same).
  if (limited ? !(enclosure.area_upper > 0.0) : enclosure.outer.empty()) {
    throw io::InputError(mech.path + ": the workspace is empty (impossible geometry): nothing to export");
  }
  io::ExportOptions options;
  options.units = mech.units;
  options.tolerance = o.tolerance ? *o.tolerance : 0.0;
  if (!enclosure.exact) {
    options.bound = bound == "inner" ? io::Bound::inner : io::Bound::outer;
    options.area_lower = enclosure.area_lower;
    options.area_upper = enclosure.area_upper;
  }
  if (o.real) {
    // Real = reachable − interference: an enclosure even when reachable is exact.
    const auto real = real_workspace(mech, region, 7).real;
    region = bound == "inner" ? real.inner : real.outer;
    options.bound = bound == "inner" ? io::Bound::inner : io::Bound::outer;
    options.area_lower = real.area_lower;
    options.area_upper = real.area_upper;
    if (real.outer.empty()) throw io::InputError(mech.path + ": the real workspace is empty: nothing to export");
  }
  if (format == io::ExportFormat::svg && !o.bare) {
    // --real: the real workspace's inner enclosure (the figure without --real draws it outlined).
    out.text = real_workspace_figure(mech, region);
  } else {
    out.text = io::to_format(region, format, options);
  }
  out.bound = enclosure.exact && !o.real ? "" : bound;
  return out;
}

std::string to_json_text(const ExportReport& r) {
  Json j{{"name", r.name},       {"mechanism", r.mechanism}, {"units", r.units},
         {"format", std::string(io::format_name(r.format))}, {"output", r.output}, {"content", r.content}};
  if (r.bound.empty()) {
    j["bound"] = nullptr;
    j["bound_reason"] = "the region is exact (or a figure), not one of two enclosures";
  } else {
    j["bound"] = r.bound;
  }
  return detail::json_text(std::move(j));
}

}  // namespace pkmws::report
