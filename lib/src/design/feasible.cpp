#include "pkmws/design/feasible.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "pkmws/io/export.hpp"
#include "pkmws/io/mechanism_file.hpp"

namespace pkmws::design {

namespace {

using io::InputError;

std::string num(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string short_num(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}


}  // namespace

FeasibleSet feasible_set(const std::filesystem::path& csv, const std::vector<std::string>& conditions) {
  const std::string name = csv.string();
  std::ifstream in(csv);
  if (!in) throw InputError(name + ": cannot open");
  std::string line;
  if (!std::getline(in, line)) throw InputError(name + ": empty file");
  if (!line.empty() && line.back() == '\r') line.pop_back();
  const std::vector<std::string> header = split_csv(line);
  const auto status_it = std::find(header.begin(), header.end(), "status");
  if (header.size() < 3 || header.front() != "index" || status_it == header.end()) {
    throw InputError(name + ": not a pkmws sweep CSV (its header has no index and status columns)");
  }
  FeasibleSet set;
  const std::size_t status_col = static_cast<std::size_t>(status_it - header.begin());
  const std::size_t np = status_col - 1;
  if (np == 0) throw InputError(name + ": no parameter columns (between index and status)");
  if (np > 16) throw InputError(name + ": " + std::to_string(np) + " parameters; at most 16 for the cells' corners");
  set.parameters.assign(header.begin() + 1, header.begin() + static_cast<std::ptrdiff_t>(status_col));

  std::vector<std::size_t> condition_cols;
  for (std::size_t k = 0; k < conditions.size(); ++k) {
    Constraint c = parse_constraint(conditions[k], "--where");
    const auto it = std::find(header.begin(), header.end(), c.column);
    if (it == header.end() || c.column == "index" || c.column == "status" || c.column == "reason") {
      std::string cols;
      for (const auto& h : header) {
        if (h != "index" && h != "status" && h != "reason") cols += (cols.empty() ? "" : ", ") + h;
      }
      throw InputError("--where: no column '" + c.column + "' in " + name + " (columns: " + cols + ")");
    }
    condition_cols.push_back(static_cast<std::size_t>(it - header.begin()));
    set.conditions.push_back(std::move(c));
  }

  // Read the designs.
  const auto number = [&](const std::string& text, std::size_t at) -> std::optional<double> {
    if (text.empty()) return std::nullopt;
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (end != text.c_str() + text.size() || !std::isfinite(v)) {
      throw InputError(name + ":" + std::to_string(at) + ": '" + text + "' is not a number");
    }
    return v;
  };
  std::map<std::vector<double>, bool> designs;
  std::vector<std::set<double>> values(np);
  std::size_t at = 1;
  while (std::getline(in, line)) {
    ++at;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    const std::vector<std::string> f = split_csv(line);
    if (f.size() != header.size()) throw InputError(name + ":" + std::to_string(at) + ": malformed row");
    std::vector<double> p(np);
    for (std::size_t k = 0; k < np; ++k) {
      const auto v = number(f[k + 1], at);
      if (!v) throw InputError(name + ":" + std::to_string(at) + ": no value of " + set.parameters[k]);
      p[k] = *v;
      values[k].insert(*v);
    }
    bool ok = f[status_col] == "ok";
    for (std::size_t j = 0; ok && j < condition_cols.size(); ++j) {
      const auto v = number(f[condition_cols[j]], at);
      const Constraint& c = set.conditions[j];
      ok = v && (c.at_least ? *v >= c.bound : *v <= c.bound);
    }
    if (!designs.emplace(p, ok).second) {
      throw InputError(name + ":" + std::to_string(at) + ": a second design with the same parameter values");
    }
    set.points.push_back(p);
    set.point_feasible.push_back(ok);
    if (ok) ++set.feasible_designs;
  }
  set.designs = designs.size();
  std::size_t grid = 1;
  for (const auto& v : values) {
    set.values.emplace_back(v.begin(), v.end());
    grid *= v.size();
  }
  if (set.designs == 0) throw InputError(name + ": no designs");
  if (grid != set.designs) {
    throw InputError(name + ": not a full grid (" + std::to_string(set.designs) + " designs, " +
                     std::to_string(grid) + " combinations of the parameters' values): sweep with sampling grid");
  }

  // Cells: per parameter, the intervals between consecutive values (one
  // degenerate cell for a parameter with one value). Row-major, the first
  // parameter slowest, as the sweep's designs.
  std::vector<std::size_t> dims(np);
  for (std::size_t k = 0; k < np; ++k) dims[k] = std::max<std::size_t>(1, set.values[k].size() - 1);
  std::size_t count = 1;
  for (std::size_t d : dims) count *= d;
  set.cells = count;
  const auto unflatten = [&](std::size_t c) {
    std::vector<std::size_t> idx(np);
    for (std::size_t k = np; k-- > 0;) {
      idx[k] = c % dims[k];
      c /= dims[k];
    }
    return idx;
  };
  const auto flatten = [&](const std::vector<std::size_t>& idx) {
    std::size_t c = 0;
    for (std::size_t k = 0; k < np; ++k) c = c * dims[k] + idx[k];
    return c;
  };
  std::vector<char> cell_ok(count, 0);
  for (std::size_t c = 0; c < count; ++c) {
    const auto idx = unflatten(c);
    bool ok = true;
    for (std::size_t corner = 0; ok && corner < (std::size_t{1} << np); ++corner) {
      std::vector<double> p(np);
      for (std::size_t k = 0; k < np; ++k) {
        const std::size_t i = idx[k] + (set.values[k].size() > 1 && ((corner >> k) & 1) ? 1 : 0);
        p[k] = set.values[k][i];
      }
      ok = designs.at(p);
    }
    cell_ok[c] = ok ? 1 : 0;
    if (ok) ++set.feasible_cells;
  }

  // Greedy merge.
  std::vector<char> taken(count, 0);
  const auto slab_free = [&](const std::vector<std::size_t>& lo, const std::vector<std::size_t>& hi, std::size_t d,
                             std::size_t at_index) {
    // Every cell of the box [lo, hi] with coordinate d set to at_index.
    std::vector<std::size_t> idx = lo;
    idx[d] = at_index;
    while (true) {
      const std::size_t c = flatten(idx);
      if (!cell_ok[c] || taken[c]) return false;
      std::size_t k = np;
      while (k-- > 0) {
        if (k == d) continue;
        if (idx[k] < hi[k]) {
          ++idx[k];
          break;
        }
        idx[k] = lo[k];
      }
      if (k == static_cast<std::size_t>(-1)) return true;
    }
  };
  for (std::size_t c = 0; c < count; ++c) {
    if (!cell_ok[c] || taken[c]) continue;
    std::vector<std::size_t> lo = unflatten(c), hi = lo;
    for (std::size_t d = 0; d < np; ++d) {
      while (hi[d] + 1 < dims[d] && slab_free(lo, hi, d, hi[d] + 1)) ++hi[d];
    }
    FeasibleBox box;
    std::vector<std::size_t> idx = lo;
    while (true) {
      taken[flatten(idx)] = 1;
      ++box.cells;
      std::size_t k = np;
      while (k-- > 0) {
        if (idx[k] < hi[k]) {
          ++idx[k];
          break;
        }
        idx[k] = lo[k];
      }
      if (k == static_cast<std::size_t>(-1)) break;
    }
    for (std::size_t k = 0; k < np; ++k) {
      box.min.push_back(set.values[k][lo[k]]);
      box.max.push_back(set.values[k][set.values[k].size() > 1 ? hi[k] + 1 : 0]);
    }
    set.boxes.push_back(std::move(box));
  }
  return set;
}

std::string feasible_csv(const FeasibleSet& set) {
  std::string out = "box,cells";
  for (const auto& p : set.parameters) out += "," + p + "_min," + p + "_max";
  out += "\n";
  for (std::size_t b = 0; b < set.boxes.size(); ++b) {
    out += std::to_string(b) + "," + std::to_string(set.boxes[b].cells);
    for (std::size_t k = 0; k < set.parameters.size(); ++k) {
      out += "," + num(set.boxes[b].min[k]) + "," + num(set.boxes[b].max[k]);
    }
    out += "\n";
  }
  return out;
}

std::string feasible_report(const FeasibleSet& set, const std::string& csv) {
  using nlohmann::json;
  json conditions = json::array();
  for (const auto& c : set.conditions) {
    conditions.push_back({{"text", c.text}, {"column", c.column}, {"sense", c.at_least ? ">=" : "<="}, {"bound", c.bound}});
  }
  json boxes = json::array();
  for (const auto& b : set.boxes) {
    json mn = json::object(), mx = json::object();
    for (std::size_t k = 0; k < set.parameters.size(); ++k) {
      mn[set.parameters[k]] = b.min[k];
      mx[set.parameters[k]] = b.max[k];
    }
    boxes.push_back({{"min", mn}, {"max", mx}, {"cells", b.cells}});
  }
  json grid = json::array();
  for (std::size_t k = 0; k < set.parameters.size(); ++k) {
    grid.push_back({{"name", set.parameters[k]}, {"values", set.values[k]}});
  }
  const json j = {{"csv", csv},
                  {"parameters", grid},
                  {"conditions", conditions},
                  {"designs", set.designs},
                  {"feasible_designs", set.feasible_designs},
                  {"cells", set.cells},
                  {"feasible_cells", set.feasible_cells},
                  {"boxes", boxes},
                  {"sampled", "a cell is feasible when its corner designs are; not certified between samples"}};
  return j.dump(1);
}

std::string feasible_figure(const FeasibleSet& set) {
  if (set.parameters.size() != 2) throw std::invalid_argument("a figure needs a sweep over two parameters");
  const double W = 640, H = 480, left = 80, right = 20, top = 40, bottom = 60;
  const auto& xs = set.values[0];
  const auto& ys = set.values[1];
  const double x0 = xs.front(), x1 = xs.back() > xs.front() ? xs.back() : xs.front() + 1;
  const double y0 = ys.front(), y1 = ys.back() > ys.front() ? ys.back() : ys.front() + 1;
  const auto px = [&](double x) { return left + (x - x0) / (x1 - x0) * (W - left - right); };
  const auto py = [&](double y) { return H - bottom - (y - y0) / (y1 - y0) * (H - top - bottom); };
  std::ostringstream s;
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H << "\" viewBox=\"0 0 " << W
    << " " << H << "\" font-family=\"sans-serif\" font-size=\"12\">\n";
  s << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  std::string title = "feasible designs";
  for (std::size_t k = 0; k < set.conditions.size(); ++k) title += (k ? ", " : ": ") + set.conditions[k].text;
  s << "<text x=\"" << W / 2 << "\" y=\"22\" text-anchor=\"middle\" font-size=\"14\">" << io::xml_escape(title)
    << "</text>\n";
  s << "<g class=\"boxes\" fill=\"#a6dba0\" stroke=\"#1b7837\" stroke-width=\"1\">\n";
  for (const auto& b : set.boxes) {
    const double bx = px(b.min[0]), by = py(b.max[1]);
    s << "<rect x=\"" << bx << "\" y=\"" << by << "\" width=\"" << std::max(1.0, px(b.max[0]) - bx) << "\" height=\""
      << std::max(1.0, py(b.min[1]) - by) << "\"/>\n";
  }
  s << "</g>\n<g class=\"designs\">\n";
  for (std::size_t i = 0; i < set.points.size(); ++i) {
    s << "<circle cx=\"" << px(set.points[i][0]) << "\" cy=\"" << py(set.points[i][1]) << "\" r=\"2.5\" fill=\""
      << (set.point_feasible[i] ? "#1b7837" : "#b2182b") << "\"/>\n";
  }
  s << "</g>\n<g class=\"axes\" stroke=\"black\" fill=\"none\">\n";
  s << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << W - left - right << "\" height=\""
    << H - top - bottom << "\"/>\n</g>\n<g class=\"ticks\">\n";
  const auto ticks = [](const std::vector<double>& v) {
    std::vector<double> t;
    const std::size_t step = std::max<std::size_t>(1, v.size() / 6);
    for (std::size_t i = 0; i < v.size(); i += step) t.push_back(v[i]);
    if (t.back() != v.back()) t.push_back(v.back());
    return t;
  };
  for (double x : ticks(xs)) {
    s << "<text x=\"" << px(x) << "\" y=\"" << H - bottom + 16 << "\" text-anchor=\"middle\">" << short_num(x)
      << "</text>\n";
  }
  for (double y : ticks(ys)) {
    s << "<text x=\"" << left - 6 << "\" y=\"" << py(y) + 4 << "\" text-anchor=\"end\">" << short_num(y)
      << "</text>\n";
  }
  s << "</g>\n";
  s << "<text x=\"" << (left + W - right) / 2 << "\" y=\"" << H - 16 << "\" text-anchor=\"middle\">"
    << io::xml_escape(set.parameters[0]) << "</text>\n";
  s << "<text transform=\"translate(18," << (top + H - bottom) / 2 << ") rotate(-90)\" text-anchor=\"middle\">"
    << io::xml_escape(set.parameters[1]) << "</text>\n";
  s << "</svg>\n";
  return s.str();
}

}  // namespace pkmws::design
