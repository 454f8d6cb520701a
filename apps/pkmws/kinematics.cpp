// pkmws ik / dk / eval: every working and assembly mode as JSON (SPEC §4).
#include <cmath>
#include <numbers>

#include "cli.hpp"

namespace pkmws::cli {

namespace {

constexpr double deg = std::numbers::pi / 180.0;

struct Args {
  std::string file;
  std::vector<std::string> values;
};

// Joint values in file units: lengths as they are, angles in degrees.
Json joints_json(const mechanisms::Mechanism& m, const std::vector<double>& q) {
  const auto info = m.joints();
  Json out = Json::object();
  for (std::size_t i = 0; i < q.size() && i < info.size(); ++i) {
    out[info[i].angle ? info[i].name + "_deg" : info[i].name] = info[i].angle ? q[i] / deg : q[i];
  }
  return out;
}

Json number_or_null(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

mechanisms::Pose read_pose(const io::MechanismFile& mech, const std::vector<std::string>& v) {
  const int dof = mech.model->dof();
  mechanisms::Pose pose;
  if (dof == 1) {
    if (v.size() != 1) throw io::InputError("expected one value: THETA_DEG");
    pose.phi = parse_number(v[0], "THETA_DEG") * deg;
    return pose;
  }
  if (v.size() < 2 || v.size() > 3 || (dof == 3 && v.size() != 3)) {
    throw io::InputError(dof == 3 ? "expected X Y PHI_DEG" : "expected X Y");
  }
  pose.x = parse_number(v[0], "X");
  pose.y = parse_number(v[1], "Y");
  if (v.size() == 3) pose.phi = parse_number(v[2], "PHI_DEG") * deg;
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
  commands.push_back({add(app, "dk", "Direct kinematics: platform pose of every assembly mode",
                          "Q1 Q2 [Q3] (joint values; angles in degrees; D for the Pi-joint)", dk),
                      [dk] {
    const auto mech = io::load_mechanism(dk->file);
    const auto info = mech.model->joints();
    if (dk->values.size() != info.size()) {
      throw io::InputError("expected " + std::to_string(info.size()) + " joint values, got " +
                           std::to_string(dk->values.size()));
    }
    std::vector<double> q;
    for (std::size_t i = 0; i < info.size(); ++i) {
      const double v = parse_number(dk->values[i], info[i].name);
      q.push_back(info[i].angle ? v * deg : v);
    }
    Json out = header(mech);
    out["joints"] = joints_json(*mech.model, q);
    Json sols = Json::array();
    for (const auto& s : mech.model->direct(q)) {
      Json j{{"mode", s.mode}, {"valid", s.valid}, {"pose", pose_json(mech.model->dof(), s.pose)}};
      if (!s.platform_points.empty()) {
        Json pts = Json::array();
        for (const auto& p : s.platform_points) pts.push_back({p.x, p.y});
        j["platform_points"] = pts;
      }
      if (!s.valid) j["reason"] = s.reason;
      sols.push_back(j);
    }
    out["solutions"] = sols;
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
    Json modes = Json::array();
    for (const auto& e : mech.model->evaluate(pose, mech.criteria)) {
      Json j{{"mode", e.mode},
             {"reachable", e.reachable},
             {"joints", joints_json(*mech.model, e.joints)},
             {"jacobian_det", number_or_null(e.jacobian_det)},
             {"condition_number", number_or_null(e.condition_number)},
             {"singular", e.singular},
             {"singularity", e.singularity},
             {"pressure_angle_deg", e.pressure_angle_deg},
             {"reactions_N", e.reactions_N},
             {"velocity_ratio", e.velocity_ratio ? number_or_null(*e.velocity_ratio) : Json(nullptr)}};
      if (!e.reachable) j["reason"] = e.reason;
      for (const auto& [k, v] : e.extra) j[k] = number_or_null(v);
      modes.push_back(j);
    }
    out["modes"] = modes;
    print_json(out);
    return 0;
  }});
}

}  // namespace pkmws::cli
