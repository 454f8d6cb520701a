// `pkmws ik`, `dk`, `eval` (pkmws/report/kinematics.hpp): moved from the
// command line's kinematics.cpp, JSON and text unchanged (the text is read
// from the JSON, as it was).
#include "pkmws/report/kinematics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <set>

#include "pkmws/criteria/fields.hpp"
#include "pkmws/io/figure.hpp"
#include "report/json.hpp"
#include "report/text.hpp"

namespace pkmws::report {

using detail::Json;
using detail::format;

namespace {

constexpr double deg = std::numbers::pi / 180.0;

std::string short_number(double v) { return format("%.6g", v); }

// dk's `elimination`: the eliminant of the mechanisms that have one
// (capability Elimination), in one shape for every mechanism.
Json elimination_json(const mechanisms::Elimination::Report& r) {
  Json out{{"method", r.method}};
  if (!r.variable.empty()) {
    Json complex = Json::array();
    for (const auto& z : r.complex_roots) complex.push_back({z.re, z.im});
    out["variable"] = r.variable;
    out["nominal_degree"] = r.nominal_degree;
    out["degree"] = r.degree;
    out["coefficients_ascending"] = r.coefficients_ascending;
    out["real_roots"] = r.real_roots;
    out["complex_roots"] = complex;
  }
  if (!r.solutions.empty()) {
    Json sols = Json::array();
    for (const auto& s : r.solutions) sols.push_back({{"values", s.values}, {"label", s.label}, {"residual", s.residual}});
    out["solution_values"] = r.solution_values;
    out["solutions"] = sols;
  }
  out["poses"] = r.poses;
  out["continuum"] = r.continuum;
  for (const auto& [key, value] : r.figures) out[key] = std::isfinite(value) ? Json(value) : Json(nullptr);
  if (!r.note.empty()) out["note"] = r.note;
  return out;
}

// The constant-orientation workspace at phi where the mechanism has one
// (empty when it is unbounded), for the per-assembly-mode figures.
geometry::Region workspace_at(const mechanisms::Mechanism& m, double phi) {
  try {
    if (const auto slice = m.capability<mechanisms::PoseSlice>()) return slice->workspace_at(phi);
    return m.workspace();
  } catch (const std::exception&) {
    return geometry::Region{};
  }
}

// Joint values keyed by joint name (docs/format.md (output vocabulary)): lengths
// in the file's unit, angles in degrees; the units are in `joint_units`.
Json joints_json(const MechanismHeader& h, const std::vector<double>& q) {
  const auto& info = h.joints;
  Json out = Json::object();
  for (std::size_t i = 0; i < q.size() && i < info.size(); ++i) {
    out[info[i].name] = info[i].angle ? q[i] / deg : q[i];
  }
  return out;
}

// Why a figure of an evaluation is not a finite number (JSON null next to it).
std::string undefined_reason(const mechanisms::Evaluation& e) {
  if (!e.reachable) return "undefined: the pose is not reachable in this mode";
  if (e.singular) return "infinite or undefined: the pose is singular (" + e.singularity + ")";
  return "undefined at this pose (not a finite number)";
}

// `key`: v, or null with `key`_reason next to it.
void put_number(Json& j, const std::string& key, double v, const std::string& reason) {
  if (std::isfinite(v)) {
    j[key] = v;
  } else {
    j[key] = nullptr;
    j[key + "_reason"] = reason;
  }
}

// `key`: the values, non-finite ones null, with `key`_reason when there is one;
// no values at all: null with `empty_reason`.
void put_numbers(Json& j, const std::string& key, const std::vector<double>& v, const std::string& reason,
                 const std::string& empty_reason) {
  if (v.empty()) {
    j[key] = nullptr;
    j[key + "_reason"] = empty_reason;
    return;
  }
  Json a = Json::array();
  bool undefined = false;
  for (double x : v) {
    a.push_back(std::isfinite(x) ? Json(x) : Json(nullptr));
    undefined = undefined || !std::isfinite(x);
  }
  j[key] = a;
  if (undefined) j[key + "_reason"] = reason;
}

Json pose_json(int dof, const mechanisms::Pose& p) {
  if (dof == 1) return Json{{"theta_deg", p.phi / deg}};
  if (dof == 2) return Json::array({p.x, p.y});
  return Json::array({p.x, p.y, p.phi / deg});
}

Json header_json(const MechanismHeader& h) {
  Json out{{"name", h.name}, {"mechanism", h.mechanism}, {"units", h.units}};
  out.update(detail::joint_vocabulary(h.joints, h.units));
  return out;
}

// --- text output: every length with the file's unit, every angle in deg ---

std::string num(const Json& v) {
  if (v.is_null()) return "undefined";
  if (v.is_number()) return short_number(v.get<double>());
  if (v.is_boolean()) return v.get<bool>() ? "yes" : "no";
  if (v.is_string()) return v.get<std::string>();
  return v.dump();
}

std::string pose_text(const MechanismHeader& h, const Json& pose) {
  if (pose.is_object()) return "theta = " + num(pose["theta_deg"]) + " deg";
  std::string t = "x = " + num(pose[0]) + " " + h.units + ", y = " + num(pose[1]) + " " + h.units;
  if (pose.size() == 3) t += ", phi = " + num(pose[2]) + " deg";
  return t;
}

std::string joints_text(const Json& out, const Json& joints) {
  std::string t;
  for (const auto& name : out["joint_names"]) {
    const std::string n = name.get<std::string>();
    if (!joints.contains(n)) continue;
    t += (t.empty() ? "" : ", ") + n + " = " + num(joints[n]) + " " + out["joint_units"][n].get<std::string>();
  }
  return t.empty() ? "no joint values" : t;
}

std::string title(const MechanismHeader& h) {
  return format("%s (%s): lengths in %s, angles in deg\n", h.name.c_str(), h.mechanism.c_str(), h.units.c_str());
}

// A value of `eval` with its unit; null: "undefined (reason)".
std::string with_reason(const Json& j, const std::string& key, const std::string& unit) {
  if (!j.contains(key)) return "";
  const Json& v = j[key];
  std::string t;
  if (v.is_array()) {
    for (const auto& x : v) t += (t.empty() ? "" : ", ") + num(x);
    t = "[" + t + "]";
  } else {
    t = num(v);
  }
  if (!unit.empty() && !v.is_null()) t += " " + unit;
  if (j.contains(key + "_reason")) t += " (" + j[key + "_reason"].get<std::string>() + ")";
  return t;
}

// The unit of an `extra` figure of `eval`, read from its key (docs/format.md (output vocabulary)).
std::string extra_unit(const std::string& key, const std::string& length_unit) {
  auto ends = [&](const std::string& s) { return key.size() > s.size() && key.compare(key.size() - s.size(), s.size(), s) == 0; };
  if (ends("_deg")) return "deg";
  if (ends("_deg_per_step")) return "deg per step";
  if (ends("_deg_s_at_max_speed")) return "deg/s";
  if (ends("_Nm_at_max_force") || ends("_Nm")) return "N m";
  if (ends("_N")) return "N";
  if (key == "d") return length_unit;
  if (ends("_length")) return length_unit;
  if (key == "jacobian") return length_unit + "/rad";
  if (key == "jacobian_inverse") return "rad/" + length_unit;
  return "";
}

Json ik_json(const IkReport& r) {
  Json out = header_json(r.header);
  out["pose"] = pose_json(r.header.dof, r.pose);
  Json sols = Json::array();
  for (const auto& s : r.solutions) {
    Json j{{"mode", s.mode}, {"valid", s.valid}, {"joints", joints_json(r.header, s.joints)}};
    if (!s.valid) j["reason"] = s.reason;
    sols.push_back(j);
  }
  out["solutions"] = sols;
  return out;
}

Json dk_json(const DkReport& r) {
  Json out = header_json(r.header);
  out["joints"] = joints_json(r.header, r.joints);
  Json sols = Json::array();
  for (std::size_t k = 0; k < r.solutions.size(); ++k) {
    const auto& s = r.solutions[k];
    Json j{{"mode", s.mode}, {"valid", s.valid}, {"pose", pose_json(r.header.dof, s.pose)}};
    if (!s.platform_points.empty()) {
      Json pts = Json::array();
      for (const auto& p : s.platform_points) pts.push_back({p.x, p.y});
      j["platform_points"] = pts;
    }
    if (!s.valid) j["reason"] = s.reason;
    if (k < r.figures.size() && !r.figures[k].empty()) j["figure"] = r.figures[k];
    sols.push_back(j);
  }
  out["solutions"] = sols;
  if (r.elimination) out["elimination"] = elimination_json(*r.elimination);
  return out;
}

Json eval_json(const EvalReport& r) {
  Json out = header_json(r.header);
  out["pose"] = pose_json(r.header.dof, r.pose);
  if (r.distance_to_type2_singularity) {
    out["distance_to_type2_singularity"] = *r.distance_to_type2_singularity;
    if (r.distance_error) out["distance_to_type2_singularity_error"] = *r.distance_error;
    out["distance_to_type2_singularity_to"] = r.distance_source;
  } else {
    out["distance_to_type2_singularity"] = nullptr;
    out["distance_to_type2_singularity_reason"] = r.distance_reason;
  }
  const std::string no_load = "no load: the file's criteria have no `load`";
  Json modes = Json::array();
  for (const auto& e : r.modes) {
    const std::string why = undefined_reason(e);
    Json j{{"mode", e.mode},
           {"reachable", e.reachable},
           {"joints", joints_json(r.header, e.joints)},
           {"singular", e.singular},
           {"singularity", e.singularity}};
    put_number(j, "jacobian_det", e.jacobian_det, why);
    put_number(j, "condition_number", e.condition_number, why);
    put_numbers(j, "pressure_angle_deg", e.pressure_angle_deg, why, e.reachable ? "not defined for this mechanism" : why);
    put_numbers(j, "reactions_N", e.reactions_N, why, r.has_load ? why : no_load);
    if (e.velocity_ratio) {
      put_number(j, "velocity_ratio", *e.velocity_ratio, why);
    } else {
      j["velocity_ratio"] = nullptr;
      j["velocity_ratio_reason"] = "not defined for this mechanism";
    }
    if (!e.reachable) j["reason"] = e.reason;
    for (const auto& [k, v] : e.extra) put_number(j, k, v, why);
    modes.push_back(j);
  }
  out["modes"] = modes;
  // docs/format.md (bodies): with bodies, which parts collide at this platform position.
  if (r.bodies) out["bodies"] = detail::collisions_json(*r.bodies);
  return out;
}

}  // namespace

MechanismHeader header_of(const io::MechanismFile& file) {
  return {file.name, file.mechanism, file.units, file.model->dof(), file.model->joints()};
}

IkReport ik(const io::MechanismFile& file, const mechanisms::Pose& pose) {
  return {header_of(file), pose, file.model->inverse(pose)};
}

DkReport dk(const io::MechanismFile& file, const std::vector<double>& joints, const std::string& figure_prefix) {
  DkReport r;
  r.header = header_of(file);
  r.joints = joints;
  r.solutions = file.model->direct(joints);
  for (std::size_t k = 0; k < r.solutions.size(); ++k) {
    r.figures.push_back(!figure_prefix.empty() && r.header.dof >= 2
                            ? figure_prefix + "_" + std::to_string(k + 1) + ".svg"
                            : std::string());
  }
  if (const auto elimination = file.model->capability<mechanisms::Elimination>()) {
    r.elimination = elimination->elimination(joints);
  }
  return r;
}

std::string dk_figure(const io::MechanismFile& mech, const DkReport& r, std::size_t k) {
  // One figure per assembly mode ([Mitsi] figure 4): the mechanism at the
  // pose over its constant-orientation workspace.
  const auto& s = r.solutions.at(k);
  const geometry::Region ws = workspace_at(*mech.model, s.pose.phi);
  io::FigureOptions fo;
  fo.title = "Assembly mode " + std::to_string(k + 1) + " of " + std::to_string(r.solutions.size()) + " (" + s.mode + ")";
  std::string pose_text = "pose x = " + short_number(s.pose.x) + ", y = " + short_number(s.pose.y);
  if (mech.model->dof() == 3) pose_text += ", phi = " + short_number(s.pose.phi / deg) + " deg";
  fo.caption = mech.name + ". " + pose_text + (ws.empty() ? "" : "; shaded: the workspace at this orientation") +
               (s.valid ? "" : "; not valid: " + s.reason);
  // The actuators where q puts them (this assembly mode), not where the file's working mode would.
  return io::workspace_figure(mech, ws, mech.model->draw_with_joints(s.pose, r.joints), fo);
}

EvalReport eval(const io::MechanismFile& mech, const mechanisms::Pose& pose) {
  EvalReport r;
  r.header = header_of(mech);
  r.pose = pose;
  // Distance in task space from the pose to the type-2 singularity: to the
  // working mode's singular set inside the workspace, traced with a bound,
  // where the mechanism gives its determinant; else to the singularity curves
  // it draws at this orientation (polylines whose vertices lie on the curve).
  const geometry::Point p{pose.x, pose.y};
  if (const auto d = mech.model->dof() >= 2 ? criteria::singularity_distance_at(mech, p) : std::nullopt) {
    if (!d->note.empty() && !std::isfinite(d->upper)) {
      r.distance_reason = d->note;
    } else {
      r.distance_to_type2_singularity = 0.5 * (d->lower + d->upper);
      r.distance_error = 0.5 * (d->upper - d->lower);
      r.distance_source = d->note.empty() ? "the working mode's type-2 singular set inside the workspace, certified"
                                          : d->note;
    }
  } else if (mech.model->dof() >= 2) {
    double best = std::numeric_limits<double>::infinity();
    for (const auto& curve : mech.model->draw(pose).singular_curves) {
      for (std::size_t k = 0; k + 1 < curve.size(); ++k) {
        const geometry::Point seg = curve[k + 1] - curve[k];
        const double len2 = geometry::dot(seg, seg);
        const double t = len2 > 0.0 ? std::clamp(geometry::dot(p - curve[k], seg) / len2, 0.0, 1.0) : 0.0;
        best = std::min(best, geometry::norm(p - (curve[k] + t * seg)));
      }
      if (curve.size() == 1) best = std::min(best, geometry::norm(p - curve[0]));
    }
    if (std::isfinite(best)) {
      r.distance_to_type2_singularity = best;
      r.distance_source = "the singularity curves drawn at this orientation";
    }
  }
  if (!r.distance_to_type2_singularity && r.distance_reason.empty()) {
    r.distance_reason = mech.model->dof() == 1
                            ? "a 1-DOF mechanism has no task-space singularity curves"
                            : "no type-2 singularity curve is traced for this mechanism at this orientation";
  }
  r.modes = mech.model->evaluate(pose, mech.criteria);
  r.has_load = static_cast<bool>(mech.criteria.load);
  if (mech.bodies) r.bodies = explain(mech, {pose.x, pose.y});
  return r;
}

std::string to_json_text(const IkReport& r) { return detail::json_text(ik_json(r)); }
std::string to_json_text(const DkReport& r) { return detail::json_text(dk_json(r)); }
std::string to_json_text(const EvalReport& r) { return detail::json_text(eval_json(r)); }

std::string to_text(const IkReport& r) {
  const Json out = ik_json(r);
  std::string t = title(r.header);
  t += format("pose %s\n", pose_text(r.header, out["pose"]).c_str());
  for (const auto& s : out["solutions"]) {
    t += format("working mode %-4s %-8s %s%s\n", s["mode"].get<std::string>().c_str(),
                s["valid"].get<bool>() ? "valid" : "invalid", joints_text(out, s["joints"]).c_str(),
                s.contains("reason") ? ("; " + s["reason"].get<std::string>()).c_str() : "");
  }
  return t;
}

std::string to_text(const DkReport& r) {
  const Json out = dk_json(r);
  std::string t = title(r.header);
  t += format("joints %s\n", joints_text(out, out["joints"]).c_str());
  if (out["solutions"].empty()) t += "no assembly mode: the joint values cannot be assembled\n";
  for (const auto& s : out["solutions"]) {
    t += format("assembly mode %-2s %-8s pose %s%s%s\n", s["mode"].get<std::string>().c_str(),
                s["valid"].get<bool>() ? "valid" : "invalid", pose_text(r.header, s["pose"]).c_str(),
                s.contains("reason") ? ("; " + s["reason"].get<std::string>()).c_str() : "",
                s.contains("figure") ? ("; figure " + s["figure"].get<std::string>()).c_str() : "");
  }
  if (out.contains("elimination")) {
    t += format("elimination: %s (--json: every coefficient and root)\n",
                out["elimination"]["method"].get<std::string>().c_str());
  }
  return t;
}

std::string to_text(const EvalReport& r) {
  const Json out = eval_json(r);
  const std::string& units = r.header.units;
  std::string t = title(r.header);
  t += format("pose %s\n", pose_text(r.header, out["pose"]).c_str());
  std::string distance = with_reason(out, "distance_to_type2_singularity", units);
  if (out.contains("distance_to_type2_singularity_error")) {
    distance += " ± " + num(out["distance_to_type2_singularity_error"]) + " " + units;
  }
  if (out.contains("distance_to_type2_singularity_to")) {
    distance += " (to " + out["distance_to_type2_singularity_to"].get<std::string>() + ")";
  }
  t += format("distance to a type-2 singularity: %s\n", distance.c_str());
  for (const auto& m : out["modes"]) {
    t += format("working mode %s: %s\n", m["mode"].get<std::string>().c_str(),
                m["reachable"].get<bool>() ? "reachable" : ("not reachable, " + m["reason"].get<std::string>()).c_str());
    t += format("  joints                %s\n", joints_text(out, m["joints"]).c_str());
    t += format("  singularity           %s\n",
                m["singular"].get<bool>() ? m["singularity"].get<std::string>().c_str() : "none");
    t += format("  jacobian_det          %s\n", with_reason(m, "jacobian_det", "").c_str());
    t += format("  condition_number      %s\n", with_reason(m, "condition_number", "").c_str());
    t += format("  pressure_angle        %s\n", with_reason(m, "pressure_angle_deg", "deg").c_str());
    t += format("  reactions             %s\n", with_reason(m, "reactions_N", "N").c_str());
    t += format("  velocity_ratio        %s\n", with_reason(m, "velocity_ratio", "").c_str());
    // The mechanism's own figures (e.g. transmission_angle_deg).
    static const std::set<std::string> shown{"mode", "reachable", "reason", "joints", "singular", "singularity",
                                             "jacobian_det", "condition_number", "pressure_angle_deg",
                                             "reactions_N", "velocity_ratio"};
    for (const auto& [k, v] : m.items()) {
      if (shown.count(k) || (k.size() > 7 && k.compare(k.size() - 7, 7, "_reason") == 0)) continue;
      t += format("  %-21s %s\n", k.c_str(), with_reason(m, k, extra_unit(k, units)).c_str());
    }
  }
  if (out.contains("bodies")) {
    const auto& b = out["bodies"];
    t += format("bodies: %s\n", !b["reachable"].get<bool>() ? "not reachable"
                                : b["collides"].get<bool>() ? "COLLISION (pkmws explain for the pairs)"
                                                            : "no collision");
  }
  return t;
}

}  // namespace pkmws::report
