// The JSON side of the reports, private to the library (and its tests):
// nlohmann-json is not in any public header.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pkmws/geometry/types.hpp"
#include "pkmws/mechanisms/mechanism.hpp"

namespace pkmws::report {
struct ExplainReport;   // pkmws/report/explain.hpp
struct CriterionLimit;  // pkmws/report/area.hpp
}

namespace pkmws::report::detail {

using Json = nlohmann::json;

/// The text of a JSON report, indented by 2, after the contract of every
/// report: no bare null. A null (or an array holding one) at `key` comes with
/// `key`_reason, or lies in an object that has a `reason` (an unreachable
/// mode); a null that slipped through without one gets a generic reason.
std::string json_text(Json j);

Json point_json(geometry::Point p);
Json box_json(const geometry::Box& b);

/// `joint_names` (in the order `dk` takes them) and `joint_units` (name ->
/// "deg" or the file's length unit `units`) of docs/format.md (output vocabulary).
Json joint_vocabulary(const std::vector<mechanisms::JointInfo>& joints, const std::string& units);

/// The pose-level collision test as `explain` and `eval` report it: reachable,
/// collides, collisions ["a / b", ...], pairs [{parts, kind, clearance, collides}].
Json collisions_json(const ExplainReport& report);
/// {"criterion", "threshold"[, "characteristic_length"]} of a criteria limit (area, batch).
Json criterion_limit_json(const CriterionLimit& limit);

}  // namespace pkmws::report::detail
