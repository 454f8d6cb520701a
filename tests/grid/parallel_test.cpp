// Grid samplers in parallel: bit-identical results with 1 and 2 threads, the
// same area with every instruction set; bad options.
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
using pkmws::test::dataset;

TEST(GridParallel, OneAndTwoThreadsGiveBitIdenticalResults) {
  const auto m = io::load_mechanism(dataset("moma_m5_gp5_gm5_l195"));
  grid::Execution one, two;
  one.threads = 1;
  two.threads = 2;

  grid::CartesianOptions co;
  co.cells_x = co.cells_y = 1200;  // above the serial threshold
  co.keep_mask = true;
  co.certified_bounds = true;
  const auto c1 = grid::cartesian(*m.model, co, one);
  const auto c2 = grid::cartesian(*m.model, co, two);
  EXPECT_EQ(c1.threads, 1);
  EXPECT_EQ(c2.threads, 2);
  EXPECT_EQ(c1.mask, c2.mask);
  EXPECT_EQ(c1.inside, c2.inside);
  EXPECT_EQ(c1.area, c2.area);
  EXPECT_EQ(*c1.area_lower, *c2.area_lower);
  EXPECT_EQ(*c1.area_upper, *c2.area_upper);

  grid::PolarOptions po;
  po.rings = 500;
  po.sectors = 1500;
  po.keep_mask = true;
  po.certified_bounds = true;
  const auto p1 = grid::polar(*m.model, po, one);
  const auto p2 = grid::polar(*m.model, po, two);
  EXPECT_EQ(p2.threads, 2);
  EXPECT_EQ(p1.mask, p2.mask);
  EXPECT_EQ(p1.area, p2.area);
  EXPECT_EQ(*p1.area_upper, *p2.area_upper);

  grid::AdaptiveOptions ao;
  ao.depth = 9;
  const auto a1 = grid::adaptive(*m.model, ao, one);
  const auto a2 = grid::adaptive(*m.model, ao, two);
  EXPECT_EQ(a2.threads, 2);
  EXPECT_EQ(a1.area, a2.area);
  EXPECT_EQ(a1.area_centre, a2.area_centre);
  EXPECT_EQ(*a1.area_lower, *a2.area_lower);
  EXPECT_EQ(a1.cells_per_level, a2.cells_per_level);
  EXPECT_EQ(a1.points_tested, a2.points_tested);

  grid::JointSweepOptions jo;
  jo.samples = 300;
  jo.keep_points = true;
  const auto j1 = grid::joint_sweep(*m.model, jo, one);
  const auto j2 = grid::joint_sweep(*m.model, jo, two);
  EXPECT_EQ(j2.threads, 2);
  ASSERT_EQ(j1.points.size(), j2.points.size());
  EXPECT_TRUE(std::equal(j1.points.begin(), j1.points.end(), j2.points.begin()));
  EXPECT_EQ(j1.area, j2.area);
}

TEST(GridParallel, InstructionSetsGiveTheSameArea) {
  const auto m = io::load_mechanism(dataset("moma_m4_gm5_gp5_l195"));
  grid::CartesianOptions co;
  co.cells_x = co.cells_y = 700;
  double first = -1.0;
  for (const grid::Isa isa : grid::available_isas()) {
    grid::Execution e;
    e.isa = isa;
    const auto r = grid::cartesian(*m.model, co, e);
    EXPECT_EQ(r.isa, grid::to_string(isa));
    if (first < 0.0) first = r.area;
    EXPECT_EQ(r.area, first) << grid::to_string(isa);
  }
}

TEST(GridSampler, BadOptionsThrow) {
  const auto m = io::load_mechanism(dataset("moma_m1_g0_l250"));
  grid::CartesianOptions zero;
  zero.cells_x = 0;
  EXPECT_THROW(grid::cartesian(*m.model, zero), std::invalid_argument);
  grid::CartesianOptions empty_box;
  empty_box.box = Box{};
  EXPECT_THROW(grid::cartesian(*m.model, empty_box), std::invalid_argument);
  grid::PolarOptions no_radius;
  no_radius.radius = -1.0;
  EXPECT_THROW(grid::polar(*m.model, no_radius), std::invalid_argument);
  grid::AdaptiveOptions deep;
  deep.depth = 41;
  EXPECT_THROW(grid::adaptive(*m.model, deep), std::invalid_argument);
  grid::Execution negative;
  negative.threads = -2;
  EXPECT_THROW(grid::cartesian(*m.model, {}, negative), std::invalid_argument);
}
