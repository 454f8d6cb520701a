// Membership kernels: the MOMA fast path against Moma::reachable ([Vasilic]
// eq. 5-6) on every bundled MOMA file, bit-identical masks across instruction
// sets and row splits, and the certified cell test against the exact Region.
#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <filesystem>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "pkmws/geometry/region.hpp"
#include "pkmws/grid/kernel.hpp"
#include "pkmws/io/mechanism_file.hpp"
#include "support/fixtures.hpp"

using namespace pkmws;
using geometry::Point;

namespace {

using pkmws::test::dataset;
using pkmws::test::dataset_files;

}  // namespace

TEST(GridKernel, MomaFastPathMatchesReachableOnEveryDataset) {
  const auto files = dataset_files("moma_");
  ASSERT_GE(files.size(), 27u);
  for (const auto& path : files) {
    const auto mech = io::load_mechanism(path);
    const grid::MembershipKernel kernel(*mech.model);
    ASSERT_EQ(kernel.name(), "moma") << path;
    const auto box = mech.model->bounds();
    // 150 x 150 points at an irrational offset, so no point sits on the boundary
    // to within rounding.
    const std::size_t n = 150;
    const double dx = box.width() / double(n), dy = box.height() / double(n);
    const double x0 = box.min.x + 0.318309886 * dx;
    std::vector<std::uint8_t> mask(n);
    std::size_t inside = 0;
    for (std::size_t j = 0; j < n; ++j) {
      const double y = box.min.y + (double(j) + 0.577215665) * dy;
      kernel.row(x0, dx, 0, n, y, mask.data());
      for (std::size_t i = 0; i < n; ++i) {
        const double x = x0 + double(i) * dx;
        ASSERT_EQ(mask[i] != 0, mech.model->reachable({x, y, 0.0})) << path << " at (" << x << ", " << y << ")";
        inside += mask[i];
      }
    }
    EXPECT_GT(inside, n * n / 50) << path;  // the workspace fills a good part of its box
    EXPECT_LT(inside, n * n) << path;
  }
}

TEST(GridKernel, InstructionSetsAndRowSplitsGiveIdenticalBits) {
  const auto mech = io::load_mechanism(dataset("moma_m5_gp5_gm5_l195"));
  const auto isas = grid::available_isas();
  ASSERT_GE(isas.size(), 2u);  // scalar and baseline at least
  const auto box = mech.model->bounds();
  const std::size_t n = 1999;  // not a multiple of any vector width
  const double dx = box.width() / double(n);
  std::vector<std::vector<std::uint8_t>> masks;
  std::vector<std::vector<std::int8_t>> states;
  std::vector<std::uint64_t> counts;
  std::vector<double> xs(n), ys(n);
  for (const grid::Isa isa : isas) {
    const grid::MembershipKernel kernel(*mech.model, {isa, 0.0});
    EXPECT_EQ(kernel.isa(), isa);
    std::vector<std::uint8_t> all;
    std::vector<std::int8_t> all_states;
    std::uint64_t count = 0;
    for (int j = 0; j < 40; ++j) {
      const double y = box.min.y + (j + 0.5) * box.height() / 40.0;
      std::vector<std::uint8_t> row(n), split(n), pts(n);
      kernel.row(box.min.x, dx, 0, n, y, row.data());
      // The same row in three pieces.
      kernel.row(box.min.x, dx, 0, 7, y, split.data());
      kernel.row(box.min.x, dx, 7, 1000, y, split.data() + 7);
      kernel.row(box.min.x, dx, 1007, n - 1007, y, split.data() + 1007);
      ASSERT_EQ(row, split) << grid::to_string(isa);
      for (std::size_t i = 0; i < n; ++i) {
        xs[i] = box.min.x + double(i) * dx;
        ys[i] = y;
      }
      kernel.points(xs.data(), ys.data(), n, pts.data());
      ASSERT_EQ(row, pts) << grid::to_string(isa);
      const std::uint64_t c = kernel.count_row(box.min.x, dx, 0, n, y);
      std::uint64_t manual = 0;
      for (auto m : row) manual += m;
      ASSERT_EQ(c, manual);
      count += c;
      all.insert(all.end(), row.begin(), row.end());
      std::vector<std::int8_t> st(n), st_row(n);
      kernel.classify(xs.data(), ys.data(), n, 0.7, st.data());
      kernel.classify_row(box.min.x, dx, 0, n, y, 0.7, st_row.data());
      ASSERT_EQ(st, st_row);
      all_states.insert(all_states.end(), st.begin(), st.end());
    }
    masks.push_back(all);
    states.push_back(all_states);
    counts.push_back(count);
  }
  for (std::size_t k = 1; k < masks.size(); ++k) {
    EXPECT_EQ(masks[k], masks[0]) << grid::to_string(isas[k]) << " vs scalar";
    EXPECT_EQ(states[k], states[0]) << grid::to_string(isas[k]) << " vs scalar";
    EXPECT_EQ(counts[k], counts[0]);
  }
  EXPECT_GT(counts[0], 0u);
}

