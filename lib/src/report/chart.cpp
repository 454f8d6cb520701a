// `pkmws chart` (pkmws/report/chart.hpp): moved from the command line's
// chart.cpp, figure and tables unchanged.
#include "pkmws/report/chart.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>

#include "pkmws/design/sweep.hpp"
#include "pkmws/io/panel_chart.hpp"
#include "pkmws/report/common.hpp"
#include "report/json.hpp"

namespace pkmws::report {

using detail::Json;

namespace {

// One metric of one sweep: values by x (midpoint and half-width for bounds).
struct Values {
  std::map<double, std::pair<double, double>> at;  // x -> (value, half-width; 0 for a plain column)
  bool bounds = false;
};

struct Sweep {
  std::string path, label;
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
};

Sweep read_sweep(const std::string& arg) {
  Sweep s;
  const auto eq = arg.find('=');
  s.path = arg.substr(0, eq);
  s.label = eq == std::string::npos ? std::filesystem::path(s.path).stem().string() : arg.substr(eq + 1);
  std::ifstream in(s.path);
  if (!in) throw io::InputError(s.path + ": cannot open");
  std::string line;
  if (!std::getline(in, line)) throw io::InputError(s.path + ": empty file");
  s.header = design::split_csv(line);
  std::size_t number = 1;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty()) continue;
    auto f = design::split_csv(line);
    if (f.size() != s.header.size()) throw io::InputError(s.path + ":" + std::to_string(number) + ": malformed row");
    s.rows.push_back(std::move(f));
  }
  return s;
}

std::optional<std::size_t> find_column(const Sweep& s, const std::string& name) {
  for (std::size_t k = 0; k < s.header.size(); ++k) {
    if (s.header[k] == name) return k;
  }
  return std::nullopt;
}

// The metric `name` of sweep `s` over column `x`: the column itself, or the
// midpoint of NAME_lower and NAME_upper; nullopt when the sweep has neither.
std::optional<Values> values_of(const Sweep& s, const std::string& x, const std::string& name) {
  const auto cx = find_column(s, x);
  if (!cx) throw io::InputError("--x: no column '" + x + "' in " + s.path);
  const auto cs = find_column(s, "status");
  if (!cs) throw io::InputError(s.path + ": no status column (not a pkmws sweep CSV)");
  auto c = find_column(s, name);
  auto lo = find_column(s, name + "_lower"), hi = find_column(s, name + "_upper");
  if (!c && !(lo && hi)) return std::nullopt;
  Values v;
  v.bounds = !c;
  bool any = false;
  for (const auto& f : s.rows) {
    const double xv = parse_number(f[*cx], x);
    if (v.at.count(xv)) {
      throw io::InputError(s.path + ": a second design at " + x + " = " + f[*cx] +
                           " (chart reads one-parameter sweeps; filter the rows)");
    }
    double value = std::numeric_limits<double>::quiet_NaN(), half = 0.0;
    if (f[*cs] == "ok") {
      if (c && !f[*c].empty()) {
        value = parse_number(f[*c], name);
      } else if (!c && !f[*lo].empty() && !f[*hi].empty()) {
        const double a = parse_number(f[*lo], name + "_lower"), b = parse_number(f[*hi], name + "_upper");
        value = 0.5 * (a + b);
        half = 0.5 * (b - a);
      }
    }
    any = any || std::isfinite(value);
    v.at[xv] = {value, half};
  }
  if (!any) return std::nullopt;  // e.g. real_area of a sweep whose file has no bodies
  return v;
}

std::string cell(double v, double half) {
  if (!std::isfinite(v)) return "\u2013";
  char buf[64];
  const auto num = [&](double a) {
    std::snprintf(buf, sizeof buf, std::abs(a) >= 100.0 ? "%.0f" : "%.4g", a);
    return std::string(buf);
  };
  if (!(half > 0.0)) return num(v);
  // Values of 100 and more print as integers with the half-width rounded up so that the printed
  // v ± h still encloses the bounds; smaller ones with two significant digits of h.
  const std::string value = num(v);
  if (std::abs(v) >= 100.0) {
    std::snprintf(buf, sizeof buf, "%.0f", std::ceil(half + 0.5));  // + the rounding of v
  } else {
    std::snprintf(buf, sizeof buf, "%.2g", half);
  }
  return value + " \u00b1 " + buf;
}

}  // namespace

