// The paper-style workspace figure: filled exact workspace (true arcs), frame
// with ticks in the file's unit, scale bar, the mechanism at a pose, title and
// caption. Geometry is drawn in a y-up group; strokes do not scale.
#include <cmath>
#include <cstdio>
#include <sstream>

#include "pkmws/io/export.hpp"

namespace pkmws::io {

namespace {

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

// 1-2-5 step giving about `target` intervals over `range`.
double nice_step(double range, int target) {
  const double raw = range / target;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    if (m * mag >= raw) return m * mag;
  }
  return 10.0 * mag;
}

std::string escape(const std::string& text) {
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

}  // namespace

std::string workspace_figure(const MechanismFile& file, const geometry::Region& region,
                             const mechanisms::Pose& pose, const FigureOptions& options) {
  using geometry::Point;
  const mechanisms::Drawing drawing = options.draw_mechanism && file.model
                                          ? file.model->draw(pose)
                                          : mechanisms::Drawing{};
  geometry::Box view = region.bbox();
  auto add = [&view](Point p) { if (std::isfinite(p.x) && std::isfinite(p.y)) view.expand(p); };
  for (const auto& s : drawing.guides) { add(s.a); add(s.b); }
  for (const auto& s : drawing.links) { add(s.a); add(s.b); }
  for (const Point& p : drawing.joints) add(p);
  for (const Point& p : drawing.base_points) add(p);
  if (view.empty()) view.expand(Point{0, 0});
  const double span = std::max({view.width(), view.height(), 1e-9});
  const double pad = 0.06 * span;
  view.min = {view.min.x - pad, view.min.y - pad};
  view.max = {view.max.x + pad, view.max.y + pad};

  const double width = 800, left = 80, right = 30, top = 60, bottom = 90;
  const double plot_w = width - left - right;
  const double scale = plot_w / view.width();
  const double plot_h = std::min(view.height() * scale, 900.0);
  const double s = std::min(scale, plot_h / view.height());
  const double height = top + plot_h + bottom;
  auto px = [&](Point p) { return Point{left + (p.x - view.min.x) * s, top + (view.max.y - p.y) * s}; };

  std::ostringstream o;
  o << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << fmt(width) << "\" height=\"" << fmt(height)
    << "\" viewBox=\"0 0 " << fmt(width) << " " << fmt(height) << "\" font-family=\"DejaVu Sans, Arial, sans-serif\">\n"
    << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
    << "<text x=\"" << fmt(width / 2) << "\" y=\"32\" font-size=\"20\" text-anchor=\"middle\">"
    << escape(options.title) << "</text>\n";

  // Grid lines and ticks.
  const double step = nice_step(std::max(view.width(), view.height()), 8);
  o << "<g stroke=\"#e6e6e6\" stroke-width=\"1\">\n";
  std::ostringstream labels;
  for (double x = std::ceil(view.min.x / step) * step; x <= view.max.x; x += step) {
    const double X = px({x, 0}).x;
    o << "<line x1=\"" << fmt(X) << "\" y1=\"" << fmt(top) << "\" x2=\"" << fmt(X) << "\" y2=\""
      << fmt(top + plot_h) << "\"/>\n";
    labels << "<text x=\"" << fmt(X) << "\" y=\"" << fmt(top + plot_h + 18)
           << "\" font-size=\"12\" text-anchor=\"middle\">" << fmt(std::abs(x) < 1e-9 * step ? 0 : x) << "</text>\n";
  }
  for (double y = std::ceil(view.min.y / step) * step; y <= view.max.y; y += step) {
    const double Y = px({0, y}).y;
    o << "<line x1=\"" << fmt(left) << "\" y1=\"" << fmt(Y) << "\" x2=\"" << fmt(left + plot_w) << "\" y2=\""
      << fmt(Y) << "\"/>\n";
    labels << "<text x=\"" << fmt(left - 8) << "\" y=\"" << fmt(Y + 4)
           << "\" font-size=\"12\" text-anchor=\"end\">" << fmt(std::abs(y) < 1e-9 * step ? 0 : y) << "</text>\n";
  }
  o << "</g>\n" << labels.str();
  // Axes through the origin when visible.
  if (view.min.x < 0 && view.max.x > 0) {
    const double X = px({0, 0}).x;
    o << "<line x1=\"" << fmt(X) << "\" y1=\"" << fmt(top) << "\" x2=\"" << fmt(X) << "\" y2=\"" << fmt(top + plot_h)
      << "\" stroke=\"#888\" stroke-width=\"1\"/>\n";
  }
  if (view.min.y < 0 && view.max.y > 0) {
    const double Y = px({0, 0}).y;
    o << "<line x1=\"" << fmt(left) << "\" y1=\"" << fmt(Y) << "\" x2=\"" << fmt(left + plot_w) << "\" y2=\""
      << fmt(Y) << "\" stroke=\"#888\" stroke-width=\"1\"/>\n";
  }

  // The workspace: true arcs, in a y-up group.
  o << "<g transform=\"translate(" << fmt(left - view.min.x * s) << " " << fmt(top + view.max.y * s)
    << ") scale(" << fmt(s) << " " << fmt(-s) << ")\">\n"
    << "<path fill=\"#f08080\" fill-opacity=\"0.75\" fill-rule=\"evenodd\" stroke=\"#8b0000\" "
       "stroke-width=\"1.5\" vector-effect=\"non-scaling-stroke\" d=\""
    << svg_path(region) << "\"/>\n</g>\n";

  // The mechanism at the pose.
  for (const auto& g : drawing.guides) {
    const Point a = px(g.a), b = px(g.b);
    o << "<line x1=\"" << fmt(a.x) << "\" y1=\"" << fmt(a.y) << "\" x2=\"" << fmt(b.x) << "\" y2=\"" << fmt(b.y)
      << "\" stroke=\"#555\" stroke-width=\"6\" stroke-opacity=\"0.35\" stroke-linecap=\"round\"/>\n"
      << "<line x1=\"" << fmt(a.x) << "\" y1=\"" << fmt(a.y) << "\" x2=\"" << fmt(b.x) << "\" y2=\"" << fmt(b.y)
      << "\" stroke=\"#333\" stroke-width=\"1.2\" stroke-dasharray=\"8 5\"/>\n";
  }
  for (const auto& l : drawing.links) {
    const Point a = px(l.a), b = px(l.b);
    o << "<line x1=\"" << fmt(a.x) << "\" y1=\"" << fmt(a.y) << "\" x2=\"" << fmt(b.x) << "\" y2=\"" << fmt(b.y)
      << "\" stroke=\"#1f3f8f\" stroke-width=\"4\" stroke-linecap=\"round\"/>\n";
  }
  for (const Point& p : drawing.sliders) {
    const Point c = px(p);
    o << "<rect x=\"" << fmt(c.x - 9) << "\" y=\"" << fmt(c.y - 6) << "\" width=\"18\" height=\"12\" "
      << "fill=\"#c9d3ea\" stroke=\"#1f3f8f\" stroke-width=\"1.5\"/>\n";
  }
  for (const Point& p : drawing.base_points) {
    const Point c = px(p);
    o << "<path d=\"M" << fmt(c.x) << " " << fmt(c.y) << " l-7 12 h14 z\" fill=\"#777\" stroke=\"#333\"/>\n";
  }
  for (const Point& p : drawing.joints) {
    const Point c = px(p);
    o << "<circle cx=\"" << fmt(c.x) << "\" cy=\"" << fmt(c.y) << "\" r=\"4.5\" fill=\"white\" stroke=\"black\" "
      << "stroke-width=\"1.5\"/>\n";
  }
  if (options.draw_mechanism && file.model) {
    const Point t = px(drawing.tool);
    o << "<circle cx=\"" << fmt(t.x) << "\" cy=\"" << fmt(t.y) << "\" r=\"3\" fill=\"#d00000\"/>\n"
      << "<text x=\"" << fmt(t.x + 8) << "\" y=\"" << fmt(t.y - 8) << "\" font-size=\"13\" fill=\"#d00000\">P</text>\n";
  }

  // Frame, scale bar, axis labels, caption.
  o << "<rect x=\"" << fmt(left) << "\" y=\"" << fmt(top) << "\" width=\"" << fmt(plot_w) << "\" height=\""
    << fmt(plot_h) << "\" fill=\"none\" stroke=\"black\" stroke-width=\"1\"/>\n";
  const double bar = step * s;
  const double bx = left + plot_w - bar - 12, by = top + plot_h - 14;
  o << "<g stroke=\"black\" stroke-width=\"2\"><line x1=\"" << fmt(bx) << "\" y1=\"" << fmt(by) << "\" x2=\""
    << fmt(bx + bar) << "\" y2=\"" << fmt(by) << "\"/><line x1=\"" << fmt(bx) << "\" y1=\"" << fmt(by - 5)
    << "\" x2=\"" << fmt(bx) << "\" y2=\"" << fmt(by + 5) << "\"/><line x1=\"" << fmt(bx + bar) << "\" y1=\""
    << fmt(by - 5) << "\" x2=\"" << fmt(bx + bar) << "\" y2=\"" << fmt(by + 5) << "\"/></g>\n"
    << "<text x=\"" << fmt(bx + bar / 2) << "\" y=\"" << fmt(by - 8) << "\" font-size=\"12\" text-anchor=\"middle\">"
    << fmt(step) << " " << escape(file.units) << "</text>\n"
    << "<text x=\"" << fmt(left + plot_w / 2) << "\" y=\"" << fmt(top + plot_h + 40)
    << "\" font-size=\"14\" text-anchor=\"middle\">x [" << escape(file.units) << "]</text>\n"
    << "<text x=\"20\" y=\"" << fmt(top + plot_h / 2) << "\" font-size=\"14\" text-anchor=\"middle\" "
    << "transform=\"rotate(-90 20 " << fmt(top + plot_h / 2) << ")\">y [" << escape(file.units) << "]</text>\n"
    << "<text x=\"" << fmt(width / 2) << "\" y=\"" << fmt(top + plot_h + 70)
    << "\" font-size=\"15\" text-anchor=\"middle\">" << escape(options.caption) << "</text>\n"
    << "</svg>\n";
  return o.str();
}

}  // namespace pkmws::io
