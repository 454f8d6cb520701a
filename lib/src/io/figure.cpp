// The paper-style workspace figure (docs/format.md "plots in the style of the
// papers' figures"): white page, light-red exact workspace with a dark outline
// (true arcs), frame with 1-2-5 ticks in the file's unit, light grid, axes
// through the origin when visible, scale bar, the mechanism at a pose (guides
// dashed, rods, sliders, joints, tool point), legend, title and caption.
//
// Canvas: 800 px wide, at most ~700 px high; the plot keeps the aspect ratio
// 1:1 (one scale s in px per length unit). Output is deterministic.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "io/text.hpp"
#include "pkmws/io/export.hpp"

namespace pkmws::io {

namespace {

using geometry::Box;
using geometry::Point;

using detail::nice_step;
using detail::px;

// Full precision for the geometry transform (the path itself is exact).
std::string g17(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// Tick label k * step.
std::string tick_label(long k, double step) { return detail::tick_label(static_cast<double>(k) * step, step); }

// Greedy word wrap at `width` characters (UTF-8 multibyte counted per byte;
// close enough for a caption).
std::vector<std::string> wrap(const std::string& text, std::size_t width) {
  std::vector<std::string> lines;
  std::string line, word;
  auto flush_word = [&] {
    if (word.empty()) return;
    if (!line.empty() && line.size() + 1 + word.size() > width) {
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
  return "<line x1=\"" + px(a.x) + "\" y1=\"" + px(a.y) + "\" x2=\"" + px(b.x) + "\" y2=\"" +
         px(b.y) + "\" " + style + "/>\n";
}

std::string text_el(Point at, const std::string& text, const std::string& style) {
  return "<text x=\"" + px(at.x) + "\" y=\"" + px(at.y) + "\" " + style + ">" + detail::xml_escape(text) +
         "</text>\n";
}

// Drawing styles, shared by the plot and the legend.
const std::string kFill = "#f4a3a3";
const std::string kOutline = "#8b1a1a";
const std::string kGuideBand = "stroke=\"#d6d6d6\" stroke-width=\"9\" stroke-linecap=\"butt\"";
const std::string kGuideLine = "stroke=\"#555555\" stroke-width=\"1.3\" stroke-dasharray=\"7 4\"";
const std::string kLink = "stroke=\"#1f3a93\" stroke-width=\"4.5\" stroke-linecap=\"round\"";
const std::string kJoint = "fill=\"white\" stroke=\"black\" stroke-width=\"1.6\"";
const std::string kSlider = "fill=\"#c8d4f0\" stroke=\"#1f3a93\" stroke-width=\"1.6\"";
const std::string kSingular = "fill=\"none\" stroke=\"#0a7d2c\" stroke-width=\"1.6\" stroke-dasharray=\"5 3\"";
const std::string kTool = "fill=\"#d40000\" stroke=\"white\" stroke-width=\"1.5\"";

}  // namespace

std::string workspace_figure(const MechanismFile& file, const geometry::Region& region,
                             const mechanisms::Pose& pose, const FigureOptions& options) {
  const bool mech = options.draw_mechanism && file.model != nullptr;
  const mechanisms::Drawing drawing = mech ? file.model->draw(pose) : mechanisms::Drawing{};

  // The view: region and mechanism, padded, then widened to whole ticks.
  Box view = region.bbox();
  auto add = [&view](Point p) {
    if (std::isfinite(p.x) && std::isfinite(p.y)) view.expand(p);
  };
  for (const auto& s : drawing.guides) { add(s.a); add(s.b); }
  for (const auto& s : drawing.links) { add(s.a); add(s.b); }
  for (const Point& p : drawing.joints) add(p);
  for (const Point& p : drawing.sliders) add(p);
  for (const Point& p : drawing.base_points) add(p);
  if (mech) add(drawing.tool);
  for (const auto& ov : options.overlays) view.expand(ov.region.bbox());
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
  // Ticks every 1-2-5 step of at least ~60 px; k indexes multiples of step.
  const double step = nice_step(60.0 / s, 1);
  const long kx0 = static_cast<long>(std::ceil(frame.min.x / step));
  const long kx1 = static_cast<long>(std::floor(frame.max.x / step));
  const long ky0 = static_cast<long>(std::ceil(frame.min.y / step));
  const long ky1 = static_cast<long>(std::floor(frame.max.y / step));
  const std::vector<std::string> caption = wrap(options.caption, 92);
  const bool legend = mech;
  // Overlay legend rows: entries wrap at the figure's width (as drawn below).
  std::size_t overlay_legends = 0;
  double overlay_rows = 0.0;
  {
    double x = 1e300;
    for (const auto& ov : options.overlays) {
      if (ov.legend.empty()) continue;
      ++overlay_legends;
      const double w = 24 + 8 + 7.0 * static_cast<double>(ov.legend.size()) + 22;
      if (x + w - 22 > width - 10) { overlay_rows += 1.0; x = 10.0; }
      x += w;
    }
  }
  const double below = 52.0 + (legend ? 30.0 : 0.0) + 20.0 * static_cast<double>(caption.size()) + 14.0 +
                       (overlay_legends ? 20.0 * overlay_rows + 20.0 : 0.0);
  const double height = std::ceil(top + plot_h + below);
  auto to_px = [&](Point p) {
    return Point{left + (p.x - frame.min.x) * s, top + (frame.max.y - p.y) * s};
  };

  std::string o;
  o += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  o += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + px(width) + "\" height=\"" + px(height) +
       "\" viewBox=\"0 0 " + px(width) + " " + px(height) +
       "\" font-family=\"DejaVu Sans, Arial, Helvetica, sans-serif\">\n";
  o += "<rect x=\"0\" y=\"0\" width=\"" + px(width) + "\" height=\"" + px(height) + "\" fill=\"white\"/>\n";
  o += text_el({width / 2, 34}, options.title,
               "font-size=\"20\" font-weight=\"bold\" text-anchor=\"middle\" fill=\"#111\"");

  // Grid, axes through the origin, ticks and tick labels.
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

  // The workspace: exact boundary with true arcs in a y-up group.
  const double outline = 1.8 / s;  // 1.8 px in file units
  o += "<g transform=\"translate(" + g17(left - frame.min.x * s) + " " + g17(top + frame.max.y * s) +
       ") scale(" + g17(s) + " " + g17(-s) + ")\">\n";
  o += "<path fill=\"" + kFill + "\" fill-rule=\"evenodd\" stroke=\"" + kOutline + "\" stroke-width=\"" +
       g17(outline) + "\" stroke-linejoin=\"round\" d=\"" + svg_path(region) + "\"/>\n";
  for (const auto& ov : options.overlays) {
    if (ov.region.empty()) continue;
    o += "<path fill=\"" + ov.fill + "\" fill-opacity=\"" + g17(ov.fill_opacity) + "\" fill-rule=\"evenodd\" stroke=\"" +
         ov.stroke + "\" stroke-width=\"" + g17(ov.stroke_px / s) + "\" stroke-linejoin=\"round\" d=\"" +
         svg_path(ov.region) + "\"/>\n";
  }
  o += "</g>\n";
  std::vector<Point> placed;  // labels already written (px), so that the next ones do not cover them
  for (const auto& ov : options.overlays) {
    if (ov.region.empty() || ov.label.empty()) continue;
    const auto comps = ov.region.components();
    if (comps.empty()) continue;
    const auto big = std::max_element(comps.begin(), comps.end(),
                                      [](const auto& a, const auto& b) { return a.area < b.area; });
    Point at = to_px(big->centroid);
    const double half = 3.2 * static_cast<double>(ov.label.size());  // ~half the label's width at 11 px
    for (int tries = 0; tries < 8; ++tries) {
      const bool clash = std::any_of(placed.begin(), placed.end(), [&](Point q) {
        return std::abs(q.x - at.x) < 2.0 * half && std::abs(q.y - at.y) < 13.0;
      });
      if (!clash) break;
      at.y += 13.0;
    }
    placed.push_back(at);
    o += text_el(at, ov.label, "font-size=\"11\" text-anchor=\"middle\" fill=\"#111\" stroke=\"white\" "
                               "stroke-width=\"3\" paint-order=\"stroke\"");
  }

  // Type-2 singularity curves (dashed), inside the frame.
  for (const auto& curve : drawing.singular_curves) {
    std::string pts;
    for (const Point& p : curve) {
      if (!frame.contains(p)) continue;
      const Point q = to_px(p);
      pts += px(q.x) + "," + px(q.y) + " ";
    }
    if (!pts.empty()) o += "<polyline points=\"" + pts + "\" " + kSingular + "/>\n";
  }

  // The mechanism at the pose.
  if (mech) {
    for (const auto& g : drawing.guides) o += line_el(to_px(g.a), to_px(g.b), kGuideBand);
    for (const auto& g : drawing.guides) o += line_el(to_px(g.a), to_px(g.b), kGuideLine);
    for (const Point& b : drawing.base_points) {
      // Ground symbol: a small triangle with a hatched base line.
      const Point c = to_px(b);
      o += "<path d=\"M" + px(c.x) + " " + px(c.y) + " l-8 13 h16 z\" fill=\"#bdbdbd\" stroke=\"#333\" "
           "stroke-width=\"1.2\"/>\n";
      o += line_el({c.x - 11, c.y + 13}, {c.x + 11, c.y + 13}, "stroke=\"#333\" stroke-width=\"1.4\"");
      for (int h = 0; h < 5; ++h) {
        const double hx = c.x - 10 + 5.0 * h;
        o += line_el({hx, c.y + 13}, {hx - 4, c.y + 18}, "stroke=\"#333\" stroke-width=\"1\"");
      }
    }
    for (const auto& l : drawing.links) o += line_el(to_px(l.a), to_px(l.b), kLink);
    for (const Point& p : drawing.sliders) {
      // Slider block along the guide it sits on (the nearest one).
      double angle = 0.0, best = INFINITY;
      for (const auto& g : drawing.guides) {
        const Point d = g.b - g.a;
        const double len2 = geometry::dot(d, d);
        const double t = len2 > 0 ? std::clamp(geometry::dot(p - g.a, d) / len2, 0.0, 1.0) : 0.0;
        const double dist = geometry::norm(p - (g.a + t * d));
        if (dist < best) { best = dist; angle = std::atan2(-d.y, d.x) * 180.0 / 3.14159265358979323846; }
      }
      const Point c = to_px(p);
      o += "<rect x=\"" + px(c.x - 12) + "\" y=\"" + px(c.y - 7) + "\" width=\"24\" height=\"14\" rx=\"2\" " +
           "transform=\"rotate(" + px(angle) + " " + px(c.x) + " " + px(c.y) + ")\" " + kSlider + "/>\n";
    }
    for (const Point& p : drawing.joints) {
      const Point c = to_px(p);
      o += "<circle cx=\"" + px(c.x) + "\" cy=\"" + px(c.y) + "\" r=\"5\" " + kJoint + "/>\n";
    }
    const Point t = to_px(drawing.tool);
    o += "<circle cx=\"" + px(t.x) + "\" cy=\"" + px(t.y) + "\" r=\"5.5\" " + kTool + "/>\n";
    o += text_el({t.x + 9, t.y - 9}, "P",
                 "font-size=\"16\" font-weight=\"bold\" fill=\"#d40000\" stroke=\"white\" "
                 "stroke-width=\"3\" paint-order=\"stroke\"");
  }

  // Frame with outward ticks and labels.
  o += "<rect x=\"" + px(x_lo) + "\" y=\"" + px(y_lo) + "\" width=\"" + px(plot_w) + "\" height=\"" +
       px(plot_h) + "\" fill=\"none\" stroke=\"black\" stroke-width=\"1.2\"/>\n";
  const std::string tick = "stroke=\"black\" stroke-width=\"1.2\"";
  const std::string label = "font-size=\"13\" fill=\"#111\"";
  for (long k = kx0; k <= kx1; ++k) {
    const double X = to_px({static_cast<double>(k) * step, 0}).x;
    o += line_el({X, y_hi}, {X, y_hi + 5}, tick);
    o += text_el({X, y_hi + 20}, tick_label(k, step), label + " text-anchor=\"middle\"");
  }
  for (long k = ky0; k <= ky1; ++k) {
    const double Y = to_px({0, static_cast<double>(k) * step}).y;
    o += line_el({x_lo - 5, Y}, {x_lo, Y}, tick);
    o += text_el({x_lo - 8, Y + 4.5}, tick_label(k, step), label + " text-anchor=\"end\"");
  }
  const std::string unit = file.units.empty() ? std::string() : " [" + file.units + "]";
  o += text_el({x_lo + plot_w / 2, y_hi + 42}, "x" + unit,
               "font-size=\"15\" font-style=\"italic\" text-anchor=\"middle\"");
  const double ylab_x = std::max(16.0, x_lo - 58.0);
  o += "<text x=\"" + px(ylab_x) + "\" y=\"" + px(y_lo + plot_h / 2) + "\" font-size=\"15\" " +
       "font-style=\"italic\" text-anchor=\"middle\" transform=\"rotate(-90 " + px(ylab_x) + " " +
       px(y_lo + plot_h / 2) + ")\">" + detail::xml_escape("y" + unit) + "</text>\n";

  // Scale bar (one tick step, two if that is short) below the frame, right-
  // aligned in the x-label row, so that it never hides the workspace.
  const double bar_units = step * (step * s < 50.0 ? 2.0 : 1.0);
  const double bar = bar_units * s;
  const double bx = std::max(x_hi, x_lo + plot_w / 2 + 45 + bar) - bar, by = y_hi + 45;
  o += "<g stroke=\"black\" stroke-width=\"2\">\n" + line_el({bx, by}, {bx + bar, by}, "") +
       line_el({bx, by - 4}, {bx, by + 4}, "") + line_el({bx + bar, by - 4}, {bx + bar, by + 4}, "") +
       "</g>\n";
  {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%g", bar_units);
    o += text_el({bx + bar / 2, by - 6}, std::string(buf) + (file.units.empty() ? "" : " " + file.units),
                 "font-size=\"12\" text-anchor=\"middle\"");
  }

  // Legend row.
  double y = y_hi + 52;
  if (legend) {
    y += 18;
    // Items: symbol 24 px, gap 8, label (~7.5 px per character at 13 px), gap 28.
    std::vector<std::string> names{"workspace", "guide", "rod / link", "joint", "tool point P"};
    if (!drawing.singular_curves.empty()) names.push_back("singularity");  // type 2, dashed
    double total = 0.0;
    for (const auto& n : names) total += 24 + 8 + 7.5 * static_cast<double>(n.size()) + 28;
    double x = width / 2 - (total - 28) / 2;
    const std::string lt = "font-size=\"13\" fill=\"#111\"";
    for (std::size_t i = 0; i < names.size(); ++i) {
      switch (i) {
        case 0:
          o += "<rect x=\"" + px(x) + "\" y=\"" + px(y - 11) + "\" width=\"24\" height=\"14\" fill=\"" +
               kFill + "\" stroke=\"" + kOutline + "\" stroke-width=\"1.5\"/>\n";
          break;
        case 1:
          o += line_el({x, y - 4}, {x + 24, y - 4}, kGuideBand);
          o += line_el({x, y - 4}, {x + 24, y - 4}, kGuideLine);
          break;
        case 2: o += line_el({x + 2, y - 4}, {x + 22, y - 4}, kLink); break;
        case 3: o += "<circle cx=\"" + px(x + 12) + "\" cy=\"" + px(y - 4) + "\" r=\"5\" " + kJoint + "/>\n"; break;
        case 4: o += "<circle cx=\"" + px(x + 12) + "\" cy=\"" + px(y - 4) + "\" r=\"5.5\" " + kTool + "/>\n"; break;
        default: o += "<polyline points=\"" + px(x) + "," + px(y - 4) + " " + px(x + 24) + "," + px(y - 4) + "\" " + kSingular + "/>\n";
      }
      o += text_el({x + 32, y}, names[i], lt);
      x += 24 + 8 + 7.5 * static_cast<double>(names[i].size()) + 28;
    }
    y += 12;
  }
  {
    std::vector<const FigureOptions::Overlay*> items;
    for (const auto& ov : options.overlays) {
      if (!ov.legend.empty()) items.push_back(&ov);
    }
    double x = 1e300;
    for (std::size_t i = 0; i < items.size(); ++i) {
      if (x + 24 + 8 + 7.0 * static_cast<double>(items[i]->legend.size()) > width - 10) {
        y += 20;
        x = 10.0;
      }
      const auto& ov = *items[i];
      o += "<rect x=\"" + px(x) + "\" y=\"" + px(y - 11) + "\" width=\"24\" height=\"14\" fill=\"" + ov.fill +
           "\" fill-opacity=\"" + g17(ov.fill_opacity) + "\" stroke=\"" + ov.stroke + "\" stroke-width=\"1.5\"/>\n";
      o += text_el({x + 32, y}, ov.legend, "font-size=\"12\" fill=\"#111\"");
      x += 24 + 8 + 7.0 * static_cast<double>(ov.legend.size()) + 22;
    }
    if (!items.empty()) y += 8;
  }

  // Caption.
  for (const std::string& line : caption) {
    y += 20;
    o += text_el({width / 2, y}, line, "font-size=\"14\" text-anchor=\"middle\" fill=\"#111\"");
  }
  o += "</svg>\n";
  return o;
}

}  // namespace pkmws::io
