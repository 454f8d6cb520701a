// pkmws._pkmws: the Python extension (pybind11) behind python/pkmws/__init__.py.
// It uses the public headers only (no CGAL): io::load_mechanism / parse_mechanism_text,
// the abstract Mechanism interface, geometry::Region and its helpers, io exports,
// design sweeps and the criteria functions taking a MechanismFile.
//
// Units: lengths in the mechanism file's unit; every angle in radians (poses,
// angle joints, pressure angles). Input errors are io::InputError, which the
// module turns into ValueError with the command line's one-line message.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "pkmws/criteria/fields.hpp"
#include "pkmws/design/optimize.hpp"
#include "pkmws/design/sweep.hpp"
#include "pkmws/geometry/inscribed.hpp"
#include "pkmws/geometry/inscribed_rectangle.hpp"
#include "pkmws/geometry/polyline.hpp"
#include "pkmws/geometry/region.hpp"
#include "pkmws/grid/sampler.hpp"
#include "pkmws/io/export.hpp"
#include "pkmws/io/mechanism_file.hpp"
#include "pkmws/io/parameters.hpp"
#include "pkmws/mechanisms/mechanism.hpp"
#include "pkmws/pkmws.hpp"
#include "pkmws/report/area.hpp"

namespace py = pybind11;

namespace {

using namespace pkmws;
using geometry::Point;
using io::InputError;
using File = std::shared_ptr<const io::MechanismFile>;
using Clock = std::chrono::steady_clock;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kDeg = std::numbers::pi / 180.0;

// ---------------------------------------------------------------- helpers

// A model call that fails with something other than InputError (e.g. a
// mechanism without a planar workspace): the CLI's one line, naming the file.
template <class F>
auto guarded(const io::MechanismFile& file, F&& fn) -> decltype(fn()) {
  try {
    return fn();
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(file.path + ": " + e.what());
  }
}


py::tuple point_py(Point p) { return py::make_tuple(p.x, p.y); }

py::object box_py(const geometry::Box& b) {
  if (b.empty()) return py::none();
  return py::make_tuple(point_py(b.min), point_py(b.max));
}

double finite(double v, const char* what) {
  if (!std::isfinite(v)) throw InputError(std::string(what) + ": must be a finite number");
  return v;
}

// An (N, k) float64 view of any array-like (any dtype convertible to float,
// any strides); `widths` lists the accepted k.
py::array_t<double> as_matrix(const py::handle& obj, const char* what, std::vector<py::ssize_t> widths) {
  auto arr = py::array_t<double, py::array::forcecast>::ensure(obj);
  std::string expected;
  for (std::size_t k = 0; k < widths.size(); ++k) {
    expected += (k ? " or (N, " : "(N, ") + std::to_string(widths[k]) + ")";
  }
  if (!arr) throw InputError(std::string(what) + ": expected a numeric array of shape " + expected);
  if (arr.ndim() != 2 || std::find(widths.begin(), widths.end(), arr.shape(1)) == widths.end()) {
    std::string shape = "(";
    for (py::ssize_t d = 0; d < arr.ndim(); ++d) shape += (d ? ", " : "") + std::to_string(arr.shape(d));
    if (arr.ndim() == 1) shape += ",";
    throw InputError(std::string(what) + ": expected an array of shape " + expected + ", got " + shape + ")");
  }
  return arr;
}

py::array_t<double> new_matrix(py::ssize_t rows, py::ssize_t cols) {
  return py::array_t<double>(std::vector<py::ssize_t>{rows, cols});
}

// ---------------------------------------------------------------- regions

struct PyRegion {
  geometry::Region region;
  std::string units;  // the file's length unit ("" when unknown)
};

io::ExportOptions export_options(const PyRegion& r, std::optional<double> tolerance) {
  io::ExportOptions o;
  o.units = r.units;
  if (tolerance) {
    if (!(*tolerance > 0.0) || !std::isfinite(*tolerance)) throw InputError("tolerance: must be a positive number");
    o.tolerance = *tolerance;
  }
  return o;
}

py::array_t<double> points_array(const std::vector<Point>& pts) {
  auto out = new_matrix(static_cast<py::ssize_t>(pts.size()), 2);
  auto m = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < pts.size(); ++i) {
    m(static_cast<py::ssize_t>(i), 0) = pts[i].x;
    m(static_cast<py::ssize_t>(i), 1) = pts[i].y;
  }
  return out;
}

double default_tolerance(const geometry::Region& region) { return io::effective_tolerance(region, {}); }

py::dict geo_interface(const PyRegion& r, std::optional<double> tolerance) {
  const io::ExportOptions o = export_options(r, tolerance);
  if (!r.region.empty()) io::check_tolerance(r.region, o);
  std::vector<io::ExportPolygon> polys;
  {
    py::gil_scoped_release release;
    if (!r.region.empty()) polys = io::export_polygons(r.region, o);
  }
  const auto ring = [](const std::vector<Point>& pts) {
    py::list l;
    for (const Point& p : pts) l.append(point_py(p));
    return l;
  };
  py::list coords;
  for (const auto& p : polys) {
    py::list poly;
    poly.append(ring(p.shell));
    for (const auto& h : p.holes) poly.append(ring(h));
    coords.append(poly);
  }
  py::dict d;
  d["type"] = "MultiPolygon";
  d["coordinates"] = coords;
  return d;
}

py::object write_or_return(const std::string& text, const std::optional<std::string>& path) {
  if (!path) return py::str(text);
  io::write_file_atomic(*path, text);
  return py::none();
}

py::dict circle_py(const geometry::InscribedCircle& c, std::size_t component) {
  py::dict d;
  d["center"] = point_py(c.center);
  d["radius"] = c.radius;
  d["radius_upper"] = c.radius_upper;
  d["component"] = component;
  return d;
}

