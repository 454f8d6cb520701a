// Grid samplers against the exact area from Region: convergence along the
// ladder, certified brackets, polar vs Cartesian, the quadtree's bracket and
// its sampled rule's failure on thin features, the DK sweep vs the IK grid.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "pkmws/geometry/region.hpp"
#include "pkmws/grid/sampler.hpp"
#include "pkmws/io/mechanism_file.hpp"
#include "support/fixtures.hpp"

using namespace pkmws;
using geometry::Box;
using geometry::Point;
using pkmws::test::dataset;

namespace {

const char* const moma_cases[] = {"moma_m1_g0_l250", "moma_m4_gm5_gp5_l195", "moma_m5_gp5_gm5_l195"};

double exact_area(const io::MechanismFile& m) { return m.model->workspace().area(); }

// Mean relative error of the Cartesian estimate over 16 grids of n cells per
// side shifted by seeded random fractions of a cell (a single grid's error
// fluctuates with how the lattice meets the boundary; the mean does not).
double mean_shifted_error(const io::MechanismFile& m, std::size_t n, double exact) {
  const Box b0 = m.model->bounds();
  const double hx = b0.width() / double(n), hy = b0.height() / double(n);
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double sum = 0.0;
  for (int s = 0; s < 16; ++s) {
    grid::CartesianOptions o;
    o.cells_x = o.cells_y = n + 1;  // one more cell so the shifted box still covers the workspace
    Box b;
    b.min = {b0.min.x - unit(rng) * hx, b0.min.y - unit(rng) * hy};
    b.max = {b.min.x + double(n + 1) * hx, b.min.y + double(n + 1) * hy};
    o.box = b;
    sum += std::abs(grid::cartesian(*m.model, o).area - exact) / exact;
  }
  return sum / 16.0;
}

}  // namespace

TEST(GridCartesian, ErrorAtFourTimesTheCellsIsBelowTheErrorBefore) {
  for (const char* stem : moma_cases) {
    const auto m = io::load_mechanism(dataset(stem));
    const double exact = exact_area(m);
    double previous = mean_shifted_error(m, 50, exact);
    for (std::size_t n = 100; n <= 1600; n *= 2) {
      const double e = mean_shifted_error(m, n, exact);
      EXPECT_LT(e, previous) << stem << ": mean error at " << n << "^2 cells vs " << n / 2 << "^2";
      previous = e;
    }
    // Cell-centre sampling of a curved boundary: the error falls about as
    // h^1.5 (a factor ~2.8 per halving); over five halvings at least 2^5 / 2.
    EXPECT_LT(previous, mean_shifted_error(m, 50, exact) / 16.0) << stem;
  }
}

TEST(GridCartesian, AreaIsInsideCountTimesCellArea) {
  const auto m = io::load_mechanism(dataset("moma_m1_g0_l250"));
  grid::CartesianOptions o;
  o.cells_x = 300;
  o.cells_y = 170;
  o.keep_mask = true;
  const auto r = grid::cartesian(*m.model, o);
  const Box b = m.model->bounds();
  ASSERT_EQ(r.mask.size(), 300u * 170u);
  std::uint64_t inside = 0;
  for (std::size_t j = 0; j < 170; ++j) {
    for (std::size_t i = 0; i < 300; ++i) {
      const double hx = b.width() / 300.0, hy = b.height() / 170.0;
      const Point c{b.min.x + 0.5 * hx + double(i) * hx, b.min.y + 0.5 * hy + double(j) * hy};
      ASSERT_EQ(r.mask[j * 300 + i] != 0, m.model->reachable({c.x, c.y, 0.0})) << i << ", " << j;
      inside += r.mask[j * 300 + i];
    }
  }
  EXPECT_EQ(r.inside, inside);
  EXPECT_EQ(r.cells, 300u * 170u);
  EXPECT_EQ(r.points_tested, 300u * 170u);
  EXPECT_DOUBLE_EQ(r.area, double(inside) * (b.width() / 300.0) * (b.height() / 170.0));
  EXPECT_GT(r.points_per_second, 0.0);
  EXPECT_EQ(r.method, "cartesian");
  EXPECT_EQ(r.kernel, "moma");
}

