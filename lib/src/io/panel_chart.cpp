// Side-by-side line-chart panels with one shared legend (pkmws/io/panel_chart.hpp).
// Deterministic output: the same figure gives the same bytes.
#include "pkmws/io/panel_chart.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "io/text.hpp"
#include "pkmws/io/plot.hpp"

namespace pkmws::io {

namespace {

using detail::px;
using detail::tick_label;
using detail::xml_escape;

// Okabe-Ito colours (colour-blind safe) and dash patterns within a group.
const char* const kColours[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000"};
const char* const kDashes[] = {"", "9 4", "2 3", "9 3 2 3"};

std::string g17(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// Characters of a UTF-8 string (code points).
double chars(const std::string& s) {
  double n = 0;
  for (unsigned char c : s) n += (c & 0xC0) != 0x80;
  return n;
}

std::vector<std::string> wrap(const std::string& text, std::size_t width) {
  std::vector<std::string> lines;
  std::string line, word;
  const auto flush_word = [&] {
    if (word.empty()) return;
    if (!line.empty() && chars(line) + 1 + chars(word) > static_cast<double>(width)) {
      lines.push_back(line);
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
    word.clear();
  };
  for (char c : text) {
    if (c == ' ') flush_word();
    else word += c;
  }
  flush_word();
  if (!line.empty()) lines.push_back(line);
  return lines;
}

std::string first_word(const std::string& s) { return s.substr(0, s.find(' ')); }

}  // namespace

void style_by_group(PanelFigure& figure) {
  std::vector<std::string> groups;            // first words, in order of appearance
  std::vector<std::pair<std::string, int>> members;  // label -> index within its group
  for (auto& panel : figure.panels) {
    for (auto& s : panel.series) {
      const std::string g = first_word(s.label);
      auto gi = std::find(groups.begin(), groups.end(), g);
      if (gi == groups.end()) gi = groups.insert(groups.end(), g);
      auto mi = std::find_if(members.begin(), members.end(), [&](const auto& m) { return m.first == s.label; });
      if (mi == members.end()) {
        int n = 0;
        for (const auto& m : members) n += first_word(m.first) == g;
        mi = members.insert(members.end(), {s.label, n});
      }
      const auto k = static_cast<std::size_t>(gi - groups.begin());
      s.colour = kColours[k % std::size(kColours)];
      s.dash = kDashes[static_cast<std::size_t>(mi->second) % std::size(kDashes)];
    }
  }
}

std::string panel_chart_svg(const PanelFigure& figure) {
  if (figure.panels.empty()) throw std::invalid_argument("panel chart: no panel");
  const std::size_t n = figure.panels.size();
  const double width = n == 1 ? 720.0 : 1040.0;
  const double margin = 16.0, left = 84.0, right = 18.0, top = 84.0, plot_h = 360.0;
  const double panel_w = (width - 2 * margin) / static_cast<double>(n);
  const double plot_w = panel_w - left - right;

  // Legend entries: one per label, first panel first.
  struct Entry {
    std::string label, colour, dash;
  };
  std::vector<Entry> entries;
  for (const Panel& p : figure.panels) {
    for (const PanelSeries& s : p.series) {
      if (s.x.size() != s.y.size()) {
        throw std::invalid_argument("panel chart: series '" + s.label + "' has x/y of different sizes");
      }
      if (std::none_of(entries.begin(), entries.end(), [&](const Entry& e) { return e.label == s.label; })) {
        entries.push_back({s.label, s.colour, s.dash});
      }
    }
  }
  const bool marks = !figure.x_marks.empty() && !figure.marks_label.empty();
  // Legend rows, wrapped to the width.
  const auto entry_w = [](const std::string& text) { return 48.0 + 7.4 * chars(text); };
  std::vector<std::vector<std::size_t>> rows(1);
  double row_w = 0.0;
  const std::size_t n_entries = entries.size() + (marks ? 1 : 0);
  for (std::size_t k = 0; k < n_entries; ++k) {
    const double w = entry_w(k < entries.size() ? entries[k].label : figure.marks_label);
    if (!rows.back().empty() && row_w + w > width - 2 * margin) {
      rows.emplace_back();
      row_w = 0.0;
    }
    rows.back().push_back(k);
    row_w += w;
  }
  const std::vector<std::string> caption = wrap(figure.caption, static_cast<std::size_t>((width - 40) / 7.6));
  const double legend_top = top + plot_h + 66.0;
  const double height = legend_top + 24.0 * static_cast<double>(rows.size()) + 10.0 +
                        22.0 * static_cast<double>(caption.size()) + 14.0;

  std::string o;
  o += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  o += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + px(width) + "\" height=\"" + px(height) +
       "\" viewBox=\"0 0 " + px(width) + " " + px(height) + "\" font-family=\"DejaVu Sans, Arial, Helvetica, sans-serif\">\n";
  o += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  o += "<text class=\"title\" x=\"" + px(width / 2) + "\" y=\"30\" font-size=\"18\" font-weight=\"bold\" "
       "text-anchor=\"middle\" fill=\"#111\">" + xml_escape(figure.title) + "</text>\n";

  for (std::size_t k = 0; k < n; ++k) {
    const Panel& p = figure.panels[k];
    double xlo = std::numeric_limits<double>::infinity(), xhi = -xlo, ylo = xlo, yhi = -xlo;
    for (const PanelSeries& s : p.series) {
      for (std::size_t i = 0; i < s.x.size(); ++i) {
        if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
        xlo = std::min(xlo, s.x[i]);
        xhi = std::max(xhi, s.x[i]);
        ylo = std::min(ylo, s.y[i]);
        yhi = std::max(yhi, s.y[i]);
      }
    }
    if (!(xlo < xhi)) throw std::invalid_argument("panel chart: panel '" + p.title + "' has no two distinct finite x values");
    // y from 0 (areas, lengths) or the data's minimum when negative, to whole ticks.
    ylo = std::min(0.0, ylo);
    if (!(yhi > ylo)) yhi = ylo + 1.0;
    const double ystep = detail::nice_step(yhi - ylo, 6);
    ylo = std::floor(ylo / ystep + 1e-9) * ystep;
    yhi = std::ceil(yhi / ystep - 1e-9) * ystep;
    const double x0 = margin + static_cast<double>(k) * panel_w + left;
    const double sx = plot_w / (xhi - xlo), sy = plot_h / (yhi - ylo);
    const auto X = [&](double x) { return x0 + (x - xlo) * sx; };
    const auto Y = [&](double y) { return top + (yhi - y) * sy; };
    const std::string clip = "panel-clip-" + std::to_string(k);

    o += "<text class=\"panel-title\" x=\"" + px(x0 + plot_w / 2) + "\" y=\"" + px(top - 26) +
         "\" font-size=\"15\" font-weight=\"bold\" text-anchor=\"middle\" fill=\"#111\">" + xml_escape(p.title) +
         "</text>\n";
    o += "<defs><clipPath id=\"" + clip + "\"><rect x=\"" + px(x0) + "\" y=\"" + px(top) + "\" width=\"" +
         px(plot_w) + "\" height=\"" + px(plot_h) + "\"/></clipPath></defs>\n";
    const auto xt = nice_ticks(xlo, xhi, 6);
    const auto yt = nice_ticks(ylo, yhi, 6);
    const double xstep = xt.size() > 1 ? xt[1] - xt[0] : xhi - xlo;
    o += "<g stroke=\"#e3e3e3\" stroke-width=\"1\">\n";
    for (double t : xt) {
      o += "<line x1=\"" + px(X(t)) + "\" y1=\"" + px(top) + "\" x2=\"" + px(X(t)) + "\" y2=\"" + px(top + plot_h) + "\"/>\n";
    }
    for (double t : yt) {
      o += "<line x1=\"" + px(x0) + "\" y1=\"" + px(Y(t)) + "\" x2=\"" + px(x0 + plot_w) + "\" y2=\"" + px(Y(t)) + "\"/>\n";
    }
    o += "</g>\n";
    if (marks) {
      o += "<g class=\"x-marks\" stroke=\"#8a8a8a\" stroke-width=\"1.2\" stroke-dasharray=\"3 3\">\n";
      for (double m : figure.x_marks) {
        if (m < xlo || m > xhi) continue;
        o += "<line x1=\"" + px(X(m)) + "\" y1=\"" + px(top) + "\" x2=\"" + px(X(m)) + "\" y2=\"" + px(top + plot_h) + "\"/>\n";
      }
      o += "</g>\n";
      // Labels above the frame, staggered when two marks are close.
      double last = -1e9;
      int level = 0;
      for (double m : figure.x_marks) {
        if (m < xlo || m > xhi) continue;
        level = X(m) - last < 30.0 ? 1 - level : 0;
        last = X(m);
        o += "<text class=\"x-mark\" x=\"" + px(X(m)) + "\" y=\"" + px(top - 5 - 11 * level) +
             "\" font-size=\"10.5\" text-anchor=\"middle\" fill=\"#555\">" + xml_escape(tick_label(m, 1.0)) + "</text>\n";
      }
    }
    o += "<rect x=\"" + px(x0) + "\" y=\"" + px(top) + "\" width=\"" + px(plot_w) + "\" height=\"" + px(plot_h) +
         "\" fill=\"none\" stroke=\"#222\" stroke-width=\"1.2\"/>\n";
    o += "<g stroke=\"#222\" stroke-width=\"1.2\">\n";
    for (double t : xt) {
      o += "<line x1=\"" + px(X(t)) + "\" y1=\"" + px(top + plot_h) + "\" x2=\"" + px(X(t)) + "\" y2=\"" + px(top + plot_h + 6) + "\"/>\n";
    }
    for (double t : yt) o += "<line x1=\"" + px(x0 - 6) + "\" y1=\"" + px(Y(t)) + "\" x2=\"" + px(x0) + "\" y2=\"" + px(Y(t)) + "\"/>\n";
    o += "</g>\n<g font-size=\"12.5\" fill=\"#111\">\n";
    for (double t : xt) {
      o += "<text x=\"" + px(X(t)) + "\" y=\"" + px(top + plot_h + 21) + "\" text-anchor=\"middle\">" +
           xml_escape(tick_label(t, xstep)) + "</text>\n";
    }
    const double ytick = yt.size() > 1 ? yt[1] - yt[0] : yhi - ylo;
    for (double t : yt) {
      o += "<text x=\"" + px(x0 - 9) + "\" y=\"" + px(Y(t) + 4.5) + "\" text-anchor=\"end\">" +
           xml_escape(tick_label(t, ytick)) + "</text>\n";
    }
    o += "</g>\n";
    o += "<text class=\"axis-label\" x=\"" + px(x0 + plot_w / 2) + "\" y=\"" + px(top + plot_h + 46) +
         "\" font-size=\"14\" font-style=\"italic\" text-anchor=\"middle\">" + xml_escape(p.x_label) + "</text>\n";
    const double ly = top + plot_h / 2, lx = x0 - left + 18;
    o += "<text class=\"axis-label\" x=\"" + px(lx) + "\" y=\"" + px(ly) + "\" font-size=\"14\" font-style=\"italic\" "
         "text-anchor=\"middle\" transform=\"rotate(-90 " + px(lx) + " " + px(ly) + ")\">" + xml_escape(p.y_label) +
         "</text>\n";
    // px = X0 + SX x, py = Y0 - SY y.
    o += "<g class=\"panel\" data-transform=\"" + g17(x0 - xlo * sx) + " " + g17(top + yhi * sy) + " " + g17(sx) + " " +
         g17(sy) + "\" clip-path=\"url(#" + clip + ")\" fill=\"none\" stroke-width=\"2\" stroke-linejoin=\"round\">\n";
    for (const PanelSeries& s : p.series) {
      std::vector<std::string> pieces(1);
      std::string dots;
      for (std::size_t i = 0; i < s.x.size(); ++i) {
        if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) {
          if (!pieces.back().empty()) pieces.emplace_back();
          continue;
        }
        pieces.back() += (pieces.back().empty() ? "" : " ") + px(X(s.x[i])) + "," + px(Y(s.y[i]));
        dots += "<circle cx=\"" + px(X(s.x[i])) + "\" cy=\"" + px(Y(s.y[i])) + "\" r=\"2.4\" fill=\"" + s.colour +
                "\" stroke=\"none\"/>";
      }
      for (const std::string& pts : pieces) {
        if (pts.empty()) continue;
        o += "<polyline class=\"series\" data-label=\"" + xml_escape(s.label) + "\" stroke=\"" + s.colour + "\"" +
             (s.dash.empty() ? "" : " stroke-dasharray=\"" + s.dash + "\"") + " points=\"" + pts + "\"/>\n";
      }
      o += "<g class=\"points\">" + dots + "</g>\n";
    }
    o += "</g>\n";
  }

  // Shared legend, centred rows.
  o += "<g class=\"legend\" font-size=\"12.5\" fill=\"#111\">\n";
  double y = legend_top;
  for (const auto& row : rows) {
    double total = 0.0;
    for (std::size_t k : row) total += entry_w(k < entries.size() ? entries[k].label : figure.marks_label);
    double x = std::max(margin, width / 2 - total / 2);
    for (std::size_t k : row) {
      if (k < entries.size()) {
        const Entry& e = entries[k];
        o += "<line x1=\"" + px(x) + "\" y1=\"" + px(y - 4) + "\" x2=\"" + px(x + 34) + "\" y2=\"" + px(y - 4) +
             "\" stroke=\"" + e.colour + "\" stroke-width=\"2.4\"" +
             (e.dash.empty() ? "" : " stroke-dasharray=\"" + e.dash + "\"") + "/>\n";
        o += "<text x=\"" + px(x + 40) + "\" y=\"" + px(y) + "\">" + xml_escape(e.label) + "</text>\n";
        x += entry_w(e.label);
      } else {
        o += "<line x1=\"" + px(x + 17) + "\" y1=\"" + px(y - 12) + "\" x2=\"" + px(x + 17) + "\" y2=\"" + px(y + 3) +
             "\" stroke=\"#8a8a8a\" stroke-width=\"1.2\" stroke-dasharray=\"3 3\"/>\n";
        o += "<text x=\"" + px(x + 40) + "\" y=\"" + px(y) + "\">" + xml_escape(figure.marks_label) + "</text>\n";
        x += entry_w(figure.marks_label);
      }
    }
    y += 24.0;
  }
  o += "</g>\n";
  y += 6.0;
  for (const std::string& line : caption) {
    o += "<text class=\"caption\" x=\"" + px(width / 2) + "\" y=\"" + px(y) +
         "\" font-size=\"13.5\" text-anchor=\"middle\" fill=\"#111\">" + xml_escape(line) + "</text>\n";
    y += 22.0;
  }
  o += "</svg>\n";
  return o;
}

}  // namespace pkmws::io
