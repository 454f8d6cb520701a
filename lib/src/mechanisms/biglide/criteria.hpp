// The biglide module's criterion fields (capability criteria::CriterionFields).
#pragma once

#include <memory>

#include "mechanisms/biglide/biglide.hpp"
#include "pkmws/criteria/fields.hpp"

namespace pkmws::criteria {

/// Biglide velocity ratio V_i / V_y = |∂q_i/∂y| of leg `leg` (0-based; [Strutynskyi]
/// fig. 8), paper's branches; surrogate (∂q_i/∂y)².
CriterionField biglide_velocity_ratio(const mechanisms::Biglide& mechanism, int leg);
/// Condition number of dq/dP (rows (1, ∂q_i/∂y)), paper's branches.
CriterionField biglide_condition_number(const mechanisms::Biglide& mechanism);
/// Simplified scheme: pressure angle α = acos|sin ε| of the rods (degrees, both
/// legs alike; [Briot]), the angle ε between the rods as `pkmws eval` gives it.
CriterionField biglide_pressure_angle(const mechanisms::Biglide& mechanism);
/// Simplified scheme: reaction f / |sin ε| in both rods (N) for a force of norm
/// `force_N` (no moment reaches the tool point).
CriterionField biglide_reaction(const mechanisms::Biglide& mechanism, double force_N);
/// The capability object (valid while `mechanism` lives).
std::shared_ptr<const CriterionFields> biglide_fields(const mechanisms::Biglide& mechanism);

}  // namespace pkmws::criteria
