// The pieces of a charted criteria-limited workspace for figures (shared by
// the area figure and the band figure; implemented in area.cpp).
#pragma once

#include <vector>

#include "pkmws/certified/level_set.hpp"
#include "pkmws/criteria/fields.hpp"

namespace pkmws::report {

/// A figure draws pieces in (x, y), which the charts' parts do not give:
/// `detail`'s pieces (inside boxes, inner polygons, undecided boxes) are
/// replaced by those of the same set traced in (x, y) alone, to the drawing's
/// accuracy: one pass, cells refined 3 levels below the cover's (1/8 of a
/// leaf, 0.2 mm for the DexTAR: under a pixel), curves traced to 1e-4 of the
/// area (DexTAR α ≤ 80°: 0.60 s instead of 1.64 s; the inner bound drawn
/// within 6.5e-4 of the area). `o`: the charted run's options; the numbers
/// stay the charted ones.
void plane_figure_pieces(const mechanisms::Design& file, const std::vector<criteria::Limit>& limits,
                         certified::LevelSetOptions o, certified::LevelSetResult& detail);

}  // namespace pkmws::report
