// `pkmws info` (pkmws/report/info.hpp): moved from the command line's info.cpp,
// JSON and text unchanged.
#include "pkmws/report/info.hpp"

#include <numbers>
#include <stdexcept>

#include "report/json.hpp"
#include "report/text.hpp"

namespace pkmws::report {

using detail::Json;

namespace {

Json info_json(const InfoReport& r) {
  Json out = Json::parse(r.document);
  Json derived{{"dof", r.header.dof}};
  derived.update(detail::joint_vocabulary(r.header.joints, r.header.units));
  // The parameter model (pkmws/io/parameters.hpp): every number by field path, with type and unit.
  Json parameters = Json::array();
  for (const auto& p : r.parameters) {
    parameters.push_back({{"path", p.path}, {"value", p.value}, {"type", p.type}, {"unit", p.unit}});
  }
  derived["parameters"] = parameters;
  out["derived"] = derived;
  if (r.bounds) {
    const auto& b = *r.bounds;
    out["derived"]["bounds"] = {{"min", {b.min.x, b.min.y}}, {"max", {b.max.x, b.max.y}}};
  } else {
    out["derived"]["bounds"] = nullptr;
    out["derived"]["bounds_reason"] = r.bounds_reason;
  }
  if (r.collision_pairs) {
    // docs/format.md (bodies): the pairs checked for collision (joined and allowed pairs excluded).
    Json pairs = Json::array();
    for (const auto& [a, b] : *r.collision_pairs) pairs.push_back({a, b});
    out["derived"]["collision_pairs"] = pairs;
  }
  return out;
}

}  // namespace

InfoReport info(const io::MechanismFile& mech) {
  InfoReport r;
  r.header = header_of(mech);
  r.document = io::document_text(mech);
  r.parameters = io::parameters(mech);
  try {
    r.bounds = mech.model->bounds();
  } catch (const std::runtime_error& e) {
    // A valid file whose workspace has no bound (a 3-RPR without leg limits,
    // a 3-PRP without strokes): say so instead of refusing the file.
    r.bounds_reason = e.what();
  }
  if (mech.bodies) {
    const auto& m = mech.bodies->model();
    r.collision_pairs.emplace();
    for (const auto& p : m.pairs()) {
      r.collision_pairs->emplace_back(m.parts[static_cast<std::size_t>(p.a)].name,
                                      m.parts[static_cast<std::size_t>(p.b)].name);
    }
  }
  r.orientation = mech.model->orientation();
  r.description = mech.description;
  return r;
}

std::string to_json_text(const InfoReport& r) { return detail::json_text(info_json(r)); }

std::string to_text(const InfoReport& r) {
  using detail::format;
  const Json out = info_json(r);
  const Json& d = out["derived"];
  const std::string& units = r.header.units;
  std::string t = format("%s (%s): lengths in %s, angles in deg\n", r.header.name.c_str(), r.header.mechanism.c_str(),
                         units.c_str());
  std::string joints;
  for (const auto& n : d["joint_names"]) {
    const std::string name = n.get<std::string>();
    joints += (joints.empty() ? "" : ", ") + name + " (" + d["joint_units"][name].get<std::string>() + ")";
  }
  t += format("dof        %d\njoints     %s\n", d["dof"].get<int>(), joints.c_str());
  if (d["bounds"].is_null()) {
    t += format("bounds     none: %s\n", d["bounds_reason"].get<std::string>().c_str());
  } else {
    const auto& b = d["bounds"];
    t += format("bounds     x %.10g .. %.10g %s, y %.10g .. %.10g %s\n", b["min"][0].get<double>(),
                b["max"][0].get<double>(), units.c_str(), b["min"][1].get<double>(), b["max"][1].get<double>(),
                units.c_str());
  }
  if (r.header.dof == 3) {
    t += format("orientation %.10g deg (the workspace's; the default PHI_DEG of ik and eval)\n",
                r.orientation * 180.0 / std::numbers::pi);
  }
  t += format("parameters %zu numbers by field path (--json: derived.parameters, with units)\n", d["parameters"].size());
  if (d.contains("collision_pairs")) t += format("collision pairs %zu\n", d["collision_pairs"].size());
  if (!r.description.empty()) t += format("%s\n", r.description.c_str());
  t += "(--json: the validated document)\n";
  return t;
}

}  // namespace pkmws::report
