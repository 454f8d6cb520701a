#include "pkmws/design/sweep.hpp"

#include "pkmws/io/parameters.hpp"

#include <algorithm>
#include <boost/random/sobol.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <mutex>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "detail/parallel.hpp"
#include "design/spec_reading.hpp"
#include "io/json_reader.hpp"
#include "pkmws/bodies/bodies.hpp"
#include "io/document.hpp"
#include "pkmws/certified/cell_region.hpp"
#include "pkmws/criteria/fields.hpp"
#include "pkmws/design/gci.hpp"
#include "pkmws/geometry/inscribed.hpp"
#include "pkmws/geometry/inscribed_rectangle.hpp"
#include "pkmws/io/export.hpp"
#include "pkmws/io/mechanism_file.hpp"

namespace pkmws::design {

namespace {

using nlohmann::json;
using io::InputError;
using io::detail::JsonReader;

}  // namespace

namespace {

// Sets the number at `path` in `doc`; the field must be in the base file (a
// sweep varies what the file states; add an optional field there to vary it).
void set_path(json& doc, const std::string& path, double value, const std::string& where) {
  json& node = io::field_at(doc, path, where, "is not in the base file");
  if (!node.is_null() && !node.is_number()) throw InputError(where + ": '" + path + "' is not a number");
  node = value;
}

struct MetricInfo {
  std::string name;
  std::vector<std::string> columns;
};

const std::vector<MetricInfo>& metric_table() {
  static const std::vector<MetricInfo> table = {
      {"area", {"area", "area_lower", "area_upper"}},
      {"components", {"components"}},
      {"inscribed_circle", {"inscribed_circle_radius"}},
      {"inscribed_rectangle", {"rectangle_width", "rectangle_height", "rectangle_area", "rectangle_area_upper"}},
      {"inscribed_rectangle_any_angle",
       {"turned_rectangle_width", "turned_rectangle_height", "turned_rectangle_angle_deg", "turned_rectangle_area",
        "turned_rectangle_area_upper"}},
      {"task_fit", {"task_inside", "task_margin", "task_area_outside"}},
      {"limited_area", {"limited_area_lower", "limited_area_upper"}},
      {"real_area", {"real_area_lower", "real_area_upper"}},
      {"gci", {"gci", "gci_error"}},
      {"task_fit_limited", {"limited_task_inside", "limited_task_margin"}},
      {"task_fit_real", {"real_task_inside", "real_task_margin"}},
  };
  return table;
}

const MetricInfo& metric_info(const std::string& name) {
  for (const MetricInfo& m : metric_table()) {
    if (m.name == name) return m;
  }
  throw std::logic_error("unknown metric " + name);
}

double elapsed_ms(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

std::string format_number(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// CSV field: quoted when it holds a comma, a quote or a line break.
std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) {
    if (c == '"') out += '"';
    out += c == '\n' || c == '\r' ? ' ' : c;
  }
  return out + "\"";
}

std::optional<double> parse_number(const std::string& s) {
  if (s.empty()) return std::nullopt;
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (end != s.c_str() + s.size()) throw std::invalid_argument("not a number");
  return v;
}

}  // namespace

std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        cur += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        cur += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      out.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  out.push_back(cur);
  return out;
}

const std::vector<std::string>& metric_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const MetricInfo& m : metric_table()) n.push_back(m.name);
    return n;
  }();
  return names;
}

