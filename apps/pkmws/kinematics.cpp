// pkmws ik / dk / eval: every working and assembly mode as JSON (docs/format.md (command line)).
#include <cmath>
#include <algorithm>
#include <cstdio>
#include <limits>
#include <numbers>

#include "bodies_cli.hpp"
#include "pkmws/io/export.hpp"

namespace pkmws::cli {

namespace {

constexpr double deg = std::numbers::pi / 180.0;

struct Args {
  std::string file;
  std::vector<std::string> values;
  std::string svg;  // dk: figure prefix
};

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

// Joint values in file units: lengths as they are, angles in degrees.
Json joints_json(const mechanisms::Mechanism& m, const std::vector<double>& q) {
  const auto info = m.joints();
  Json out = Json::object();
  for (std::size_t i = 0; i < q.size() && i < info.size(); ++i) {
    out[info[i].angle ? info[i].name + "_deg" : info[i].name] = info[i].angle ? q[i] / deg : q[i];
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

// `key`: the values, non-finite ones null, with `key`_reason when there is one.
void put_numbers(Json& j, const std::string& key, const std::vector<double>& v, const std::string& reason) {
  Json a = Json::array();
  bool undefined = false;
  for (double x : v) {
    a.push_back(std::isfinite(x) ? Json(x) : Json(nullptr));
    undefined = undefined || !std::isfinite(x);
  }
  j[key] = a;
  if (undefined) j[key + "_reason"] = reason;
}

mechanisms::Pose read_pose(const io::MechanismFile& mech, const std::vector<std::string>& v) {
  const int dof = mech.model->dof();
  mechanisms::Pose pose;
  if (dof == 1) {
    if (v.size() != 1) throw io::InputError("expected one value: THETA_DEG");
    pose.phi = parse_angle(v[0], "THETA_DEG") * deg;
    return pose;
  }
  if (v.size() < 2 || v.size() > 3 || (dof == 3 && v.size() != 3)) {
    throw io::InputError(dof == 3 ? "expected X Y PHI_DEG" : "expected X Y");
  }
  pose.x = parse_length(v[0], "X");
  pose.y = parse_length(v[1], "Y");
  if (v.size() == 3) pose.phi = parse_angle(v[2], "PHI_DEG") * deg;
  return pose;
}

Json pose_json(int dof, const mechanisms::Pose& p) {
  if (dof == 1) return Json{{"theta_deg", p.phi / deg}};
  if (dof == 2) return Json::array({p.x, p.y});
  return Json::array({p.x, p.y, p.phi / deg});
}

Json header(const io::MechanismFile& mech) {
  return Json{{"name", mech.name}, {"mechanism", mech.mechanism}, {"units", mech.units}};
}

CLI::App* add(CLI::App& app, const char* name, const char* help, const char* values_help,
              std::shared_ptr<Args> a) {
  auto* sub = app.add_subcommand(name, help);
  sub->add_option("FILE", a->file, "Mechanism file (JSON)")->required();
  sub->add_option("VALUES", a->values, values_help)->required()->expected(1, 3);
  return sub;
}

}  // namespace

void add_kinematics(CLI::App& app, std::vector<Command>& commands) {
  auto ik = std::make_shared<Args>();
  commands.push_back({add(app, "ik", "Inverse kinematics: joint values of every working mode",
                          "X Y [PHI_DEG] (THETA_DEG for the Pi-joint)", ik),
                      [ik] {
    const auto mech = io::load_mechanism(ik->file);
    const auto pose = read_pose(mech, ik->values);
    Json out = header(mech);
    out["pose"] = pose_json(mech.model->dof(), pose);
    Json sols = Json::array();
    for (const auto& s : mech.model->inverse(pose)) {
      Json j{{"mode", s.mode}, {"valid", s.valid}, {"joints", joints_json(*mech.model, s.joints)}};
      if (!s.valid) j["reason"] = s.reason;
      sols.push_back(j);
    }
    out["solutions"] = sols;
    print_json(out);
    return 0;
  }});

  auto dk = std::make_shared<Args>();
  auto* dk_app = add(app, "dk", "Direct kinematics: platform pose of every assembly mode",
                     "Q1 Q2 [Q3] (joint values; angles in degrees; D for the Pi-joint)", dk);
  dk_app->add_option("--svg", dk->svg,
                     "Write a figure per assembly mode to PREFIX_<k>.svg (the mechanism over its workspace)");
  commands.push_back({dk_app, [dk] {
    const auto mech = io::load_mechanism(dk->file);
    const auto info = mech.model->joints();
    if (dk->values.size() != info.size()) {
      throw io::InputError("expected " + std::to_string(info.size()) + " joint values, got " +
                           std::to_string(dk->values.size()));
    }
    std::vector<double> q;
    for (std::size_t i = 0; i < info.size(); ++i) {
      const double v = info[i].angle ? parse_angle(dk->values[i], info[i].name + "_deg")
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
    print_json(out);
    return 0;
  }});

  auto ev = std::make_shared<Args>();
  commands.push_back({add(app, "eval", "Every criterion at a pose, per working mode",
                          "X Y [PHI_DEG] (THETA_DEG for the Pi-joint)", ev),
                      [ev] {
    const auto mech = io::load_mechanism(ev->file);
    const auto pose = read_pose(mech, ev->values);
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
      out["distance_to_type2_singularity_reason"] = "no type-2 singularity curve is traced for this mechanism at this orientation";
    }
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
      put_numbers(j, "pressure_angle_deg", e.pressure_angle_deg, why);
      put_numbers(j, "reactions_N", e.reactions_N, why);
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
    print_json(out);
    return 0;
  }});
}

}  // namespace pkmws::cli
