// `pkmws explain` (pkmws/report/explain.hpp): moved from the command line's
// explain.cpp, JSON and text unchanged.
#include "pkmws/report/explain.hpp"

#include <numbers>

#include "pkmws/report/area.hpp"
#include "report/json.hpp"
#include "report/text.hpp"

namespace pkmws::report {

using detail::Json;

namespace detail {

Json collisions_json(const ExplainReport& r) {
  const auto& check = r.check;
  Json out{{"reachable", check.reachable}, {"collides", check.collides()}};
  Json hits = Json::array(), pairs = Json::array();
  for (const auto& c : check.contacts) {
    Json j{{"parts", {c.a, c.b}}, {"kind", c.kind}, {"collides", c.collides}};
    if (c.kind == "link_angle") {
      j["angle_margin_deg"] = c.clearance * 180.0 / std::numbers::pi;
    } else {
      j["clearance"] = c.clearance;
    }
    pairs.push_back(j);
    if (c.collides) hits.push_back(pair_label(c.a, c.b, c.kind));
  }
  out["collisions"] = hits;
  out["pairs"] = pairs;
  if (!check.reachable) out["reason"] = "not in the reachable workspace (inverse kinematics or a stroke fails)";
  return out;
}

}  // namespace detail

namespace {

Json explain_json(const ExplainReport& r) {
  Json out = detail::collisions_json(r);
  out["name"] = r.name;
  out["mechanism"] = r.mechanism;
  out["point"] = {r.point.x, r.point.y};
  out["units"] = r.units;
  return out;
}

}  // namespace

ExplainReport explain(const io::MechanismFile& file, geometry::Point p) {
  if (!file.bodies) {
    throw io::InputError(file.path + ": the file lists no `bodies` (docs/format.md (bodies)): nothing can collide");
  }
  return {file.name, file.mechanism, file.units, p, bodies::check_pose(*file.bodies, p)};
}

std::string to_json_text(const ExplainReport& r) { return detail::json_text(explain_json(r)); }

std::string to_text(const ExplainReport& r) {
  using detail::format;
  const Json out = explain_json(r);
  std::string t = format("%s at (%.6g, %.6g) %s\n", r.name.c_str(), r.point.x, r.point.y, r.units.c_str());
  if (!out["reachable"].get<bool>()) {
    return t + format("not reachable: %s\n", out["reason"].get<std::string>().c_str());
  }
  t += format("%s\n", out["collides"].get<bool>() ? "COLLISION" : "no collision");
  for (const auto& p : out["pairs"]) {
    const std::string label = pair_label(p["parts"][0], p["parts"][1], p["kind"]);
    if (p["kind"] == "link_angle") {
      t += format("  %-28s %s  angle %+.4g deg from the minimum\n", label.c_str(),
                  p["collides"].get<bool>() ? "collide" : "clear  ", p["angle_margin_deg"].get<double>());
    } else {
      t += format("  %-28s %s  clearance %+.6g %s\n", label.c_str(), p["collides"].get<bool>() ? "collide" : "clear  ",
                  p["clearance"].get<double>(), r.units.c_str());
    }
  }
  return t;
}

}  // namespace pkmws::report