py::dict rectangle_py(const geometry::InscribedRectangle& r, std::size_t component) {
  py::dict d;
  d["min"] = point_py(r.box.min);
  d["max"] = point_py(r.box.max);
  d["width"] = r.box.width();
  d["height"] = r.box.height();
  d["area"] = r.area;
  d["area_upper"] = r.area_upper;
  d["verified"] = r.verified;
  d["component"] = component;
  if (r.orientations > 0) {  // at any orientation: min/max are in the frame turned by the angle
    d["angle"] = r.angle;
    py::list corners;
    for (const auto& p : r.corners()) corners.append(point_py(p));
    d["corners"] = corners;
  }
  return d;
}

py::object contains(const PyRegion& r, const py::handle& points) {
  // A single point (x, y) gives a bool; an (N, 2) array a bool array.
  auto flat = py::array_t<double, py::array::forcecast>::ensure(points);
  if (flat && flat.ndim() == 1 && flat.shape(0) == 2) {
    const Point p{flat.at(0), flat.at(1)};
    py::gil_scoped_release release;
    return py::bool_(r.region.contains(p));
  }
  const auto arr = as_matrix(points, "points", {2});
  const py::ssize_t n = arr.shape(0);
  py::array_t<bool> out(n);
  auto in = arr.unchecked<2>();
  auto o = out.mutable_unchecked<1>();
  {
    py::gil_scoped_release release;
    for (py::ssize_t i = 0; i < n; ++i) o(i) = r.region.contains({in(i, 0), in(i, 1)});
  }
  return out;
}

template <class Op>
PyRegion boolean(const PyRegion& a, const PyRegion& b, Op op) {
  py::gil_scoped_release release;
  return PyRegion{op(a.region, b.region), a.units.empty() ? b.units : a.units};
}

// ---------------------------------------------------------------- mechanisms

struct PyMechanism {
  File file;
  const mechanisms::Mechanism& model() const { return *file->model; }
};

File load_path(const std::string& path) {
  return std::make_shared<const io::MechanismFile>(io::load_mechanism(path));
}

File load_document(const std::string& text, const std::string& origin) {
  return std::make_shared<const io::MechanismFile>(io::parse_mechanism_text(text, origin));
}

// The numbers at field paths of the file ("legs[1].rod_length").
py::object get_parameter(const PyMechanism& m, const std::string& path) {
  const io::Parameter p = io::parameter_info(*m.file, path);
  if (p.type == "integer") return py::int_(static_cast<std::int64_t>(p.value));
  return py::float_(p.value);
}

// A new mechanism: the file's document with the values set, validated by the
// loader (its one-line messages, naming the file).
PyMechanism with_parameters(const PyMechanism& m, const py::dict& values) {
  std::vector<std::pair<std::string, double>> set;
  for (const auto& [key, value] : values) {
    const std::string path = py::str(key);
    if (py::isinstance<py::bool_>(value)) {
      throw InputError(m.file->path + ": '" + path + "': expected a number, got a bool");
    }
    try {
      set.emplace_back(path, py::float_(py::reinterpret_borrow<py::object>(value)).cast<double>());
    } catch (const py::error_already_set&) {
      throw InputError(m.file->path + ": '" + path + "': expected a number");
    }
  }
  File file = std::make_shared<const io::MechanismFile>(io::with_parameters(*m.file, set));
  return PyMechanism{std::move(file)};
}

mechanisms::Pose make_pose(const PyMechanism& m, double x, double y, std::optional<double> phi) {
  mechanisms::Pose p;
  p.x = finite(x, "x");
  p.y = finite(y, "y");
  p.phi = phi ? finite(*phi, "phi") : m.model().orientation();
  return p;
}

py::list joint_list(const std::vector<double>& q) {
  py::list l;
  for (double v : q) l.append(v);
  return l;
}

py::list inverse(const PyMechanism& m, double x, double y, std::optional<double> phi) {
  const auto pose = make_pose(m, x, y, phi);
  std::vector<mechanisms::JointSolution> sols;
  {
    py::gil_scoped_release release;
    sols = guarded(*m.file, [&] { return m.model().inverse(pose); });
  }
  py::list out;
  for (const auto& s : sols) {
    py::dict d;
    d["mode"] = s.mode;
    d["joints"] = joint_list(s.joints);
    d["valid"] = s.valid;
    d["reason"] = s.reason;
    out.append(d);
  }
  return out;
}

std::vector<double> joint_values(const PyMechanism& m, const py::handle& q) {
  const auto arr = py::array_t<double, py::array::forcecast>::ensure(q);
  const int dof = m.model().dof();
  if (!arr || arr.ndim() != 1 || arr.shape(0) != dof) {
    throw InputError("q: expected " + std::to_string(dof) + " joint value" + (dof == 1 ? "" : "s"));
  }
  std::vector<double> v(static_cast<std::size_t>(dof));
  for (int k = 0; k < dof; ++k) v[static_cast<std::size_t>(k)] = finite(arr.at(k), "q");
  return v;
}

py::list direct(const PyMechanism& m, const py::handle& q) {
  const auto joints = joint_values(m, q);
  std::vector<mechanisms::PoseSolution> sols;
  {
    py::gil_scoped_release release;
    sols = guarded(*m.file, [&] { return m.model().direct(joints); });
  }
  py::list out;
  for (const auto& s : sols) {
    py::dict d;
    d["mode"] = s.mode;
    d["pose"] = py::make_tuple(s.pose.x, s.pose.y, s.pose.phi);
    py::list pts;
    for (const Point& p : s.platform_points) pts.append(point_py(p));
    d["platform_points"] = pts;
    d["valid"] = s.valid;
    d["reason"] = s.reason;
    out.append(d);
  }
  return out;
}

