// The criteria-limited workspace of a file for tests: traced (the method) or
// cells only (a shallow quadtree: wide but independent bounds).
#pragma once

#include "pkmws/criteria/fields.hpp"
#include "pkmws/io/mechanism_file.hpp"

namespace pkmws::test {

inline criteria::LimitedWorkspace limited(const io::MechanismFile& f, double tol, bool trace) {
  certified::LevelSetOptions o;
  o.relative_tolerance = tol;
  o.trace = trace;
  if (!trace) o.refine_depth = 4;
  return criteria::limited_workspace(f, criteria::file_limits(f), o);
}

// Traced, on `threads` threads (the file's limits, default options otherwise).
inline criteria::LimitedWorkspace limited_on(const io::MechanismFile& f, double tol, int threads) {
  certified::LevelSetOptions o;
  o.relative_tolerance = tol;
  o.threads = threads;
  return criteria::limited_workspace(f, criteria::file_limits(f), o);
}

}  // namespace pkmws::test
