// The optional `bodies` field of MOMA and five-bar files (docs/format.md (bodies)). Private.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "io/json_reader.hpp"
#include "pkmws/bodies/bodies.hpp"

namespace pkmws::bodies {

/// Capability (Mechanism::capability): a mechanism whose parts can be
/// modelled (docs/format.md (bodies)). Its module reads the parts only it has
/// and builds the rig; load_bodies reads what every rig shares.
struct RigFactory {
  static constexpr std::string_view capability_name =
      "body model (bodies are supported for moma and five_bar mechanisms only)";
  virtual ~RigFactory() = default;
  /// The mechanism's own keys of `bodies` (besides platform_joint, obstacles, allowed_contacts).
  virtual std::vector<std::string> part_fields() const = 0;
  /// Reads those parts into `model` (after the platform joint, before the obstacles).
  virtual void read_parts(io::detail::JsonReader& bodies, BodyModel& model) const = 0;
  /// The rig of `self` (the mechanism that offered this capability).
  virtual std::shared_ptr<const BodyRig> make(std::shared_ptr<const mechanisms::Mechanism> self,
                                              BodyModel model) const = 0;
};

}  // namespace pkmws::bodies

namespace pkmws::io::detail {

/// A length of a part: positive or non-negative, at most 1e15 in magnitude.
double part_length(JsonReader& r, const std::string& key, bool positive);
/// A part of leg `leg` (-1: none) with its name and kind.
bodies::Part leg_part(std::string name, bodies::PartKind kind, int leg);
/// Two capsule links [{radius} x 2] under `key`, named stem1, stem2.
void read_capsules(JsonReader& bodies, const std::string& key, const std::string& stem, bool proximal,
                   bodies::BodyModel& model);

/// Reads document["bodies"] for the mechanism; throws InputError with the field path.
std::shared_ptr<const bodies::BodyRig> load_bodies(JsonReader& document,
                                                   const std::shared_ptr<const mechanisms::Mechanism>& mechanism);

}  // namespace pkmws::io::detail
