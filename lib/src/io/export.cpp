// Boundary exports: SVG with true arcs, DXF R12 with LINE/ARC/CIRCLE, WKT and
// GeoJSON polylines at a stated tolerance, CSV of the exact curves.
#include "pkmws/io/export.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <sstream>
#include <system_error>
#include <unistd.h>

namespace pkmws::io {

using geometry::Component;
using geometry::Curve;
using geometry::Loop;
using geometry::Point;
using geometry::Region;

namespace {

constexpr double rad2deg = 180.0 / std::numbers::pi;

// Shortest text that reads back as the same double.
std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  double back = 0.0;
  for (int digits = 6; digits < 17; ++digits) {
    char shorter[32];
    std::snprintf(shorter, sizeof shorter, "%.*g", digits, v);
    back = std::strtod(shorter, nullptr);
    if (back == v) return shorter;
  }
  return buf;
}

double diagonal(const Region& r) {
  const auto b = r.bbox();
  return std::hypot(b.width(), b.height());
}

std::vector<Component> components_of(const Region& region, const ExportOptions& options) {
  return region.components(effective_min_area(region, options));
}

// Closed ring of a loop's polyline, first point repeated at the end.
std::vector<Point> ring(const Loop& loop, double tolerance) {
  std::vector<Point> pts = loop.polyline(tolerance);
  if (!pts.empty()) pts.push_back(pts.front());
  return pts;
}

}  // namespace

ExportFormat parse_export_format(std::string_view name) {
  if (name == "svg") return ExportFormat::svg;
  if (name == "dxf") return ExportFormat::dxf;
  if (name == "wkt") return ExportFormat::wkt;
  if (name == "geojson") return ExportFormat::geojson;
  if (name == "csv") return ExportFormat::csv;
  throw InputError("--format: unknown format \"" + std::string(name) +
                   "\" (expected svg, dxf, wkt, geojson or csv)");
}

std::string_view format_name(ExportFormat format) {
  switch (format) {
    case ExportFormat::svg: return "svg";
    case ExportFormat::dxf: return "dxf";
    case ExportFormat::wkt: return "wkt";
    case ExportFormat::geojson: return "geojson";
    case ExportFormat::csv: return "csv";
  }
  return "";
}

double effective_tolerance(const Region& region, const ExportOptions& options) {
  if (options.tolerance > 0.0) return options.tolerance;
  const double d = diagonal(region);
  return d > 0.0 ? 1e-6 * d : 1e-9;
}

double effective_min_area(const Region& region, const ExportOptions& options) {
  if (options.min_area > 0.0) return options.min_area;
  const auto b = region.bbox();
  return 1e-12 * b.width() * b.height();
}

std::string svg_path(const Region& region, const ExportOptions& options) {
  // Path data in mathematical coordinates (the caller flips y). Arcs: A r r 0
  // large sweep x y, sweep = 1 for counter-clockwise; full circles as two halves.
  std::string d;
  for (const Component& c : components_of(region, options)) {
    std::vector<const Loop*> loops{&c.outer};
    for (const Loop& h : c.holes) loops.push_back(&h);
    for (const Loop* loop : loops) {
      if (loop->curves.empty()) continue;
      d += "M" + num(loop->curves.front().source.x) + " " + num(loop->curves.front().source.y);
      for (const Curve& cv : loop->curves) {
        if (cv.kind == Curve::Kind::segment) {
          d += " L" + num(cv.target.x) + " " + num(cv.target.y);
          continue;
        }
        const double sweep = cv.sweep();
        const std::string r = num(cv.radius) + " " + num(cv.radius) + " 0 ";
        const std::string flag = cv.ccw ? " 1 " : " 0 ";
        if (std::abs(sweep) > std::numbers::pi) {
          const Point mid = cv.at(0.5);  // two arcs of at most pi each
          d += " A" + r + "0" + flag + num(mid.x) + " " + num(mid.y);
          d += " A" + r + "0" + flag + num(cv.target.x) + " " + num(cv.target.y);
        } else {
          d += " A" + r + "0" + flag + num(cv.target.x) + " " + num(cv.target.y);
        }
      }
      d += " Z ";
    }
  }
  return d;
}

std::string to_svg(const Region& region, const ExportOptions& options) {
  const auto b = region.bbox();
  const double margin = 0.05 * std::max(b.width(), b.height());
  std::ostringstream s;
  s << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    << "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"" << num(b.min.x - margin) << " "
    << num(-b.max.y - margin) << " " << num(b.width() + 2 * margin) << " " << num(b.height() + 2 * margin)
    << "\">\n"
    << "  <!-- pkmws exact boundary: segments and true circular arcs; area = " << num(region.area())
    << " -->\n"
    << "  <g transform=\"scale(1,-1)\">\n"
    << "    <path fill=\"#f4a6a6\" fill-rule=\"evenodd\" stroke=\"#7a1010\" stroke-width=\""
    << num(0.004 * std::max(b.width(), b.height())) << "\" d=\"" << svg_path(region, options) << "\"/>\n"
    << "  </g>\n</svg>\n";
  return s.str();
}

