// The biglide module's capabilities: velocity-ratio criterion fields (criteria.cpp).
#include "mechanisms/biglide/biglide.hpp"
#include "mechanisms/biglide/criteria.hpp"

namespace pkmws::mechanisms {

Offer Biglide::provide(std::type_index which) const {
  if (Offer::asks<criteria::CriterionFields>(which)) return Offer::owned(criteria::biglide_fields(*this));
  return Mechanism::provide(which);
}

}  // namespace pkmws::mechanisms
