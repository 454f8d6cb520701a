// Five-bar test fixtures: DexTAR ([Briot]) built in code.
#pragma once

#include "mechanisms/five_bar/five_bar.hpp"

namespace pkmws::test::five_bar {

inline constexpr double L = 0.23, A = 0.1375;  // DexTAR ([Briot])

/// DexTAR in working mode (s1, s2): bases (-+A, 0), proximal and distal links L.
inline mechanisms::FiveBar dextar(int s1, int s2) {
  using mechanisms::FiveBarLeg;
  return mechanisms::FiveBar({FiveBarLeg{{-A, 0}, L, L, s1, {}, {}}, FiveBarLeg{{A, 0}, L, L, s2, {}, {}}});
}

}  // namespace pkmws::test::five_bar
