// One loader per mechanism keyword. Each reads its own parameters from the
// document reader (common fields are read by load_mechanism) and validates
// every value, throwing InputError with the field path. Private.
#pragma once

#include <memory>

#include "io/json_reader.hpp"
#include "pkmws/mechanisms/mechanism.hpp"

namespace pkmws::io::detail {

using MechanismPtr = std::shared_ptr<const mechanisms::Mechanism>;

MechanismPtr load_moma(JsonReader& document);
MechanismPtr load_five_bar(JsonReader& document);
MechanismPtr load_biglide(JsonReader& document);
MechanismPtr load_pi_joint(JsonReader& document);
MechanismPtr load_three_rrp(JsonReader& document);
MechanismPtr load_three_prp(JsonReader& document);
MechanismPtr load_three_rpr(JsonReader& document);

}  // namespace pkmws::io::detail
