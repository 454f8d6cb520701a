// The three_rpr module's criterion fields (capability criteria::CriterionFields).
#pragma once

#include <memory>
#include <optional>

#include "mechanisms/three_rpr/three_rpr.hpp"
#include "pkmws/criteria/fields.hpp"

namespace pkmws::criteria {

/// 3-RPR at its file orientation: R_i,max of leg `leg` (0-based), N. With
/// `assembly_reference`, the surrogate's box enclosures count only the assembly
/// mode of that point (the field must then come with three_rpr_assembly_mode of
/// the same point): boxes across the type-2 singular curve are then decided.
CriterionField three_rpr_reaction(const mechanisms::ThreeRpr& mechanism, const mechanisms::Load& load, int leg,
                                  std::optional<geometry::Point> assembly_reference = std::nullopt);
/// 3-RPR assembly mode of `reference`: field -sign(det A(reference)) det A'
/// (<= 0 on the side of the type-2 singularity curve that holds `reference`).
CriterionField three_rpr_assembly_mode(const mechanisms::ThreeRpr& mechanism, geometry::Point reference);
/// 3-RPR pressure angle α_i of leg `leg` (0-based), degrees.
CriterionField three_rpr_pressure_angle(const mechanisms::ThreeRpr& mechanism, int leg);
/// The capability object (valid while `mechanism` lives).
std::shared_ptr<const CriterionFields> three_rpr_fields(const mechanisms::ThreeRpr& mechanism);

}  // namespace pkmws::criteria
