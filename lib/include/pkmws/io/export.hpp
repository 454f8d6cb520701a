// Boundary export (docs/format.md): SVG with true arcs, DXF with ARC/LINE entities,
// WKT / GeoJSON polylines at a stated tolerance, CSV of the boundary curves.
#pragma once

#include <filesystem>
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

struct ExportOptions {
  /// Max deviation of polylines from the exact boundary (WKT, GeoJSON), in the
  /// file's length unit; <= 0 picks 1e-6 of the bounding-box diagonal.
  double tolerance = 0.0;
  /// Components smaller than this area are dropped (near-tangency slivers);
  /// <= 0 picks 1e-12 of the bounding-box area.
  double min_area = 0.0;
  /// Length unit written into the files' metadata ("mm", "m"; empty: unitless).
  std::string units;
};

/// Resolved tolerance / sliver threshold for a region (see ExportOptions).
double effective_tolerance(const geometry::Region& region, const ExportOptions& options);
double effective_min_area(const geometry::Region& region, const ExportOptions& options);
/// Upper bound of |area(WKT/GeoJSON polygons) - area(exported components)| at
/// the effective tolerance: every chord cuts off a circular segment of area
/// <= (pi/4) * tolerance * chord, so the bound is (pi/4) * tolerance * (total
/// arc length), plus rounding (unit: the file's length unit squared).
double polyline_area_error_bound(const geometry::Region& region, const ExportOptions& options);

/// SVG path data of the boundary in mathematical coordinates (y up): M, L,
/// and A commands (true arcs), one closed subpath per loop; fill with evenodd.
std::string svg_path(const geometry::Region& region, const ExportOptions& options = {});
/// Bare SVG of the region's boundary with true arcs (path commands A).
std::string to_svg(const geometry::Region& region, const ExportOptions& options = {});
/// DXF (R12 ASCII) with LINE and ARC entities on layers BOUNDARY / HOLES.
std::string to_dxf(const geometry::Region& region, const ExportOptions& options = {});
/// WKT MULTIPOLYGON of polylines within the tolerance.
std::string to_wkt(const geometry::Region& region, const ExportOptions& options = {});
/// GeoJSON FeatureCollection with one MultiPolygon feature.
std::string to_geojson(const geometry::Region& region, const ExportOptions& options = {});
/// CSV, one row per boundary curve:
/// component,loop,hole,kind,x0,y0,x1,y1,cx,cy,r,sweep_deg
std::string to_csv(const geometry::Region& region, const ExportOptions& options = {});

/// The paper-style figure (FigureOptions, workspace_figure): pkmws/io/figure.hpp.

/// Writes `content` to `path` atomically (temporary file + rename), so a failure
/// never leaves a partial file behind. Throws InputError when it cannot.
void write_file_atomic(const std::filesystem::path& path, std::string_view content);

/// Escapes &, <, > and " for XML (SVG) text and attribute values.
std::string xml_escape(std::string_view text);

}  // namespace pkmws::io
