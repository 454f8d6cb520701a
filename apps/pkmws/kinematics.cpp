// pkmws ik / dk / eval: every working and assembly mode as JSON (docs/format.md (command line)).
#include <cmath>
#include <algorithm>
#include <cstdio>
#include <limits>
#include <numbers>
#include <set>

#include "bodies_cli.hpp"
#include "pkmws/io/export.hpp"

namespace pkmws::cli {

namespace {

constexpr double deg = std::numbers::pi / 180.0;

std::string short_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

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
Json joints_json(const mechanisms::Mechanism& m, const std::vector<double>& q) {
  const auto info = m.joints();
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

// What a command's VALUES are, for its one-line errors.
std::string pose_usage(const io::MechanismFile& mech) {
  switch (mech.model->dof()) {
    case 1: return "THETA_DEG";
    case 3: return "X Y [PHI_DEG]";
    default: return "X Y";
  }
}

std::string count_text(std::size_t n) { return std::to_string(n) + (n == 1 ? " value" : " values"); }

// The pose of `ik` / `eval`: X Y (2-DOF), X Y [PHI_DEG] with PHI defaulting to
// the file's orientation_deg (3-DOF), THETA_DEG (1-DOF). Any other number of
// values is an error naming the command and what it expects.
mechanisms::Pose read_pose(const std::string& command, const io::MechanismFile& mech,
                           const std::vector<std::string>& v) {
  const int dof = mech.model->dof();
  const std::size_t need_min = dof == 1 ? 1 : 2, need_max = dof == 3 ? 3 : need_min;
  if (v.size() < need_min || v.size() > need_max) {
    throw io::InputError(command + ": expected " + pose_usage(mech) + " for a " + mech.mechanism + " file (got " +
                         count_text(v.size()) + ")");
  }
  mechanisms::Pose pose;
  if (dof == 1) {
    pose.phi = parse_angle(v[0], "THETA_DEG") * deg;
    return pose;
  }
  pose.x = parse_length(v[0], "X");
  pose.y = parse_length(v[1], "Y");
  if (dof == 3) pose.phi = v.size() == 3 ? parse_angle(v[2], "PHI_DEG") * deg : mech.model->orientation();
  return pose;
}

Json pose_json(int dof, const mechanisms::Pose& p) {
  if (dof == 1) return Json{{"theta_deg", p.phi / deg}};
  if (dof == 2) return Json::array({p.x, p.y});
  return Json::array({p.x, p.y, p.phi / deg});
}

Json header(const io::MechanismFile& mech) {
  Json out{{"name", mech.name}, {"mechanism", mech.mechanism}, {"units", mech.units}};
  out.update(joint_vocabulary(mech));
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

std::string pose_text(const io::MechanismFile& mech, const Json& pose) {
  if (pose.is_object()) return "theta = " + num(pose["theta_deg"]) + " deg";
  std::string t = "x = " + num(pose[0]) + " " + mech.units + ", y = " + num(pose[1]) + " " + mech.units;
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

void print_title(const io::MechanismFile& mech) {
  std::printf("%s (%s): lengths in %s, angles in deg\n", mech.name.c_str(), mech.mechanism.c_str(), mech.units.c_str());
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

struct Args {
  std::string file;
  std::vector<std::string> values;
  std::string svg;  // dk: figure prefix
  bool json = false;
};

CLI::App* add(CLI::App& app, const char* name, const char* help, const char* values_help,
              std::shared_ptr<Args> a) {
  auto* sub = app.add_subcommand(name, help);
  sub->add_option("FILE", a->file, "Mechanism file (JSON)")->required();
  // Any number is taken here and checked against the mechanism, so that a wrong
  // count gives one line naming the command and what it expects.
  sub->add_option("VALUES", a->values, values_help)->expected(0, -1);
  sub->add_flag("--json", a->json, "Print one JSON object (docs/schema/" + std::string(name) + ".output.schema.json)");
  return sub;
}

}  // namespace

void add_kinematics(CLI::App& app, std::vector<Command>& commands) {
  auto ik = std::make_shared<Args>();
  commands.push_back({add(app, "ik", "Inverse kinematics: joint values of every working mode",
                          "X Y [PHI_DEG] (PHI_DEG: default the file's orientation_deg; THETA_DEG for the Pi-joint)", ik),
                      [ik] {
    const auto mech = io::load_mechanism(ik->file);
    const auto pose = read_pose("ik", mech, ik->values);
    Json out = header(mech);
    out["pose"] = pose_json(mech.model->dof(), pose);
    Json sols = Json::array();
    for (const auto& s : mech.model->inverse(pose)) {
      Json j{{"mode", s.mode}, {"valid", s.valid}, {"joints", joints_json(*mech.model, s.joints)}};
      if (!s.valid) j["reason"] = s.reason;
      sols.push_back(j);
    }
    out["solutions"] = sols;
    if (ik->json) {
      print_json(out);
      return 0;
    }
    print_title(mech);
    std::printf("pose %s\n", pose_text(mech, out["pose"]).c_str());
    for (const auto& s : out["solutions"]) {
      std::printf("working mode %-4s %-8s %s%s\n", s["mode"].get<std::string>().c_str(),
                  s["valid"].get<bool>() ? "valid" : "invalid", joints_text(out, s["joints"]).c_str(),
                  s.contains("reason") ? ("; " + s["reason"].get<std::string>()).c_str() : "");
    }
    return 0;
  }});

  auto dk = std::make_shared<Args>();
  auto* dk_app = add(app, "dk", "Direct kinematics: platform pose of every assembly mode",
                     "Q1 Q2 [Q3] (joint values in the file's units, angles in degrees; D for the Pi-joint)", dk);
  dk_app->add_option("--svg", dk->svg,
                     "Write a figure per assembly mode to PREFIX_<k>.svg (the mechanism over its workspace)");
  commands.push_back({dk_app, [dk] {
    const auto mech = io::load_mechanism(dk->file);
    const auto info = mech.model->joints();
    if (dk->values.size() != info.size()) {
      std::string names;
      for (const auto& j : info) names += (names.empty() ? "" : " ") + j.name;
      throw io::InputError("dk: expected " + count_text(info.size()) + " (" + names + ") for a " + mech.mechanism +
                           " file (got " + count_text(dk->values.size()) + ")");
    }
    std::vector<double> q;
    for (std::size_t i = 0; i < info.size(); ++i) {
      const double v = info[i].angle ? parse_angle(dk->values[i], info[i].name + " (deg)")
                                     : parse_length(dk->values[i], info[i].name);
      q.push_back(info[i].angle ? v * deg : v);
    }
    Json out = header(mech);
    out["joints"] = joints_json(*mech.model, q);
    Json sols = Json::array();
    const auto solutions = mech.model->direct(q);
    std::vector<std::pair<std::string, std::string>> figures;  // written together, all or nothing
    if (!dk->svg.empty()) check_outputs({dk->svg + "_1.svg"});
    for (std::size_t k = 0; k < solutions.size(); ++k) {
      const auto& s = solutions[k];
      Json j{{"mode", s.mode}, {"valid", s.valid}, {"pose", pose_json(mech.model->dof(), s.pose)}};
      if (!s.platform_points.empty()) {
        Json pts = Json::array();
        for (const auto& p : s.platform_points) pts.push_back({p.x, p.y});
        j["platform_points"] = pts;
      }
      if (!s.valid) j["reason"] = s.reason;
      if (!dk->svg.empty() && mech.model->dof() >= 2) {
        // One figure per assembly mode ([Mitsi] figure 4): the mechanism at the
        // pose over its constant-orientation workspace.
        const std::string path = dk->svg + "_" + std::to_string(k + 1) + ".svg";
        const geometry::Region ws = workspace_at(*mech.model, s.pose.phi);
        io::FigureOptions fo;
        fo.title = "Assembly mode " + std::to_string(k + 1) + " of " + std::to_string(solutions.size()) + " (" +
                   s.mode + ")";
        std::string pose_text = "pose x = " + short_number(s.pose.x) + ", y = " + short_number(s.pose.y);
        if (mech.model->dof() == 3) pose_text += ", phi = " + short_number(s.pose.phi / deg) + " deg";
        fo.caption = mech.name + ". " + pose_text + (ws.empty() ? "" : "; shaded: the workspace at this orientation") +
                     (s.valid ? "" : "; not valid: " + s.reason);
        // The actuators where q puts them (this assembly mode), not where the file's working mode would.
        figures.emplace_back(path, io::workspace_figure(mech, ws, mech.model->draw_with_joints(s.pose, q), fo));
        j["figure"] = path;
      }
      sols.push_back(j);
    }
    out["solutions"] = sols;
    write_outputs(figures);
    if (const auto elimination = mech.model->capability<mechanisms::Elimination>()) {
      out["elimination"] = elimination_json(elimination->elimination(q));
    }
    if (dk->json) {
      print_json(out);
      return 0;
    }
    print_title(mech);
    std::printf("joints %s\n", joints_text(out, out["joints"]).c_str());
    if (out["solutions"].empty()) std::printf("no assembly mode: the joint values cannot be assembled\n");
    for (const auto& s : out["solutions"]) {
      std::printf("assembly mode %-2s %-8s pose %s%s%s\n", s["mode"].get<std::string>().c_str(),
                  s["valid"].get<bool>() ? "valid" : "invalid", pose_text(mech, s["pose"]).c_str(),
                  s.contains("reason") ? ("; " + s["reason"].get<std::string>()).c_str() : "",
                  s.contains("figure") ? ("; figure " + s["figure"].get<std::string>()).c_str() : "");
    }
    if (out.contains("elimination")) {
      std::printf("elimination: %s (--json: every coefficient and root)\n",
                  out["elimination"]["method"].get<std::string>().c_str());
    }
    return 0;
  }});

  auto ev = std::make_shared<Args>();
  commands.push_back({add(app, "eval", "Every criterion at a pose, per working mode",
                          "X Y [PHI_DEG] (PHI_DEG: default the file's orientation_deg; THETA_DEG for the Pi-joint)", ev),
                      [ev] {
    const auto mech = io::load_mechanism(ev->file);
    const auto pose = read_pose("eval", mech, ev->values);
    Json out = header(mech);
    out["pose"] = pose_json(mech.model->dof(), pose);
    // Distance in task space from the pose to the traced type-2 singularity
    // curves at this orientation (polylines whose vertices lie on the curve),
    // null when the mechanism has none drawn.
    Json distance_type2 = nullptr;
    if (mech.model->dof() >= 2) {
      double best = std::numeric_limits<double>::infinity();
      const geometry::Point p{pose.x, pose.y};
      for (const auto& curve : mech.model->draw(pose).singular_curves) {
        for (std::size_t k = 0; k + 1 < curve.size(); ++k) {
          const geometry::Point d = curve[k + 1] - curve[k];
          const double len2 = geometry::dot(d, d);
          const double t = len2 > 0.0 ? std::clamp(geometry::dot(p - curve[k], d) / len2, 0.0, 1.0) : 0.0;
          best = std::min(best, geometry::norm(p - (curve[k] + t * d)));
        }
        if (curve.size() == 1) best = std::min(best, geometry::norm(p - curve[0]));
      }
      if (std::isfinite(best)) distance_type2 = best;
    }
    out["distance_to_type2_singularity"] = distance_type2;
    if (distance_type2.is_null()) {
      out["distance_to_type2_singularity_reason"] =
          mech.model->dof() == 1 ? "a 1-DOF mechanism has no task-space singularity curves"
                                 : "no type-2 singularity curve is traced for this mechanism at this orientation";
    }
    const std::string no_load = "no load: the file's criteria have no `load`";
    Json modes = Json::array();
    for (const auto& e : mech.model->evaluate(pose, mech.criteria)) {
      const std::string why = undefined_reason(e);
      Json j{{"mode", e.mode},
             {"reachable", e.reachable},
             {"joints", joints_json(*mech.model, e.joints)},
             {"singular", e.singular},
             {"singularity", e.singularity}};
      put_number(j, "jacobian_det", e.jacobian_det, why);
      put_number(j, "condition_number", e.condition_number, why);
      put_numbers(j, "pressure_angle_deg", e.pressure_angle_deg, why,
                  e.reachable ? "not defined for this mechanism" : why);
      put_numbers(j, "reactions_N", e.reactions_N, why, mech.criteria.load ? why : no_load);
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
    if (mech.bodies) out["bodies"] = collisions_json(mech, {pose.x, pose.y});
    if (ev->json) {
      print_json(out);
      return 0;
    }
    print_title(mech);
    std::printf("pose %s\n", pose_text(mech, out["pose"]).c_str());
    std::printf("distance to a type-2 singularity: %s\n",
                with_reason(out, "distance_to_type2_singularity", mech.units).c_str());
    for (const auto& m : out["modes"]) {
      std::printf("working mode %s: %s\n", m["mode"].get<std::string>().c_str(),
                  m["reachable"].get<bool>() ? "reachable" : ("not reachable, " + m["reason"].get<std::string>()).c_str());
      std::printf("  joints                %s\n", joints_text(out, m["joints"]).c_str());
      std::printf("  singularity           %s\n",
                  m["singular"].get<bool>() ? m["singularity"].get<std::string>().c_str() : "none");
      std::printf("  jacobian_det          %s\n", with_reason(m, "jacobian_det", "").c_str());
      std::printf("  condition_number      %s\n", with_reason(m, "condition_number", "").c_str());
      std::printf("  pressure_angle        %s\n", with_reason(m, "pressure_angle_deg", "deg").c_str());
      std::printf("  reactions             %s\n", with_reason(m, "reactions_N", "N").c_str());
      std::printf("  velocity_ratio        %s\n", with_reason(m, "velocity_ratio", "").c_str());
      // The mechanism's own figures (e.g. transmission_angle_deg).
      static const std::set<std::string> shown{"mode", "reachable", "reason", "joints", "singular", "singularity",
                                               "jacobian_det", "condition_number", "pressure_angle_deg",
                                               "reactions_N", "velocity_ratio"};
      for (const auto& [k, v] : m.items()) {
        if (shown.count(k) || (k.size() > 7 && k.compare(k.size() - 7, 7, "_reason") == 0)) continue;
        std::printf("  %-21s %s\n", k.c_str(), with_reason(m, k, extra_unit(k, mech.units)).c_str());
      }
    }
    if (out.contains("bodies")) {
      const auto& b = out["bodies"];
      std::printf("bodies: %s\n", !b["reachable"].get<bool>() ? "not reachable"
                                  : b["collides"].get<bool>() ? "COLLISION (pkmws explain for the pairs)"
                                                              : "no collision");
    }
    return 0;
  }});
}

}  // namespace pkmws::cli
