// Charts of the level sets (docs/theory/level_sets.md, "Charts"): where the
// five-bar's fields are singular on W's boundary (a leg stretched) and at the
// base joints of equal links, W is cut into a part traced in (x, y) and polar
// charts. Checks: the partition itself (a limit that never binds gives W's
// exact area), the charted bounds against the plane's (the same fields traced
// in (x, y) alone: two valid enclosures of one area must meet) and against a
// dense grid of the mechanism's own evaluation, on the DexTAR's working modes
// and on random five-bars with equal and unequal links.
#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <cstdio>
#include <random>
#include <string>

#include "pkmws/criteria/fields.hpp"
#include "pkmws/geometry/primitives.hpp"
#include "pkmws/io/mechanism_file.hpp"
#include "support/fixtures.hpp"

namespace {

using namespace pkmws;
using geometry::Box;
using geometry::Point;

std::string num(double v) {
  char s[32];
  std::snprintf(s, sizeof s, "%.17g", v);
  return s;
}

io::MechanismFile five_bar(double a, double l11, double l12, double l21, double l22, int m1, int m2, double alpha) {
  const std::string text = R"({"name": "five-bar", "mechanism": "five_bar", "units": "m",
      "base": [[)" + num(-a) + R"(, 0], [)" + num(a) + R"(, 0]], "proximal": [)" + num(l11) + ", " + num(l21) +
                           R"(], "distal": [)" + num(l12) + ", " + num(l22) + R"(], "working_mode": [)" +
                           std::to_string(m1) + ", " + std::to_string(m2) +
                           R"(], "criteria": {"max_pressure_angle_deg": )" + num(alpha) + "}}";
  return io::parse_mechanism_text(text, "five_bar.json");
}

// The charted bounds (limited_workspace without regions) and the plane's
// (the same constraints traced in (x, y) over W alone).
struct Both {
  certified::CertifiedRegion charted, plane;
};
Both both(const io::MechanismFile& f, double tol) {
  certified::LevelSetOptions o;
  o.relative_tolerance = tol;
  Both out;
  out.charted = criteria::limited_workspace(f, criteria::file_limits(f), o).region;
  const auto fields = criteria::fields_for(f, "pressure_angle");
  std::vector<certified::Constraint> cs;
  for (const auto& c : fields) cs.push_back({c.surrogate.get(), c.level(f.criteria.max_pressure_angle_deg.value())});
  out.plane = certified::sublevel_set(cs, f.model->workspace(), fields.front().within_test, o).region;
  return out;
}

TEST(LevelSetCharts, FiveBarsHaveChartsWhereTheirFieldsAreSingular) {
  const auto dextar = five_bar(0.125, 0.2, 0.2, 0.2, 0.2, 1, -1, 40.0);
  const auto fields = dextar.model->capability<criteria::CriterionFields>();
  ASSERT_TRUE(fields);
  const auto charts = fields->charts(dextar.model->workspace());
  ASSERT_TRUE(charts);
  EXPECT_EQ(charts->charts.size(), 4u);  // two bands, two base disks
  // Unequal links: the bands only.
  const auto other = five_bar(0.1, 0.25, 0.2, 0.22, 0.27, 1, 1, 40.0);
  const auto c2 = other.model->capability<criteria::CriterionFields>()->charts(other.model->workspace());
  ASSERT_TRUE(c2);
  EXPECT_EQ(c2->charts.size(), 2u);
  // The charts map onto the plane as described: the band chart's v = 0 is the circle r = l1 + l2.
  const auto& band = charts->charts.front();
  const Point p = band.to_plane({0.1, 0.0});
  EXPECT_NEAR(std::hypot(p.x + 0.125, p.y), 0.4, 1e-15);
}

TEST(LevelSetCharts, TheRestAndTheChartsPartsAddUpToTheWorkspace) {
  // The charts' parts (their cuts alone, traced in the charts' coordinates
  // with their area elements) and the exact rest partition W: their areas
  // add up to W's exact area.
  for (const auto& f : {five_bar(0.125, 0.2, 0.2, 0.2, 0.2, 1, -1, 40.0), five_bar(0.1, 0.25, 0.2, 0.22, 0.27, -1, 1, 40.0),
                        five_bar(0.08, 0.21, 0.21, 0.26, 0.26, 1, 1, 40.0),
                        // bases closer than two base disks: the bands only
                        five_bar(0.009, 0.2, 0.2, 0.2, 0.2, 1, -1, 40.0)}) {
    const geometry::Region w = f.model->workspace();
    const auto charts = f.model->capability<criteria::CriterionFields>()->charts(w);
    ASSERT_TRUE(charts);
    double lower = charts->rest.area(), upper = lower;
    for (const auto& chart : charts->charts) {
      upper += chart.uncovered;
      if (chart.cuts.empty()) {  // the whole window (a base disk): ∫∫ ρ, exact for an affine ρ
        lower += chart.weight.box(chart.window) * (1.0 - 1e-14) - chart.overlap;
        upper += chart.weight.box(chart.window) * (1.0 + 1e-14);
        continue;
      }
      std::vector<certified::Constraint> cs;
      for (const auto& cut : chart.cuts) cs.push_back({cut.field.get(), cut.level});
      certified::LevelSetOptions o;
      o.relative_tolerance = 1e-10;
      o.weight = chart.weight;
      const auto r = certified::sublevel_set(cs, geometry::rectangle(chart.window),
                                             [](const Box&) { return certified::CellState::inside; }, o);
      EXPECT_GT(r.region.area_lower, 0.0);
      lower += r.region.area_lower - chart.overlap;
      upper += r.region.area_upper;
    }
    const double exact = w.area();
    EXPECT_LE(lower, exact * (1.0 + 1e-12)) << f.name;
    EXPECT_GE(upper, exact * (1.0 - 1e-12)) << f.name;
    EXPECT_LE(upper - lower, 1e-8 * exact) << f.name;
  }
}

TEST(LevelSetCharts, TheSliverBetweenAWindowAndTheRestIsBounded) {
  // A chart's window ends just below the rest's circle (v <= vt < vc): the
  // annular sliver between the image of its top edge and that circle is in
  // neither part, and `uncovered` must bound its area. The DexTAR: bands at
  // r_k = 0.4 · 31/32 (charts 0, 1), base disks of radius 0.4 / 6 (2, 3).
  const auto dextar = five_bar(0.125, 0.2, 0.2, 0.2, 0.2, 1, -1, 40.0);
  const auto charts = dextar.model->capability<criteria::CriterionFields>()->charts(dextar.model->workspace());
  ASSERT_TRUE(charts);
  ASSERT_EQ(charts->charts.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    const auto& chart = charts->charts[i];
    const Point base{i % 2 == 0 ? -0.125 : 0.125, 0.0};
    const double rho = i < 2 ? 0.4 * 31.0 / 32.0 : 0.4 / 6.0;
    const Point top = chart.to_plane({0.0, chart.window.max.y});
    const double rt = std::hypot(top.x - base.x, top.y - base.y);
    EXPECT_TRUE(i < 2 ? rt > rho : rt < rho) << i;  // the window stops short of the rest
    // θ = c u with ρ(u, v) = c v: the window's angle is c × its width.
    const double sector = 0.5 * chart.weight.cy * chart.window.width() * std::abs(rt * rt - rho * rho);
    EXPECT_GT(sector, 0.0) << i;
    EXPECT_GE(chart.uncovered, sector) << i;
    EXPECT_LE(chart.uncovered, 1.5 * sector) << i;
  }
}

TEST(LevelSetCharts, BoundsAtEveryToleranceMeet) {
  // Different tolerances trace different pieces: every pair of enclosures of
  // one area must meet (each chart's own bounds are checked through the total).
  for (const auto& f : {five_bar(0.125, 0.2, 0.2, 0.2, 0.2, 1, 1, 80.0), five_bar(0.125, 0.2, 0.2, 0.2, 0.2, 1, -1, 60.0)}) {
    std::vector<certified::CertifiedRegion> rs;
    for (double tol : {1e-3, 1e-4, 1e-5, 1e-6, 1e-7}) {
      certified::LevelSetOptions o;
      o.relative_tolerance = tol;
      rs.push_back(criteria::limited_workspace(f, criteria::file_limits(f), o).region);
      EXPECT_LE(rs.back().area_lower, rs.back().area_upper) << tol;
      EXPECT_LE(rs.back().width(), tol * rs.back().area_upper) << tol;
    }
    for (const auto& a : rs) {
      for (const auto& b : rs) EXPECT_LE(a.area_lower, b.area_upper);
    }
  }
}

TEST(LevelSetCharts, ChartedBoundsMeetThePlanesAndHoldADenseGrid) {
  std::vector<io::MechanismFile> files;
  files.push_back(five_bar(0.125, 0.2, 0.2, 0.2, 0.2, 1, 1, 20.0));  // DexTAR
  files.push_back(five_bar(0.125, 0.2, 0.2, 0.2, 0.2, 1, -1, 80.0));
  std::mt19937 rng(303);
  std::uniform_real_distribution<double> half_span(0.05, 0.2), link(0.15, 0.3), alpha(25.0, 75.0);
  for (int k = 0; k < 4; ++k) {
    const double a = half_span(rng), l1 = link(rng), l2 = link(rng), l3 = link(rng);
    // Designs 0 and 1: equal links in each leg (base charts); 2 and 3: unequal.
    const double l4 = link(rng);
    files.push_back(k < 2 ? five_bar(a, l1, l1, l2, l2, k == 0 ? 1 : -1, 1, alpha(rng))
                          : five_bar(a, l1, l3, l2, l4, 1, k == 2 ? -1 : 1, alpha(rng)));
  }
  for (const auto& f : files) {
    const double tol = 1e-6;
    const Both b = both(f, tol);
    const auto& c = b.charted;
    EXPECT_LE(c.width(), tol * c.area_upper) << f.name;
    // Two valid enclosures of one area meet.
    EXPECT_LE(c.area_lower, b.plane.area_upper) << f.name;
    EXPECT_LE(b.plane.area_lower, c.area_upper) << f.name;
    // A 600² grid of the mechanism's own evaluation (not the surrogate).
    const auto fields = criteria::fields_for(f, "pressure_angle");
    const double limit = f.criteria.max_pressure_angle_deg.value();
    const Box box = f.model->workspace().bbox();
    const int n = 600;
    const double grid = test::grid_area(box, n, [&](Point p) { return fields.front().value(p) <= limit; });
    const double h = std::max(box.width(), box.height()) / n;
    const double slack = (box.width() + box.height()) * h;
    EXPECT_LE(c.area_lower, grid + slack) << f.name << " grid " << grid;
    EXPECT_GE(c.area_upper, grid - slack) << f.name << " grid " << grid;
  }
}

}  // namespace

