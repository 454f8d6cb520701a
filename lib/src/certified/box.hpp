// The box [x0, x1] x [y0, y1] (private to the certified layer: the level-set
// tracer and the zero-set tracer split cells with it).
#pragma once

#include "pkmws/geometry/types.hpp"

namespace pkmws::certified {

inline geometry::Box make_box(double x0, double y0, double x1, double y1) {
  geometry::Box b;
  b.min = {x0, y0};
  b.max = {x1, y1};
  return b;
}

}  // namespace pkmws::certified
