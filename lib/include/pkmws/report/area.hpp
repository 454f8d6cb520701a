// `pkmws area`: the area of a file's workspace with what it is (exact,
// certified, criteria-limited), its components with their inscribed circle and
// rectangle, and with `bodies` the real workspace (docs/format.md (command
// line), docs/schema/area.output.schema.json). `pkmws batch` and the figures of
// `export` draw from the same report.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "pkmws/bodies/bodies.hpp"
#include "pkmws/certified/cell_region.hpp"
#include "pkmws/criteria/fields.hpp"
#include "pkmws/geometry/inscribed.hpp"
#include "pkmws/geometry/inscribed_rectangle.hpp"
#include "pkmws/io/mechanism_file.hpp"
#include "pkmws/report/common.hpp"

namespace pkmws::report {

struct AreaOptions {
  /// Files with bodies: quadtree depth of the certified interference regions.
  int interference_depth = 7;
  /// Relative width of each inscribed rectangle's certified area bounds.
  double rectangle_precision = 1e-6;
  /// The inscribed rectangles at any orientation (geometry::
  /// largest_inscribed_rectangle_any_angle) instead of axis-aligned.
  bool rectangle_any_angle = false;
  /// Files with criteria: the certified level sets' bound width relative to the area.
  double criteria_tolerance = 1e-6;
  /// Files with criteria: the limited workspace's pieces cover all of it in
  /// (x, y), as its figure needs (then no charts: docs/theory/level_sets.md).
  bool figure_pieces = false;
  /// Files with criteria: their deadline and progress (the report then may be `stopped`).
  Budget budget;
};

/// One connected component of the workspace.
struct ComponentReport {
  double area = 0.0;
  double perimeter = 0.0;
  std::size_t holes = 0;
  geometry::Box bbox;
  geometry::Point centroid;
  geometry::InscribedCircle inscribed_circle;
  /// The largest axis-aligned rectangle inside the component, or at any
  /// orientation when asked (for a certified workspace: inside the inner
  /// enclosure, so that it fits the true workspace).
  geometry::InscribedRectangle inscribed_rectangle;
};

/// A criterion limit of the file: `criterion` <= `threshold`.
struct CriterionLimit {
  std::string criterion;
  double threshold = 0.0;
  /// L of x' = (x, y, L φ) when the criterion depends on one (3-DOF velocity
  /// ratio and condition number), else 0.
  double characteristic_length = 0.0;
};
/// "condition_number <= 4 (characteristic length L = 86.6 mm)" (the length
/// only when the criterion uses one).
std::string criterion_limit_text(const CriterionLimit& limit, const std::string& units);

struct AreaReport {
  std::string name, mechanism, units;
  /// "exact", "certified" (an enclosure, or criteria limits: level sets).
  std::string method;
  double area = 0.0;  // exact, or the certified bounds' estimate
  double area_lower = 0.0;
  double area_upper = 0.0;
  /// The components (of the outer enclosure where the workspace is certified;
  /// none for a criteria-limited workspace: not enumerated).
  std::vector<ComponentReport> components;
  bool components_of_outer_enclosure = false;
  /// The workspace's bounding box and boundary curve count (not for criteria files).
  std::optional<geometry::Box> bbox;
  std::size_t boundary_curves = 0;
  /// Criteria files: the limits, and why the result is cut short or empty ("" when not).
  std::vector<CriterionLimit> criteria;
  std::string stopped;
  std::string note;
  /// Computation time (kComputeTimeMeaning), milliseconds.
  double time_ms = 0.0;

  // The regions behind the numbers (for figures and exports).
  certified::CertifiedRegion enclosure;               // the workspace (criteria files: the limited one)
  std::optional<criteria::LimitedWorkspace> limited;  // criteria files (traced pieces for figures)
  std::optional<bodies::RealWorkspace> real;          // files with bodies
};

/// What `time_ms` (area --json, summary.json) and the summary's time column cover.
inline constexpr const char* kComputeTimeMeaning =
    "computation: workspace, area, components with inscribed circles, criteria limits or real workspace; "
    "loading and figures excluded";

/// The area report of a file. Throws InputError naming the file when it has no
/// planar workspace or an empty one.
AreaReport area(const io::MechanismFile& file, const AreaOptions& options = {});

/// `pkmws area --json` (indented, no trailing newline).
std::string to_json_text(const AreaReport& report);
/// `pkmws area` without --json (lines ending in a newline).
std::string to_text(const AreaReport& report);

/// How a criteria-limited workspace is computed: the certified level sets'
/// bound width relative to the area, whether their inner and outer regions are
/// built (for figures and exports), threads (0: all), deadline and progress.
struct LimitedOptions {
  double tolerance = 1e-6;
  bool build_regions = false;
  certified::LevelSetOptions::Regions regions = certified::LevelSetOptions::Regions::both;  // which (an export: one)
  bool charts = true;  // certified::LevelSetOptions::charts
  int threads = 0;
  /// certified::LevelSetOptions::refine_depth (its default when not given) and retries.
  std::optional<int> refine_depth;
  bool retries = true;
  Budget budget;
};
/// The workspace of a file with `criteria`, limited by them (docs/theory/level_sets.md):
/// what `area` reports for such a file, `export` writes and the Python module's
/// `limited_area` / `limited_workspace` give. Throws InputError for a tolerance
/// outside (0, 1) ("tolerance: ...") and for a file without criteria limits.
criteria::LimitedWorkspace limited_workspace(const io::MechanismFile& file, const LimitedOptions& options = {});

/// The real workspace of a file with bodies: `reachable` minus the interference
/// regions, certified with quadtree depth `depth`.
bodies::RealWorkspace real_workspace(const io::MechanismFile& file, const geometry::Region& reachable, int depth);

/// The precision (a length) of the report's inscribed circle in a component
/// with bounding box `bbox`: 1e-5 of its larger side.
double inscribed_circle_precision(const geometry::Box& bbox);

/// A pair of parts as printed and drawn: "rod1 / housing2", "rod1 ∠ rod2" for a link angle.
std::string pair_label(const std::string& a, const std::string& b, const std::string& kind);

}  // namespace pkmws::report