namespace reading {

json read_spec_file(const std::filesystem::path& file, const std::string& what) {
  std::ifstream in(file);
  if (!in) throw InputError(file.string() + ": cannot open the " + what + " file");
  json doc;
  try {
    doc = json::parse(in);
  } catch (const json::exception& e) {
    throw InputError(file.string() + ": not valid JSON (" + std::string(e.what()) + ")");
  }
  if (!doc.is_object()) throw InputError(file.string() + ": a " + what + " file is a JSON object");
  return doc;
}

json read_base(JsonReader& r, const std::filesystem::path& dir, SweepSpec& spec) {
  spec.base_file = dir / r.string("base");
  {
    std::ifstream base(spec.base_file);
    if (!base) throw InputError(r.field("base") + ": cannot open " + spec.base_file.string());
    std::stringstream ss;
    ss << base.rdbuf();
    spec.base_document = ss.str();
  }
  // The base must load on its own: its errors are the file's, not a design's.
  (void)io::load_mechanism(spec.base_file);
  return json::parse(spec.base_document);
}

void read_paths(JsonReader& p, json& base_doc, SweepParameter& sp) {
  const json& paths = p.raw("path");
  if (paths.is_string()) {
    sp.paths.push_back(paths.get<std::string>());
  } else if (paths.is_array() && !paths.empty() && std::all_of(paths.begin(), paths.end(), [](const json& v) {
               return v.is_string();
             })) {
    for (const json& v : paths) sp.paths.push_back(v.get<std::string>());
  } else {
    p.fail("path", "must be a field path or a non-empty array of field paths (tied parameters)");
  }
  for (const std::string& path : sp.paths) set_path(base_doc, path, 0.0, p.field("path"));  // path exists
  sp.name = p.has("name") ? p.string("name") : sp.paths.front();
}

void read_task(JsonReader& r, SweepSpec& spec) {
  if (!r.has("task")) return;
  JsonReader t = r.object("task");
  if (t.has("polygon")) {
    const json& poly = t.raw("polygon");
    if (!poly.is_array() || poly.size() < 3) t.fail("polygon", "must list at least 3 points [x, y]");
    for (std::size_t k = 0; k < poly.size(); ++k) {
      const std::string where = t.field(io::detail::item("polygon", k));
      if (!poly[k].is_array() || poly[k].size() != 2) throw InputError(where + ": must be a point [x, y]");
      spec.task.push_back({JsonReader::as_number(poly[k][0], where), JsonReader::as_number(poly[k][1], where)});
    }
  } else {
    const geometry::Point c = t.point("center");
    const std::vector<double> size = t.numbers("size", 2);
    if (!(size[0] > 0 && size[1] > 0)) t.fail("size", "must be positive");
    spec.task = {{c.x - size[0] / 2, c.y - size[1] / 2},
                 {c.x + size[0] / 2, c.y - size[1] / 2},
                 {c.x + size[0] / 2, c.y + size[1] / 2},
                 {c.x - size[0] / 2, c.y + size[1] / 2}};
  }
  t.finish();
}

void read_accuracy(JsonReader& r, SweepSpec& spec) {
  if (auto v = r.optional_positive("rectangle_precision")) spec.rectangle_precision = *v;
  if (auto v = r.optional_positive("criteria_tolerance")) spec.criteria_tolerance = *v;
  if (r.has("interference_depth")) {
    spec.interference_depth = r.integer("interference_depth");
    if (spec.interference_depth < 0 || spec.interference_depth > 12) r.fail("interference_depth", "must be 0 to 12");
  }
  if (r.has("gci_cells")) {
    spec.gci_cells = r.integer("gci_cells");
    if (spec.gci_cells < 2 || spec.gci_cells > 4096) r.fail("gci_cells", "must be 2 to 4096");
  }
}

nlohmann::json design_document(const SweepSpec& spec, const std::vector<double>& values) {
  json doc = json::parse(spec.base_document);
  for (std::size_t k = 0; k < spec.parameters.size() && k < values.size(); ++k) {
    for (const std::string& path : spec.parameters[k].paths) set_path(doc, path, values[k], path);
  }
  return doc;
}

}  // namespace reading

std::string metric_of_column(const std::string& column) {
  for (const MetricInfo& m : metric_table()) {
    if (std::find(m.columns.begin(), m.columns.end(), column) != m.columns.end()) return m.name;
  }
  return "";
}

