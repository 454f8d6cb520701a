// Cartesian grid ([Vasilic] §4.2, fig. 8 with Cartesian q1, q2): the IK test at
// every cell centre; area = inside count x cell area.
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "grid/common.hpp"
#include "pkmws/grid/sampler.hpp"

namespace pkmws::grid {

CartesianResult cartesian(const mechanisms::Mechanism& mechanism, const CartesianOptions& options,
                          const Execution& execution) {
  const auto start = detail::Clock::now();
  if (options.cells_x == 0 || options.cells_y == 0) throw std::invalid_argument("grid: cells must be positive");
  if (options.cells_x > (std::size_t{1} << 31) || options.cells_y > (std::size_t{1} << 31)) {
    throw std::invalid_argument("grid: at most 2^31 cells per side");
  }
  const MembershipKernel kernel(mechanism, {execution.isa, execution.phi});
  const auto policy = detail::policy_of(execution);
  CartesianResult r;
  detail::fill_common(r, kernel, "cartesian");
  r.box = detail::sample_box(mechanism, options.box);
  const std::size_t nx = options.cells_x, ny = options.cells_y;
  const double hx = r.box.width() / double(nx);   // cell width (unit)
  const double hy = r.box.height() / double(ny);  // cell height (unit)
  const double cell_area = hx * hy;
  // Centre of cell (i, j): (x0 + i hx, y0 + j hy).
  const double x0 = r.box.min.x + 0.5 * hx;
  const double y0 = r.box.min.y + 0.5 * hy;
  if (options.keep_mask) r.mask.assign(nx * ny, 0);

  // Blocks of whole rows, about 64k points each, fixed by the grid size only.
  const std::size_t rows_per_block = std::max<std::size_t>(1, (std::size_t{1} << 16) / nx);
  const std::size_t work = nx * ny * (kernel.vectorised() ? 1 : 64);
  const std::size_t blocks = pkmws::detail::block_count(ny, rows_per_block);
  r.threads = pkmws::detail::threads_for(policy, blocks, work);
  std::vector<std::uint64_t> inside(blocks, 0);
  pkmws::detail::for_each_block(policy, blocks, work, [&](std::size_t b) {
    const std::size_t j_end = std::min(ny, (b + 1) * rows_per_block);
    std::uint64_t count = 0;
    for (std::size_t j = b * rows_per_block; j < j_end; ++j) {
      const double y = y0 + double(j) * hy;
      if (options.keep_mask) {
        std::uint8_t* row = r.mask.data() + j * nx;
        kernel.row(x0, hx, 0, nx, y, row);
        for (std::size_t i = 0; i < nx; ++i) count += row[i];
      } else {
        count += kernel.count_row(x0, hx, 0, nx, y);
      }
    }
    inside[b] = count;
  });
  for (const std::uint64_t c : inside) r.inside += c;
  r.cells = std::uint64_t(nx) * ny;
  r.points_tested = r.cells;
  r.area = double(r.inside) * cell_area;

  if (options.certified_bounds && kernel.certified()) {
    const auto bounds_start = detail::Clock::now();
    const double radius = 0.5 * std::hypot(hx, hy);  // cell half-diagonal
    std::vector<std::uint64_t> sure(blocks, 0), unsure(blocks, 0);
    pkmws::detail::for_each_block(policy, blocks, work, [&](std::size_t b) {
      std::vector<std::int8_t> state(nx);
      const std::size_t j_end = std::min(ny, (b + 1) * rows_per_block);
      for (std::size_t j = b * rows_per_block; j < j_end; ++j) {
        kernel.classify_row(x0, hx, 0, nx, y0 + double(j) * hy, radius, state.data());
        for (const std::int8_t s : state) {
          sure[b] += s == cell_inside;
          unsure[b] += s == cell_undecided;
        }
      }
    });
    std::uint64_t n_sure = 0, n_unsure = 0;
    for (std::size_t b = 0; b < blocks; ++b) {
      n_sure += sure[b];
      n_unsure += unsure[b];
    }
    r.area_lower = double(n_sure) * cell_area;
    r.area_upper = double(n_sure + n_unsure) * cell_area;
    r.bounds_certified = true;
    r.bounds_time_ms = detail::ms_since(bounds_start);
  }
  r.time_ms = detail::ms_since(start);
  detail::set_rate(r);
  return r;
}

}  // namespace pkmws::grid
