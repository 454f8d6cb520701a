#include "report/json.hpp"

#include "pkmws/report/common.hpp"

#include <vector>

namespace pkmws::report::detail {

namespace {

void give_nulls_reasons(Json& j, bool reason_in_scope) {
  if (j.is_array()) {
    for (auto& e : j) give_nulls_reasons(e, reason_in_scope);
    return;
  }
  if (!j.is_object()) return;
  const bool scope = reason_in_scope || (j.contains("reason") && j["reason"].is_string());
  std::vector<std::string> missing;
  for (auto it = j.begin(); it != j.end(); ++it) {
    bool holds_null = it.value().is_null();
    if (it.value().is_array()) {
      for (const auto& e : it.value()) holds_null = holds_null || e.is_null();
    }
    if (holds_null && !scope && !j.contains(it.key() + "_reason")) missing.push_back(it.key());
    give_nulls_reasons(it.value(), scope);
  }
  for (const auto& k : missing) j[k + "_reason"] = "undefined here (not a finite number)";
}

}  // namespace

std::string json_text(Json j) {
  give_nulls_reasons(j, false);
  return j.dump(2);
}

Json point_json(geometry::Point p) { return Json::array({p.x, p.y}); }

Json box_json(const geometry::Box& b) { return Json{{"min", point_json(b.min)}, {"max", point_json(b.max)}}; }

Json joint_vocabulary(const std::vector<mechanisms::JointInfo>& joints, const std::string& length_unit) {
  Json names = Json::array(), units = Json::object();
  for (const auto& j : joints) {
    names.push_back(j.name);
    units[j.name] = j.angle ? "deg" : length_unit;
  }
  return Json{{"joint_names", names}, {"joint_units", units}};
}

}  // namespace pkmws::report::detail

namespace pkmws::report {

std::string json_with_null_reasons(const std::string& json_text) {
  return detail::json_text(detail::Json::parse(json_text));
}

}  // namespace pkmws::report
