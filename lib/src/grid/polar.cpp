// Polar grid ([Vasilic] §4.2, fig. 8 with polar q1 = r, q2 = theta; figs. 9,
// 10, 11a): the IK test at one point per ring-sector cell about a centre.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "grid/common.hpp"
#include "pkmws/grid/sampler.hpp"

namespace pkmws::grid {

PolarResult polar(const mechanisms::Mechanism& mechanism, const PolarOptions& options,
                  const Execution& execution) {
  const auto start = detail::Clock::now();
  if (options.rings == 0 || options.sectors == 0) throw std::invalid_argument("grid: rings and sectors must be positive");
  if (options.sectors > (std::size_t{1} << 31) || options.rings > (std::size_t{1} << 31)) {
    throw std::invalid_argument("grid: at most 2^31 rings and sectors");
  }
  const MembershipKernel kernel(mechanism, {execution.isa, execution.phi});
  const auto policy = detail::policy_of(execution);
  PolarResult r;
  detail::fill_common(r, kernel, "polar");
  const Box bounds = detail::sample_box(mechanism, std::nullopt);
  r.centre = options.centre ? *options.centre
                            : geometry::Point{0.5 * (bounds.min.x + bounds.max.x), 0.5 * (bounds.min.y + bounds.max.y)};
  if (options.radius) {
    r.radius = *options.radius;
  } else {
    for (const geometry::Point c : {bounds.min, bounds.max, geometry::Point{bounds.min.x, bounds.max.y},
                                    geometry::Point{bounds.max.x, bounds.min.y}}) {
      r.radius = std::max(r.radius, geometry::norm(c - r.centre));
    }
  }
  if (!(r.radius > 0.0) || !std::isfinite(r.radius) || !std::isfinite(r.centre.x) || !std::isfinite(r.centre.y)) {
    throw std::invalid_argument("grid: the polar radius must be positive and finite");
  }
  const std::size_t nr = options.rings, ns = options.sectors;
  const double dr = r.radius / double(nr);                         // ring width (unit)
  const double dth = 2.0 * std::numbers::pi / double(ns);          // sector angle (rad)
  std::vector<double> cos_t(ns), sin_t(ns);
  for (std::size_t j = 0; j < ns; ++j) {
    const double th = (double(j) + 0.5) * dth;
    cos_t[j] = std::cos(th);
    sin_t[j] = std::sin(th);
  }
  auto ring_in = [&](std::size_t k) { return double(k) * dr; };
  auto ring_out = [&](std::size_t k) { return double(k + 1) * dr; };
  // Sample radius: halves the cell's area, so straight boundaries through the
  // cell are weighted like the centre test of a Cartesian cell.
  auto ring_sample = [&](std::size_t k) {
    const double a = ring_in(k), b = ring_out(k);
    return std::sqrt(0.5 * (a * a + b * b));
  };
  auto cell_area = [&](std::size_t k) {
    const double a = ring_in(k), b = ring_out(k);
    return 0.5 * (b * b - a * a) * dth;
  };
  if (options.keep_mask) r.mask.assign(nr * ns, 0);

  const std::size_t rings_per_block = std::max<std::size_t>(1, (std::size_t{1} << 16) / ns);
  const std::size_t work = nr * ns * (kernel.vectorised() ? 1 : 64);
  const std::size_t blocks = pkmws::detail::block_count(nr, rings_per_block);
  r.threads = pkmws::detail::threads_for(policy, blocks, work);
  std::vector<std::uint64_t> per_ring(nr, 0);
  pkmws::detail::for_each_block(policy, blocks, work, [&](std::size_t b) {
    std::vector<double> xs(ns), ys(ns);
    std::vector<std::uint8_t> local(options.keep_mask ? 0 : ns);
    const std::size_t k_end = std::min(nr, (b + 1) * rings_per_block);
    for (std::size_t k = b * rings_per_block; k < k_end; ++k) {
      const double rho = ring_sample(k);
      for (std::size_t j = 0; j < ns; ++j) {
        xs[j] = r.centre.x + rho * cos_t[j];
        ys[j] = r.centre.y + rho * sin_t[j];
      }
      std::uint8_t* m = options.keep_mask ? r.mask.data() + k * ns : local.data();
      kernel.points(xs.data(), ys.data(), ns, m);
      std::uint64_t c = 0;
      for (std::size_t j = 0; j < ns; ++j) c += m[j];
      per_ring[k] = c;
    }
  });
  for (std::size_t k = 0; k < nr; ++k) {  // ring order: deterministic sum
    r.inside += per_ring[k];
    r.area += double(per_ring[k]) * cell_area(k);
  }
  r.cells = std::uint64_t(nr) * ns;
  r.points_tested = r.cells;

  if (options.certified_bounds && kernel.certified()) {
    const auto bounds_start = detail::Clock::now();
    std::vector<std::uint64_t> sure(nr, 0), unsure(nr, 0);
    pkmws::detail::for_each_block(policy, blocks, work, [&](std::size_t b) {
      std::vector<double> xs(ns), ys(ns);
      std::vector<std::int8_t> state(ns);
      const std::size_t k_end = std::min(nr, (b + 1) * rings_per_block);
      for (std::size_t k = b * rings_per_block; k < k_end; ++k) {
        const double rho = ring_sample(k);
        // The farthest point of the cell from its sample is a corner
        // (distance to a point on an arc or a radial edge is extreme at its ends).
        const double c = std::cos(0.5 * dth);
        double radius = 0.0;
        for (const double rr : {ring_in(k), ring_out(k)}) {
          radius = std::max(radius, std::sqrt(std::max(0.0, rho * rho + rr * rr - 2.0 * rho * rr * c)));
        }
        radius *= 1.0 + 1e-12;
        for (std::size_t j = 0; j < ns; ++j) {
          xs[j] = r.centre.x + rho * cos_t[j];
          ys[j] = r.centre.y + rho * sin_t[j];
        }
        kernel.classify(xs.data(), ys.data(), ns, radius, state.data());
        for (const std::int8_t s : state) {
          sure[k] += s == cell_inside;
          unsure[k] += s == cell_undecided;
        }
      }
    });
    double lower = 0.0, upper = 0.0;
    for (std::size_t k = 0; k < nr; ++k) {
      lower += double(sure[k]) * cell_area(k);
      upper += double(sure[k] + unsure[k]) * cell_area(k);
    }
    r.area_lower = lower;
    r.area_upper = upper;
    r.bounds_certified = true;
    r.bounds_time_ms = detail::ms_since(bounds_start);
  }
  r.time_ms = detail::ms_since(start);
  detail::set_rate(r);
  return r;
}

}  // namespace pkmws::grid
