// Boundary export (docs/format.md): SVG with true arcs, DXF with ARC/LINE entities,
// WKT / GeoJSON polylines at a stated tolerance, CSV of the boundary curves.
#pragma once

#include <filesystem>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "pkmws/geometry/region.hpp"
#include "pkmws/io/figure.hpp"
#include "pkmws/io/mechanism_file.hpp"

namespace pkmws::io {

enum class ExportFormat { svg, dxf, wkt, geojson, csv };

/// "svg" | "dxf" | "wkt" | "geojson" | "csv"; throws InputError otherwise.
ExportFormat parse_export_format(std::string_view name);
std::string_view format_name(ExportFormat format);

/// Which side of the true region an export lies on. `exact`: the curves are
/// the region's own (an exact workspace); WKT/GeoJSON polygons have their
/// vertices on them (chords) and an area within `area_error_bound`. `inner`:
/// every exported point is in the true region (a certified inner enclosure,
/// and polygons inside it). `outer`: every point of the true region is
/// exported (an outer enclosure, and polygons containing it).
enum class Bound { exact, inner, outer };
std::string_view bound_name(Bound bound);

struct ExportOptions {
  /// Max deviation of polylines from the exact boundary (WKT, GeoJSON), in the
  /// file's length unit; <= 0 picks 1e-6 of the bounding-box diagonal. An
  /// explicit value outside [min_tolerance, max_tolerance] is refused.
  double tolerance = 0.0;
  /// Components smaller than this area are dropped (near-tangency slivers);
  /// <= 0 picks 1e-12 of the bounding-box area.
  double min_area = 0.0;
  /// Length unit written into the files' metadata ("mm", "m"; empty: unitless).
  std::string units;
  /// See Bound. With `exact`, the region exported is the true one; with
  /// `inner`/`outer` it is an enclosure of the true one (or the exact region
  /// itself, whose polygons are then approximated from inside / outside).
  Bound bound = Bound::exact;
  /// Certified bounds of the true region's area, stated in GeoJSON, DXF and
  /// SVG when finite (enclosures of certified regions).
  double area_lower = std::numeric_limits<double>::quiet_NaN();
  double area_upper = std::numeric_limits<double>::quiet_NaN();
};

/// Resolved tolerance / sliver threshold for a region (see ExportOptions).
double effective_tolerance(const geometry::Region& region, const ExportOptions& options);
double effective_min_area(const geometry::Region& region, const ExportOptions& options);
/// The range of tolerances for which the polygons keep their stated bound:
/// below min_tolerance, double rounding of the coordinates (1e-12 of the
/// region's size: its diagonal or largest coordinate) is no longer negligible;
/// above max_tolerance (a tenth of the diagonal) the polygons are no longer a
/// picture of the region. Polygons over `max_polygon_vertices` are refused.
double min_tolerance(const geometry::Region& region);
double max_tolerance(const geometry::Region& region);
inline constexpr double max_polygon_vertices = 2e6;
/// Throws InputError (naming --tolerance) when the effective tolerance is out
/// of range or would give more than max_polygon_vertices vertices.
void check_tolerance(const geometry::Region& region, const ExportOptions& options);
/// Upper bound of |area(WKT/GeoJSON polygons) - area(exported components)| at
/// the effective tolerance: every chord or tangent piece deviates at most the
/// tolerance and cuts off or adds at most (pi/4) * tolerance * (its arc's
/// length), so the bound is (pi/4) * tolerance * (total arc length), plus
/// rounding (unit: the file's length unit squared). With `inner`/`outer` the
/// error is also one-sided (polygon area <= / >= the region's).
double polyline_area_error_bound(const geometry::Region& region, const ExportOptions& options);

/// The polygons written to WKT and GeoJSON: valid in the OGC / GEOS model
/// (rings closed, no self-touching ring: a loop that pinches is split into
/// rings at the pinch; no zero-length edges; exterior rings counter-clockwise,
/// holes clockwise; polygons may touch each other at points). Pieces of arcs
/// whose polylines would cross or touch are refined until they do not.
struct ExportPolygon {
  std::vector<geometry::Point> shell;               // closed: first point repeated
  std::vector<std::vector<geometry::Point>> holes;  // closed
};
std::vector<ExportPolygon> export_polygons(const geometry::Region& region, const ExportOptions& options = {});

/// SVG path data of the boundary in mathematical coordinates (y up): M, L,
/// and A commands (true arcs), one closed subpath per loop; fill with evenodd.
std::string svg_path(const geometry::Region& region, const ExportOptions& options = {});
/// Bare SVG of the region's boundary with true arcs (path commands A); width
/// and height in millimetres (units "mm" or "m"), so it imports at 1:1.
std::string to_svg(const geometry::Region& region, const ExportOptions& options = {});
/// DXF (R12 ASCII) with LINE and ARC entities on layers BOUNDARY / HOLES;
/// $INSUNITS 4 (mm) or 6 (m); no entity shorter than the rounding of the
/// coordinates (such pieces of the exact boundary are left out).
std::string to_dxf(const geometry::Region& region, const ExportOptions& options = {});
/// WKT MULTIPOLYGON of export_polygons().
std::string to_wkt(const geometry::Region& region, const ExportOptions& options = {});
/// GeoJSON FeatureCollection with one MultiPolygon feature (export_polygons());
/// properties: bound, area, tolerance, area_error_bound, polygon_area,
/// components, units, and area_lower/area_upper for certified regions.
std::string to_geojson(const geometry::Region& region, const ExportOptions& options = {});
/// CSV, one row per boundary curve:
/// component,loop,hole,kind,x0,y0,x1,y1,cx,cy,r,sweep_deg
std::string to_csv(const geometry::Region& region, const ExportOptions& options = {});
/// The boundary in `format`: to_svg (bare), to_dxf, to_wkt, to_geojson or to_csv.
std::string to_format(const geometry::Region& region, ExportFormat format, const ExportOptions& options = {});

/// The paper-style figure (FigureOptions, workspace_figure): pkmws/io/figure.hpp.

/// Writes `content` to `path` atomically (temporary file + rename), so a failure
/// never leaves a partial file behind. Throws InputError when it cannot.
void write_file_atomic(const std::filesystem::path& path, std::string_view content);

/// Escapes &, <, > and " for XML (SVG) text and attribute values.
std::string xml_escape(std::string_view text);

}  // namespace pkmws::io