TEST(GridCartesian, CertifiedBracketContainsTheExactAreaAndShrinksWithTheCells) {
  for (const char* stem : moma_cases) {
    const auto m = io::load_mechanism(dataset(stem));
    const double exact = exact_area(m);
    double previous_width = 0.0;
    for (std::size_t n : {50, 100, 200, 400, 800}) {
      grid::CartesianOptions o;
      o.cells_x = o.cells_y = n;
      o.certified_bounds = true;
      const auto r = grid::cartesian(*m.model, o);
      ASSERT_TRUE(r.area_lower && r.area_upper && r.bounds_certified);
      EXPECT_LE(*r.area_lower, exact) << stem << " n = " << n;
      EXPECT_GE(*r.area_upper, exact) << stem << " n = " << n;
      EXPECT_LE(*r.area_lower, r.area);
      EXPECT_GE(*r.area_upper, r.area);
      const double width = *r.area_upper - *r.area_lower;
      // The undecided cells form a band of ~2 half-diagonals around the
      // boundary: the width halves with the cell size.
      if (previous_width > 0.0) {
        EXPECT_GT(width, 0.35 * previous_width) << stem;
        EXPECT_LT(width, 0.65 * previous_width) << stem;
      }
      previous_width = width;
    }
  }
}

TEST(GridCartesian, GenericKernelConvergesForTheFiveBar) {
  const auto m = io::load_mechanism(dataset("five_bar_dextar_pp"));
  const double exact = exact_area(m);
  const double e100 = mean_shifted_error(m, 100, exact);
  const double e400 = mean_shifted_error(m, 400, exact);
  EXPECT_LT(e400, e100 / 3.0);
  EXPECT_LT(e400, 1e-3);
}

TEST(GridPolar, AgreesWithCartesianWithinTheirBounds) {
  for (const char* stem : moma_cases) {
    const auto m = io::load_mechanism(dataset(stem));
    const double exact = exact_area(m);
    grid::CartesianOptions co;
    co.cells_x = co.cells_y = 600;
    co.certified_bounds = true;
    const auto c = grid::cartesian(*m.model, co);
    grid::PolarOptions po;
    po.rings = 600;
    po.sectors = 1884;
    po.certified_bounds = true;
    const auto p = grid::polar(*m.model, po);
    ASSERT_TRUE(p.area_lower && p.area_upper);
    EXPECT_LE(*p.area_lower, exact) << stem;
    EXPECT_GE(*p.area_upper, exact) << stem;
    // Both brackets contain the true area, so they overlap, and each estimate
    // lies in the other's bracket widened by its own.
    EXPECT_LE(std::max(*p.area_lower, *c.area_lower), std::min(*p.area_upper, *c.area_upper)) << stem;
    const double tolerance = (*p.area_upper - *p.area_lower) + (*c.area_upper - *c.area_lower);
    EXPECT_LT(std::abs(p.area - c.area), tolerance) << stem;
    EXPECT_LT(std::abs(p.area - exact) / exact, 1e-3) << stem;
    EXPECT_EQ(p.cells, 600u * 1884u);
  }
}

TEST(GridPolar, CellAreasSumToTheDisk) {
  // With every cell inside (a centre deep in the workspace and a small
  // radius), the polar estimate is the disk's area pi R^2 to rounding.
  const auto m = io::load_mechanism(dataset("moma_m1_g0_l250"));
  grid::PolarOptions po;
  po.centre = Point{0.0, -300.0};
  po.radius = 20.0;
  po.rings = 37;
  po.sectors = 101;
  const auto p = grid::polar(*m.model, po);
  ASSERT_TRUE(m.model->reachable({0.0, -300.0, 0.0}));
  EXPECT_EQ(p.inside, 37u * 101u);
  EXPECT_NEAR(p.area, std::numbers::pi * 400.0, 1e-10);
}

