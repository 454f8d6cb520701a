// Biglide workspace ([Strutynskyi]): the simplified scheme against its closed
// form, the real scheme certified.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "pkmws/io/mechanism_file.hpp"
#include "mechanisms/biglide/biglide.hpp"
#include "support/fixtures.hpp"

using namespace pkmws;
using geometry::Point;
using mechanisms::Biglide;
using pkmws::test::dataset;

namespace {

// Antiderivative of sqrt(l² - t²).
double F(double t, double l) { return 0.5 * (t * std::sqrt(l * l - t * t) + l * l * std::asin(t / l)); }

}  // namespace

TEST(BiglideWorkspace, SimplifiedAreaEqualsItsClosedForm) {
  // Equal rods l, strokes [0, S] with S > l: at height y the legs reach x in
  // [w_i, S + w_i], w1 = sqrt(l² - (B + y)²), w2 = sqrt(l² - (B - y)²), so the
  // area is S · 2(l - B) - ∫|w1 - w2| dy = 2 S (l - B) - 2 ∫_{B-l}^0 (w1 - w2) dy.
  const auto f = io::load_mechanism(dataset("biglide_simplified"));
  const auto& m = dynamic_cast<const Biglide&>(*f.model);
  const double b = m.params().half_width, l = m.params().rods[0], s = m.params().strokes[0][1];
  const double int_w1 = F(b, l) - F(2 * b - l, l);
  const double int_w2 = F(l, l) - F(b, l);
  const double closed = 2 * s * (l - b) - 2 * (int_w1 - int_w2);
  const auto ws = m.workspace();
  EXPECT_LE(std::abs(ws.area() - closed), 1e-12 * closed) << ws.area() << " " << closed;
  // Membership agrees with the point test.
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> ux(-100, 2700), uy(-500, 500);
  for (int n = 0; n < 1000; ++n) {
    const Point p{ux(rng), uy(rng)};
    EXPECT_EQ(ws.contains(p), m.reachable({p.x, p.y, 0})) << p.x << " " << p.y;
  }
}

TEST(BiglideWorkspace, RealSchemeExplainsWhyThereIsNoExactRegion) {
  const auto f = io::load_mechanism(dataset("biglide_real"));
  try {
    (void)f.model->workspace();
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("coupler curve"), std::string::npos) << e.what();
  }
}

TEST(BiglideWorkspace, RealSchemeIsCertified) {
  // inner ⊆ true ⊆ outer: points in inner are reachable, points outside outer
  // are not (random poses against the IK test); the bounds contain a dense
  // grid estimate and their width halves with each quadtree level.
  const auto f = io::load_mechanism(dataset("biglide_real"));
  const auto coarse = f.model->workspace_enclosure(5);
  const auto fine = f.model->workspace_enclosure(7);
  EXPECT_FALSE(fine.exact);
  EXPECT_EQ(fine.method(), "certified");
  EXPECT_LE(coarse.area_lower, fine.area_lower + 1e-6);
  EXPECT_GE(coarse.area_upper, fine.area_upper - 1e-6);
  EXPECT_NEAR(fine.width() / coarse.width(), 0.25, 0.06);
  const auto box = f.model->bounds();
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> ux(box.min.x, box.max.x), uy(box.min.y, box.max.y);
  int in_inner = 0, out_outer = 0;
  for (int n = 0; n < 3000; ++n) {
    const Point p{ux(rng), uy(rng)};
    const bool reach = f.model->reachable({p.x, p.y, 0});
    if (fine.inner.contains(p)) { EXPECT_TRUE(reach) << p.x << " " << p.y; ++in_inner; }
    if (!fine.outer.contains(p)) { EXPECT_FALSE(reach) << p.x << " " << p.y; ++out_outer; }
  }
  EXPECT_GT(in_inner, 400);
  EXPECT_GT(out_outer, 400);
  // Dense grid estimate (1000^2 cell centres) inside the bounds widened by its own
  // error (boundary cells ~ perimeter x cell size).
  const int n = 1000;
  const double dx = box.width() / n, dy = box.height() / n;
  long count = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      count += f.model->reachable({box.min.x + (i + 0.5) * dx, box.min.y + (j + 0.5) * dy, 0}) ? 1 : 0;
  const double grid = static_cast<double>(count) * dx * dy;
  const double grid_error = fine.outer.components().front().perimeter * std::max(dx, dy);
  EXPECT_GE(grid, fine.area_lower - grid_error);
  EXPECT_LE(grid, fine.area_upper + grid_error);
}