// Mechanism-specific figures: names ending in _deg (or holding _deg_) are
// converted to radians and renamed (_rad), so that every angle is in radians.
std::pair<std::string, double> extra_in_radians(const std::string& name, double value) {
  const std::string suffix = "_deg";
  if (name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0) {
    return {name.substr(0, name.size() - suffix.size()), value * kDeg};
  }
  if (const auto at = name.find("_deg_"); at != std::string::npos) {
    return {name.substr(0, at) + "_rad_" + name.substr(at + 5), value * kDeg};
  }
  return {name, value};
}

py::dict evaluation_py(const mechanisms::Evaluation& e) {
  py::dict d;
  d["mode"] = e.mode;
  d["reachable"] = e.reachable;
  d["reason"] = e.reason;
  d["joints"] = joint_list(e.joints);
  d["jacobian_det"] = e.jacobian_det;
  d["condition_number"] = e.condition_number;
  d["singular"] = e.singular;
  d["singularity"] = e.singularity;
  py::list pa;
  for (double a : e.pressure_angle_deg) pa.append(a * kDeg);
  d["pressure_angle"] = pa;
  d["reactions_N"] = joint_list(e.reactions_N);
  d["velocity_ratio"] = e.velocity_ratio ? py::object(py::float_(*e.velocity_ratio)) : py::none();
  py::dict extra;
  for (const auto& [name, value] : e.extra) {
    const auto [n, v] = extra_in_radians(name, value);
    extra[py::str(n)] = v;
  }
  d["extra"] = extra;
  return d;
}

py::list evaluate_modes(const PyMechanism& m, double x, double y, std::optional<double> phi) {
  const auto pose = make_pose(m, x, y, phi);
  std::vector<mechanisms::Evaluation> evs;
  {
    py::gil_scoped_release release;
    evs = guarded(*m.file, [&] { return m.model().evaluate(pose, m.file->criteria); });
  }
  py::list out;
  for (const auto& e : evs) out.append(evaluation_py(e));
  return out;
}

// Poses from an (N, 2) or (N, 3) array: phi from the third column, else the
// file's orientation. Read without the GIL (plain memory).
struct PoseRows {
  py::array_t<double> arr;
  double orientation = 0.0;
  py::ssize_t size() const { return arr.shape(0); }
};
PoseRows pose_rows(const PyMechanism& m, const py::handle& poses) {
  return PoseRows{as_matrix(poses, "poses", {2, 3}), m.model().orientation()};
}

py::tuple inverse_many(const PyMechanism& m, const py::handle& poses) {
  const auto rows = pose_rows(m, poses);
  const py::ssize_t n = rows.size(), dof = m.model().dof();
  auto joints = new_matrix(n, dof);
  py::array_t<bool> valid(n);
  auto in = rows.arr.unchecked<2>();
  auto q = joints.mutable_unchecked<2>();
  auto ok = valid.mutable_unchecked<1>();
  const bool has_phi = rows.arr.shape(1) == 3;
  {
    py::gil_scoped_release release;
    guarded(*m.file, [&] {
      for (py::ssize_t i = 0; i < n; ++i) {
        const mechanisms::Pose pose{in(i, 0), in(i, 1), has_phi ? in(i, 2) : rows.orientation};
        const auto sols = m.model().inverse(pose);
        const mechanisms::JointSolution* s = sols.empty() ? nullptr : &sols.front();
        for (py::ssize_t k = 0; k < dof; ++k) {
          q(i, k) = s && static_cast<std::size_t>(k) < s->joints.size() ? s->joints[static_cast<std::size_t>(k)]
                                                                         : kNaN;
        }
        ok(i) = s && s->valid;
      }
      return 0;
    });
  }
  return py::make_tuple(joints, valid);
}

py::tuple direct_many(const PyMechanism& m, const py::handle& q) {
  const py::ssize_t dof = m.model().dof();
  const auto arr = as_matrix(q, "q", {dof});
  const py::ssize_t n = arr.shape(0);
  auto poses = new_matrix(n, 3);
  py::array_t<bool> valid(n);
  auto in = arr.unchecked<2>();
  auto out = poses.mutable_unchecked<2>();
  auto ok = valid.mutable_unchecked<1>();
  {
    py::gil_scoped_release release;
    guarded(*m.file, [&] {
      std::vector<double> joints(static_cast<std::size_t>(dof));
      for (py::ssize_t i = 0; i < n; ++i) {
        for (py::ssize_t k = 0; k < dof; ++k) joints[static_cast<std::size_t>(k)] = in(i, k);
        const mechanisms::PoseSolution* found = nullptr;
        const auto sols = m.model().direct(joints);
        for (const auto& s : sols) {
          if (s.valid) {
            found = &s;
            break;
          }
        }
        out(i, 0) = found ? found->pose.x : kNaN;
        out(i, 1) = found ? found->pose.y : kNaN;
        out(i, 2) = found ? found->pose.phi : kNaN;
        ok(i) = found != nullptr;
      }
      return 0;
    });
  }
  return py::make_tuple(poses, valid);
}

