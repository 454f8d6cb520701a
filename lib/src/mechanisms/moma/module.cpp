// The MOMA module's capabilities: rod-on-guide legs (the vectorised grid
// kernel), criterion fields (criteria.cpp) and a body model (rig.cpp).
#include "io/load_bodies.hpp"
#include "mechanisms/moma/criteria.hpp"
#include "mechanisms/moma/moma.hpp"

namespace pkmws::bodies {
std::shared_ptr<const RigFactory> moma_rig_factory();  // rig.cpp
}

namespace pkmws::mechanisms {

Offer Moma::provide(std::type_index which) const {
  if (Offer::asks<GuidedRodLegs>(which)) return Offer::of<GuidedRodLegs>(this);
  if (Offer::asks<criteria::CriterionFields>(which)) return Offer::owned(criteria::moma_fields(*this));
  if (Offer::asks<bodies::RigFactory>(which)) return Offer::owned(bodies::moma_rig_factory());
  return Mechanism::provide(which);
}

}  // namespace pkmws::mechanisms