TEST(GridAdaptive, CertifiedBracketContainsTheExactAreaAtEveryDepth) {
  for (const char* stem : {"moma_m1_g0_l250", "moma_m4_gm5_gp5_l195", "moma_m5_gp5_gm5_l195", "moma_m2_l180",
                           "moma_m3_l250"}) {
    const auto m = io::load_mechanism(dataset(stem));
    const double exact = exact_area(m);
    double previous_width = 0.0;
    for (int depth = 0; depth <= 10; ++depth) {
      grid::AdaptiveOptions o;
      o.base_cells = 16;
      o.depth = depth;
      const auto r = grid::adaptive(*m.model, o);
      ASSERT_EQ(r.rule, "certified");
      ASSERT_TRUE(r.bounds_certified);
      EXPECT_LE(*r.area_lower, exact) << stem << " depth " << depth;
      EXPECT_GE(*r.area_upper, exact) << stem << " depth " << depth;
      EXPECT_DOUBLE_EQ(r.area, 0.5 * (*r.area_lower + *r.area_upper));
      const double width = *r.area_upper - *r.area_lower;
      if (depth >= 3) {
        EXPECT_LT(width, 0.65 * previous_width) << stem << " depth " << depth;
      }
      previous_width = width;
      EXPECT_EQ(r.effective_cells, std::size_t{16} << depth);
      ASSERT_EQ(r.cells_per_level.size(), std::size_t(depth) + 1);
      EXPECT_EQ(r.cells_per_level[0], 256u);
      // Only the boundary band is refined: far fewer cells than the uniform grid.
      if (depth >= 6) {
        std::uint64_t evaluated = 0;
        for (auto c : r.cells_per_level) evaluated += c;
        const double uniform = std::pow(double(r.effective_cells), 2.0);
        EXPECT_LT(double(evaluated), uniform / 10.0) << stem;
      }
    }
    // The undecided leaves are the cells with |F(centre)| <= half a diagonal;
    // near the boundary F is the distance to it (|grad F| = 1), so they cover
    // a band one diagonal wide: area_upper - area_lower ~ perimeter x diagonal.
    double perimeter = 0.0;
    for (const auto& c : m.model->workspace().components()) perimeter += c.perimeter;
    const Box b = m.model->bounds();
    const double diagonal = std::hypot(b.width(), b.height()) / 16384.0;
    EXPECT_GT(previous_width, 0.6 * perimeter * diagonal) << stem;
    EXPECT_LT(previous_width, 1.2 * perimeter * diagonal) << stem;
  }
}

TEST(GridAdaptive, SampledRuleMissesThinFeaturesTheCertifiedRuleKeeps) {
  // One root cell whose centre and corners all miss the workspace of M1 (the
  // box reaches far to the right): the sampled rule calls it outside, the
  // certified rule refines it.
  const auto m = io::load_mechanism(dataset("moma_m1_g0_l250"));
  const double exact = exact_area(m);
  const Box b0 = m.model->bounds();
  Box box;
  box.min = b0.min;
  box.max = {b0.max.x + 3.0 * b0.width(), b0.max.y + 1.0 * b0.height()};
  const Point samples[] = {{0.5 * (box.min.x + box.max.x), 0.5 * (box.min.y + box.max.y)},
                           box.min, box.max, {box.min.x, box.max.y}, {box.max.x, box.min.y}};
  for (const Point p : samples) ASSERT_FALSE(m.model->reachable({p.x, p.y, 0.0}));
  grid::AdaptiveOptions o;
  o.base_cells = 1;
  o.depth = 8;
  o.box = box;
  o.rule = grid::StraddleRule::sampled;
  const auto sampled = grid::adaptive(*m.model, o);
  EXPECT_EQ(sampled.rule, "sampled");
  EXPECT_FALSE(sampled.bounds_certified);
  EXPECT_EQ(sampled.area, 0.0);  // the whole workspace lost
  EXPECT_EQ(*sampled.area_upper, 0.0);
  o.rule = grid::StraddleRule::certified;
  const auto certified = grid::adaptive(*m.model, o);
  EXPECT_LE(*certified.area_lower, exact);
  EXPECT_GE(*certified.area_upper, exact);
  EXPECT_LT(std::abs(certified.area - exact) / exact, 0.02);
}