std::string to_dxf(const Region& region, const ExportOptions& options) {
  std::ostringstream s;
  auto pair = [&s](int code, const std::string& value) { s << code << "\n" << value << "\n"; };
  pair(999, "pkmws exact workspace boundary: LINE and ARC entities (arcs counter-clockwise)");
  pair(0, "SECTION");
  pair(2, "ENTITIES");
  for (const Component& c : components_of(region, options)) {
    std::vector<const Loop*> loops{&c.outer};
    for (const Loop& h : c.holes) loops.push_back(&h);
    for (const Loop* loop : loops) {
      const std::string layer = loop->hole ? "HOLES" : "BOUNDARY";
      for (const Curve& cv : loop->curves) {
        if (cv.kind == Curve::Kind::segment) {
          pair(0, "LINE");
          pair(8, layer);
          pair(10, num(cv.source.x)); pair(20, num(cv.source.y)); pair(30, "0");
          pair(11, num(cv.target.x)); pair(21, num(cv.target.y)); pair(31, "0");
          continue;
        }
        const double sweep = cv.sweep();
        if (std::abs(std::abs(sweep) - 2 * std::numbers::pi) < 1e-12) {
          pair(0, "CIRCLE");
          pair(8, layer);
          pair(10, num(cv.center.x)); pair(20, num(cv.center.y)); pair(30, "0");
          pair(40, num(cv.radius));
          continue;
        }
        // DXF arcs run counter-clockwise from start to end angle.
        const Point from = cv.ccw ? cv.source : cv.target;
        const Point to = cv.ccw ? cv.target : cv.source;
        pair(0, "ARC");
        pair(8, layer);
        pair(10, num(cv.center.x)); pair(20, num(cv.center.y)); pair(30, "0");
        pair(40, num(cv.radius));
        pair(50, num(std::atan2(from.y - cv.center.y, from.x - cv.center.x) * rad2deg));
        pair(51, num(std::atan2(to.y - cv.center.y, to.x - cv.center.x) * rad2deg));
      }
    }
  }
  pair(0, "ENDSEC");
  pair(0, "EOF");
  return s.str();
}

// Rings of inscribed polylines: every vertex on the exact curve, chords within
// the tolerance, so |area error| <= perimeter * tolerance.
std::string to_wkt(const Region& region, const ExportOptions& options) {
  const double tol = effective_tolerance(region, options);
  const auto comps = components_of(region, options);
  if (comps.empty()) return "MULTIPOLYGON EMPTY\n";
  std::string out = "MULTIPOLYGON (";
  for (std::size_t k = 0; k < comps.size(); ++k) {
    out += k ? ", (" : "(";
    std::vector<const Loop*> loops{&comps[k].outer};
    for (const Loop& h : comps[k].holes) loops.push_back(&h);
    for (std::size_t i = 0; i < loops.size(); ++i) {
      out += i ? ", (" : "(";
      const auto pts = ring(*loops[i], tol);
      for (std::size_t j = 0; j < pts.size(); ++j) {
        out += (j ? ", " : "") + num(pts[j].x) + " " + num(pts[j].y);
      }
      out += ")";
    }
    out += ")";
  }
  return out + ")\n";
}

std::string to_geojson(const Region& region, const ExportOptions& options) {
  const double tol = effective_tolerance(region, options);
  std::string coords = "[";
  const auto comps = components_of(region, options);
  for (std::size_t k = 0; k < comps.size(); ++k) {
    coords += k ? ", [" : "[";
    std::vector<const Loop*> loops{&comps[k].outer};
    for (const Loop& h : comps[k].holes) loops.push_back(&h);
    for (std::size_t i = 0; i < loops.size(); ++i) {
      coords += i ? ", [" : "[";
      const auto pts = ring(*loops[i], tol);  // exterior ccw, holes cw (RFC 7946)
      for (std::size_t j = 0; j < pts.size(); ++j) {
        coords += (j ? ", [" : "[") + num(pts[j].x) + ", " + num(pts[j].y) + "]";
      }
      coords += "]";
    }
    coords += "]";
  }
  coords += "]";
  return "{\"type\": \"FeatureCollection\", \"features\": [{\"type\": \"Feature\", "
         "\"properties\": {\"area\": " + num(region.area()) + ", \"tolerance\": " + num(tol) +
         "}, \"geometry\": {\"type\": \"MultiPolygon\", \"coordinates\": " + coords + "}}]}\n";
}

std::string to_csv(const Region& region, const ExportOptions& options) {
  std::string out = "component,loop,hole,kind,x0,y0,x1,y1,cx,cy,r,sweep_deg\n";
  const auto comps = components_of(region, options);
  for (std::size_t k = 0; k < comps.size(); ++k) {
    std::vector<const Loop*> loops{&comps[k].outer};
    for (const Loop& h : comps[k].holes) loops.push_back(&h);
    for (std::size_t i = 0; i < loops.size(); ++i) {
      for (const Curve& c : loops[i]->curves) {
        const bool arc = c.kind == Curve::Kind::arc;
        out += std::to_string(k) + "," + std::to_string(i) + "," + (loops[i]->hole ? "1" : "0") + "," +
               (arc ? "arc" : "segment") + "," + num(c.source.x) + "," + num(c.source.y) + "," +
               num(c.target.x) + "," + num(c.target.y) + "," + (arc ? num(c.center.x) : "") + "," +
               (arc ? num(c.center.y) : "") + "," + (arc ? num(c.radius) : "") + "," +
               (arc ? num(c.sweep() * rad2deg) : "") + "\n";
      }
    }
  }
  return out;
}

void write_file_atomic(const std::filesystem::path& path, std::string_view content) {
  namespace fs = std::filesystem;
  const fs::path tmp = path.string() + ".tmp-" + std::to_string(::getpid());
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) {
      throw InputError(path.string() + ": cannot write: " + std::generic_category().message(errno));
    }
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.flush();
    if (!out) {
      std::error_code ignore;
      fs::remove(tmp, ignore);
      throw InputError(path.string() + ": cannot write: write failed");
    }
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) {
    std::error_code ignore;
    fs::remove(tmp, ignore);
    throw InputError(path.string() + ": cannot write: " + ec.message());
  }
}

}  // namespace pkmws::io
