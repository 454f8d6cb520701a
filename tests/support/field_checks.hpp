// Checks of a criterion field: jets against finite differences, and interval
// enclosures over a box that contain the values and derivatives sampled in it.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <initializer_list>

#include "pkmws/criteria/fields.hpp"
#include "pkmws/geometry/types.hpp"

namespace pkmws::test {

// The side test (ScalarField::side) against 81 sampled values, at levels
// below, between and above them: `inside` only where every sample is <= the
// level, `outside` only where every one is above it (the middle level has
// samples on both sides, so neither answer may come). Returns how many of
// the two outer levels (just beyond the samples' range) it decided.
template <class Field>
int check_side(const Field& f, const geometry::Box& box) {
  std::vector<double> values;
  for (int a = 0; a <= 8; ++a) {
    for (int b = 0; b <= 8; ++b) {
      const double v = f.value({box.min.x + box.width() * a / 8.0, box.min.y + box.height() * b / 8.0});
      if (std::isfinite(v)) values.push_back(v);
    }
  }
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  const double lo = values.front(), hi = values.back(), spread = hi - lo;
  int decided = 0;
  for (const auto& [level, outer] : {std::pair{lo - 0.5 * spread, true}, std::pair{0.5 * (lo + hi), false},
                                     std::pair{hi + 0.5 * spread, true}}) {
    const certified::CellState s = f.side(box, level);
    const std::size_t above = static_cast<std::size_t>(std::count_if(values.begin(), values.end(), [&](double v) { return v > level; }));
    if (s == certified::CellState::inside) {
      EXPECT_EQ(above, 0u) << "level " << level;
    }
    if (s == certified::CellState::outside) {
      EXPECT_EQ(above, values.size()) << "level " << level;
    }
    if (s != certified::CellState::undecided && outer) ++decided;
  }
  return decided;
}

// Jets by finite differences; interval enclosures contain sampled values.
template <class Field>
void check_field(const Field& f, geometry::Point p, double h, const geometry::Box& box) {
  const auto j = f.jet(p);
  auto v = [&](double x, double y) { return f.value({x, y}); };
  const double gx = (v(p.x + h, p.y) - v(p.x - h, p.y)) / (2 * h);
  const double gy = (v(p.x, p.y + h) - v(p.x, p.y - h)) / (2 * h);
  const double hxx = (v(p.x + h, p.y) - 2 * v(p.x, p.y) + v(p.x - h, p.y)) / (h * h);
  const double hyy = (v(p.x, p.y + h) - 2 * v(p.x, p.y) + v(p.x, p.y - h)) / (h * h);
  const double hxy = (v(p.x + h, p.y + h) - v(p.x + h, p.y - h) - v(p.x - h, p.y + h) + v(p.x - h, p.y - h)) / (4 * h * h);
  const double scale1 = 1e-5 * (1.0 + std::abs(j.dx) + std::abs(j.dy));
  const double scale2 = 1e-3 * (1.0 + std::abs(j.dxx) + std::abs(j.dyy) + std::abs(j.dxy));
  EXPECT_NEAR(j.v, f.value(p), 1e-12 * (1.0 + std::abs(j.v)));
  EXPECT_NEAR(j.dx, gx, scale1);
  EXPECT_NEAR(j.dy, gy, scale1);
  EXPECT_NEAR(j.dxx, hxx, scale2);
  EXPECT_NEAR(j.dyy, hyy, scale2);
  EXPECT_NEAR(j.dxy, hxy, scale2);
  const auto g = f.grad(p);
  EXPECT_DOUBLE_EQ(g.dx, j.dx);
  EXPECT_DOUBLE_EQ(g.dy, j.dy);
  // Enclosures over the box contain the values, gradients and Hessians at sample points.
  const auto e = f.enclose(box);
  const auto cheap = f.enclose_cheap(box);
  const auto jb = f.jet(box);
  const auto gb = f.grad(box);
  for (int a = 0; a <= 4; ++a) {
    for (int b = 0; b <= 4; ++b) {
      const geometry::Point q{box.min.x + box.width() * a / 4.0, box.min.y + box.height() * b / 4.0};
      const auto jq = f.jet(q);
      EXPECT_TRUE(e.contains(jq.v));
      EXPECT_TRUE(cheap.contains(jq.v));
      EXPECT_TRUE(f.enclose(geometry::Box{q, q}).contains(jq.v));
      EXPECT_TRUE(jb.v.contains(jq.v));
      EXPECT_TRUE(jb.dx.contains(jq.dx) && jb.dy.contains(jq.dy));
      EXPECT_TRUE(gb.dx.contains(jq.dx) && gb.dy.contains(jq.dy));
      EXPECT_TRUE(jb.dxx.contains(jq.dxx) && jb.dxy.contains(jq.dxy) && jb.dyy.contains(jq.dyy));
      // Over the degenerate box {q}: the interval jet is tight, so a wrong
      // term its box enclosure would hide shows here (within rounding).
      const auto jp = f.jet(geometry::Box{q, q});
      const auto at = [](const certified::Interval& i, double x) {
        const double slack = 1e-9 * (1.0 + std::abs(x));
        return i.lo - slack <= x && x <= i.hi + slack;
      };
      EXPECT_TRUE(at(jp.v, jq.v) && at(jp.dx, jq.dx) && at(jp.dy, jq.dy));
      EXPECT_TRUE(at(jp.dxx, jq.dxx) && at(jp.dxy, jq.dxy) && at(jp.dyy, jq.dyy));
    }
  }
  check_side(f, box);
}

// The field's sub-level sets are the criterion's at p: value <= t <=>
// surrogate <= level(t), for each threshold not within 1e-9 of the value.
inline void expect_same_sublevel(const criteria::CriterionField& f, geometry::Point p, double value,
                                 std::initializer_list<double> thresholds) {
  for (double t : thresholds) {
    if (std::abs(value - t) > 1e-9 * t) {
      EXPECT_EQ(value <= t, f.surrogate->value(p) <= f.level(t)) << "threshold " << t;
    }
  }
}

}  // namespace pkmws::test
