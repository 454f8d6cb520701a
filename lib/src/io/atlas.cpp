#include "pkmws/io/atlas.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <stdexcept>
#include <utility>

#include "text.hpp"

namespace pkmws::io {

namespace {

using detail::px;
using detail::xml_escape;

struct P {
  double x, y;
};

// Viridis at nine stops, interpolated: a sequential palette that stays
// readable in grey and for colour-blind readers.
std::string band_colour(double t) {
  static const double stops[9][3] = {{68, 1, 84},    {71, 45, 123},  {59, 82, 139},  {44, 114, 142}, {33, 145, 140},
                                     {39, 173, 129}, {92, 200, 99},  {170, 220, 50}, {253, 231, 37}};
  t = std::clamp(t, 0.0, 1.0) * 8.0;
  const int k = std::min(7, static_cast<int>(t));
  const double f = t - k;
  char buf[16];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", static_cast<int>(std::lround(stops[k][0] + f * (stops[k + 1][0] - stops[k][0]))),
                static_cast<int>(std::lround(stops[k][1] + f * (stops[k + 1][1] - stops[k][1]))),
                static_cast<int>(std::lround(stops[k][2] + f * (stops[k + 1][2] - stops[k][2]))));
  return buf;
}

// Number with `digits` significant digits, typographic minus, thin-space thousands.
std::string value_label(double v, double step) {
  std::string s = detail::tick_label(v, step);
  const std::size_t dot = s.find('.');
  std::size_t end = dot == std::string::npos ? s.size() : dot;
  std::size_t begin = s.rfind("\u2212", 0) == 0 ? 3 : 0;
  if (end - begin > 4) {
    for (std::ptrdiff_t k = static_cast<std::ptrdiff_t>(end) - 3; k > static_cast<std::ptrdiff_t>(begin); k -= 3) {
      s.insert(static_cast<std::size_t>(k), "\u2009");
    }
  }
  return s;
}

std::string path_of(const std::vector<P>& poly) {
  std::string d;
  for (std::size_t k = 0; k < poly.size(); ++k) d += (k ? "L" : "M") + px(poly[k].x) + " " + px(poly[k].y);
  return d + "Z";
}

}  // namespace