const std::vector<std::string>& all_metric_columns() {
  static const std::vector<std::string> columns = [] {
    std::vector<std::string> c;
    for (const MetricInfo& m : metric_table()) c.insert(c.end(), m.columns.begin(), m.columns.end());
    return c;
  }();
  return columns;
}

SweepSpec load_sweep(const std::filesystem::path& file) {
  const json doc = reading::read_spec_file(file, "sweep");
  JsonReader r(doc, "");
  SweepSpec spec;
  json base_doc = reading::read_base(r, file.parent_path(), spec);

  const std::string sampling = r.has("sampling") ? r.one_of("sampling", {"grid", "sobol"}) : "grid";
  spec.sampling = sampling == "grid" ? SweepSpec::Sampling::grid : SweepSpec::Sampling::sobol;
  if (spec.sampling == SweepSpec::Sampling::sobol) {
    const int n = r.integer("samples");
    if (n < 1) r.fail("samples", "must be at least 1");
    spec.samples = static_cast<std::size_t>(n);
  }
  const json& params = r.raw("parameters");
  if (!params.is_array() || params.empty()) r.fail("parameters", "must be a non-empty array");
  for (std::size_t i = 0; i < params.size(); ++i) {
    const std::string where = io::detail::item("parameters", i);
    if (!params[i].is_object()) throw InputError(where + ": must be an object");
    JsonReader p(params[i], where);
    SweepParameter sp;
    reading::read_paths(p, base_doc, sp);
    if (spec.sampling == SweepSpec::Sampling::grid) {
      if (p.has("values")) {
        const json& v = p.raw("values");
        if (!v.is_array() || v.empty()) p.fail("values", "must be a non-empty array of numbers");
        for (std::size_t k = 0; k < v.size(); ++k) sp.values.push_back(JsonReader::as_number(v[k], p.field(io::detail::item("values", k))));
      } else {
        const double from = p.number("from"), to = p.number("to");
        const int steps = p.integer("steps");
        if (steps < 1) p.fail("steps", "must be at least 1");
        if (steps == 1 && from != to) p.fail("steps", "must be at least 2 when from != to");
        for (int k = 0; k < steps; ++k) sp.values.push_back(steps == 1 ? from : from + (to - from) * k / (steps - 1));
      }
    } else {
      sp.from = p.number("from");
      sp.to = p.number("to");
      if (!(sp.to > sp.from)) p.fail("to", "must be greater than from");
    }
    p.finish();
    spec.parameters.push_back(std::move(sp));
  }
  if (spec.sampling == SweepSpec::Sampling::sobol && spec.parameters.size() > 1000) {
    r.fail("parameters", "at most 1000 parameters with Sobol sampling");
  }
  if (r.has("metrics")) {
    const json& m = r.raw("metrics");
    if (!m.is_array() || m.empty()) r.fail("metrics", "must be a non-empty array of metric names");
    for (std::size_t k = 0; k < m.size(); ++k) {
      const std::string where = io::detail::item("metrics", k);
      if (!m[k].is_string()) throw InputError(where + ": must be a metric name");
      const std::string name = m[k].get<std::string>();
      const auto& names = metric_names();
      if (std::find(names.begin(), names.end(), name) == names.end()) {
        std::string list;
        for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
        throw InputError(where + ": unknown metric '" + name + "' (expected one of: " + list + ")");
      }
      if (std::find(spec.metrics.begin(), spec.metrics.end(), name) != spec.metrics.end()) {
        throw InputError(where + ": metric '" + name + "' listed twice");
      }
      spec.metrics.push_back(name);
    }
  } else {
    spec.metrics = {"area", "components", "inscribed_circle", "inscribed_rectangle"};
  }
  reading::read_task(r, spec);
  for (const char* m : {"task_fit", "task_fit_limited", "task_fit_real"}) {
    const bool wants_task = std::find(spec.metrics.begin(), spec.metrics.end(), m) != spec.metrics.end();
    if (wants_task && spec.task.empty()) r.fail("task", std::string("is required by the metric ") + m);
  }
  reading::read_accuracy(r, spec);
  r.finish();
  return spec;
}

