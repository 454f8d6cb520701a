// SVG line charts of data series (pkmws/io/plot.hpp): frame, 1-2-5 ticks with
// labels, light grid, axis labels, title, legend and caption. Deterministic
// output; non-finite y values break a curve; points outside the y range are
// clipped by an SVG clip path.
#include "io/text.hpp"
#include "pkmws/io/plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace pkmws::io {

namespace {

using detail::nice_step;
using detail::px;
using detail::tick_label;

// Widen [lo, hi] to whole ticks; a degenerate range gets a margin.
std::array<double, 2> widen(double lo, double hi) {
  if (!(hi > lo)) {
    const double m = lo == 0.0 ? 1.0 : 0.1 * std::abs(lo);
    lo -= m;
    hi += m;
  }
  const double step = nice_step(hi - lo, 6);
  return {std::floor(lo / step + 1e-9) * step, std::ceil(hi / step - 1e-9) * step};
}

const char* const palette[] = {"#1f4e9c", "#c0392b", "#2e8b57", "#8e44ad", "#d68910", "#117a8b", "#555555"};

}  // namespace

std::vector<double> nice_ticks(double lo, double hi, int target) {
  if (!(lo < hi) || !std::isfinite(lo) || !std::isfinite(hi)) {
    throw std::invalid_argument("nice_ticks: need finite lo < hi");
  }
  const double step = nice_step(hi - lo, target);
  std::vector<double> ticks;
  const double first = std::ceil(lo / step - 1e-9);
  for (double k = first; k * step <= hi + 1e-9 * step; k += 1.0) {
    const double v = k * step;
    ticks.push_back(std::abs(v) < 1e-12 * step ? 0.0 : v);
  }
  return ticks;
}

