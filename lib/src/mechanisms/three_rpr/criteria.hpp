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
/// 3-RPR velocity ratio at the file orientation: the largest singular value of
/// dq/dx', x' = (x, y, L φ), as `pkmws eval` gives it; L from criteria.characteristic_length
/// or the platform's (three_rpr_characteristic_length).
CriterionField three_rpr_velocity_ratio(const mechanisms::ThreeRpr& mechanism, const mechanisms::Criteria& criteria);
/// 3-RPR condition number κ = σ_max / σ_min of dq/dx' (same L).
CriterionField three_rpr_condition_number(const mechanisms::ThreeRpr& mechanism, const mechanisms::Criteria& criteria);
/// L: the file's criteria.characteristic_length, else the largest distance
/// from the platform's centroid to its joints (the circumradius of PAMINSA's
/// equilateral platform).
double three_rpr_characteristic_length(const mechanisms::ThreeRpr& mechanism, const mechanisms::Criteria& criteria);
/// The capability object (valid while `mechanism` lives).
std::shared_ptr<const CriterionFields> three_rpr_fields(const mechanisms::ThreeRpr& mechanism);

}  // namespace pkmws::criteria
