// The five_bar module's criterion fields (capability criteria::CriterionFields).
#pragma once

#include <memory>

#include "mechanisms/five_bar/five_bar.hpp"
#include "pkmws/criteria/fields.hpp"

namespace pkmws::criteria {

/// Five-bar (any link lengths; crank limits bound the workspace): α in degrees.
CriterionField five_bar_pressure_angle(const mechanisms::FiveBar& mechanism);
/// Five-bar reaction f / |sin ε| (N) for a force of norm `force_N`.
CriterionField five_bar_reaction(const mechanisms::FiveBar& mechanism, double force_N);
/// Velocity ratio: the largest singular value of dq/dC (worst-case |dq| / |dC|,
/// as `pkmws eval` reports it).
CriterionField five_bar_velocity_ratio(const mechanisms::FiveBar& mechanism);
/// Condition number κ = σ_max / σ_min of dq/dC.
CriterionField five_bar_condition_number(const mechanisms::FiveBar& mechanism);
/// The capability object (valid while `mechanism` lives).
std::shared_ptr<const CriterionFields> five_bar_fields(const mechanisms::FiveBar& mechanism);

}  // namespace pkmws::criteria