std::string line_chart_svg(const LineChart& chart, int width, int height) {
  // Data ranges over finite points.
  double xlo = std::numeric_limits<double>::infinity(), xhi = -xlo, ylo = xlo, yhi = -xlo;
  bool any = false;
  for (const PlotSeries& s : chart.series) {
    if (s.x.size() != s.y.size()) throw std::invalid_argument("line chart: series '" + s.label + "' has x/y of different sizes");
    int finite = 0;
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
      ++finite;
      xlo = std::min(xlo, s.x[i]);
      xhi = std::max(xhi, s.x[i]);
      ylo = std::min(ylo, s.y[i]);
      yhi = std::max(yhi, s.y[i]);
    }
    any = any || finite >= 2;
  }
  if (!any) throw std::invalid_argument("line chart: no series with two finite points");
  const auto xr = chart.x_range ? *chart.x_range : widen(xlo, xhi);
  const auto yr = chart.y_range ? *chart.y_range : widen(ylo, yhi);
  if (!(xr[0] < xr[1]) || !(yr[0] < yr[1])) throw std::invalid_argument("line chart: empty axis range");

  // Layout (pixels).
  const double left = 86, right = 24, top = 52, bottom = 86;
  const double w = width - left - right, h = height - top - bottom;
  auto X = [&](double x) { return left + (x - xr[0]) / (xr[1] - xr[0]) * w; };
  auto Y = [&](double y) { return top + (yr[1] - y) / (yr[1] - yr[0]) * h; };

  std::string o;
  o += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  o += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(width) + "\" height=\"" +
       std::to_string(height) + "\" viewBox=\"0 0 " + std::to_string(width) + " " + std::to_string(height) +
       "\" font-family=\"DejaVu Sans, Arial, Helvetica, sans-serif\">\n";
  o += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  o += "<defs><clipPath id=\"plot\"><rect x=\"" + px(left) + "\" y=\"" + px(top) + "\" width=\"" + px(w) +
       "\" height=\"" + px(h) + "\"/></clipPath></defs>\n";
  // Title, smaller when long (about 0.6 em per character).
  const double title_size = std::clamp(width / (0.6 * std::max<double>(1.0, static_cast<double>(chart.title.size()))), 11.0, 18.0);
  o += "<text x=\"" + px(width / 2.0) + "\" y=\"30\" font-size=\"" + px(title_size) +
       "\" font-weight=\"bold\" text-anchor=\"middle\" fill=\"#111\">" + detail::xml_escape(chart.title) + "</text>\n";
  // Grid and ticks.
  o += "<g stroke=\"#e3e3e3\" stroke-width=\"1\">\n";
  std::vector<double> xt;
  if (chart.x_tick_step && *chart.x_tick_step > 0.0 && (xr[1] - xr[0]) / *chart.x_tick_step <= 40.0) {
    const double step = *chart.x_tick_step;
    for (double k = std::ceil(xr[0] / step - 1e-9); k * step <= xr[1] + 1e-9 * step; k += 1.0) {
      xt.push_back(std::abs(k) < 0.5 ? 0.0 : k * step);
    }
  } else {
    xt = nice_ticks(xr[0], xr[1]);
  }
  const auto yt = nice_ticks(yr[0], yr[1]);
  for (double t : xt) o += "<line x1=\"" + px(X(t)) + "\" y1=\"" + px(top) + "\" x2=\"" + px(X(t)) + "\" y2=\"" + px(top + h) + "\"/>\n";
  for (double t : yt) o += "<line x1=\"" + px(left) + "\" y1=\"" + px(Y(t)) + "\" x2=\"" + px(left + w) + "\" y2=\"" + px(Y(t)) + "\"/>\n";
  o += "</g>\n";
  // Zero lines when inside.
  o += "<g stroke=\"#999\" stroke-width=\"1\">\n";
  if (xr[0] < 0 && xr[1] > 0) o += "<line x1=\"" + px(X(0)) + "\" y1=\"" + px(top) + "\" x2=\"" + px(X(0)) + "\" y2=\"" + px(top + h) + "\"/>\n";
  if (yr[0] < 0 && yr[1] > 0) o += "<line x1=\"" + px(left) + "\" y1=\"" + px(Y(0)) + "\" x2=\"" + px(left + w) + "\" y2=\"" + px(Y(0)) + "\"/>\n";
  o += "</g>\n";
  // Frame and tick marks with labels.
  o += "<rect x=\"" + px(left) + "\" y=\"" + px(top) + "\" width=\"" + px(w) + "\" height=\"" + px(h) +
       "\" fill=\"none\" stroke=\"#222\" stroke-width=\"1.2\"/>\n";
  const double xstep = xt.size() > 1 ? xt[1] - xt[0] : xr[1] - xr[0];
  const double ystep = yt.size() > 1 ? yt[1] - yt[0] : yr[1] - yr[0];
  o += "<g stroke=\"#222\" stroke-width=\"1.2\">\n";
  for (double t : xt) o += "<line x1=\"" + px(X(t)) + "\" y1=\"" + px(top + h) + "\" x2=\"" + px(X(t)) + "\" y2=\"" + px(top + h + 6) + "\"/>\n";
  for (double t : yt) o += "<line x1=\"" + px(left - 6) + "\" y1=\"" + px(Y(t)) + "\" x2=\"" + px(left) + "\" y2=\"" + px(Y(t)) + "\"/>\n";
  o += "</g>\n<g font-size=\"13\" fill=\"#111\">\n";
  for (double t : xt) {
    o += "<text x=\"" + px(X(t)) + "\" y=\"" + px(top + h + 22) + "\" text-anchor=\"middle\">" +
         detail::xml_escape(tick_label(t, xstep)) + "</text>\n";
  }
  for (double t : yt) {
    o += "<text x=\"" + px(left - 10) + "\" y=\"" + px(Y(t) + 4.5) + "\" text-anchor=\"end\">" +
         detail::xml_escape(tick_label(t, ystep)) + "</text>\n";
  }
  o += "</g>\n";
  // Axis labels.
  o += "<text x=\"" + px(left + w / 2) + "\" y=\"" + px(top + h + 48) +
       "\" font-size=\"15\" font-style=\"italic\" text-anchor=\"middle\">" + detail::xml_escape(chart.x_label) + "</text>\n";
  o += "<text x=\"22\" y=\"" + px(top + h / 2) + "\" font-size=\"15\" font-style=\"italic\" text-anchor=\"middle\" "
       "transform=\"rotate(-90 22 " + px(top + h / 2) + ")\">" + detail::xml_escape(chart.y_label) + "</text>\n";
  // Curves, broken at non-finite values.
  o += "<g clip-path=\"url(#plot)\" fill=\"none\" stroke-width=\"2\" stroke-linejoin=\"round\">\n";
  for (std::size_t k = 0; k < chart.series.size(); ++k) {
    const PlotSeries& s = chart.series[k];
    std::string d;
    bool pen = false;
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) {
        pen = false;
        continue;
      }
      // Keep far-away points finite for the renderer (the clip path hides them).
      const double yy = std::clamp(Y(s.y[i]), -10.0 * height, 11.0 * height);
      d += (pen ? " L" : (d.empty() ? "M" : " M")) + px(X(s.x[i])) + " " + px(yy);
      pen = true;
    }
    o += "<path d=\"" + d + "\" stroke=\"" + palette[k % std::size(palette)] + "\"" +
         (s.dashed ? " stroke-dasharray=\"7 4\"" : "") + "/>\n";
  }
  o += "</g>\n";
  // Legend (top right inside the frame).
  if (!chart.series.empty()) {
    std::size_t longest = 0;
    for (const PlotSeries& s : chart.series) longest = std::max(longest, s.label.size());
    const double lw = 44 + 7.4 * static_cast<double>(longest), lh = 8 + 20.0 * static_cast<double>(chart.series.size());
    // The corner whose legend box covers the fewest data points.
    double lx = left + w - lw - 10, ly = top + 10;
    std::size_t fewest = std::numeric_limits<std::size_t>::max();
    for (const auto& [cx, cy] : {std::pair{left + w - lw - 10, top + 10}, {left + 10, top + 10},
                                 {left + w - lw - 10, top + h - lh - 10}, {left + 10, top + h - lh - 10}}) {
      std::size_t covered = 0;
      for (const PlotSeries& s : chart.series) {
        for (std::size_t i = 0; i < s.x.size(); ++i) {
          if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
          const double px_ = X(s.x[i]), py_ = Y(s.y[i]);
          covered += px_ >= cx - 4 && px_ <= cx + lw + 4 && py_ >= cy - 4 && py_ <= cy + lh + 4;
        }
      }
      if (covered < fewest) {
        fewest = covered;
        lx = cx;
        ly = cy;
      }
    }
    o += "<g font-size=\"13\" fill=\"#111\">\n<rect x=\"" + px(lx) + "\" y=\"" + px(ly) + "\" width=\"" + px(lw) +
         "\" height=\"" + px(lh) + "\" fill=\"white\" fill-opacity=\"0.9\" stroke=\"#888\"/>\n";
    for (std::size_t k = 0; k < chart.series.size(); ++k) {
      const double yy = ly + 18 + 20.0 * static_cast<double>(k);
      o += "<line x1=\"" + px(lx + 8) + "\" y1=\"" + px(yy - 4) + "\" x2=\"" + px(lx + 34) + "\" y2=\"" + px(yy - 4) +
           "\" stroke=\"" + palette[k % std::size(palette)] + "\" stroke-width=\"2\"" +
           (chart.series[k].dashed ? " stroke-dasharray=\"7 4\"" : "") + "/>\n";
      o += "<text x=\"" + px(lx + 40) + "\" y=\"" + px(yy) + "\">" + detail::xml_escape(chart.series[k].label) + "</text>\n";
    }
    o += "</g>\n";
  }
  if (!chart.caption.empty()) {
    o += "<text x=\"" + px(left) + "\" y=\"" + px(height - 12.0) + "\" font-size=\"12\" fill=\"#444\">" +
         detail::xml_escape(chart.caption) + "</text>\n";
  }
  o += "</svg>\n";
  return o;
}

}  // namespace pkmws::io
