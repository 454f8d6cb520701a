// pkmws ik / dk / eval: every working and assembly mode as JSON (docs/format.md (command line));
// the reports are the library's (pkmws/report/kinematics.hpp): this file reads the values.
#include <iostream>
#include <numbers>

#include "cli.hpp"
#include "pkmws/report/kinematics.hpp"

namespace pkmws::cli {

namespace {

constexpr double deg = std::numbers::pi / 180.0;

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
    const report::IkReport r = report::ik(mech, read_pose("ik", mech, ik->values));
    std::cout << (ik->json ? report::to_json_text(r) + "\n" : report::to_text(r));
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
    const report::DkReport r = report::dk(mech, q, dk->svg);
    std::vector<std::pair<std::string, std::string>> figures;  // written together, all or nothing
    if (!dk->svg.empty()) check_outputs({dk->svg + "_1.svg"});
    for (std::size_t k = 0; k < r.figures.size(); ++k) {
      if (!r.figures[k].empty()) figures.emplace_back(r.figures[k], report::dk_figure(mech, r, k));
    }
    write_outputs(figures);
    std::cout << (dk->json ? report::to_json_text(r) + "\n" : report::to_text(r));
    return 0;
  }});

  auto ev = std::make_shared<Args>();
  commands.push_back({add(app, "eval", "Every criterion at a pose, per working mode",
                          "X Y [PHI_DEG] (PHI_DEG: default the file's orientation_deg; THETA_DEG for the Pi-joint)", ev),
                      [ev] {
    const auto mech = io::load_mechanism(ev->file);
    const report::EvalReport r = report::eval(mech, read_pose("eval", mech, ev->values));
    std::cout << (ev->json ? report::to_json_text(r) + "\n" : report::to_text(r));
    return 0;
  }});
}

}  // namespace pkmws::cli
