// Boundary exports (docs/format.md): SVG with true arcs, DXF R12 with LINE / ARC /
// CIRCLE, WKT and GeoJSON polylines at a stated tolerance, CSV of the exact
// curves; and the atomic file writer used for every output file.
//
// All lengths are in the mechanism file's unit, angles in the file formats'
// own convention (SVG: flags, DXF: degrees ccw, CSV: degrees signed).
#include "io/text.hpp"
#include "pkmws/io/export.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <numbers>
#include <system_error>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace pkmws::io {

using geometry::Component;
using geometry::Curve;
using geometry::Loop;
using geometry::Point;
using geometry::Region;

namespace {

constexpr double pi = std::numbers::pi;
constexpr double rad2deg = 180.0 / pi;

// Shortest decimal text that reads back (strtod) as the same double; at most
// 17 significant digits, which always round-trips.
std::string num(double v) {
  if (v == 0.0) return "0";  // also folds -0
  char buf[40];
  for (int digits = 6; digits < 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    if (std::strtod(buf, nullptr) == v) return buf;
  }
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

double diagonal(const Region& r) {
  const auto b = r.bbox();
  return std::hypot(b.width(), b.height());
}

std::vector<Component> components_of(const Region& region, const ExportOptions& options) {
  return region.components(effective_min_area(region, options));
}

// Outer loop then holes, in the order of the component.
std::vector<const Loop*> loops_of(const Component& c) {
  std::vector<const Loop*> loops{&c.outer};
  for (const Loop& h : c.holes) loops.push_back(&h);
  return loops;
}

// Closed ring of a loop's polyline, first point repeated at the end.
std::vector<Point> ring(const Loop& loop, double tolerance) {
  std::vector<Point> pts = loop.polyline(tolerance);
  if (!pts.empty()) pts.push_back(pts.front());
  return pts;
}

bool full_circle(const Curve& c) { return c.kind == Curve::Kind::arc && c.source == c.target; }

// Number of SVG `A` commands used for an arc of signed sweep s (radians).
// An SVG arc is given by its endpoints, so its centre is recomputed by the
// reader at distance d = r |cos(s/2)| from the chord; rounding the endpoints
// by e moves the centre by e |tan(s/2)| (large near s = pi) and tilts the chord
// by e / (2 r sin(s/2)) (large near s = 2 pi). One command is used where both
// factors are <= 2 (|s| <= 2pi/3 or 4pi/3 <= |s| <= 5pi/3, the latter with the
// large-arc flag), otherwise equal pieces of at most 2pi/3 (a full circle: 3).
int svg_arc_pieces(double s) {
  const double a = std::abs(s);
  if (a <= 2.0 * pi / 3.0 || (a >= 4.0 * pi / 3.0 && a <= 5.0 * pi / 3.0)) return 1;
  return static_cast<int>(std::ceil(a / (2.0 * pi / 3.0)));
}

// Sum of arc lengths over the exported loops and the largest |coordinate|.
struct LoopMeasure {
  double arc_length = 0.0;
  double perimeter = 0.0;
  double extent = 0.0;
};

LoopMeasure measure(const std::vector<Component>& comps) {
  LoopMeasure m;
  for (const Component& c : comps) {
    for (const Loop* loop : loops_of(c)) {
      for (const Curve& cv : loop->curves) {
        const double len = cv.length();
        m.perimeter += len;
        if (cv.kind == Curve::Kind::arc) m.arc_length += len;
      }
    }
    m.extent = std::max({m.extent, std::abs(c.bbox.min.x), std::abs(c.bbox.min.y),
                         std::abs(c.bbox.max.x), std::abs(c.bbox.max.y)});
  }
  return m;
}

std::string json_escape(std::string_view text) {
  std::string out;
  for (char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else {
      out += c;
    }
  }
  return out;
}

// DXF angle in degrees in [0, 360) of point p seen from the centre c.
double dxf_angle(Point p, Point c) {
  double a = std::atan2(p.y - c.y, p.x - c.x) * rad2deg;
  if (a < 0.0) a += 360.0;
  if (a >= 360.0) a -= 360.0;
  return a;
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

double polyline_area_error_bound(const Region& region, const ExportOptions& options) {
  // A chord spanning 2a (a <= pi/2, see Loop::polyline) of an arc of radius r
  // cuts off a circular segment of area r^2 (a - sin a cos a), which is at most
  // (pi/4) * chord * sagitta (ratio 2/3 as a -> 0, pi/4 at a = pi/2), and the
  // sagitta is <= tolerance, the chord <= the arc: so the polygon's area is
  // within (pi/4) * tolerance * (total arc length) of the exact one. Add the
  // shoelace rounding: ~eps * |coordinate| per unit of perimeter, 16x margin.
  const double tol = effective_tolerance(region, options);
  const LoopMeasure m = measure(components_of(region, options));
  return 0.25 * pi * tol * m.arc_length +
         16.0 * std::numeric_limits<double>::epsilon() * m.perimeter * (m.extent + tol);
}

std::string svg_path(const Region& region, const ExportOptions& options) {
  // Path data in mathematical coordinates (the caller flips y). Arc command:
  // A r r 0 large-arc sweep x y, with sweep = 1 for counter-clockwise (the
  // positive-angle direction of the path's own, unflipped coordinates) and
  // large-arc = 1 when the piece sweeps more than pi. See svg_arc_pieces.
  std::string d;
  for (const Component& c : components_of(region, options)) {
    for (const Loop* loop : loops_of(c)) {
      if (loop->curves.empty()) continue;
      if (!d.empty()) d += ' ';
      d += "M" + num(loop->curves.front().source.x) + " " + num(loop->curves.front().source.y);
      for (const Curve& cv : loop->curves) {
        if (cv.kind == Curve::Kind::segment) {
          d += " L" + num(cv.target.x) + " " + num(cv.target.y);
          continue;
        }
        const double sweep = cv.sweep();
        const int n = svg_arc_pieces(sweep);
        const std::string r = num(cv.radius);
        const std::string large = std::abs(sweep / n) > pi ? " 1" : " 0";
        const std::string flag = cv.ccw ? " 1 " : " 0 ";
        for (int k = 1; k <= n; ++k) {
          const Point q = k == n ? cv.target : cv.at(static_cast<double>(k) / n);
          d += " A" + r + " " + r + " 0" + large + flag + num(q.x) + " " + num(q.y);
        }
      }
      d += " Z";
    }
  }
  return d;
}

std::string to_svg(const Region& region, const ExportOptions& options) {
  // y is flipped by the group's transform, so the viewBox spans [-max.y, -min.y].
  auto b = region.bbox();
  if (b.empty()) b = geometry::Box{{0.0, 0.0}, {1.0, 1.0}};
  const double size = std::max({b.width(), b.height(), 1e-300});
  const double margin = 0.05 * size;
  std::string s = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  s += "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"" + num(b.min.x - margin) + " " +
       num(-b.max.y - margin) + " " + num(b.width() + 2 * margin) + " " +
       num(b.height() + 2 * margin) + "\">\n";
  s += "  <!-- pkmws exact workspace boundary: line segments and true circular arcs in the"
       " mechanism's coordinates (y up, flipped by the group transform)";
  if (!options.units.empty()) s += "; unit: " + detail::xml_escape(options.units);
  s += "; area = " + num(region.area()) + " -->\n";
  s += "  <g transform=\"scale(1,-1)\">\n";
  s += "    <path fill=\"#f4a6a6\" fill-rule=\"evenodd\" stroke=\"#7a1010\" stroke-width=\"" +
       num(0.004 * size) + "\" stroke-linejoin=\"round\" d=\"" + svg_path(region, options) +
       "\"/>\n";
  s += "  </g>\n</svg>\n";
  return s;
}

std::string to_dxf(const Region& region, const ExportOptions& options) {
  // AutoCAD R12 ASCII DXF: HEADER, TABLES (LTYPE, LAYER), ENTITIES, EOF.
  std::string s;
  auto pair = [&s](int code, std::string_view value) {
    s += std::to_string(code);
    s += '\n';
    s += value;
    s += '\n';
  };
  const auto comps = components_of(region, options);
  auto b = region.bbox();
  if (b.empty()) b = geometry::Box{{0.0, 0.0}, {0.0, 0.0}};

  pair(999, "pkmws exact workspace boundary: LINE, ARC (counter-clockwise) and CIRCLE entities");
  pair(999, "layers: BOUNDARY (outer loops), HOLES; unit: " +
                (options.units.empty() ? std::string("drawing unit") : options.units));
  pair(0, "SECTION");
  pair(2, "HEADER");
  pair(9, "$ACADVER");
  pair(1, "AC1009");
  pair(9, "$MEASUREMENT");  // 1 = metric (R12 has no $INSUNITS)
  pair(70, options.units == "in" || options.units == "ft" ? "0" : "1");
  pair(9, "$EXTMIN");
  pair(10, num(b.min.x)); pair(20, num(b.min.y)); pair(30, "0");
  pair(9, "$EXTMAX");
  pair(10, num(b.max.x)); pair(20, num(b.max.y)); pair(30, "0");
  pair(0, "ENDSEC");

  pair(0, "SECTION");
  pair(2, "TABLES");
  pair(0, "TABLE");
  pair(2, "LTYPE");
  pair(70, "1");
  pair(0, "LTYPE");
  pair(2, "CONTINUOUS");
  pair(70, "0");
  pair(3, "Solid line");
  pair(72, "65");
  pair(73, "0");
  pair(40, "0");
  pair(0, "ENDTAB");
  pair(0, "TABLE");
  pair(2, "LAYER");
  pair(70, "2");
  for (const auto& [name, color] : {std::pair{"BOUNDARY", "1"}, std::pair{"HOLES", "5"}}) {
    pair(0, "LAYER");
    pair(2, name);
    pair(70, "0");
    pair(62, color);  // ACI colour: 1 red, 5 blue
    pair(6, "CONTINUOUS");
  }
  pair(0, "ENDTAB");
  pair(0, "ENDSEC");

  pair(0, "SECTION");
  pair(2, "ENTITIES");
  for (const Component& c : comps) {
    for (const Loop* loop : loops_of(c)) {
      const std::string layer = loop->hole ? "HOLES" : "BOUNDARY";
      for (const Curve& cv : loop->curves) {
        if (cv.kind == Curve::Kind::segment) {
          pair(0, "LINE");
          pair(8, layer);
          pair(10, num(cv.source.x)); pair(20, num(cv.source.y)); pair(30, "0");
          pair(11, num(cv.target.x)); pair(21, num(cv.target.y)); pair(31, "0");
          continue;
        }
        if (full_circle(cv)) {
          pair(0, "CIRCLE");
          pair(8, layer);
          pair(10, num(cv.center.x)); pair(20, num(cv.center.y)); pair(30, "0");
          pair(40, num(cv.radius));
          continue;
        }
        // DXF arcs always run counter-clockwise from the start to the end angle:
        // a clockwise curve is written with its ends swapped.
        const Point from = cv.ccw ? cv.source : cv.target;
        const Point to = cv.ccw ? cv.target : cv.source;
        pair(0, "ARC");
        pair(8, layer);
        pair(10, num(cv.center.x)); pair(20, num(cv.center.y)); pair(30, "0");
        pair(40, num(cv.radius));
        pair(50, num(dxf_angle(from, cv.center)));
        pair(51, num(dxf_angle(to, cv.center)));
      }
    }
  }
  pair(0, "ENDSEC");
  pair(0, "EOF");
  return s;
}

// Rings of inscribed polylines (every vertex on the exact curve, chord
// deviation <= tolerance): the polygons' area is within
// polyline_area_error_bound() = (pi/4) * tolerance * (arc length) of the exact
// area (about (2/3) * tolerance * arc length when tolerance << radius).
// Outer rings counter-clockwise, holes clockwise, first point repeated.
std::string to_wkt(const Region& region, const ExportOptions& options) {
  const double tol = effective_tolerance(region, options);
  const auto comps = components_of(region, options);
  if (comps.empty()) return "MULTIPOLYGON EMPTY\n";
  std::string out = "MULTIPOLYGON (";
  for (std::size_t k = 0; k < comps.size(); ++k) {
    out += k ? ", (" : "(";
    const auto loops = loops_of(comps[k]);
    for (std::size_t i = 0; i < loops.size(); ++i) {
      out += i ? ", (" : "(";
      const auto pts = ring(*loops[i], tol);
      for (std::size_t j = 0; j < pts.size(); ++j) {
        if (j) out += ", ";
        out += num(pts[j].x) + " " + num(pts[j].y);
      }
      out += ")";
    }
    out += ")";
  }
  return out + ")\n";
}

std::string to_geojson(const Region& region, const ExportOptions& options) {
  // RFC 7946 §3.1.6: exterior rings counter-clockwise, holes clockwise. The
  // coordinates are the mechanism's plane coordinates (not longitude/latitude).
  const double tol = effective_tolerance(region, options);
  std::string coords = "[";
  const auto comps = components_of(region, options);
  for (std::size_t k = 0; k < comps.size(); ++k) {
    coords += k ? ", [" : "[";
    const auto loops = loops_of(comps[k]);
    for (std::size_t i = 0; i < loops.size(); ++i) {
      coords += i ? ", [" : "[";
      const auto pts = ring(*loops[i], tol);
      for (std::size_t j = 0; j < pts.size(); ++j) {
        coords += (j ? ", [" : "[") + num(pts[j].x) + ", " + num(pts[j].y) + "]";
      }
      coords += "]";
    }
    coords += "]";
  }
  coords += "]";
  double area = 0.0;
  for (const Component& c : comps) area += c.area;
  std::string props = "\"area\": " + num(area) + ", \"tolerance\": " + num(tol) +
                      ", \"area_error_bound\": " + num(polyline_area_error_bound(region, options)) +
                      ", \"components\": " + std::to_string(comps.size());
  if (!options.units.empty()) props += ", \"units\": \"" + json_escape(options.units) + "\"";
  return "{\"type\": \"FeatureCollection\", \"features\": [{\"type\": \"Feature\", "
         "\"properties\": {" + props + "}, "
         "\"geometry\": {\"type\": \"MultiPolygon\", \"coordinates\": " + coords + "}}]}\n";
}

std::string to_csv(const Region& region, const ExportOptions& options) {
  // One row per exact boundary curve; cx, cy, r empty for segments; sweep_deg
  // signed (positive counter-clockwise), 0 for segments.
  std::string out = "component,loop,hole,kind,x0,y0,x1,y1,cx,cy,r,sweep_deg\n";
  const auto comps = components_of(region, options);
  for (std::size_t k = 0; k < comps.size(); ++k) {
    const auto loops = loops_of(comps[k]);
    for (std::size_t i = 0; i < loops.size(); ++i) {
      for (const Curve& c : loops[i]->curves) {
        const bool arc = c.kind == Curve::Kind::arc;
        out += std::to_string(k) + "," + std::to_string(i) + "," + (loops[i]->hole ? "1" : "0") +
               "," + (arc ? "arc" : "segment") + "," + num(c.source.x) + "," + num(c.source.y) +
               "," + num(c.target.x) + "," + num(c.target.y) + "," +
               (arc ? num(c.center.x) : "") + "," + (arc ? num(c.center.y) : "") + "," +
               (arc ? num(c.radius) : "") + "," + (arc ? num(c.sweep() * rad2deg) : "0") + "\n";
      }
    }
  }
  return out;
}

std::string xml_escape(std::string_view text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

void write_file_atomic(const std::filesystem::path& path, std::string_view content) {
  // The temporary file lives in the target's directory so that rename(2) is
  // atomic; any failure removes it. Missing directories are not created.
  namespace fs = std::filesystem;
  auto fail = [&path](const std::string& reason) {
    throw InputError(path.string() + ": cannot write: " + reason);
  };
  if (path.empty() || !path.has_filename()) fail("not a file name");
  const fs::path dir = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) fail("directory " + dir.string() + " does not exist");
  if (fs::is_directory(path, ec)) fail("is a directory");

  const fs::path tmp = path.string() + ".tmp-" + std::to_string(::getpid());
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) fail(std::strerror(errno));
  auto abandon = [&](const std::string& reason) {
    std::error_code ignore;
    fs::remove(tmp, ignore);
    fail(reason);
  };
  const char* data = content.data();
  std::size_t left = content.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, data, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      const std::string reason = std::strerror(errno);
      ::close(fd);
      abandon(reason);
    }
    data += n;
    left -= static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0 && errno != EINVAL && errno != EROFS) {
    const std::string reason = std::strerror(errno);
    ::close(fd);
    abandon(reason);
  }
  if (::close(fd) != 0) abandon(std::strerror(errno));
  fs::rename(tmp, path, ec);
  if (ec) abandon(ec.message());
}

}  // namespace pkmws::io
