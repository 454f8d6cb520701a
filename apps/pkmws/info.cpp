// pkmws info FILE [--json]: the parsed mechanism.
#include <cstdio>
#include <numbers>
#include <stdexcept>

#include "bodies_cli.hpp"
#include "pkmws/io/parameters.hpp"

namespace pkmws::cli {

void add_info(CLI::App& app, std::vector<Command>& commands) {
  auto* sub = app.add_subcommand("info", "Print the parsed mechanism");
  auto file = std::make_shared<std::string>();
  auto json = std::make_shared<bool>(false);
  sub->add_option("FILE", *file, "Mechanism file (JSON)")->required();
  sub->add_flag("--json", *json, "Print the validated document with `derived` (docs/schema/info.output.schema.json)");
  commands.push_back({sub, [file, json] {
    const auto mech = io::load_mechanism(*file);
    Json out = Json::parse(io::document_text(mech));
    Json derived{{"dof", mech.model->dof()}};
    derived.update(joint_vocabulary(mech));
    // The parameter model (pkmws/io/parameters.hpp): every number by field path, with type and unit.
    Json parameters = Json::array();
    for (const auto& p : io::parameters(mech)) {
      parameters.push_back({{"path", p.path}, {"value", p.value}, {"type", p.type}, {"unit", p.unit}});
    }
    derived["parameters"] = parameters;
    out["derived"] = derived;
    try {
      const auto b = mech.model->bounds();
      out["derived"]["bounds"] = {{"min", {b.min.x, b.min.y}}, {"max", {b.max.x, b.max.y}}};
    } catch (const std::runtime_error& e) {
      // A valid file whose workspace has no bound (a 3-RPR without leg limits,
      // a 3-PRP without strokes): say so instead of refusing the file.
      out["derived"]["bounds"] = nullptr;
      out["derived"]["bounds_reason"] = e.what();
    }
    if (mech.bodies) {
      // docs/format.md (bodies): the pairs checked for collision (joined and allowed pairs excluded).
      const auto& m = mech.bodies->model();
      Json pairs = Json::array();
      for (const auto& p : m.pairs()) {
        pairs.push_back({m.parts[static_cast<std::size_t>(p.a)].name, m.parts[static_cast<std::size_t>(p.b)].name});
      }
      out["derived"]["collision_pairs"] = pairs;
    }
    if (*json) {
      print_json(out);
      return 0;
    }
    const Json& d = out["derived"];
    std::printf("%s (%s): lengths in %s, angles in deg\n", mech.name.c_str(), mech.mechanism.c_str(),
                mech.units.c_str());
    std::string joints;
    for (const auto& n : d["joint_names"]) {
      const std::string name = n.get<std::string>();
      joints += (joints.empty() ? "" : ", ") + name + " (" + d["joint_units"][name].get<std::string>() + ")";
    }
    std::printf("dof        %d\njoints     %s\n", d["dof"].get<int>(), joints.c_str());
    if (d["bounds"].is_null()) {
      std::printf("bounds     none: %s\n", d["bounds_reason"].get<std::string>().c_str());
    } else {
      const auto& b = d["bounds"];
      std::printf("bounds     x %.10g .. %.10g %s, y %.10g .. %.10g %s\n", b["min"][0].get<double>(),
                  b["max"][0].get<double>(), mech.units.c_str(), b["min"][1].get<double>(),
                  b["max"][1].get<double>(), mech.units.c_str());
    }
    if (mech.model->dof() == 3) {
      std::printf("orientation %.10g deg (the workspace's; the default PHI_DEG of ik and eval)\n",
                  mech.model->orientation() * 180.0 / std::numbers::pi);
    }
    std::printf("parameters %zu numbers by field path (--json: derived.parameters, with units)\n", d["parameters"].size());
    if (d.contains("collision_pairs")) std::printf("collision pairs %zu\n", d["collision_pairs"].size());
    if (!mech.description.empty()) std::printf("%s\n", mech.description.c_str());
    std::printf("(--json: the validated document)\n");
    return 0;
  }});
}

}  // namespace pkmws::cli
