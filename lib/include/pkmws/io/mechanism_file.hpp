// Mechanism files (docs/format.md): JSON with `name`, `mechanism`, `units`, the
// mechanism's parameters and optional `criteria`, `source`, `description`.
#pragma once

#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pkmws/mechanisms/mechanism.hpp"

namespace pkmws::bodies {
class BodyRig;  // pkmws/bodies/bodies.hpp
}

namespace pkmws::io {

/// Bad input: the message is one line naming the problem (and the field path).
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct MechanismFile {
  std::string path;
  std::string name;
  std::string mechanism;        // the file's `mechanism` keyword
  std::string units;            // "mm" or "m"
  std::string description;
  nlohmann::json source;        // paper, figure, notes (free-form object), null if absent
  mechanisms::Criteria criteria;
  /// criteria.reaction_legs: the legs (1-based) whose R_i,max is limited by
  /// max_reaction_N ([Briot] figs. 12-13 limit the joint B_1 only); empty: every leg.
  std::vector<int> reaction_legs;
  nlohmann::json document;      // the validated document as read
  std::shared_ptr<const mechanisms::Mechanism> model;
  /// The optional `bodies` (docs/format.md (bodies); moma and five_bar), null when absent.
  std::shared_ptr<const bodies::BodyRig> bodies;
};

/// Parse and validate; throws InputError with the field's path on any problem.
MechanismFile load_mechanism(const std::filesystem::path& path);
MechanismFile parse_mechanism(const nlohmann::json& document, const std::string& origin);

}  // namespace pkmws::io