std::string atlas_figure(const AtlasData& a) {
  const std::size_t nx = a.xs.size(), ny = a.ys.size();
  if (nx < 2 || ny < 2 || a.z.size() != nx * ny) {
    throw std::invalid_argument("atlas: needs a grid of at least 2 x 2 designs");
  }
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  std::size_t best = a.z.size();
  for (std::size_t k = 0; k < a.z.size(); ++k) {
    if (!a.z[k] || !std::isfinite(*a.z[k])) continue;
    lo = std::min(lo, *a.z[k]);
    hi = std::max(hi, *a.z[k]);
    if (best == a.z.size() || (a.maximize ? *a.z[k] > *a.z[best] : *a.z[k] < *a.z[best])) best = k;
  }
  if (best == a.z.size()) throw std::invalid_argument("atlas: the metric has no value on the grid");
  // Levels: a 1-2-5 step giving about eight bands.
  const double step = hi > lo ? detail::nice_step(hi - lo, 8) : 1.0;
  std::vector<double> levels;
  for (double t = std::ceil(lo / step) * step; t < hi; t += step) {
    if (t > lo) levels.push_back(t);
  }
  const std::size_t bands = levels.size() + 1;

  // Page layout (px): plot area, colour bar to its right.
  const double L = 84, T = 58, W = 560, H = 430, page_w = 860, page_h = 580;
  const double x0 = a.xs.front(), x1 = a.xs.back(), y0 = a.ys.front(), y1 = a.ys.back();
  const auto X = [&](double x) { return L + (x - x0) / (x1 - x0) * W; };
  const auto Y = [&](double y) { return T + H - (y - y0) / (y1 - y0) * H; };
  const auto z_at = [&](std::size_t i, std::size_t j) { return a.z[j * nx + i]; };
  // Calls f(v, c) for every cell whose four corners have values: v and c
  // the corner values and page points, counter-clockwise from (i, j).
  const auto for_each_cell = [&](auto&& f) {
    for (std::size_t j = 0; j + 1 < ny; ++j) {
      for (std::size_t i = 0; i + 1 < nx; ++i) {
        const std::optional<double> o[4] = {z_at(i, j), z_at(i + 1, j), z_at(i + 1, j + 1), z_at(i, j + 1)};
        if (!o[0] || !o[1] || !o[2] || !o[3]) continue;
        const double v[4] = {*o[0], *o[1], *o[2], *o[3]};
        const P c[4] = {{X(a.xs[i]), Y(a.ys[j])}, {X(a.xs[i + 1]), Y(a.ys[j])}, {X(a.xs[i + 1]), Y(a.ys[j + 1])},
                        {X(a.xs[i]), Y(a.ys[j + 1])}};
        f(v, c);
      }
    }
  };
  // Where the value crosses t on edge k (linear along the edge).
  const auto crossing = [](const double* v, const P* c, int k, double t) {
    const int n = (k + 1) % 4;
    const double f = (t - v[k]) / (v[n] - v[k]);
    return P{c[k].x + f * (c[n].x - c[k].x), c[k].y + f * (c[n].y - c[k].y)};
  };

  std::string svg;
  svg += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + px(page_w) + "\" height=\"" + px(page_h) +
         "\" viewBox=\"0 0 " + px(page_w) + " " + px(page_h) + "\" font-family=\"DejaVu Sans, Arial, sans-serif\">\n";
  svg += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  svg += "<text x=\"" + px(L + W / 2) + "\" y=\"30\" font-size=\"17\" text-anchor=\"middle\">" + xml_escape(a.title) +
         "</text>\n";
  // Cells without a value (invalid or empty designs): grey.
  std::string missing;
  for (std::size_t j = 0; j + 1 < ny; ++j) {
    for (std::size_t i = 0; i + 1 < nx; ++i) {
      if (z_at(i, j) && z_at(i + 1, j) && z_at(i + 1, j + 1) && z_at(i, j + 1)) continue;
      missing += path_of({{X(a.xs[i]), Y(a.ys[j])}, {X(a.xs[i + 1]), Y(a.ys[j])}, {X(a.xs[i + 1]), Y(a.ys[j + 1])},
                          {X(a.xs[i]), Y(a.ys[j + 1])}});
    }
  }
  if (!missing.empty()) svg += "<path d=\"" + missing + "\" fill=\"#d9d9d9\"/>\n";
  // Bands, painted from the lowest up: level k's super-level set {z >= t_k}
  // as one path (adjacent cells share edges, so the fill has no seams).
  // Within a cell the value is linear along each edge; the polygon walks the
  // cell's corners counter-clockwise, keeping corners at or above t and the
  // crossings of the edges.
  for (std::size_t b = 0; b < bands; ++b) {
    const double t = b == 0 ? -std::numeric_limits<double>::infinity() : levels[b - 1];
    std::string d;
    for_each_cell([&](const double* v, const P* c) {
      std::vector<P> poly;
      for (int k = 0; k < 4; ++k) {
        if (v[k] >= t) poly.push_back(c[k]);
        if ((v[k] >= t) != (v[(k + 1) % 4] >= t)) poly.push_back(crossing(v, c, k, t));
      }
      if (poly.size() >= 3) d += path_of(poly);
    });
    if (!d.empty()) {
      svg += "<path d=\"" + d + "\" fill=\"" + band_colour(bands > 1 ? static_cast<double>(b) / static_cast<double>(bands - 1) : 0.5) +
             "\"/>\n";
    }
  }
  // Isolines, joined into polylines, each labelled at its middle.
  for (double t : levels) {
    std::vector<std::pair<P, P>> segs;
    for_each_cell([&](const double* v, const P* c) {
      std::vector<P> cross;
      for (int k = 0; k < 4; ++k) {
        if ((v[k] >= t) != (v[(k + 1) % 4] >= t)) cross.push_back(crossing(v, c, k, t));
      }
      if (cross.size() == 2) segs.push_back({cross[0], cross[1]});
      if (cross.size() == 4) {  // saddle: as the band polygons join the corners at or above t
        const bool joined = v[0] >= t;
        segs.push_back(joined ? std::pair{cross[0], cross[1]} : std::pair{cross[0], cross[3]});
        segs.push_back(joined ? std::pair{cross[2], cross[3]} : std::pair{cross[1], cross[2]});
      }
    });
    // Chain segments sharing end points (keys rounded to 1e-6 px).
    const auto key = [](P p) { return std::pair{std::llround(p.x * 1e6), std::llround(p.y * 1e6)}; };
    std::multimap<std::pair<long long, long long>, std::size_t> ends;
    for (std::size_t s = 0; s < segs.size(); ++s) {
      ends.insert({key(segs[s].first), s});
      ends.insert({key(segs[s].second), s});
    }
    std::vector<char> used(segs.size(), 0);
    std::string d;
    std::vector<P> longest;
    for (std::size_t s = 0; s < segs.size(); ++s) {
      if (used[s]) continue;
      used[s] = 1;
      std::vector<P> line = {segs[s].first, segs[s].second};
      for (int dir = 0; dir < 2; ++dir) {
        for (;;) {
          const P tip = line.back();
          bool extended = false;
          auto range = ends.equal_range(key(tip));
          for (auto it = range.first; it != range.second; ++it) {
            if (used[it->second]) continue;
            used[it->second] = 1;
            const auto& sg = segs[it->second];
            line.push_back(key(sg.first) == key(tip) ? sg.second : sg.first);
            extended = true;
            break;
          }
          if (!extended) break;
        }
        std::reverse(line.begin(), line.end());
      }
      for (std::size_t k = 0; k < line.size(); ++k) d += (k ? "L" : "M") + px(line[k].x) + " " + px(line[k].y);
      if (line.size() > longest.size()) longest = line;
    }
    if (d.empty()) continue;
    svg += "<path d=\"" + d + "\" fill=\"none\" stroke=\"#1a1a1a\" stroke-width=\"0.9\" stroke-opacity=\"0.85\"/>\n";
    if (longest.size() >= 4) {
      const P m = longest[longest.size() / 2];
      svg += "<text x=\"" + px(m.x) + "\" y=\"" + px(m.y + 4) +
             "\" font-size=\"11\" text-anchor=\"middle\" stroke=\"white\" stroke-width=\"3\" paint-order=\"stroke\">" +
             value_label(t, step) + "</text>\n";
    }
  }
  // Frame, ticks and axis titles.
  svg += "<rect x=\"" + px(L) + "\" y=\"" + px(T) + "\" width=\"" + px(W) + "\" height=\"" + px(H) +
         "\" fill=\"none\" stroke=\"black\"/>\n";
  const double sx = detail::nice_step(x1 - x0, 8), sy = detail::nice_step(y1 - y0, 8);
  for (double x = std::ceil(x0 / sx - 1e-9) * sx; x <= x1 + 1e-9 * sx; x += sx) {
    svg += "<line x1=\"" + px(X(x)) + "\" y1=\"" + px(T + H) + "\" x2=\"" + px(X(x)) + "\" y2=\"" + px(T + H + 5) +
           "\" stroke=\"black\"/><text x=\"" + px(X(x)) + "\" y=\"" + px(T + H + 20) +
           "\" font-size=\"12\" text-anchor=\"middle\">" + detail::tick_label(x, sx) + "</text>\n";
  }
  for (double y = std::ceil(y0 / sy - 1e-9) * sy; y <= y1 + 1e-9 * sy; y += sy) {
    svg += "<line x1=\"" + px(L - 5) + "\" y1=\"" + px(Y(y)) + "\" x2=\"" + px(L) + "\" y2=\"" + px(Y(y)) +
           "\" stroke=\"black\"/><text x=\"" + px(L - 8) + "\" y=\"" + px(Y(y) + 4) +
           "\" font-size=\"12\" text-anchor=\"end\">" + detail::tick_label(y, sy) + "</text>\n";
  }
  svg += "<text x=\"" + px(L + W / 2) + "\" y=\"" + px(T + H + 46) + "\" font-size=\"14\" text-anchor=\"middle\">" +
         xml_escape(a.x_label) + "</text>\n";
  svg += "<text transform=\"translate(" + px(L - 56) + " " + px(T + H / 2) +
         ") rotate(-90)\" font-size=\"14\" text-anchor=\"middle\">" + xml_escape(a.y_label) + "</text>\n";
  // The best design.
  const std::size_t bi = best % nx, bj = best / nx;
  const double bx = X(a.xs[bi]), by = Y(a.ys[bj]);
  svg += "<circle cx=\"" + px(bx) + "\" cy=\"" + px(by) + "\" r=\"6\" fill=\"#e8112d\" stroke=\"white\" stroke-width=\"2\"/>\n";
  char at[128];
  std::snprintf(at, sizeof at, ": %.6g at (%.6g, %.6g)", *a.z[best], a.xs[bi], a.ys[bj]);
  const std::string best_text = std::string(a.maximize ? "largest" : "smallest") + at;
  const bool left = bx > L + W * 0.6;
  svg += "<text x=\"" + px(bx + (left ? -10 : 10)) + "\" y=\"" + px(by + (by < T + 20 ? 16 : -10)) +
         "\" font-size=\"12\" text-anchor=\"" + (left ? "end" : "start") +
         "\" stroke=\"white\" stroke-width=\"3\" paint-order=\"stroke\">" + xml_escape(best_text) + "</text>\n";
  // Colour bar: one box per band with its bounds.
  const double cb_x = L + W + 40, cb_w = 22, cb_h = H / static_cast<double>(bands);
  svg += "<text x=\"" + px(cb_x) + "\" y=\"" + px(T - 12) + "\" font-size=\"12\">" + xml_escape(a.metric_label) +
         "</text>\n";
  for (std::size_t b = 0; b < bands; ++b) {
    const double y = T + H - static_cast<double>(b + 1) * cb_h;
    svg += "<rect x=\"" + px(cb_x) + "\" y=\"" + px(y) + "\" width=\"" + px(cb_w) + "\" height=\"" + px(cb_h) +
           "\" fill=\"" + band_colour(bands > 1 ? static_cast<double>(b) / static_cast<double>(bands - 1) : 0.5) +
           "\" stroke=\"white\" stroke-width=\"0.5\"/>\n";
    const std::string from = b == 0 ? value_label(lo, step / 10) : value_label(levels[b - 1], step);
    const std::string to = b + 1 == bands ? value_label(hi, step / 10) : value_label(levels[b], step);
    svg += "<text x=\"" + px(cb_x + cb_w + 6) + "\" y=\"" + px(y + cb_h / 2 + 4) + "\" font-size=\"11\">" + from +
           " \u2013 " + to + "</text>\n";
  }
  if (!missing.empty()) {
    svg += "<rect x=\"" + px(cb_x) + "\" y=\"" + px(T + H + 14) + "\" width=\"" + px(cb_w) +
           "\" height=\"12\" fill=\"#d9d9d9\"/><text x=\"" + px(cb_x + cb_w + 6) + "\" y=\"" + px(T + H + 24) +
           "\" font-size=\"11\">no design (invalid or empty)</text>\n";
  }
  return svg + "</svg>\n";
}

}  // namespace pkmws::io