std::size_t design_count(const SweepSpec& spec) {
  if (spec.sampling == SweepSpec::Sampling::sobol) return spec.samples;
  std::size_t n = 1;
  for (const SweepParameter& p : spec.parameters) n *= p.values.size();
  return n;
}

std::vector<double> design_values(const SweepSpec& spec, std::size_t index) {
  std::vector<double> v(spec.parameters.size());
  if (spec.sampling == SweepSpec::Sampling::grid) {
    for (std::size_t k = spec.parameters.size(); k-- > 0;) {
      const auto& values = spec.parameters[k].values;
      v[k] = values[index % values.size()];
      index /= values.size();
    }
    return v;
  }
  // The index-th point of the Sobol sequence (Joe-Kuo directions,
  // Boost.Random), counting the origin as point 0 as the sequence's
  // definition does (Boost starts after it), so that the first 2^m points
  // form a (t, m, s)-net.
  boost::random::sobol engine(static_cast<unsigned>(spec.parameters.size()));
  if (index > 0) engine.seed(index - 1);
  const double scale = std::ldexp(1.0, -64);  // outputs are 64-bit: [0, 2^64)
  for (std::size_t k = 0; k < v.size(); ++k) {
    const double u = index == 0 ? 0.0 : static_cast<double>(engine()) * scale;
    const SweepParameter& p = spec.parameters[k];
    v[k] = p.from + (p.to - p.from) * u;
  }
  return v;
}

std::vector<std::string> metric_columns(const SweepSpec& spec) {
  std::vector<std::string> cols;
  for (const std::string& m : spec.metrics) {
    for (const std::string& c : metric_info(m).columns) cols.push_back(c);
  }
  return cols;
}

DesignRow evaluate_design(const SweepSpec& spec, std::size_t index) {
  return evaluate_design(spec, index, design_values(spec, index));
}

