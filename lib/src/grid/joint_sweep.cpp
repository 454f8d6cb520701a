// Joint-space sweep ([Vasilic] §4.1, algorithm of fig. 4): the direct
// kinematics at every sample of a grid over the joint ranges; the valid
// assembly modes are points of the workspace.
//
// Area: rasterisation of the DK points onto a uniform grid (hit cells x cell
// area, minus half the boundary cells). Chosen over an alpha shape because it is O(points), has no shape
// parameter to tune, keeps holes and separate components, is deterministic,
// and needs no exact geometry outside lib/src/geometry. Its bias is known: a
// hit cell only has to meet the workspace, so the raster over-estimates by
// about half of the boundary cells; where the DK spreads the samples apart
// (near type-2 singularities, |dP/dq| large) interior cells can be missed.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "grid/common.hpp"
#include "pkmws/grid/sampler.hpp"

namespace pkmws::grid {

std::vector<std::pair<double, double>> default_joint_ranges(const mechanisms::Mechanism& m) {
  // A joint's own travel where the file bounds it (strokes, crank limits), a
  // full turn for a free angle.
  std::vector<std::pair<double, double>> ranges;
  for (const auto& j : m.joints()) {
    if (j.range) {
      ranges.emplace_back((*j.range)[0], (*j.range)[1]);
    } else if (j.angle) {
      ranges.emplace_back(-std::numbers::pi, std::numbers::pi);
    } else {
      throw std::invalid_argument("joint-space sweep: no known range for joint " + j.name + " of " +
                                  std::string(m.kind()) + "; give the ranges");
    }
  }
  return ranges;
}

JointSweepResult joint_sweep(const mechanisms::Mechanism& mechanism, const JointSweepOptions& options,
                             const Execution& execution) {
  const auto start = detail::Clock::now();
  if (mechanism.dof() != 2) {
    throw std::invalid_argument("joint-space sweep: 2-DOF mechanisms only (a 3-DOF sweep does not keep the "
                                "orientation constant)");
  }
  if (options.samples < 2) throw std::invalid_argument("joint-space sweep: at least 2 samples per joint");
  if (options.raster_cells == 0) throw std::invalid_argument("joint-space sweep: raster_cells must be positive");
  JointSweepResult r;
  r.method = "joint_sweep";
  r.kernel = "direct";
  r.isa = "scalar";
  r.ranges = options.ranges.empty() ? default_joint_ranges(mechanism) : options.ranges;
  if (r.ranges.size() != 2) throw std::invalid_argument("joint-space sweep: need two joint ranges");
  for (const auto& [lo, hi] : r.ranges) {
    if (!(lo <= hi) || !std::isfinite(lo) || !std::isfinite(hi)) {
      throw std::invalid_argument("joint-space sweep: each range must be finite with min <= max");
    }
  }
  r.box = detail::sample_box(mechanism, options.box);
  const auto policy = detail::policy_of(execution);
  const std::size_t n = options.samples;
  // Joint samples include both ends of each range: q_k = lo + k (hi - lo) / (n - 1).
  auto joint = [&](int axis, std::size_t k) {
    const auto [lo, hi] = r.ranges[std::size_t(axis)];
    return k + 1 == n ? hi : lo + double(k) * (hi - lo) / double(n - 1);
  };
  const std::size_t m = options.raster_cells;
  const double hx = r.box.width() / double(m), hy = r.box.height() / double(m);
  std::vector<std::uint8_t> hit(m * m, 0);
  // One block per q1 sample, collecting its valid poses in q2 order; blocks
  // run in chunks so that memory stays bounded (~chunk x 2 samples points),
  // each chunk rasterised serially in block order.
  constexpr std::size_t chunk = 64;
  std::vector<std::vector<geometry::Point>> per_block(std::min(chunk, n));
  r.threads = pkmws::detail::threads_for(policy, std::min(chunk, n), std::min(chunk, n) * n * 64);
  for (std::size_t first = 0; first < n; first += chunk) {
    const std::size_t count = std::min(chunk, n - first);
    pkmws::detail::for_each_block(policy, count, count * n * 64, [&](std::size_t k) {
      std::vector<geometry::Point>& out = per_block[k];
      out.clear();
      double q[2] = {joint(0, first + k), 0.0};
      for (std::size_t b = 0; b < n; ++b) {
        q[1] = joint(1, b);
        for (const auto& s : mechanism.direct(std::span<const double>(q, 2))) {
          if (s.valid) out.push_back({s.pose.x, s.pose.y});
        }
      }
    });
    for (std::size_t k = 0; k < count; ++k) {
      for (const geometry::Point p : per_block[k]) {
        ++r.poses;
        if (!r.box.contains(p)) continue;
        const auto i = std::min(m - 1, std::size_t((p.x - r.box.min.x) / hx));
        const auto j = std::min(m - 1, std::size_t((p.y - r.box.min.y) / hy));
        hit[j * m + i] = 1;
      }
      if (options.keep_points) r.points.insert(r.points.end(), per_block[k].begin(), per_block[k].end());
    }
  }
  for (std::size_t j = 0; j < m; ++j) {
    for (std::size_t i = 0; i < m; ++i) {
      if (!hit[j * m + i]) continue;
      ++r.inside;
      const bool edge = i == 0 || j == 0 || i + 1 == m || j + 1 == m || !hit[j * m + i - 1] ||
                        !hit[j * m + i + 1] || !hit[(j - 1) * m + i] || !hit[(j + 1) * m + i];
      r.boundary_cells += edge;
    }
  }
  const double cell_area = hx * hy;
  r.cells = std::uint64_t(m) * m;
  r.points_tested = std::uint64_t(n) * n;
  r.area_upper = double(r.inside) * cell_area;
  r.area_lower = double(r.inside - r.boundary_cells) * cell_area;
  r.area = 0.5 * (*r.area_lower + *r.area_upper);
  r.bounds_certified = false;
  if (options.keep_mask) r.mask = std::move(hit);
  r.time_ms = detail::ms_since(start);
  detail::set_rate(r);
  return r;
}

}  // namespace pkmws::grid
