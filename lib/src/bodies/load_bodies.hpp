// The optional `bodies` field of MOMA and five-bar files (docs/format.md (bodies)). Private.
#pragma once

#include <memory>

#include "io/json_reader.hpp"
#include "pkmws/bodies/bodies.hpp"

namespace pkmws::io::detail {

/// Reads document["bodies"] for the mechanism; throws InputError with the field path.
std::shared_ptr<const bodies::BodyRig> load_bodies(JsonReader& document,
                                                   const std::shared_ptr<const mechanisms::Mechanism>& mechanism);

}  // namespace pkmws::io::detail
