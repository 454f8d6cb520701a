// The five-bar module's capabilities: criterion fields (criteria.cpp) and a
// body model (rig.cpp).
#include "io/load_bodies.hpp"
#include "mechanisms/five_bar/criteria.hpp"
#include "mechanisms/five_bar/five_bar.hpp"

namespace pkmws::bodies {
std::shared_ptr<const RigFactory> five_bar_rig_factory();  // rig.cpp
}

namespace pkmws::mechanisms {

Offer FiveBar::provide(std::type_index which) const {
  if (Offer::asks<criteria::CriterionFields>(which)) return Offer::owned(criteria::five_bar_fields(*this));
  if (Offer::asks<bodies::RigFactory>(which)) return Offer::owned(bodies::five_bar_rig_factory());
  return Mechanism::provide(which);
}

}  // namespace pkmws::mechanisms