DesignRow evaluate_design(const SweepSpec& spec, std::size_t index, const std::vector<double>& values) {
  const auto start = std::chrono::steady_clock::now();
  DesignRow row;
  row.index = index;
  row.values = values;
  row.metrics.assign(metric_columns(spec).size(), std::nullopt);
  const auto finish = [&](std::string status, std::string reason) {
    row.status = std::move(status);
    row.reason = std::move(reason);
    row.time_ms = elapsed_ms(start);
    return row;
  };
  io::MechanismFile file;
  try {
    file = io::parse_mechanism(reading::design_document(spec, row.values), "design " + std::to_string(index));
  } catch (const std::exception& e) {
    return finish("invalid", e.what());
  }
  try {
    const certified::CertifiedRegion enclosure = criteria::workspace_enclosure(file);
    if (enclosure.inner.empty() && enclosure.outer.empty()) return finish("empty", "the workspace is empty");
    // Exact: the region. Certified: areas of the enclosure, shapes inside its inner region.
    const geometry::Region& inside = enclosure.inner;
    const double min_area = inside.empty() ? 0.0 : io::effective_min_area(inside, {});
    const std::vector<geometry::Component> comps = inside.components(min_area);
    // The criteria-limited and the real workspace, computed once for the
    // metrics that need them.
    std::optional<criteria::LimitedWorkspace> limited;
    const auto limited_ws = [&]() -> const criteria::LimitedWorkspace& {
      if (!limited) {
        certified::LevelSetOptions o;
        o.relative_tolerance = spec.criteria_tolerance;
        limited = criteria::limited_workspace(file, criteria::file_limits(file), o);
      }
      return *limited;
    };
    // The inner enclosure of the limited workspace near the task: W's inside
    // ∩ the certified-inside cells at least 1/64 of the task's size that meet
    // the task's box widened by its size (the full enclosure, every cell as
    // exact Boolean operations, takes minutes). Smaller cells and the cells
    // traced across the level curve are left out: a smaller set than the full
    // inner enclosure, still inside the true one.
    std::optional<geometry::Region> limited_inner;
    const auto limited_inner_near_task = [&]() -> const geometry::Region& {
      if (!limited_inner) {
        geometry::Box window;
        for (const geometry::Point& p : spec.task) window.expand(p);
        const double d = std::max(window.width(), window.height());
        window.min = {window.min.x - d, window.min.y - d};
        window.max = {window.max.x + d, window.max.y + d};
        std::vector<geometry::Box> near;
        for (const geometry::Box& b : limited_ws().detail.inside_boxes) {
          if (b.width() >= d / 64 && b.max.x >= window.min.x && b.min.x <= window.max.x && b.max.y >= window.min.y &&
              b.min.y <= window.max.y) {
            near.push_back(b);
          }
        }
        limited_inner = near.empty() ? geometry::Region() : inside.intersect(certified::boxes_region(near));
      }
      return *limited_inner;
    };
    std::optional<bodies::RealWorkspace> real;
    const auto real_ws = [&]() -> const bodies::RealWorkspace& {
      if (!real) {
        bodies::InterferenceOptions o;
        o.max_depth = spec.interference_depth;
        o.threads = 1;  // the sweep is parallel over designs
        real = bodies::real_workspace(*file.bodies, enclosure.exact ? inside : enclosure.outer, o);
      }
      return *real;
    };
    std::size_t col = 0;
    for (const std::string& m : spec.metrics) {
      if (m == "area") {
        const double area = enclosure.exact ? inside.area() : enclosure.area_estimate();
        const double rounding = enclosure.exact ? 64 * std::numeric_limits<double>::epsilon() * area : 0.0;
        row.metrics[col++] = area;
        row.metrics[col++] = enclosure.exact ? area - rounding : enclosure.area_lower;
        row.metrics[col++] = enclosure.exact ? area + rounding : enclosure.area_upper;
      } else if (m == "components") {
        row.metrics[col++] = static_cast<double>((enclosure.exact ? inside : enclosure.outer).components(min_area).size());
      } else if (m == "inscribed_circle") {
        double best = 0.0;
        for (const auto& c : comps) {
          const double precision = 1e-5 * std::max(c.bbox.width(), c.bbox.height());  // as `pkmws area`
          best = std::max(best, geometry::largest_inscribed_circle(c, precision).radius);
        }
        row.metrics[col++] = best;
      } else if (m == "inscribed_rectangle" || m == "inscribed_rectangle_any_angle") {
        const bool turned = m == "inscribed_rectangle_any_angle";
        geometry::InscribedRectangle best;
        for (const auto& c : comps) {
          const auto r = turned ? geometry::largest_inscribed_rectangle_any_angle(c, spec.rectangle_precision, {}, &inside)
                                : geometry::largest_inscribed_rectangle(c, spec.rectangle_precision, {}, &inside);
          const double upper = std::max(best.area_upper, r.area_upper);
          if (r.area > best.area) best = r;
          best.area_upper = upper;
        }
        row.metrics[col++] = best.box.width();
        row.metrics[col++] = best.box.height();
        if (turned) row.metrics[col++] = best.angle * 180.0 / std::numbers::pi;
        row.metrics[col++] = best.area;
        row.metrics[col++] = best.area_upper;
      } else if (m == "task_fit") {
        const auto f = geometry::fit(inside, spec.task, 1e-9);
        row.metrics[col++] = f.inside ? 1.0 : 0.0;
        row.metrics[col++] = f.margin;
        row.metrics[col++] = f.area_outside;
      } else if (m == "limited_area") {
        if (file.criteria.any()) {
          row.metrics[col] = limited_ws().region.area_lower;
          row.metrics[col + 1] = limited_ws().region.area_upper;
        }
        col += 2;
      } else if (m == "real_area") {
        if (file.bodies) {
          row.metrics[col] = real_ws().real.area_lower;
          row.metrics[col + 1] = real_ws().real.area_upper;
        }
        col += 2;
      } else if (m == "task_fit_limited" || m == "task_fit_real") {
        // The task inside the certified inner enclosure: the criteria hold
        // on it (limited), no part collides anywhere on it (real).
        const bool lim = m == "task_fit_limited";
        if (lim ? file.criteria.any() : file.bodies != nullptr) {
          const auto f = geometry::fit(lim ? limited_inner_near_task() : real_ws().real.inner, spec.task, 1e-9);
          row.metrics[col] = f.inside ? 1.0 : 0.0;
          row.metrics[col + 1] = f.margin;
        }
        col += 2;
      } else if (m == "gci") {
        GciOptions o;
        o.cells = spec.gci_cells;
        const GciResult g = global_conditioning_index(*file.model, enclosure, o);
        if (g.value) {
          row.metrics[col] = *g.value;
          row.metrics[col + 1] = g.error;
        } else {
          row.reason = "gci: " + g.reason;  // status ok: the reason says why the column is empty
        }
        col += 2;
      }
    }
  } catch (const std::exception& e) {
    return finish("failed", e.what());
  }
  return finish("ok", row.reason);
}