TEST(GridAdaptive, SampledRuleOnResolvedFeaturesAndGenericMechanisms) {
  // With root cells smaller than every feature the sampled rule's bracket
  // holds; the five-bar has no certified test, so automatic picks sampled.
  const auto five_bar = io::load_mechanism(dataset("five_bar_dextar_pp"));
  grid::AdaptiveOptions o;
  o.base_cells = 32;
  o.depth = 6;
  const auto r = grid::adaptive(*five_bar.model, o);
  EXPECT_EQ(r.rule, "sampled");
  EXPECT_EQ(r.kernel, "generic");
  const double exact = exact_area(five_bar);
  EXPECT_LE(*r.area_lower, exact);
  EXPECT_GE(*r.area_upper, exact);
  EXPECT_LT(std::abs(r.area_centre - exact) / exact, 1e-3);
  EXPECT_THROW(
      {
        grid::AdaptiveOptions c = o;
        c.rule = grid::StraddleRule::certified;
        (void)grid::adaptive(*five_bar.model, c);
      },
      std::invalid_argument);
}

TEST(GridJointSweep, AgreesWithTheIkGrid) {
  for (const char* stem : moma_cases) {
    const auto m = io::load_mechanism(dataset(stem));
    const std::size_t cells = 80;
    grid::JointSweepOptions jo;
    jo.samples = 500;
    jo.raster_cells = cells;
    jo.keep_mask = true;
    jo.keep_points = true;
    const auto sweep = grid::joint_sweep(*m.model, jo);
    EXPECT_EQ(sweep.points_tested, 500u * 500u);
    // Every valid DK pose passes the IK test ([Vasilic] fig. 4 vs fig. 8).
    const grid::MembershipKernel kernel(*m.model);
    std::size_t rejected = 0;
    for (const Point p : sweep.points) {
      if (!kernel.contains(p)) {
        // only rounding on the boundary (stroke ends): the IK stroke is within 1e-9 of the limit
        const auto ik = m.model->inverse({p.x, p.y, 0.0});
        ASSERT_FALSE(ik.empty());
        ++rejected;
      }
    }
    EXPECT_LT(rejected, sweep.points.size() / 100) << stem;
    // Same raster as an IK grid: hit cells = IK cells up to one cell at the boundary.
    grid::CartesianOptions co;
    co.cells_x = co.cells_y = cells;
    co.keep_mask = true;
    const auto ik = grid::cartesian(*m.model, co);
    ASSERT_EQ(ik.box.min, sweep.box.min);
    auto at = [&](const std::vector<std::uint8_t>& mask, long i, long j) -> int {
      if (i < 0 || j < 0 || i >= long(cells) || j >= long(cells)) return 0;
      return mask[std::size_t(j) * cells + std::size_t(i)];
    };
    for (long j = 0; j < long(cells); ++j) {
      for (long i = 0; i < long(cells); ++i) {
        int ik_all = 1, ik_any = 0;
        for (long dj = -1; dj <= 1; ++dj) {
          for (long di = -1; di <= 1; ++di) {
            ik_all &= at(ik.mask, i + di, j + dj);
            ik_any |= at(ik.mask, i + di, j + dj);
          }
        }
        if (ik_all) {
          EXPECT_TRUE(at(sweep.mask, i, j)) << stem << ": interior cell " << i << ", " << j << " not hit";
        }
        if (at(sweep.mask, i, j)) {
          EXPECT_TRUE(ik_any) << stem << ": hit cell " << i << ", " << j << " far outside";
        }
      }
    }
    const double exact = exact_area(m);
    EXPECT_LE(*sweep.area_lower, exact) << stem;
    EXPECT_GE(*sweep.area_upper, exact) << stem;
    EXPECT_LT(std::abs(sweep.area - ik.area), *sweep.area_upper - *sweep.area_lower) << stem;
  }
}

TEST(GridJointSweep, DefaultRangesAndErrors) {
  const auto moma = io::load_mechanism(dataset("moma_m1_g0_l250"));
  const auto ranges = grid::default_joint_ranges(*moma.model);
  ASSERT_EQ(ranges.size(), 2u);
  EXPECT_EQ(ranges[0], (std::pair<double, double>{0.0, 200.0}));
  const auto five_bar = io::load_mechanism(dataset("five_bar_dextar_pp"));
  EXPECT_EQ(grid::default_joint_ranges(*five_bar.model).size(), 2u);
  grid::JointSweepOptions bad;
  bad.samples = 1;
  EXPECT_THROW(grid::joint_sweep(*moma.model, bad), std::invalid_argument);
  grid::JointSweepOptions wrong;
  wrong.ranges = {{0.0, 1.0}};
  EXPECT_THROW(grid::joint_sweep(*moma.model, wrong), std::invalid_argument);
}
