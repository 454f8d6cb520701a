// The paper-style workspace figure (pkmws/io/figure.hpp): white page, filled
// region with a dark outline (true arcs), frame with 1-2-5 ticks in the file's
// unit, light grid, axes through the origin when visible, scale bar,
// overlays, parts, the mechanism at a pose, legend, title and caption.
//
// Canvas: 800 px wide; the plot keeps the aspect ratio 1:1 (one scale s in px
// per length unit). Every path is written in px with two decimals, runs of
// segments simplified to 0.08 px (a traced level curve has thousands of
// points; the figure needs a few hundred), so figures stay small. Output is
// deterministic.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <functional>
#include <map>
#include <numbers>
#include <regex>
#include <string>
#include <vector>

#include "io/document.hpp"
#include "io/text.hpp"
#include "pkmws/certified/cell_region.hpp"
#include "pkmws/geometry/inscribed.hpp"
#include "pkmws/geometry/primitives.hpp"
#include "pkmws/io/export.hpp"
#include "pkmws/io/figure.hpp"

namespace pkmws::io {

namespace {

using geometry::Box;
using geometry::Curve;
using geometry::Point;
using geometry::Region;

using detail::nice_step;
using detail::px;

constexpr double kPi = std::numbers::pi;

std::string g17(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// Characters of UTF-8 text (code points), for widths and wrapping.
std::size_t glyphs(const std::string& s) {
  std::size_t n = 0;
  for (unsigned char c : s) n += (c & 0xC0) != 0x80 ? 1 : 0;
  return n;
}
// Width of a text in px (DejaVu Sans averages ~0.6 em per glyph).
double text_width(const std::string& s, double font) { return 0.6 * font * static_cast<double>(glyphs(s)); }

// Greedy word wrap at `width` glyphs.
std::vector<std::string> wrap(const std::string& text, std::size_t width) {
  std::vector<std::string> lines;
  std::string line, word;
  auto flush_word = [&] {
    if (word.empty()) return;
    if (!line.empty() && glyphs(line) + 1 + glyphs(word) > width) {
      lines.push_back(line);
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
    word.clear();
  };
  for (char c : text) {
    if (c == ' ' || c == '\n') flush_word();
    else word += c;
  }
  flush_word();
  if (!line.empty()) lines.push_back(line);
  return lines;
}

std::string line_el(Point a, Point b, const std::string& style) {
  return "<line x1=\"" + px(a.x) + "\" y1=\"" + px(a.y) + "\" x2=\"" + px(b.x) + "\" y2=\"" + px(b.y) + "\" " +
         style + "/>\n";
}

std::string text_el(Point at, const std::string& text, const std::string& style) {
  return "<text x=\"" + px(at.x) + "\" y=\"" + px(at.y) + "\" " + style + ">" + detail::xml_escape(text) +
         "</text>\n";
}

// Drawing styles, shared by the plot and the legend.
const std::string kGuideBand = "stroke=\"#d6d6d6\" stroke-width=\"9\" stroke-linecap=\"butt\"";
const std::string kGuideLine = "stroke=\"#555555\" stroke-width=\"1.3\" stroke-dasharray=\"7 4\"";
const std::string kLink = "stroke=\"#1f3a93\" stroke-width=\"4.5\" stroke-linecap=\"round\"";
// The platform outlined only: a small workspace under it stays visible.
const std::string kPlatform = "fill=\"none\" stroke=\"#1f3a93\" stroke-width=\"2.5\" stroke-linejoin=\"round\"";
const std::string kJoint = "fill=\"white\" stroke=\"black\" stroke-width=\"1.6\"";
const std::string kSlider = "fill=\"#c8d4f0\" stroke=\"#1f3a93\" stroke-width=\"1.6\"";
const std::string kSingular = "fill=\"none\" stroke=\"#0a7d2c\" stroke-width=\"1.6\" stroke-dasharray=\"5 3\"";
const std::string kTool = "fill=\"#d40000\" stroke=\"white\" stroke-width=\"1.5\"";

// Figure coordinates: (x, y) of the file's frame -> px.
struct Mapping {
  double x0 = 0.0, y0 = 0.0, s = 1.0;
  Point operator()(Point p) const { return {x0 + s * p.x, y0 - s * p.y}; }
};

// Douglas-Peucker on pts[i..j] (kept: i, j), tolerance in px.
void simplify(const std::vector<Point>& pts, std::size_t i, std::size_t j, double tol, std::vector<char>& keep) {
  if (j <= i + 1) return;
  const Point a = pts[i], d = pts[j] - pts[i];
  const double len = geometry::norm(d);
  double worst = -1.0;
  std::size_t at = i;
  for (std::size_t k = i + 1; k < j; ++k) {
    const Point v = pts[k] - a;
    const double dist = len > 0.0 ? std::abs(d.x * v.y - d.y * v.x) / len : geometry::norm(v);
    if (dist > worst) { worst = dist; at = k; }
  }
  if (worst <= tol) return;
  keep[at] = 1;
  simplify(pts, i, at, tol, keep);
  simplify(pts, at, j, tol, keep);
}

// SVG path data (px) of a region's loops: runs of segments simplified, arcs as
// A commands (y is flipped, so a counter-clockwise arc has sweep flag 0).
std::string region_path(const Region& region, const Mapping& m) {
  constexpr double tol = 0.08;
  std::string d;
  for (const auto& loop : region.loops()) {
    if (loop.curves.empty()) continue;
    std::vector<Point> run{m(loop.curves.front().source)};
    auto flush = [&] {
      if (run.size() >= 2) {
        std::vector<char> keep(run.size(), 0);
        keep.front() = keep.back() = 1;
        simplify(run, 0, run.size() - 1, tol, keep);
        for (std::size_t k = 1; k < run.size(); ++k) {
          if (keep[k]) d += "L" + px(run[k].x) + " " + px(run[k].y);
        }
      }
      run.erase(run.begin(), run.end() - 1);
    };
    d += (d.empty() ? "M" : " M") + px(run.front().x) + " " + px(run.front().y);
    for (const Curve& c : loop.curves) {
      const double sweep = c.kind == Curve::Kind::arc ? c.sweep() : 0.0;
      if (c.kind == Curve::Kind::segment || std::abs(sweep) * c.radius * m.s < 1.0) {
        run.push_back(m(c.target));
        continue;
      }
      flush();
      const int n = std::max(1, static_cast<int>(std::ceil(std::abs(sweep) / (2.0 * kPi / 3.0))));
      const std::string r = px(c.radius * m.s);
      const std::string flag = c.ccw ? " 0 " : " 1 ";
      for (int k = 1; k <= n; ++k) {
        const Point q = m(k == n ? c.target : c.at(static_cast<double>(k) / n));
        d += "A" + r + " " + r + " 0 0" + flag + px(q.x) + " " + px(q.y);
      }
      run.assign(1, m(c.target));
    }
    flush();
    d += "Z";
  }
  return d;
}

// SVG path data (px) of closed rings, each simplified to 0.08 px.
std::string rings_path(const std::vector<std::vector<Point>>& rings, const Mapping& m) {
  std::string d;
  for (const auto& ring : rings) {
    if (ring.size() < 3) continue;
    std::vector<Point> pts;
    for (const Point& p : ring) pts.push_back(m(p));
    pts.push_back(pts.front());
    std::vector<char> keep(pts.size(), 0);
    keep.front() = keep.back() = 1;
    simplify(pts, 0, pts.size() - 1, 0.08, keep);
    std::string sub = "M" + px(pts[0].x) + " " + px(pts[0].y);
    std::size_t n = 1;
    for (std::size_t k = 1; k + 1 < pts.size(); ++k) {
      if (!keep[k]) continue;
      sub += "L" + px(pts[k].x) + " " + px(pts[k].y);
      ++n;
    }
    if (n >= 3) d += sub + "Z";
  }
  return d;
}

// Outline of a part: the points within `radius` of its core, in px.
std::string part_element(const FigureOptions::Part& part, const Mapping& m) {
  const std::string style = "class=\"" + part.css_class + "\" fill=\"" + part.fill + "\" stroke=\"" + part.stroke +
                            "\" stroke-width=\"1.2\"";
  const double r = part.radius * m.s;
  if (part.core.size() == 1) {
    const Point c = m(part.core[0]);
    return "<circle cx=\"" + px(c.x) + "\" cy=\"" + px(c.y) + "\" r=\"" + px(r) + "\" " + style + "/>\n";
  }
  if (part.core.size() == 2) {
    // A capsule: the segment's two sides and two half circles.
    const Point a = m(part.core[0]), b = m(part.core[1]);
    const Point d = b - a;
    const double len = geometry::norm(d);
    if (!(len > 0.0)) return "<circle cx=\"" + px(a.x) + "\" cy=\"" + px(a.y) + "\" r=\"" + px(r) + "\" " + style + "/>\n";
    const Point n{-d.y / len * r, d.x / len * r};
    const std::string R = px(r);
    return "<path d=\"M" + px(a.x + n.x) + " " + px(a.y + n.y) + "L" + px(b.x + n.x) + " " + px(b.y + n.y) + "A" + R +
           " " + R + " 0 0 0 " + px(b.x - n.x) + " " + px(b.y - n.y) + "L" + px(a.x - n.x) + " " + px(a.y - n.y) +
           "A" + R + " " + R + " 0 0 0 " + px(a.x + n.x) + " " + px(a.y + n.y) + "Z\" " + style + "/>\n";
  }
  std::string pts;
  for (const Point& p : part.core) {
    const Point q = m(p);
    pts += px(q.x) + "," + px(q.y) + " ";
  }
  const std::string grow = r > 0.0 ? " stroke-linejoin=\"round\" paint-order=\"stroke\"" : "";
  if (r > 0.0) {
    // Grown polygon: the polygon stroked with 2r in its own colour, outlined thinly.
    return "<polygon points=\"" + pts + "\" class=\"" + part.css_class + "\" fill=\"" + part.fill + "\" stroke=\"" +
           part.fill + "\" stroke-width=\"" + px(2 * r) + "\"" + grow + "/>\n";
  }
  return "<polygon points=\"" + pts + "\" " + style + "/>\n";
}

// A legend entry: its swatch (drawn at x, baseline y) and its text.
struct LegendEntry {
  std::string text;
  int rank = 0;
  std::function<std::string(double, double)> swatch;
};

double entry_width(const LegendEntry& e) { return 24 + 7 + text_width(e.text, 12.5) + 20; }

// Hatch pattern id of overlay k.
std::string hatch_id(std::size_t k) { return "hatch" + std::to_string(k); }

}  // namespace

std::string workspace_figure(const MechanismFile& file, const geometry::Region& region,
                             const mechanisms::Pose& pose, const FigureOptions& options) {
  const bool mech = options.draw_mechanism && file.model != nullptr;
  const mechanisms::Drawing drawing = mech ? file.model->draw(pose) : mechanisms::Drawing{};
  return workspace_figure(file, region, drawing, options);
}

std::string workspace_figure(const MechanismFile& file, const geometry::Region& region,
                             const mechanisms::Drawing& drawing, const FigureOptions& options) {
  const bool mech = options.draw_mechanism && file.model != nullptr;

  // The view: region, mechanism, overlays and parts, padded.
  Box view = region.bbox();
  auto add = [&view](Point p) {
    if (std::isfinite(p.x) && std::isfinite(p.y)) view.expand(p);
  };
  if (mech) {
    for (const auto& s : drawing.guides) { add(s.a); add(s.b); }
    for (const auto& s : drawing.links) { add(s.a); add(s.b); }
    for (const Point& p : drawing.joints) add(p);
    for (const Point& p : drawing.sliders) add(p);
    for (const Point& p : drawing.base_points) add(p);
    for (const Point& p : drawing.platform) add(p);
    add(drawing.tool);
  }
  for (const auto& ov : options.overlays) {
    view.expand(ov.region.bbox());
    for (const auto& ring : ov.rings) {
      for (const Point& p : ring) add(p);
    }
  }
  for (const auto& part : options.parts) {
    for (const Point& p : part.core) {
      add({p.x - part.radius, p.y - part.radius});
      add({p.x + part.radius, p.y + part.radius});
    }
  }
  if (view.empty()) view.expand(Point{0.0, 0.0});
  double span = std::max(view.width(), view.height());
  if (!(span > 0.0)) span = 1.0;
  const double pad = 0.06 * span;
  const Box frame{{view.min.x - pad, view.min.y - pad}, {view.max.x + pad, view.max.y + pad}};

  // Layout in px: 800 wide; plot at most 660 x 520, centred; room for the
  // title above and tick labels, axis label, legend and caption below.
  const double width = 800.0;
  const double top = 58.0, left_room = 78.0, right_room = 36.0;
  const double s = std::min(660.0 / frame.width(), 520.0 / frame.height());  // px per unit
  const double plot_w = frame.width() * s, plot_h = frame.height() * s;
  const double left = left_room + 0.5 * (width - left_room - right_room - plot_w);
  const Mapping to_px{left - frame.min.x * s, top + frame.max.y * s, s};
  // Ticks every 1-2-5 step of at least ~60 px; k indexes multiples of step.
  const double step = nice_step(60.0 / s, 1);
  const long kx0 = static_cast<long>(std::ceil(frame.min.x / step));
  const long kx1 = static_cast<long>(std::floor(frame.max.x / step));
  const long ky0 = static_cast<long>(std::ceil(frame.min.y / step));
  const long ky1 = static_cast<long>(std::floor(frame.max.y / step));

  // Singular curves split where they leave the frame.
  std::vector<std::vector<Point>> singular;
  if (mech) {
    for (const auto& curve : drawing.singular_curves) {
      std::vector<Point> piece;
      for (const Point& p : curve) {
        if (frame.contains(p)) {
          piece.push_back(to_px(p));
        } else if (!piece.empty()) {
          if (piece.size() >= 2) singular.push_back(piece);
          piece.clear();
        }
      }
      if (piece.size() >= 2) singular.push_back(piece);
    }
  }

  // Legend entries.
  std::vector<LegendEntry> legend;
  if (!options.region_legend.empty() && !region.empty()) {
    const std::string fill = options.region_fill, stroke = options.region_stroke;
    legend.push_back({options.region_legend, options.region_legend_rank, [fill, stroke](double x, double y) {
                        return "<rect x=\"" + px(x) + "\" y=\"" + px(y - 11) + "\" width=\"24\" height=\"14\" fill=\"" +
                               fill + "\" stroke=\"" + stroke + "\" stroke-width=\"1.5\"/>\n";
                      }});
  }
  for (std::size_t k = 0; k < options.overlays.size(); ++k) {
    const auto& ov = options.overlays[k];
    if (ov.legend.empty()) continue;
    const std::string fill = std::isfinite(ov.hatch_deg) ? "url(#" + hatch_id(k) + ")" : ov.fill;
    const std::string stroke = ov.stroke == "none" && std::isfinite(ov.hatch_deg) ? ov.fill : ov.stroke;
    const double opacity = ov.fill_opacity;
    legend.push_back({ov.legend, ov.legend_rank, [fill, stroke, opacity](double x, double y) {
                        return "<rect x=\"" + px(x) + "\" y=\"" + px(y - 11) + "\" width=\"24\" height=\"14\" fill=\"" +
                               fill + "\" fill-opacity=\"" + g17(opacity) + "\" stroke=\"" + stroke +
                               "\" stroke-width=\"1.5\"/>\n";
                      }});
  }
  {
    std::vector<std::string> seen;
    for (const auto& part : options.parts) {
      if (part.legend.empty() || std::find(seen.begin(), seen.end(), part.legend) != seen.end()) continue;
      seen.push_back(part.legend);
      const std::string fill = part.fill, stroke = part.stroke;
      legend.push_back({part.legend, 0, [fill, stroke](double x, double y) {
                          return "<rect x=\"" + px(x) + "\" y=\"" + px(y - 11) +
                                 "\" width=\"24\" height=\"14\" rx=\"2\" fill=\"" + fill + "\" stroke=\"" + stroke +
                                 "\" stroke-width=\"1.2\"/>\n";
                        }});
    }
  }
  if (mech) {
    if (!drawing.guides.empty()) {
      legend.push_back({drawing.guides_legend, 0, [](double x, double y) {
                          return line_el({x, y - 4}, {x + 24, y - 4}, kGuideBand) +
                                 line_el({x, y - 4}, {x + 24, y - 4}, kGuideLine);
                        }});
    }
    if (!drawing.links.empty()) {
      legend.push_back({drawing.platform.empty() ? "rod / link" : "leg / link", 0, [](double x, double y) {
                          return line_el({x + 2, y - 4}, {x + 22, y - 4}, kLink);
                        }});
    }
    if (!drawing.platform.empty()) {
      legend.push_back({"platform", 0, [](double x, double y) {
                          return "<polygon points=\"" + px(x + 2) + "," + px(y + 2) + " " + px(x + 22) + "," +
                                 px(y + 2) + " " + px(x + 12) + "," + px(y - 11) + "\" " + kPlatform + "/>\n";
                        }});
    }
    if (!drawing.sliders.empty()) {
      legend.push_back({"slider", 0, [](double x, double y) {
                          return "<rect x=\"" + px(x) + "\" y=\"" + px(y - 11) + "\" width=\"24\" height=\"14\" rx=\"2\" " +
                                 kSlider + "/>\n";
                        }});
    }
    if (!drawing.joints.empty()) {
      legend.push_back({"joint", 0, [](double x, double y) {
                          return "<circle cx=\"" + px(x + 12) + "\" cy=\"" + px(y - 4) + "\" r=\"5\" " + kJoint + "/>\n";
                        }});
    }
    legend.push_back({"tool point P", 0, [](double x, double y) {
                        return "<circle cx=\"" + px(x + 12) + "\" cy=\"" + px(y - 4) + "\" r=\"5.5\" " + kTool + "/>\n";
                      }});
    if (!singular.empty()) {
      legend.push_back({"type-2 singularity", 0, [](double x, double y) {
                          return "<polyline points=\"" + px(x) + "," + px(y - 4) + " " + px(x + 24) + "," + px(y - 4) +
                                 "\" " + kSingular + "/>\n";
                        }});
    }
  }
  std::stable_sort(legend.begin(), legend.end(), [](const auto& a, const auto& b) { return a.rank < b.rank; });
  // Rows: entries left to right, wrapped at the page width, each row centred.
  std::vector<std::vector<std::size_t>> rows;
  {
    double x = 0.0;
    for (std::size_t i = 0; i < legend.size(); ++i) {
      const double w = entry_width(legend[i]);
      if (rows.empty() || x + w - 20 > width - 20) {
        rows.emplace_back();
        x = 0.0;
      }
      rows.back().push_back(i);
      x += w;
    }
  }

  const std::vector<std::string> caption = wrap(options.caption, 88);
  const double below = 56.0 + 22.0 * static_cast<double>(rows.size()) + 20.0 * static_cast<double>(caption.size()) + 16.0;
  const double height = std::ceil(top + plot_h + below);

  std::string o;
  o += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  o += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + px(width) + "\" height=\"" + px(height) +
       "\" viewBox=\"0 0 " + px(width) + " " + px(height) +
       "\" font-family=\"DejaVu Sans, Arial, Helvetica, sans-serif\">\n";
  // Hatch patterns of hatched overlays (px space).
  {
    std::string defs;
    for (std::size_t k = 0; k < options.overlays.size(); ++k) {
      const auto& ov = options.overlays[k];
      if (!std::isfinite(ov.hatch_deg)) continue;
      defs += "<pattern id=\"" + hatch_id(k) + "\" patternUnits=\"userSpaceOnUse\" width=\"7\" height=\"7\" "
              "patternTransform=\"rotate(" + px(ov.hatch_deg) + ")\"><line x1=\"0\" y1=\"0\" x2=\"0\" y2=\"7\" stroke=\"" +
              ov.fill + "\" stroke-width=\"2.2\"/></pattern>\n";
    }
    const bool clip = !region.empty() && std::any_of(options.overlays.begin(), options.overlays.end(),
                                                     [](const auto& ov) { return !ov.rings.empty(); });
    if (clip) {
      defs += "<clipPath id=\"clip-region\"><path clip-rule=\"evenodd\" d=\"" + region_path(region, to_px) +
              "\"/></clipPath>\n";
    }
    if (!defs.empty()) o += "<defs>\n" + defs + "</defs>\n";
  }
  o += "<rect x=\"0\" y=\"0\" width=\"" + px(width) + "\" height=\"" + px(height) + "\" fill=\"white\"/>\n";
  o += text_el({width / 2, 34}, options.title,
               "class=\"title\" font-size=\"20\" font-weight=\"bold\" text-anchor=\"middle\" fill=\"#111\"");

  // Grid, axes through the origin.
  const double x_lo = left, x_hi = left + plot_w, y_lo = top, y_hi = top + plot_h;
  o += "<g stroke=\"#ebebeb\" stroke-width=\"1\">\n";
  for (long k = kx0; k <= kx1; ++k) {
    const double X = to_px({static_cast<double>(k) * step, 0}).x;
    o += line_el({X, y_lo}, {X, y_hi}, "");
  }
  for (long k = ky0; k <= ky1; ++k) {
    const double Y = to_px({0, static_cast<double>(k) * step}).y;
    o += line_el({x_lo, Y}, {x_hi, Y}, "");
  }
  o += "</g>\n";
  if (frame.min.x < 0.0 && frame.max.x > 0.0) {
    const double X = to_px({0, 0}).x;
    o += line_el({X, y_lo}, {X, y_hi}, "stroke=\"#9a9a9a\" stroke-width=\"1\"");
  }
  if (frame.min.y < 0.0 && frame.max.y > 0.0) {
    const double Y = to_px({0, 0}).y;
    o += line_el({x_lo, Y}, {x_hi, Y}, "stroke=\"#9a9a9a\" stroke-width=\"1\"");
  }

  // The plot: regions, parts, markers, singular curves, mechanism.
  o += "<g class=\"plot\" data-transform=\"" + g17(to_px.x0) + " " + g17(to_px.y0) + " " + g17(s) + "\">\n";
  if (!region.empty()) {
    o += "<path class=\"workspace\" fill=\"" + options.region_fill + "\" fill-rule=\"evenodd\" stroke=\"" +
         options.region_stroke + "\" stroke-width=\"1.8\" stroke-linejoin=\"round\" d=\"" + region_path(region, to_px) +
         "\"/>\n";
  }
  for (std::size_t k = 0; k < options.overlays.size(); ++k) {
    const auto& ov = options.overlays[k];
    if (!ov.rings.empty()) {
      // Rings (traced bands): nonzero fill, clipped to the main region.
      o += "<path class=\"" + ov.css_class + "\" fill=\"" + ov.fill + "\" fill-opacity=\"" + g17(ov.fill_opacity) +
           "\" fill-rule=\"nonzero\" stroke=\"" + ov.stroke + "\" stroke-width=\"" + px(ov.stroke_px) +
           "\" stroke-linejoin=\"round\"" + (region.empty() ? "" : " clip-path=\"url(#clip-region)\"") + " d=\"" +
           rings_path(ov.rings, to_px) + "\"/>\n";
      continue;
    }
    if (ov.region.empty()) continue;
    const bool hatch = std::isfinite(ov.hatch_deg);
    const std::string fill = hatch ? "url(#" + hatch_id(k) + ")" : ov.fill;
    const std::string stroke = ov.stroke == "none" && hatch ? ov.fill : ov.stroke;
    const double stroke_px = ov.stroke == "none" && hatch ? 1.0 : ov.stroke_px;
    o += "<path class=\"" + ov.css_class + "\" fill=\"" + fill + "\" fill-opacity=\"" + g17(ov.fill_opacity) +
         "\" fill-rule=\"evenodd\" stroke=\"" + stroke + "\" stroke-width=\"" + px(stroke_px) +
         "\" stroke-linejoin=\"round\" d=\"" + region_path(ov.region, to_px) + "\"/>\n";
  }
  for (const auto& part : options.parts) o += part_element(part, to_px);

  // Overlay tags: inside the overlay's largest component, at the centre of its
  // largest inscribed circle, moved around it while another tag is too close.
  std::vector<Point> placed;
  for (const auto& ov : options.overlays) {
    if (ov.region.empty() || ov.label.empty()) continue;
    const auto comps = ov.region.components();
    if (comps.empty()) continue;
    const auto big = std::max_element(comps.begin(), comps.end(),
                                      [](const auto& a, const auto& b) { return a.area < b.area; });
    const auto circle = geometry::largest_inscribed_circle(*big, 1e-3 * std::sqrt(big->area));
    const double half_w = 0.5 * text_width(ov.label, 11) + 5;
    std::vector<Point> candidates{circle.center};
    for (double f : {0.5, 0.85}) {
      for (int i = 0; i < 8; ++i) {
        const double a = i * kPi / 4;
        candidates.push_back({circle.center.x + f * circle.radius * std::cos(a),
                              circle.center.y + f * circle.radius * std::sin(a)});
      }
    }
    Point at = to_px(circle.center);
    for (const Point& c : candidates) {
      const Point q = to_px(c);
      const bool clash = std::any_of(placed.begin(), placed.end(), [&](Point p) {
        return std::abs(p.x - q.x) < 2 * half_w && std::abs(p.y - q.y) < 16.0;
      });
      if (!clash) { at = q; break; }
    }
    placed.push_back(at);
    o += "<g class=\"tag\"><rect x=\"" + px(at.x - half_w) + "\" y=\"" + px(at.y - 8) + "\" width=\"" + px(2 * half_w) +
         "\" height=\"15\" rx=\"7\" fill=\"white\" fill-opacity=\"0.9\" stroke=\"" +
         (ov.fill == "none" ? ov.stroke : ov.fill) + "\" stroke-width=\"1.5\"/>" +
         text_el({at.x, at.y + 4}, ov.label, "font-size=\"11\" font-weight=\"bold\" text-anchor=\"middle\" fill=\"#111\"") +
         "</g>\n";
  }

  for (const auto& piece : singular) {
    std::string pts;
    for (const Point& q : piece) pts += px(q.x) + "," + px(q.y) + " ";
    o += "<polyline class=\"singular\" points=\"" + pts + "\" " + kSingular + "/>\n";
  }

  // The mechanism at the pose.
  if (mech) {
    for (const auto& g : drawing.guides) o += line_el(to_px(g.a), to_px(g.b), kGuideBand);
    for (const auto& g : drawing.guides) o += line_el(to_px(g.a), to_px(g.b), "class=\"guide\" " + kGuideLine);
    for (const Point& b : drawing.base_points) {
      // Ground symbol: a small triangle with a hatched base line.
      const Point c = to_px(b);
      o += "<path class=\"base\" d=\"M" + px(c.x) + " " + px(c.y) + " l-8 13 h16 z\" fill=\"#bdbdbd\" stroke=\"#333\" "
           "stroke-width=\"1.2\"/>\n";
      o += line_el({c.x - 11, c.y + 13}, {c.x + 11, c.y + 13}, "stroke=\"#333\" stroke-width=\"1.4\"");
      for (int h = 0; h < 5; ++h) {
        const double hx = c.x - 10 + 5.0 * h;
        o += line_el({hx, c.y + 13}, {hx - 4, c.y + 18}, "stroke=\"#333\" stroke-width=\"1\"");
      }
    }
    if (drawing.platform.size() >= 3) {
      std::string pts;
      for (const Point& p : drawing.platform) {
        const Point q = to_px(p);
        pts += px(q.x) + "," + px(q.y) + " ";
      }
      o += "<polygon class=\"platform\" points=\"" + pts + "\" " + kPlatform + "/>\n";
    }
    for (const auto& l : drawing.links) o += line_el(to_px(l.a), to_px(l.b), "class=\"link\" " + kLink);
    for (const Point& p : drawing.sliders) {
      // Slider block along the guide it sits on (the nearest guide, else the nearest link).
      double angle = 0.0, best = INFINITY;
      auto consider = [&](const mechanisms::Drawing::Segment& g) {
        const Point d = g.b - g.a;
        const double len2 = geometry::dot(d, d);
        if (!(len2 > 0.0)) return;
        const double t = std::clamp(geometry::dot(p - g.a, d) / len2, 0.0, 1.0);
        const double dist = geometry::norm(p - (g.a + t * d));
        if (dist < best) { best = dist; angle = std::atan2(-d.y, d.x) * 180.0 / kPi; }
      };
      for (const auto& g : drawing.guides) consider(g);
      if (drawing.guides.empty()) {
        for (const auto& l : drawing.links) consider(l);
      }
      const Point c = to_px(p);
      o += "<rect class=\"slider\" x=\"" + px(c.x - 12) + "\" y=\"" + px(c.y - 7) +
           "\" width=\"24\" height=\"14\" rx=\"2\" transform=\"rotate(" + px(angle) + " " + px(c.x) + " " + px(c.y) +
           ")\" " + kSlider + "/>\n";
    }
    for (const Point& p : drawing.joints) {
      const Point c = to_px(p);
      o += "<circle class=\"joint\" cx=\"" + px(c.x) + "\" cy=\"" + px(c.y) + "\" r=\"5\" " + kJoint + "/>\n";
    }
    const Point t = to_px(drawing.tool);
    o += "<circle class=\"tool\" cx=\"" + px(t.x) + "\" cy=\"" + px(t.y) + "\" r=\"5.5\" " + kTool + "/>\n";
    o += text_el({t.x + 9, t.y - 9}, "P",
                 "font-size=\"16\" font-weight=\"bold\" fill=\"#d40000\" stroke=\"white\" "
                 "stroke-width=\"3\" paint-order=\"stroke\"");
  }
  o += "</g>\n";

  // Frame with outward ticks and labels.
  o += "<rect class=\"frame\" x=\"" + px(x_lo) + "\" y=\"" + px(y_lo) + "\" width=\"" + px(plot_w) + "\" height=\"" +
       px(plot_h) + "\" fill=\"none\" stroke=\"black\" stroke-width=\"1.2\"/>\n";
  const std::string tick = "stroke=\"black\" stroke-width=\"1.2\"";
  const std::string label = "class=\"tick\" font-size=\"13\" fill=\"#111\"";
  for (long k = kx0; k <= kx1; ++k) {
    const double X = to_px({static_cast<double>(k) * step, 0}).x;
    o += line_el({X, y_hi}, {X, y_hi + 5}, tick);
    o += text_el({X, y_hi + 20}, detail::tick_label(static_cast<double>(k) * step, step), label + " text-anchor=\"middle\"");
  }
  for (long k = ky0; k <= ky1; ++k) {
    const double Y = to_px({0, static_cast<double>(k) * step}).y;
    o += line_el({x_lo - 5, Y}, {x_lo, Y}, tick);
    o += text_el({x_lo - 8, Y + 4.5}, detail::tick_label(static_cast<double>(k) * step, step),
                 label + " text-anchor=\"end\"");
  }
  const std::string unit = file.units.empty() ? std::string() : " [" + file.units + "]";
  o += text_el({x_lo + plot_w / 2, y_hi + 42}, "x" + unit,
               "class=\"axis-label\" font-size=\"15\" font-style=\"italic\" text-anchor=\"middle\"");
  const double ylab_x = std::max(16.0, x_lo - 58.0);
  o += "<text class=\"axis-label\" x=\"" + px(ylab_x) + "\" y=\"" + px(y_lo + plot_h / 2) + "\" font-size=\"15\" " +
       "font-style=\"italic\" text-anchor=\"middle\" transform=\"rotate(-90 " + px(ylab_x) + " " +
       px(y_lo + plot_h / 2) + ")\">" + detail::xml_escape("y" + unit) + "</text>\n";

  // Scale bar (one tick step, two if that is short) below the frame, right-
  // aligned in the x-label row, so that it never hides the workspace.
  const double bar_units = step * (step * s < 50.0 ? 2.0 : 1.0);
  const double bar = bar_units * s;
  const double bx = std::max(x_hi, x_lo + plot_w / 2 + 45 + bar) - bar, by = y_hi + 45;
  o += "<g class=\"scale-bar\" stroke=\"black\" stroke-width=\"2\">\n" + line_el({bx, by}, {bx + bar, by}, "") +
       line_el({bx, by - 4}, {bx, by + 4}, "") + line_el({bx + bar, by - 4}, {bx + bar, by + 4}, "") + "</g>\n";
  {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%g", bar_units);
    o += text_el({bx + bar / 2, by - 6}, std::string(buf) + (file.units.empty() ? "" : " " + file.units),
                 "font-size=\"12\" text-anchor=\"middle\"");
  }

  // Legend rows, centred.
  double y = y_hi + 56;
  o += "<g class=\"legend\">\n";
  for (const auto& row : rows) {
    y += 22;
    double total = -20.0;
    for (std::size_t i : row) total += entry_width(legend[i]);
    double x = std::max(10.0, width / 2 - total / 2);
    for (std::size_t i : row) {
      o += legend[i].swatch(x, y);
      o += text_el({x + 31, y}, legend[i].text, "font-size=\"12.5\" fill=\"#111\"");
      x += entry_width(legend[i]);
    }
  }
  o += "</g>\n";

  // Caption.
  y += 8;
  for (const std::string& line : caption) {
    y += 20;
    o += text_el({width / 2, y}, line, "class=\"caption\" font-size=\"14\" text-anchor=\"middle\" fill=\"#111\"");
  }
  o += "</svg>\n";
  return o;
}

namespace {

using IPoint = std::pair<std::int64_t, std::int64_t>;

// Net directed coverage of collinear axis-parallel edges on one line: events
// (t, +-1) for edges running in +t (+1) or -t (-1); the output runs where the
// sum is not zero, as edges in the direction of its sign (|sum| copies).
void cancel_line(std::vector<std::pair<std::int64_t, int>>& events,
                 const std::function<void(std::int64_t, std::int64_t)>& emit) {
  std::sort(events.begin(), events.end());
  int sum = 0;
  std::int64_t at = 0;
  for (std::size_t k = 0; k < events.size();) {
    const std::int64_t t = events[k].first;
    if (sum != 0 && t > at) {
      for (int c = 0; c < std::abs(sum); ++c) sum > 0 ? emit(at, t) : emit(t, at);
    }
    while (k < events.size() && events[k].first == t) sum += events[k++].second;
    at = t;
  }
}

}  // namespace

std::vector<std::vector<Point>> traced_inner_rings(const certified::LevelSetResult& result) {
  // Pieces as counter-clockwise polygons.
  std::vector<std::vector<Point>> pieces;
  Box extent;
  for (const Box& b : result.inside_boxes) {
    if (!(b.width() > 0.0 && b.height() > 0.0)) continue;
    pieces.push_back({b.min, {b.max.x, b.min.y}, b.max, {b.min.x, b.max.y}});
    extent.expand(b);
  }
  for (const auto& poly : result.inner_polygons) {
    if (poly.size() < 3) continue;
    double a2 = 0.0;
    for (std::size_t k = 0; k < poly.size(); ++k) {
      const Point p = poly[k], q = poly[(k + 1) % poly.size()];
      a2 += p.x * q.y - p.y * q.x;
    }
    if (!(std::abs(a2) > 0.0)) continue;
    pieces.push_back(poly);
    if (a2 < 0.0) std::reverse(pieces.back().begin(), pieces.back().end());
    for (const Point& p : poly) extent.expand(p);
  }
  if (pieces.empty()) return {};
  // Snap to an integer lattice of 2^-26 of the extent: edges shared by two
  // pieces then have equal end points (or lie on one lattice line).
  const double q = std::max(extent.width(), extent.height()) * std::ldexp(1.0, -26);
  auto snap = [&](Point p) {
    return IPoint{std::llround((p.x - extent.min.x) / q), std::llround((p.y - extent.min.y) / q)};
  };
  std::map<std::int64_t, std::vector<std::pair<std::int64_t, int>>> rows, cols;  // y -> x events, x -> y events
  std::map<std::pair<IPoint, IPoint>, int> slanted;                               // other edges, with multiplicity
  for (const auto& piece : pieces) {
    for (std::size_t k = 0; k < piece.size(); ++k) {
      const IPoint a = snap(piece[k]), b = snap(piece[(k + 1) % piece.size()]);
      if (a == b) continue;
      if (a.second == b.second) {
        auto& ev = rows[a.second];
        const int dir = b.first > a.first ? 1 : -1;
        ev.push_back({std::min(a.first, b.first), dir});
        ev.push_back({std::max(a.first, b.first), -dir});
      } else if (a.first == b.first) {
        auto& ev = cols[a.first];
        const int dir = b.second > a.second ? 1 : -1;
        ev.push_back({std::min(a.second, b.second), dir});
        ev.push_back({std::max(a.second, b.second), -dir});
      } else {
        auto back = slanted.find({b, a});
        if (back != slanted.end()) {
          if (--back->second == 0) slanted.erase(back);
        } else {
          ++slanted[{a, b}];
        }
      }
    }
  }
  // The boundary edges, as a graph: every vertex has as many edges in as out.
  std::map<IPoint, std::vector<IPoint>> out;
  for (auto& [y, ev] : rows) {
    cancel_line(ev, [&, y = y](std::int64_t x0, std::int64_t x1) { out[{x0, y}].push_back({x1, y}); });
  }
  for (auto& [x, ev] : cols) {
    cancel_line(ev, [&, x = x](std::int64_t y0, std::int64_t y1) { out[{x, y0}].push_back({x, y1}); });
  }
  for (const auto& [e, n] : slanted) {
    for (int c = 0; c < n; ++c) out[e.first].push_back(e.second);
  }
  // Closed walks: from any vertex with an unused edge, follow unused edges
  // until back at the start (a balanced graph cannot get stuck elsewhere).
  auto unsnap = [&](IPoint p) {
    return Point{extent.min.x + static_cast<double>(p.first) * q, extent.min.y + static_cast<double>(p.second) * q};
  };
  std::vector<std::vector<Point>> rings;
  for (auto& [start, edges] : out) {
    while (!edges.empty()) {
      std::vector<Point> ring{unsnap(start)};
      IPoint at = start;
      for (;;) {
        auto& from = out[at];
        if (from.empty()) break;  // unbalanced by rounding: close here
        const IPoint next = from.back();
        from.pop_back();
        at = next;
        if (at == start) break;
        ring.push_back(unsnap(at));
      }
      if (ring.size() >= 3) rings.push_back(std::move(ring));
    }
  }
  return rings;
}

double rings_area(const std::vector<std::vector<Point>>& rings) {
  double a2 = 0.0;
  for (const auto& ring : rings) {
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const Point p = ring[k], q = ring[(k + 1) % ring.size()];
      a2 += p.x * q.y - p.y * q.x;
    }
  }
  return 0.5 * a2;
}

geometry::Region largest_ring_region(const std::vector<std::vector<Point>>& rings, const geometry::Region& within) {
  const std::vector<Point>* best = nullptr;
  double best_area = 0.0;
  for (const auto& ring : rings) {
    const double a = rings_area({ring});
    if (a > best_area) { best_area = a; best = &ring; }
  }
  if (!best) return Region();
  // Simplified (Douglas-Peucker at 1e-3 of its size) to a simple polygon.
  Box b;
  for (const Point& p : *best) b.expand(p);
  std::vector<char> keep(best->size() + 1, 0);
  std::vector<Point> closed = *best;
  closed.push_back(best->front());
  keep.front() = keep.back() = 1;
  simplify(closed, 0, closed.size() - 1, 1e-3 * std::max(b.width(), b.height()), keep);
  std::vector<Point> v;
  for (std::size_t k = 0; k + 1 < closed.size(); ++k) {
    if (keep[k]) v.push_back(closed[k]);
  }
  if (v.size() < 3) return Region();
  try {
    return within.intersect(geometry::polygon(v));
  } catch (const std::exception&) {
    return Region();  // not simple after simplification: the caller falls back to `within`
  }
}

std::string interval_text(double lo, double hi, int min_digits) {
  char a[64], b[64];
  for (int d = std::max(1, min_digits); d <= 17; ++d) {
    std::snprintf(a, sizeof a, "%.*g", d, lo);
    std::snprintf(b, sizeof b, "%.*g", d, hi);
    if (std::string(a) != b || lo == hi) break;
  }
  return "[" + std::string(a) + ", " + std::string(b) + "]";
}

std::string source_citation(const MechanismFile& file) {
  const nlohmann::json source = source_json(file);
  if (!source.is_object()) return "";
  std::string out;
  if (source.contains("paper") && source["paper"].is_string()) {
    const std::string paper = source["paper"].get<std::string>();
    std::smatch m;
    if (std::regex_search(paper, m, std::regex(R"(\[[A-Z][A-Za-z]+\])"))) out = m.str();
  }
  if (out.empty()) return "";
  for (const char* key : {"figure", "table"}) {
    if (!source.contains(key) || !source[key].is_string()) continue;
    std::string where = source[key].get<std::string>();
    const auto cut = where.find(" (");
    if (cut != std::string::npos) where.resize(cut);
    const auto comma = where.find(", ");
    if (comma != std::string::npos && where.size() > 24) where.resize(comma);
    if (!where.empty()) out += " " + where;
    break;
  }
  return out;
}

}  // namespace pkmws::io
