// The MOMA module's criterion fields (capability criteria::CriterionFields).
#pragma once

#include <memory>

#include "mechanisms/moma/moma.hpp"
#include "pkmws/criteria/fields.hpp"

namespace pkmws::criteria {

/// Pressure angle α = acos|sin ε| of the rods (ε the angle between them), in degrees.
CriterionField moma_pressure_angle(const mechanisms::Moma& mechanism);
/// Reaction f / |sin ε| in each rod (N) for a force of norm `force_N`.
CriterionField moma_reaction(const mechanisms::Moma& mechanism, double force_N);
/// Velocity ratio: the largest singular value of dq/dP (worst-case |dq| / |dP|,
/// as `pkmws eval` reports it).
CriterionField moma_velocity_ratio(const mechanisms::Moma& mechanism);
/// Condition number κ = σ_max / σ_min of dq/dP (as `pkmws eval` reports it).
CriterionField moma_condition_number(const mechanisms::Moma& mechanism);
/// The capability object (valid while `mechanism` lives).
std::shared_ptr<const CriterionFields> moma_fields(const mechanisms::Moma& mechanism);

}  // namespace pkmws::criteria