py::dict evaluate_many(const PyMechanism& m, const py::handle& poses) {
  const auto rows = pose_rows(m, poses);
  const py::ssize_t n = rows.size();
  const bool has_phi = rows.arr.shape(1) == 3;
  auto in = rows.arr.unchecked<2>();
  std::vector<mechanisms::Evaluation> evs(static_cast<std::size_t>(n));
  {
    py::gil_scoped_release release;
    guarded(*m.file, [&] {
      for (py::ssize_t i = 0; i < n; ++i) {
        const mechanisms::Pose pose{in(i, 0), in(i, 1), has_phi ? in(i, 2) : rows.orientation};
        auto e = m.model().evaluate(pose, m.file->criteria);
        if (!e.empty()) evs[static_cast<std::size_t>(i)] = std::move(e.front());
      }
      return 0;
    });
  }
  std::size_t legs = 0;
  for (const auto& e : evs) legs = std::max(legs, e.pressure_angle_deg.size());
  py::array_t<bool> reachable(n), singular(n);
  py::array_t<double> det(n), cond(n), ratio(n);
  auto pa = new_matrix(n, static_cast<py::ssize_t>(legs));
  auto r = reachable.mutable_unchecked<1>();
  auto s = singular.mutable_unchecked<1>();
  auto d = det.mutable_unchecked<1>();
  auto c = cond.mutable_unchecked<1>();
  auto v = ratio.mutable_unchecked<1>();
  auto a = pa.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < n; ++i) {
    const auto& e = evs[static_cast<std::size_t>(i)];
    r(i) = e.reachable;
    s(i) = e.singular;
    d(i) = e.reachable ? e.jacobian_det : kNaN;
    c(i) = e.reachable ? e.condition_number : kNaN;
    v(i) = e.reachable && e.velocity_ratio ? *e.velocity_ratio : kNaN;
    for (std::size_t k = 0; k < legs; ++k) {
      a(i, static_cast<py::ssize_t>(k)) =
          e.reachable && k < e.pressure_angle_deg.size() ? e.pressure_angle_deg[k] * kDeg : kNaN;
    }
  }
  py::dict out;
  out["reachable"] = reachable;
  out["jacobian_det"] = det;
  out["condition_number"] = cond;
  out["singular"] = singular;
  out["pressure_angle"] = pa;
  out["velocity_ratio"] = ratio;
  return out;
}

py::object reachable(const PyMechanism& m, const py::handle& poses) {
  auto flat = py::array_t<double, py::array::forcecast>::ensure(poses);
  if (flat && flat.ndim() == 1 && (flat.shape(0) == 2 || flat.shape(0) == 3)) {
    const mechanisms::Pose pose{flat.at(0), flat.at(1), flat.shape(0) == 3 ? flat.at(2) : m.model().orientation()};
    return py::bool_(guarded(*m.file, [&] { return m.model().reachable(pose); }));
  }
  const auto rows = pose_rows(m, poses);
  const py::ssize_t n = rows.size();
  const bool has_phi = rows.arr.shape(1) == 3;
  py::array_t<bool> out(n);
  auto in = rows.arr.unchecked<2>();
  auto o = out.mutable_unchecked<1>();
  {
    py::gil_scoped_release release;
    guarded(*m.file, [&] {
      for (py::ssize_t i = 0; i < n; ++i) {
        o(i) = m.model().reachable({in(i, 0), in(i, 1), has_phi ? in(i, 2) : rows.orientation});
      }
      return 0;
    });
  }
  return out;
}

// The front door's workspace, as `pkmws area` takes it (errors name the file).
certified::CertifiedRegion enclosure(const PyMechanism& m) {
  py::gil_scoped_release release;
  return pkmws::workspace(*m.file);
}

PyRegion workspace_region(const PyMechanism& m, std::optional<std::string> bound) {
  const certified::CertifiedRegion e = enclosure(m);
  if (bound && *bound != "inner" && *bound != "outer") {
    throw InputError("bound: expected 'inner' or 'outer', got '" + *bound + "'");
  }
  if (!e.exact && !bound) {
    throw InputError(m.file->path + ": the workspace is certified, not exact (its boundary is not made of arcs "
                                    "and segments): pass bound='inner' or bound='outer'");
  }
  const bool outer = bound && *bound == "outer";
  return PyRegion{outer ? e.outer : e.inner, m.file->units};
}

py::tuple workspace_area_bounds(const PyMechanism& m) {
  const certified::CertifiedRegion e = enclosure(m);
  if (e.exact) {
    // As `pkmws area`: the double rounding of Green's theorem on the exact boundary.
    const report::AreaBounds b = report::exact_area_bounds(e.inner.area());
    return py::make_tuple(b.lower, b.upper);
  }
  return py::make_tuple(e.area_lower, e.area_upper);
}

// The criteria-limited workspace as `pkmws area` and `export` compute it (the report layer).
criteria::LimitedWorkspace limited(const PyMechanism& m, double tolerance, bool regions, int threads) {
  report::LimitedOptions o;
  o.tolerance = tolerance;
  o.build_regions = regions;
  o.threads = threads;
  py::gil_scoped_release release;
  return guarded(*m.file, [&] { return report::limited_workspace(*m.file, o); });
}

py::dict drawing(const PyMechanism& m, double x, double y, std::optional<double> phi) {
  const auto pose = make_pose(m, x, y, phi);
  const mechanisms::Drawing dr = guarded(*m.file, [&] { return m.model().draw(pose); });
  const auto segments = [](const std::vector<mechanisms::Drawing::Segment>& s) {
    py::list l;
    for (const auto& seg : s) l.append(py::make_tuple(point_py(seg.a), point_py(seg.b)));
    return l;
  };
  const auto points = [](const std::vector<Point>& pts) {
    py::list l;
    for (const Point& p : pts) l.append(point_py(p));
    return l;
  };
  py::dict d;
  d["guides"] = segments(dr.guides);
  d["links"] = segments(dr.links);
  d["joints"] = points(dr.joints);
  d["sliders"] = points(dr.sliders);
  d["base_points"] = points(dr.base_points);
  d["tool"] = point_py(dr.tool);
  d["platform"] = points(dr.platform);
  py::list curves;
  for (const auto& c : dr.singular_curves) curves.append(points_array(c));
  d["singular_curves"] = curves;
  return d;
}

// ---------------------------------------------------------------- sweeps

