// `pkmws info`: the parsed mechanism, its validated document with `derived`
// (dof, joints, parameters by field path, bounds, collision pairs;
// docs/schema/info.output.schema.json).
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "pkmws/geometry/types.hpp"
#include "pkmws/io/mechanism_file.hpp"
#include "pkmws/io/parameters.hpp"
#include "pkmws/report/kinematics.hpp"

namespace pkmws::report {

struct InfoReport {
  MechanismHeader header;
  std::string document;                       // the validated document (JSON text)
  std::vector<io::Parameter> parameters;      // every number by field path, with type and unit
  std::optional<geometry::Box> bounds;        // absent for a workspace without bound, with the reason
  std::string bounds_reason;
  std::optional<std::vector<std::pair<std::string, std::string>>> collision_pairs;  // files with bodies
  double orientation = 0.0;                   // radians (3-DOF: the workspace's)
  std::string description;
};
InfoReport info(const io::MechanismFile& file);

std::string to_json_text(const InfoReport& report);
std::string to_text(const InfoReport& report);

}  // namespace pkmws::report
