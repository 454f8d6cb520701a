// pkmws info FILE: the parsed mechanism.
#include <stdexcept>

#include "bodies_cli.hpp"

namespace pkmws::cli {

void add_info(CLI::App& app, std::vector<Command>& commands) {
  auto* sub = app.add_subcommand("info", "Print the parsed mechanism");
  auto file = std::make_shared<std::string>();
  sub->add_option("FILE", *file, "Mechanism file (JSON)")->required();
  commands.push_back({sub, [file] {
    const auto mech = io::load_mechanism(*file);
    Json out = mech.document;
    Json joints = Json::array();
    for (const auto& j : mech.model->joints()) {
      joints.push_back(Json{{"name", j.name}, {"unit", j.angle ? "deg" : mech.units}});
    }
    out["derived"] = Json{{"dof", mech.model->dof()}, {"joints", joints}};
    try {
      const auto b = mech.model->bounds();
      out["derived"]["bounds"] = {{"min", {b.min.x, b.min.y}}, {"max", {b.max.x, b.max.y}}};
    } catch (const std::runtime_error& e) {
      // A valid file whose workspace has no bound (a 3-RPR without leg limits,
      // a 3-PRP without strokes): say so instead of refusing the file.
      out["derived"]["bounds"] = nullptr;
      out["derived"]["unbounded"] = e.what();
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
    print_json(out);
    return 0;
  }});
}

}  // namespace pkmws::cli