py::tuple run_sweep(const std::string& spec_file, int threads) {
  const design::SweepSpec spec = design::load_sweep(spec_file);
  std::vector<std::size_t> indices(design::design_count(spec));
  for (std::size_t i = 0; i < indices.size(); ++i) indices[i] = i;
  std::vector<design::DesignRow> rows;
  {
    py::gil_scoped_release release;
    rows = design::run_sweep(spec, indices, threads);
  }
  std::vector<std::string> columns{"index"};
  for (const auto& p : spec.parameters) columns.push_back(p.name);
  columns.push_back("status");
  const auto metrics = design::metric_columns(spec);
  columns.insert(columns.end(), metrics.begin(), metrics.end());
  columns.push_back("time_ms");
  columns.push_back("reason");
  py::list out;
  for (const auto& row : rows) {
    py::dict d;
    d["index"] = row.index;
    for (std::size_t k = 0; k < spec.parameters.size(); ++k) d[py::str(spec.parameters[k].name)] = row.values[k];
    d["status"] = row.status;
    for (std::size_t k = 0; k < metrics.size(); ++k) {
      d[py::str(metrics[k])] = row.metrics[k] ? py::object(py::float_(*row.metrics[k])) : py::none();
    }
    d["time_ms"] = row.time_ms;
    d["reason"] = row.reason;
    out.append(d);
  }
  return py::make_tuple(columns, out);
}

// ---------------------------------------------------------------- benchmarks

// Seconds per call of the C++ loops the vectorised methods run (no Python).
double time_contains(const PyRegion& r, const py::handle& points) {
  const auto arr = as_matrix(points, "points", {2});
  auto in = arr.unchecked<2>();
  const py::ssize_t n = arr.shape(0);
  py::gil_scoped_release release;
  std::size_t inside = 0;
  const auto start = Clock::now();
  for (py::ssize_t i = 0; i < n; ++i) inside += r.region.contains({in(i, 0), in(i, 1)}) ? 1 : 0;
  const double s = std::chrono::duration<double>(Clock::now() - start).count();
  volatile std::size_t sink = inside;
  (void)sink;
  return n > 0 ? s / static_cast<double>(n) : 0.0;
}

// Seconds per pose of `per_pose(pose) -> count` over the poses, the loop a
// vectorised method runs, without the arrays.
template <class PerPose>
double time_pose_loop(const PyMechanism& m, const py::handle& poses, PerPose&& per_pose) {
  const auto rows = pose_rows(m, poses);
  const py::ssize_t n = rows.size();
  const bool has_phi = rows.arr.shape(1) == 3;
  auto in = rows.arr.unchecked<2>();
  py::gil_scoped_release release;
  std::size_t count = 0;
  const auto start = Clock::now();
  guarded(*m.file, [&] {
    for (py::ssize_t i = 0; i < n; ++i) {
      count += per_pose(mechanisms::Pose{in(i, 0), in(i, 1), has_phi ? in(i, 2) : rows.orientation});
    }
    return 0;
  });
  const double s = std::chrono::duration<double>(Clock::now() - start).count();
  volatile std::size_t sink = count;
  (void)sink;
  return n > 0 ? s / static_cast<double>(n) : 0.0;
}

// The loop inverse_many runs.
double time_inverse(const PyMechanism& m, const py::handle& poses) {
  return time_pose_loop(m, poses, [&m](const mechanisms::Pose& p) { return m.model().inverse(p).size(); });
}

// The loop evaluate_many runs (file's working mode first).
double time_evaluate(const PyMechanism& m, const py::handle& poses) {
  return time_pose_loop(m, poses,
                        [&m](const mechanisms::Pose& p) { return m.model().evaluate(p, m.file->criteria).size(); });
}

// ---------------------------------------------------------------- grid samplers

// The grid baseline (`pkmws grid`): one sampler run as a dict of the
// SampleResult fields (areas in unit², times in ms); `mask=True` adds the
// cell mask as a uint8 array (cartesian: (cells_y, cells_x), y upwards;
// polar: (rings, sectors)). Criteria files sample their limited workspace,
// as the command line does.
py::dict grid_sample(const PyMechanism& m, std::size_t cells, const std::string& sampler, int depth, int threads,
                     bool certified_bounds, bool mask) {
  if (cells < 1 || cells > 16384) throw InputError("cells: must lie in [1, 16384]");
  if (depth < 0 || depth > 20) throw InputError("depth: must lie in [0, 20]");
  if (threads < 0) throw InputError("threads: must be >= 0");
  const auto model = m.file->criteria.any() ? criteria::limited_mechanism(*m.file) : m.file->model;
  grid::Execution exec;
  exec.threads = threads;
  py::dict out;
  auto common = [&out](const grid::SampleResult& r) {
    out["method"] = r.method;
    out["kernel"] = r.kernel;
    out["isa"] = r.isa;
    out["threads"] = r.threads;
    out["area"] = r.area;
    out["area_lower"] = r.area_lower ? py::object(py::float_(*r.area_lower)) : py::object(py::none());
    out["area_upper"] = r.area_upper ? py::object(py::float_(*r.area_upper)) : py::object(py::none());
    out["bounds_certified"] = r.bounds_certified;
    out["cells"] = r.cells;
    out["points_tested"] = r.points_tested;
    out["inside"] = r.inside;
    out["time_ms"] = r.time_ms;
  };
  auto mask_array = [](const std::vector<std::uint8_t>& v, std::size_t rows, std::size_t cols) {
    py::array_t<std::uint8_t> a({rows, cols});
    std::copy(v.begin(), v.end(), a.mutable_data());
    return a;
  };
  if (sampler == "cartesian") {
    grid::CartesianOptions o;
    o.cells_x = o.cells_y = cells;
    o.certified_bounds = certified_bounds;
    o.keep_mask = mask;
    grid::CartesianResult r;
    {
      py::gil_scoped_release release;
      r = guarded(*m.file, [&] { return grid::cartesian(*model, o, exec); });
    }
    common(r);
    out["box"] = box_py(r.box);
    if (mask) out["mask"] = mask_array(r.mask, o.cells_y, o.cells_x);
  } else if (sampler == "polar") {
    grid::PolarOptions o;
    o.rings = cells;
    o.sectors = std::max<std::size_t>(4, 4 * std::size_t(std::llround(std::numbers::pi * double(cells) / 4.0)));
    o.certified_bounds = certified_bounds;
    o.keep_mask = mask;
    grid::PolarResult r;
    {
      py::gil_scoped_release release;
      r = guarded(*m.file, [&] { return grid::polar(*model, o, exec); });
    }
    common(r);
    out["centre"] = point_py(r.centre);
    out["radius"] = r.radius;
    if (mask) out["mask"] = mask_array(r.mask, o.rings, o.sectors);
  } else if (sampler == "adaptive") {
    grid::AdaptiveOptions o;
    o.base_cells = cells;
    o.depth = depth;
    grid::AdaptiveResult r;
    {
      py::gil_scoped_release release;
      r = guarded(*m.file, [&] { return grid::adaptive(*model, o, exec); });
    }
    common(r);
    out["rule"] = r.rule;
    out["undecided"] = r.undecided;
    out["effective_cells"] = r.effective_cells;
  } else {
    throw InputError("sampler: expected cartesian, polar or adaptive, got \"" + sampler + "\"");
  }
  return out;
}

}  // namespace