TEST(LevelSetCharts, TheRestsSignedDisksAreTheRest) {
  // rest_disks must describe rest exactly: the level sets take the areas of
  // boxes across rest's boundary from them in closed form. Boxes at random
  // points of W's bounding box, of sizes 1e-4 to 0.05: the closed form's
  // enclosure holds CGAL's exact area of box ∩ rest.
  std::mt19937 rng(17);
  for (const auto& f : {five_bar(0.125, 0.2, 0.2, 0.2, 0.2, 1, -1, 40.0), five_bar(0.1, 0.25, 0.2, 0.22, 0.27, -1, 1, 40.0),
                        five_bar(0.08, 0.21, 0.21, 0.26, 0.26, 1, 1, 40.0), five_bar(0.009, 0.2, 0.2, 0.2, 0.2, 1, -1, 40.0)}) {
    const geometry::Region w = f.model->workspace();
    const auto charts = f.model->capability<criteria::CriterionFields>()->charts(w);
    ASSERT_TRUE(charts);
    ASSERT_FALSE(charts->rest_disks.empty());
    const Box bb = w.bbox();
    std::uniform_real_distribution<double> ux(bb.min.x, bb.max.x), uy(bb.min.y, bb.max.y), lg(-4.0, -1.3),
        turn(0.0, 6.283185307179586);
    std::uniform_int_distribution<std::size_t> which(0, charts->rest_disks.size() - 1);
    int decided = 0, partial = 0;
    for (int k = 0; k < 300; ++k) {
      const double s = std::pow(10.0, lg(rng));
      Point c{ux(rng), uy(rng)};
      if (k % 2 == 1) {  // at a point of one of the circles
        const certified::SignedDisk& d = charts->rest_disks[which(rng)];
        const double t = turn(rng);
        c = {d.centre.x + d.radius * std::cos(t) - 0.5 * s, d.centre.y + d.radius * std::sin(t) - 0.5 * s};
      }
      const std::vector<Point> box{{c.x, c.y}, {c.x + s, c.y}, {c.x + s, c.y + s}, {c.x, c.y + s}};
      const auto a = certified::area_in_disks(box, charts->rest_disks);
      if (!a) continue;
      ++decided;
      const double exact = charts->rest.intersect(geometry::polygon(box)).area();
      if (exact > 0.0 && exact < s * s * (1.0 - 1e-9)) ++partial;
      // CGAL's area() sums the exact boundary's curves rounded to doubles: ~1e-16 of W's size along the box's edges.
      const double slack = 1e-14 * bb.width() * s;
      EXPECT_LE(a->lo, exact + slack) << f.name << " box " << k << std::setprecision(17) << " [" << a->lo << ", " << a->hi
                                      << "] exact " << exact;
      EXPECT_GE(a->hi, exact - slack) << f.name << " box " << k;
      EXPECT_LE(a->hi - a->lo, 1e-12 * bb.width() * bb.width()) << f.name << " box " << k;  // rounding at W's scale
    }
    EXPECT_GE(decided, 200) << f.name;
    EXPECT_GE(partial, 25) << f.name;  // across rest's boundary
  }
}

TEST(LevelSetCharts, OneAndTwoThreadsGiveIdenticalResults) {
  // The rest, then the charts as parallel tasks (each parallel inside),
  // added in chart order: 1 and 2 threads agree bit for bit.
  const auto f = five_bar(0.125, 0.2, 0.2, 0.2, 0.2, -1, 1, 40.0);
  criteria::LimitedWorkspace r[2];
  for (int k = 0; k < 2; ++k) {
    certified::LevelSetOptions o;
    o.threads = k + 1;
    r[k] = criteria::limited_workspace(f, criteria::file_limits(f), o);
  }
  ASSERT_TRUE(r[0].charted);
  EXPECT_EQ(r[0].region.area_lower, r[1].region.area_lower);
  EXPECT_EQ(r[0].region.area_upper, r[1].region.area_upper);
  EXPECT_EQ(r[0].detail.traced_cells, r[1].detail.traced_cells);
  EXPECT_EQ(r[0].detail.cell_tests, r[1].detail.cell_tests);
  ASSERT_EQ(r[0].curves.size(), r[1].curves.size());
  for (std::size_t i = 0; i < r[0].curves.size(); ++i) EXPECT_EQ(r[0].curves[i], r[1].curves[i]);
}
