// Shared pieces of the grid samplers (private).
#pragma once

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include "detail/parallel.hpp"
#include "pkmws/grid/sampler.hpp"

namespace pkmws::grid::detail {

using Clock = std::chrono::steady_clock;

inline double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

inline pkmws::detail::ParallelPolicy policy_of(const Execution& e) {
  if (e.threads < 0) throw std::invalid_argument("grid: threads must be >= 0 (0 = all)");
  pkmws::detail::ParallelPolicy p;
  p.threads = e.threads;
  return p;
}

/// The box to sample: the given one or the mechanism's bounds; must be finite
/// and non-degenerate.
inline Box sample_box(const mechanisms::Mechanism& m, const std::optional<Box>& box) {
  const Box b = box ? *box : m.bounds();
  if (b.empty() || !(b.width() > 0.0) || !(b.height() > 0.0) || !std::isfinite(b.width()) ||
      !std::isfinite(b.height())) {
    throw std::invalid_argument("grid: the sampling box is empty or not finite");
  }
  return b;
}

inline void fill_common(SampleResult& r, const MembershipKernel& k, std::string method) {
  r.method = std::move(method);
  r.kernel = std::string(k.name());
  r.isa = std::string(to_string(k.isa()));
}

inline void set_rate(SampleResult& r) {
  const double ms = r.time_ms - r.bounds_time_ms;
  r.points_per_second = ms > 0.0 ? double(r.points_tested) / (ms * 1e-3) : 0.0;
}

}  // namespace pkmws::grid::detail
