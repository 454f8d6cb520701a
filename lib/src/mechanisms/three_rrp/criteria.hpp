// The three_rrp module's criterion fields (capability criteria::CriterionFields):
// 3-RRP and 3-PRP at the file orientation.
#pragma once

#include <memory>

#include "mechanisms/three_rrp/three_rrp.hpp"
#include "pkmws/criteria/fields.hpp"

namespace pkmws::criteria {

/// Pressure angle α_i of chain `leg` (0-based), degrees: the angle between the
/// force line (through A_i along the side's normal n_i) and the velocity of A_i
/// with only actuator i free ([Briot]), as `pkmws eval` gives it.
CriterionField three_rrp_pressure_angle(const mechanisms::ThreeRrp& mechanism, int leg);
/// R_i,max of chain `leg` (0-based) for the load, N ([Briot]; docs/theory/three_dof.md).
CriterionField three_rrp_reaction(const mechanisms::ThreeRrp& mechanism, const mechanisms::Load& load, int leg);
/// Largest singular value of dq/dx', x' = (x, y, L φ) (velocity ratio, as `pkmws eval`).
CriterionField three_rrp_velocity_ratio(const mechanisms::ThreeRrp& mechanism, const mechanisms::Criteria& criteria);
/// Condition number κ of dq/dx' (same L).
CriterionField three_rrp_condition_number(const mechanisms::ThreeRrp& mechanism, const mechanisms::Criteria& criteria);
/// The capability object (valid while `mechanism` lives).
std::shared_ptr<const CriterionFields> three_rrp_fields(const mechanisms::ThreeRrp& mechanism);

}  // namespace pkmws::criteria