PYBIND11_MODULE(_pkmws, mod) {
  mod.doc() = "pkmws native module (see the pkmws package for the documented API)";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });

  // ---- Loop / Component / Region
  py::class_<geometry::Curve>(mod, "Curve", "A boundary curve: a segment or a circular arc (file's length unit).")
      .def_property_readonly("kind", [](const geometry::Curve& c) {
        return c.kind == geometry::Curve::Kind::arc ? "arc" : "segment";
      }, "'segment' or 'arc'")
      .def_property_readonly("source", [](const geometry::Curve& c) { return point_py(c.source); })
      .def_property_readonly("target", [](const geometry::Curve& c) { return point_py(c.target); })
      .def_property_readonly("center", [](const geometry::Curve& c) { return point_py(c.center); },
                             "arcs: the centre")
      .def_property_readonly("radius", [](const geometry::Curve& c) { return c.radius; }, "arcs: the radius")
      .def_property_readonly("sweep", &geometry::Curve::sweep,
                             "arcs: signed swept angle in radians (positive: counter-clockwise)")
      .def_property_readonly("length", &geometry::Curve::length)
      .def("__repr__", [](const geometry::Curve& c) {
        return c.kind == geometry::Curve::Kind::arc
                   ? "<Curve arc centre (" + std::to_string(c.center.x) + ", " + std::to_string(c.center.y) +
                         ") r " + std::to_string(c.radius) + ">"
                   : std::string("<Curve segment>");
      });

  py::class_<geometry::Loop>(mod, "Loop", "A closed boundary loop: outer loops counter-clockwise, holes clockwise.")
      .def_readonly("hole", &geometry::Loop::hole)
      .def_readonly("curves", &geometry::Loop::curves)
      .def_property_readonly("signed_area", &geometry::Loop::signed_area)
      .def_property_readonly("perimeter", &geometry::Loop::perimeter)
      .def_property_readonly("bbox", [](const geometry::Loop& l) { return box_py(l.bbox()); })
      .def("polyline", [](const geometry::Loop& l, double tolerance) {
        if (!(tolerance > 0.0) || !std::isfinite(tolerance)) throw InputError("tolerance: must be a positive number");
        return points_array(l.polyline(tolerance));
      }, py::arg("tolerance"),
           "(N, 2) float64 vertices on the curves, deviation <= tolerance; closed, first point not repeated.");

  py::class_<geometry::Component>(mod, "Component", "A connected component: one outer loop and its holes.")
      .def_readonly("outer", &geometry::Component::outer)
      .def_readonly("holes", &geometry::Component::holes)
      .def_readonly("area", &geometry::Component::area)
      .def_readonly("perimeter", &geometry::Component::perimeter)
      .def_property_readonly("centroid", [](const geometry::Component& c) { return point_py(c.centroid); })
      .def_property_readonly("bbox", [](const geometry::Component& c) { return box_py(c.bbox); });

  py::class_<PyRegion>(mod, "Region")
      .def(py::init<>())
      .def_readonly("units", &PyRegion::units)
      .def_property_readonly("area", [](const PyRegion& r) { return r.region.area(); })
      .def_property_readonly("empty", [](const PyRegion& r) { return r.region.empty(); })
      .def_property_readonly("bbox", [](const PyRegion& r) { return box_py(r.region.bbox()); })
      .def_property_readonly("curve_count", [](const PyRegion& r) { return r.region.curve_count(); })
      .def("components", [](const PyRegion& r, double min_area) {
        py::gil_scoped_release release;
        return r.region.components(min_area);
      }, py::arg("min_area") = 0.0)
      .def("loops", [](const PyRegion& r) {
        py::gil_scoped_release release;
        return r.region.loops();
      })
      .def("polyline", [](const PyRegion& r, std::optional<double> tolerance) {
        if (r.region.empty()) return py::list();
        const double t = tolerance ? *tolerance : default_tolerance(r.region);
        if (!(t > 0.0) || !std::isfinite(t)) throw InputError("tolerance: must be a positive number");
        py::list out;
        for (const auto& l : r.region.loops()) out.append(points_array(l.polyline(t)));
        return out;
      }, py::arg("tolerance") = py::none())
      .def("default_tolerance", [](const PyRegion& r) { return default_tolerance(r.region); })
      .def("contains", &contains, py::arg("points"),
           "Exact membership (boundary inside): (x, y) -> bool, or an (N, 2) array -> (N,) bool array\n"
           "(any dtype or strides; looped in C++ without the GIL).")
      .def("geo_interface", &geo_interface, py::arg("tolerance") = py::none(),
           "GeoJSON MultiPolygon dict (the exporter's polygons, valid in GEOS's model) with vertices on\n"
           "the exact curves, at most `tolerance` (file's unit; default 1e-6 of the diagonal) from them;\n"
           "its area is within area_error_bound(tolerance) of .area.")
      .def("area_error_bound", [](const PyRegion& r, std::optional<double> tolerance) {
        return r.region.empty() ? 0.0 : io::polyline_area_error_bound(r.region, export_options(r, tolerance));
      }, py::arg("tolerance") = py::none())
      .def("inscribed_circles", [](const PyRegion& r, std::optional<double> precision) {
        py::list out;
        std::size_t k = 0;
        for (const auto& c : r.region.components(io::effective_min_area(r.region, {}))) {
          // Default: the precision of `pkmws area`'s inscribed circles.
          const double p = precision ? *precision : report::inscribed_circle_precision(c.bbox);
          if (!(p > 0.0)) throw InputError("precision: must be positive");
          geometry::InscribedCircle circle;
          {
            py::gil_scoped_release release;
            circle = geometry::largest_inscribed_circle(c, p);
          }
          out.append(circle_py(circle, k++));
        }
        return out;
      }, py::arg("precision") = py::none())
      .def("inscribed_rectangles", [](const PyRegion& r, double precision, std::optional<double> aspect,
                                      std::optional<double> width, bool any_angle) {
        if (!(precision >= 1e-12 && precision <= 0.5)) throw InputError("precision: must be in [1e-12, 0.5]");
        if (aspect && width) throw InputError("inscribed_rectangle: give aspect or width, not both");
        if (any_angle && width) throw InputError("inscribed_rectangle: a given width needs a fixed orientation (any_angle=False)");
        geometry::RectangleShape shape;
        if (aspect) shape = {geometry::RectangleShape::Kind::aspect, finite(*aspect, "aspect")};
        if (width) shape = {geometry::RectangleShape::Kind::width, finite(*width, "width")};
        if ((aspect || width) && !(shape.value > 0.0)) throw InputError("aspect/width: must be positive");
        py::list out;
        std::size_t k = 0;
        for (const auto& c : r.region.components(io::effective_min_area(r.region, {}))) {
          geometry::InscribedRectangle rect;
          {
            py::gil_scoped_release release;
            rect = any_angle ? geometry::largest_inscribed_rectangle_any_angle(c, precision, shape, &r.region)
                             : geometry::largest_inscribed_rectangle(c, precision, shape, &r.region);
          }
          out.append(rectangle_py(rect, k++));
        }
        return out;
      }, py::arg("precision") = 1e-6, py::arg("aspect") = py::none(), py::arg("width") = py::none(),
         py::arg("any_angle") = false)
      .def("__or__", [](const PyRegion& a, const PyRegion& b) { return boolean(a, b, std::bit_or<>{}); })
      .def("__and__", [](const PyRegion& a, const PyRegion& b) { return boolean(a, b, std::bit_and<>{}); })
      .def("__sub__", [](const PyRegion& a, const PyRegion& b) { return boolean(a, b, std::minus<>{}); })
      .def("__xor__", [](const PyRegion& a, const PyRegion& b) { return boolean(a, b, std::bit_xor<>{}); })
      .def("to_svg", [](const PyRegion& r, std::optional<std::string> path) {
        return write_or_return(io::to_svg(r.region, export_options(r, std::nullopt)), path);
      }, py::arg("path") = py::none())
      .def("to_dxf", [](const PyRegion& r, std::optional<std::string> path) {
        return write_or_return(io::to_dxf(r.region, export_options(r, std::nullopt)), path);
      }, py::arg("path") = py::none())
      .def("to_csv", [](const PyRegion& r, std::optional<std::string> path) {
        return write_or_return(io::to_csv(r.region, export_options(r, std::nullopt)), path);
      }, py::arg("path") = py::none())
      .def("to_wkt", [](const PyRegion& r, std::optional<std::string> path, std::optional<double> tolerance) {
        const auto o = export_options(r, tolerance);
        if (!r.region.empty()) io::check_tolerance(r.region, o);
        return write_or_return(io::to_wkt(r.region, o), path);
      }, py::arg("path") = py::none(), py::arg("tolerance") = py::none())
      .def("to_geojson", [](const PyRegion& r, std::optional<std::string> path, std::optional<double> tolerance) {
        const auto o = export_options(r, tolerance);
        if (!r.region.empty()) io::check_tolerance(r.region, o);
        return write_or_return(io::to_geojson(r.region, o), path);
      }, py::arg("path") = py::none(), py::arg("tolerance") = py::none());

  // ---- Mechanism
  py::class_<PyMechanism>(mod, "Mechanism")
      .def_property_readonly("path", [](const PyMechanism& m) { return m.file->path; })
      .def_property_readonly("name", [](const PyMechanism& m) { return m.file->name; })
      .def_property_readonly("kind", [](const PyMechanism& m) { return std::string(m.model().kind()); })
      .def_property_readonly("units", [](const PyMechanism& m) { return m.file->units; })
      .def_property_readonly("description", [](const PyMechanism& m) { return m.file->description; })
      .def_property_readonly("dof", [](const PyMechanism& m) { return m.model().dof(); })
      .def_property_readonly("joints", [](const PyMechanism& m) {
        py::list out;
        for (const auto& j : m.model().joints()) {
          py::dict d;
          d["name"] = j.name;
          d["unit"] = j.angle ? std::string("rad") : m.file->units;
          out.append(d);
        }
        return out;
      })
      .def_property_readonly("orientation", [](const PyMechanism& m) { return m.model().orientation(); })
      .def_property_readonly("bounds", [](const PyMechanism& m) {
        return box_py(guarded(*m.file, [&] { return m.model().bounds(); }));
      })
      .def_property_readonly("has_criteria", [](const PyMechanism& m) { return m.file->criteria.any(); })
      .def_property_readonly("has_bodies", [](const PyMechanism& m) { return m.file->bodies != nullptr; })
      .def_property_readonly("document",
                             [](const PyMechanism& m) {
                               return py::module_::import("json").attr("loads")(io::document_text(*m.file));
                             })
      .def("_get", &get_parameter, py::arg("path"))
      .def("_parameters",
           [](const PyMechanism& m) {
             py::list out;
             for (const auto& p : io::parameters(*m.file)) out.append(py::make_tuple(p.path, p.value, p.type, p.unit));
             return out;
           })
      .def("_with", &with_parameters, py::arg("values"))
      .def("_assign", [](PyMechanism& self, const PyMechanism& other) { self.file = other.file; })
      .def("inverse", &inverse, py::arg("x"), py::arg("y"), py::arg("phi") = py::none(),
           "Inverse kinematics at the pose (x, y in the file's unit; phi in radians, default: the file's\n"
           "orientation; for the 1-DOF Pi-joint phi is the crank angle). One dict per working mode, the\n"
           "file's first: mode, joints (prismatic: file's unit; revolute: radians), valid, reason.")
      .def("direct", &direct, py::arg("q"),
           "Direct kinematics for dof joint values q (file's unit / radians). One dict per assembly mode:\n"
           "mode, pose (x, y, phi in radians), platform_points (3-DOF), valid, reason.")
      .def("evaluate", &evaluate_modes, py::arg("x"), py::arg("y"), py::arg("phi") = py::none(),
           "Every criterion at the pose (as `pkmws eval`), one dict per working mode; angles in radians\n"
           "(pressure_angle per leg), reactions in N with the file's criteria.load.")
      .def("inverse_many", &inverse_many, py::arg("poses"),
           "Vectorised inverse for the file's working mode: poses (N, 2) or (N, 3) [x, y(, phi rad)] ->\n"
           "(joints (N, dof) float64, NaN where none; valid (N,) bool). Loops in C++ without the GIL.")
      .def("direct_many", &direct_many, py::arg("q"),
           "Vectorised direct kinematics: q (N, dof) -> (poses (N, 3) [x, y, phi rad] of the first valid\n"
           "assembly mode, NaN where none; valid (N,) bool).")
      .def("evaluate_many", &evaluate_many, py::arg("poses"),
           "Vectorised evaluate for the file's working mode: dict of arrays reachable, jacobian_det,\n"
           "condition_number, singular, pressure_angle (N, legs; radians), velocity_ratio (NaN: undefined).")
      .def("reachable", &reachable, py::arg("poses"),
           "The grid baseline's double membership test: one pose (x, y[, phi]) -> bool, or (N, 2)/(N, 3) -> bool array.")
      .def("workspace", &workspace_region, py::arg("bound") = py::none(),
           "The exact reachable workspace (3-DOF: at the file's orientation) as a Region, lengths in the\n"
           "file's unit. Certified workspaces (real-scheme biglide) need bound='inner' or 'outer'.")
      .def("workspace_area_bounds", &workspace_area_bounds,
           "(lower, upper) containing the true area (file's unit squared), as `pkmws area`.")
      .def("limited_area", [](const PyMechanism& m, double tolerance, int threads) {
        const auto lw = limited(m, tolerance, false, threads);
        return py::make_tuple(lw.region.area_lower, lw.region.area_upper);
      }, py::arg("tolerance") = 1e-6, py::arg("threads") = 0)
      .def("limited_workspace", [](const PyMechanism& m, const std::string& bound, double tolerance, int threads) {
        if (bound != "inner" && bound != "outer") {
          throw InputError("bound: expected 'inner' or 'outer', got '" + bound + "'");
        }
        const auto lw = limited(m, tolerance, true, threads);
        return PyRegion{bound == "inner" ? lw.region.inner : lw.region.outer, m.file->units};
      }, py::arg("bound") = "inner", py::arg("tolerance") = 1e-6, py::arg("threads") = 0)
      .def("draw", &drawing, py::arg("x"), py::arg("y"), py::arg("phi") = py::none())
      .def("grid", &grid_sample, py::arg("cells") = 400, py::arg("sampler") = "cartesian", py::arg("depth") = 8,
           py::arg("threads") = 0, py::arg("certified_bounds") = false, py::arg("mask") = false,
           "The grid baseline (`pkmws grid`): sampler 'cartesian' (cells per side), 'polar' (cells rings) or\n"
           "'adaptive' (cells root cells per side, `depth` levels); a dict with `area` (file's unit squared),\n"
           "`area_lower`/`area_upper` (None unless certified_bounds and the kernel certifies cells),\n"
           "`points_tested`, `time_ms`, ... and with mask=True the cell mask (uint8). Files with criteria\n"
           "sample their criteria-limited workspace.");

  mod.def("_load_path", [](const std::string& path) { return PyMechanism{load_path(path)}; });
  mod.def("_load_document", [](const std::string& text, const std::string& origin) {
    return PyMechanism{load_document(text, origin)};
  });
  mod.def("_run_sweep", &run_sweep, py::arg("spec_file"), py::arg("threads") = 0);
  mod.def("_metric_names", [] { return design::metric_names(); });
  // Design synthesis: (the report of `pkmws optimize --json`, the history CSV).
  mod.def("_optimize", [](const std::string& text, const std::string& dir, const std::string& name) {
    const design::OptimizeSpec spec = design::parse_optimize(text, dir, name);
    design::OptimizeResult r;
    {
      py::gil_scoped_release release;
      r = design::optimize(spec);
    }
    std::string csv = design::csv_header(spec.sweep, true) + "\n";
    for (const auto& row : r.history) csv += design::csv_line(row, true) + "\n";
    return py::make_tuple(design::optimize_report(spec, r), csv);
  });
  mod.def("_time_contains", &time_contains);
  mod.def("_time_inverse", &time_inverse);
  mod.def("_time_evaluate", &time_evaluate);
}
