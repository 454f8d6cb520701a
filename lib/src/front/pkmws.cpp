// The front door (pkmws/pkmws.hpp): each call is a few lines over the layers.
#include "pkmws/pkmws.hpp"

#include <cmath>

#include "pkmws/criteria/fields.hpp"

namespace pkmws {

namespace {

bool has_limits(const MechanismFile& file) { return file.criteria.any(); }

certified::CertifiedRegion limited(const MechanismFile& file, double relative_tolerance, bool build_regions) {
  if (!(relative_tolerance > 0.0 && relative_tolerance < 1.0)) {
    throw InputError("relative_tolerance: must be in (0, 1), got " + std::to_string(relative_tolerance));
  }
  certified::LevelSetOptions options;
  options.relative_tolerance = relative_tolerance;
  options.build_regions = build_regions;
  return criteria::limited_workspace(file, criteria::file_limits(file), options).region;
}

}  // namespace

certified::CertifiedRegion workspace(const MechanismFile& file) {
  try {
    return criteria::workspace_enclosure(file);  // a coupler-curve boundary traced (the real-scheme biglide)
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(file.path + ": " + e.what());
  }
}

MechanismFile load(const std::filesystem::path& file) { return io::load_mechanism(file); }

Area area(const MechanismFile& file, double relative_tolerance) {
  const certified::CertifiedRegion r = has_limits(file) ? limited(file, relative_tolerance, false) : workspace(file);
  Area a;
  a.lower = r.area_lower;
  a.upper = r.area_upper;
  a.exact = r.exact;
  a.limited = has_limits(file);
  a.units = file.units;
  return a;
}

certified::CertifiedRegion region(const MechanismFile& file, double relative_tolerance) {
  return has_limits(file) ? limited(file, relative_tolerance, true) : workspace(file);
}

std::vector<mechanisms::Evaluation> evaluate(const MechanismFile& file, double x, double y,
                                             std::optional<double> phi_rad) {
  if (!std::isfinite(x) || !std::isfinite(y) || (phi_rad && !std::isfinite(*phi_rad))) {
    throw InputError("evaluate: the pose must be finite");
  }
  return file.model->evaluate({x, y, phi_rad ? *phi_rad : file.model->orientation()}, file.criteria);
}

std::string export_boundary(const MechanismFile& file, io::ExportFormat format, io::Bound bound) {
  if (bound == io::Bound::exact) bound = io::Bound::outer;
  const certified::CertifiedRegion r = region(file);
  if (r.outer.empty()) throw InputError(file.path + ": the workspace is empty: nothing to export");
  io::ExportOptions options;
  options.units = file.units;
  if (!r.exact) {
    options.bound = bound;
    options.area_lower = r.area_lower;
    options.area_upper = r.area_upper;
  }
  return io::to_format(r.exact || bound == io::Bound::outer ? r.outer : r.inner, format, options);
}

void export_boundary(const MechanismFile& file, io::ExportFormat format, const std::filesystem::path& out,
                     io::Bound bound) {
  io::write_file_atomic(out, export_boundary(file, format, bound));
}

}  // namespace pkmws