std::vector<DesignRow> run_sweep(const SweepSpec& spec, const std::vector<std::size_t>& indices, int threads,
                                 const std::function<void(const DesignRow&)>& done) {
  std::vector<DesignRow> rows(indices.size());
  std::mutex mutex;
  detail::ParallelPolicy policy;
  policy.threads = threads;
  policy.serial_threshold = 2;  // one design is plenty of work for a task
  detail::for_each_block(policy, indices.size(), indices.size(), [&](std::size_t k) {
    rows[k] = evaluate_design(spec, indices[k]);
    if (done) {
      const std::lock_guard<std::mutex> lock(mutex);
      done(rows[k]);
    }
  });
  std::sort(rows.begin(), rows.end(), [](const DesignRow& a, const DesignRow& b) { return a.index < b.index; });
  return rows;
}

std::string csv_header(const SweepSpec& spec, bool timing) {
  std::string h = "index";
  for (const SweepParameter& p : spec.parameters) h += "," + csv_field(p.name);
  h += ",status";
  for (const std::string& c : metric_columns(spec)) h += "," + c;
  if (timing) h += ",time_ms";
  return h + ",reason";
}

std::string csv_line(const DesignRow& row, bool timing) {
  std::string s = std::to_string(row.index);
  for (double v : row.values) s += "," + format_number(v);
  s += "," + row.status;
  for (const auto& m : row.metrics) s += "," + (m ? format_number(*m) : std::string());
  if (timing) s += "," + format_number(std::round(row.time_ms * 1000.0) / 1000.0);
  return s + "," + csv_field(row.reason);
}

std::optional<DesignRow> parse_csv_line(const std::string& line, std::size_t parameters, std::size_t metrics,
                                        bool timing) {
  const std::vector<std::string> f = split_csv(line);
  if (f.size() != 1 + parameters + 1 + metrics + (timing ? 1 : 0) + 1) return std::nullopt;
  try {
    DesignRow row;
    std::size_t k = 0;
    const std::string& idx = f[k++];
    if (idx.empty() || !std::all_of(idx.begin(), idx.end(), [](char c) { return c >= '0' && c <= '9'; })) {
      return std::nullopt;
    }
    row.index = std::stoull(idx);
    for (std::size_t i = 0; i < parameters; ++i) {
      const auto v = parse_number(f[k++]);
      if (!v) return std::nullopt;
      row.values.push_back(*v);
    }
    row.status = f[k++];
    if (row.status != "ok" && row.status != "invalid" && row.status != "empty" && row.status != "failed") {
      return std::nullopt;
    }
    for (std::size_t i = 0; i < metrics; ++i) row.metrics.push_back(parse_number(f[k++]));
    if (timing) row.time_ms = parse_number(f[k++]).value_or(0.0);
    row.reason = f[k++];
    return row;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

}  // namespace pkmws::design