ChartReport chart(const ChartOptions& a) {
  if (!a.y_labels.empty() && a.y_labels.size() != a.ys.size()) {
    throw io::InputError("--y-label: give one per --y (" + std::to_string(a.ys.size()) + ")");
  }
  std::vector<double> marks;
  if (!a.marks.empty()) {
    std::size_t start = 0;
    while (start <= a.marks.size()) {
      const auto end = std::min(a.marks.find(',', start), a.marks.size());
      marks.push_back(parse_number(a.marks.substr(start, end - start), "--mark"));
      start = end + 1;
    }
  }
  std::vector<Sweep> sweeps;
  for (const auto& arg : a.csvs) sweeps.push_back(read_sweep(arg));
  ChartReport r;
  r.x = a.x;
  r.metrics = a.ys;
  r.output = a.output;
  r.markdown_output = a.markdown_output;
  for (const Sweep& s : sweeps) r.sweeps.push_back({s.path, s.label, {}});
  const std::string x_label = a.x_label.empty() ? a.x : a.x_label;

  io::PanelFigure fig;
  fig.title = a.title;
  fig.x_marks = marks;
  fig.marks_label = marks.empty() ? "" : a.marks_label;
  fig.caption = a.caption;
  std::string md;
  for (std::size_t k = 0; k < a.ys.size(); ++k) {
    const std::string& y = a.ys[k];
    const std::string y_label = a.y_labels.empty() ? y : a.y_labels[k];
    io::Panel panel;
    panel.title = y_label;
    panel.x_label = x_label;
    panel.y_label = y_label;
    std::vector<std::pair<const Sweep*, Values>> found;
    std::set<double> xs;
    for (const Sweep& s : sweeps) {
      if (auto v = values_of(s, a.x, y)) {
        r.sweeps[static_cast<std::size_t>(&s - sweeps.data())].metrics.push_back(y);
        for (const auto& [xv, _] : v->at) xs.insert(xv);
        found.emplace_back(&s, std::move(*v));
      }
    }
    if (found.empty()) throw io::InputError("--y: no file has values of '" + y + "' (or " + y + "_lower/_upper)");
    for (const auto& [s, v] : found) {
      io::PanelSeries series;
      series.label = s->label;
      for (const auto& [xv, value] : v.at) {
        series.x.push_back(xv);
        series.y.push_back(value.first);
      }
      panel.series.push_back(std::move(series));
    }
    fig.panels.push_back(std::move(panel));
    // Markdown: rows = files, columns = x values; marked x values in bold.
    const auto marked = [&](double xv) {
      return std::any_of(marks.begin(), marks.end(), [&](double m) { return std::abs(m - xv) <= 1e-9 * std::abs(m); });
    };
    md += (md.empty() ? "" : "\n") + std::string("#### ") + y_label +
          (found.front().second.bounds ? " (certified bounds: midpoint \u00b1 half-width)" : "") + "\n\n| " + x_label +
          " |";
    for (double xv : xs) {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%g", xv);
      md += std::string(" ") + (marked(xv) ? "**" + std::string(buf) + "**" : buf) + " |";
    }
    md += "\n|---|";
    for (std::size_t i = 0; i < xs.size(); ++i) md += "--:|";
    md += "\n";
    for (const auto& [s, v] : found) {
      md += "| " + s->label + " |";
      for (double xv : xs) {
        const auto it = v.at.find(xv);
        const std::string c = it == v.at.end() ? "\u2013" : cell(it->second.first, it->second.second);
        md += " " + (marked(xv) && c != "\u2013" ? "**" + c + "**" : c) + " |";
      }
      md += "\n";
    }
  }
  if (!a.output.empty()) {
    io::style_by_group(fig);
    try {
      r.svg = io::panel_chart_svg(fig);
    } catch (const std::invalid_argument& e) {
      throw io::InputError(std::string("chart: ") + e.what());
    }
  }
  if (!a.markdown_output.empty()) r.markdown = md;
  return r;
}

std::string to_json_text(const ChartReport& r) {
  Json sweeps = Json::array();
  for (const auto& s : r.sweeps) sweeps.push_back({{"csv", s.csv}, {"label", s.label}, {"metrics", s.metrics}});
  Json j{{"x", r.x}, {"metrics", r.metrics}, {"sweeps", sweeps}};
  const auto file = [&j](const char* key, const std::string& path, const char* option) {
    if (path.empty()) {
      j[key] = nullptr;
      j[std::string(key) + "_reason"] = std::string("no ") + option + " given";
    } else {
      j[key] = path;
    }
  };
  file("figure", r.output, "-o FIG.svg");
  file("markdown", r.markdown_output, "--markdown TABLE.md");
  return detail::json_text(std::move(j));
}

std::string to_text(const ChartReport& r) {
  std::string t;
  if (!r.output.empty()) t += r.output + "\n";
  if (!r.markdown_output.empty()) t += r.markdown_output + "\n";
  return t;
}

}  // namespace pkmws::report