TEST(GridKernel, CertifiedCellTestNeverContradictsTheExactRegion) {
  std::mt19937_64 rng(7);
  for (const char* stem : {"moma_m1_g0_l250", "moma_m4_gm5_gp5_l195", "moma_m5_gp5_gm5_l195", "moma_m3_l180",
                           "moma_m2_l195"}) {
    const auto mech = io::load_mechanism(dataset(stem));
    const geometry::Region region = mech.model->workspace();
    const grid::MembershipKernel kernel(*mech.model);
    ASSERT_TRUE(kernel.certified());
    const auto box = mech.model->bounds();
    std::uniform_real_distribution<double> ux(box.min.x, box.max.x), uy(box.min.y, box.max.y), unit(-1.0, 1.0);
    int decided_in = 0, decided_out = 0, undecided = 0;
    for (const double radius : {20.0, 5.0, 1.0}) {
      for (int k = 0; k < 150; ++k) {
        const Point c{ux(rng), uy(rng)};
        std::int8_t s = 0;
        kernel.classify(&c.x, &c.y, 1, radius, &s);
        if (s == grid::cell_undecided) {
          ++undecided;
          continue;
        }
        s == grid::cell_inside ? ++decided_in : ++decided_out;
        // Points of the disk, its rim first (where a wrong claim would show).
        for (int m = 0; m < 12; ++m) {
          const double a = 2.0 * std::numbers::pi * m / 12.0 + 0.1;
          const double rr = m < 8 ? radius * (1.0 - 1e-9) : radius * std::abs(unit(rng));
          const Point p{c.x + rr * std::cos(a), c.y + rr * std::sin(a)};
          ASSERT_EQ(region.contains(p), s == grid::cell_inside)
              << stem << ": disk at (" << c.x << ", " << c.y << ") r = " << radius << " claimed "
              << int(s) << " but (" << p.x << ", " << p.y << ") disagrees";
        }
      }
    }
    EXPECT_GT(decided_in, 20) << stem;
    EXPECT_GT(decided_out, 20) << stem;
    EXPECT_GT(undecided, 5) << stem;
  }
}

TEST(GridKernel, CertifiedTestDecidesEveryDiskClearOfTheBoundary) {
  // A disk whose centre is farther than radius + margin from the boundary is
  // decided: along a row across M1 at y = -300, the undecided disks are
  // exactly those within reach of a boundary crossing of that row.
  const auto mech = io::load_mechanism(dataset("moma_m1_g0_l250"));
  const grid::MembershipKernel kernel(*mech.model);
  const auto box = mech.model->bounds();
  const std::size_t n = 4000;
  const double dx = box.width() / double(n), y = -300.0, radius = 2.0;
  std::vector<std::uint8_t> mask(n);
  std::vector<std::int8_t> state(n);
  kernel.row(box.min.x, dx, 0, n, y, mask.data());
  kernel.classify_row(box.min.x, dx, 0, n, y, radius, state.data());
  std::vector<double> crossings;
  for (std::size_t i = 1; i < n; ++i) {
    if (mask[i] != mask[i - 1]) crossings.push_back(box.min.x + (double(i) - 0.5) * dx);
  }
  ASSERT_EQ(crossings.size(), 2u);
  for (std::size_t i = 0; i < n; ++i) {
    const double x = box.min.x + double(i) * dx;
    double d = 1e300;
    for (double c : crossings) d = std::min(d, std::abs(x - c));
    if (state[i] != grid::cell_undecided) {
      EXPECT_EQ(state[i] == grid::cell_inside, mask[i] != 0) << x;
    }
    // The boundary there is steep arcs: the 1-Lipschitz bound is within a
    // factor ~2 of the distance, so disks 3 radii away are decided.
    if (d > 3.0 * radius + dx) {
      EXPECT_NE(state[i], grid::cell_undecided) << "x = " << x;
    }
  }
}

TEST(GridKernel, GenericKernelForOtherMechanisms) {
  const auto mech = io::load_mechanism(dataset("five_bar_dextar_pp"));
  const grid::MembershipKernel kernel(*mech.model);
  EXPECT_EQ(kernel.name(), "generic");
  EXPECT_FALSE(kernel.certified());
  EXPECT_EQ(kernel.isa(), grid::Isa::scalar);
  const auto box = mech.model->bounds();
  const double y = 0.5 * (box.min.y + box.max.y);
  std::vector<std::uint8_t> mask(300);
  kernel.row(box.min.x, box.width() / 300.0, 0, 300, y, mask.data());
  for (std::size_t i = 0; i < 300; ++i) {
    EXPECT_EQ(mask[i] != 0, mech.model->reachable({box.min.x + double(i) * box.width() / 300.0, y, 0.0}));
  }
  double x = box.min.x, yy = y;
  std::int8_t s = 0;
  EXPECT_THROW(kernel.classify(&x, &yy, 1, 1.0, &s), std::logic_error);
}
