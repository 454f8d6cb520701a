// Certified criteria-limited areas of random designs, not only the bundled
// ones: five-bars with unequal links, base spacings and working modes under a
// pressure-angle limit, and 3-RPRs with random base and platform sizes and
// orientations under a reaction or pressure-angle limit. Each traced interval
// (the method) must meet the pure cell method's (a shallow quadtree with
// independent, wide bounds) and contain a dense grid of the criterion itself
// (the mechanism's own evaluation at cell centres, not the surrogate) within
// the grid's error.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "pkmws/criteria/fields.hpp"
#include "pkmws/io/mechanism_file.hpp"
#include "support/fixtures.hpp"
#include "support/limited.hpp"

namespace {

using namespace pkmws;
using geometry::Box;
using geometry::Point;


// The traced interval meets the cell method's and holds the grid estimate
// within `slack`; it is as narrow as asked.
void check(const io::MechanismFile& f, double tol, double grid, double slack, const std::string& what) {
  const auto traced = test::limited(f, tol, true);
  const auto cells = test::limited(f, 1e-3, false);
  const auto& r = traced.region;
  EXPECT_LE(r.area_lower, r.area_upper) << what;
  EXPECT_LE(r.width(), tol * r.area_upper + 1e-15) << what;
  EXPECT_LE(r.area_lower, cells.region.area_upper) << what;
  EXPECT_LE(cells.region.area_lower, r.area_upper) << what;
  EXPECT_LE(r.area_lower, grid + slack) << what << ": grid " << grid;
  EXPECT_GE(r.area_upper, grid - slack) << what << ": grid " << grid;
}

std::string num(double v) {
  char s[32];
  std::snprintf(s, sizeof s, "%.17g", v);
  return s;
}

TEST(LevelSetsRandomDesigns, FiveBarPressureAngleAgainstTheCellMethodAndAGrid) {
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> half_span(0.05, 0.2), link(0.15, 0.3), alpha(25.0, 75.0);
  std::uniform_int_distribution<int> sign(0, 1);
  for (int design = 0; design < 4; ++design) {
    const double a = half_span(rng), l11 = link(rng), l21 = link(rng), l12 = link(rng), l22 = link(rng);
    const int m1 = sign(rng) ? 1 : -1, m2 = sign(rng) ? 1 : -1;
    const double limit = alpha(rng);
    const std::string text = R"({"name": "random five-bar", "mechanism": "five_bar", "units": "m",
      "base": [[)" + num(-a) + R"(, 0], [)" + num(a) + R"(, 0]], "proximal": [)" + num(l11) + ", " + num(l21) +
                             R"(], "distal": [)" + num(l12) + ", " + num(l22) + R"(], "working_mode": [)" +
                             std::to_string(m1) + ", " + std::to_string(m2) +
                             R"(], "criteria": {"max_pressure_angle_deg": )" + num(limit) + "}}";
    const io::MechanismFile f = io::parse_mechanism_text(text, "random_five_bar.json");
    const auto fields = criteria::fields_for(f, "pressure_angle");
    const Box b = f.model->workspace().bbox();
    const int n = 700;
    const double grid = test::grid_area(b, n, [&](Point p) {
      for (const auto& c : fields) {
        if (!(c.value(p) <= limit)) return false;  // NaN outside W or in no working mode
      }
      return true;
    });
    // Grid error: at most the cells the boundary meets, each off by h² at
    // most; the boundary is shorter than the box's half-perimeter for these
    // lens-like regions, and the errors of the cells mostly cancel (observed:
    // 5e-6 to 3e-5 against this slack of ~1e-3).
    const double h = std::max(b.width(), b.height()) / n;
    const double slack = (b.width() + b.height()) * h;
    check(f, 1e-4, grid, slack, "five-bar " + text);
  }
}

TEST(LevelSetsRandomDesigns, ThreeRprReactionAndPressureAngleAgainstTheCellMethodAndAGrid) {
  std::mt19937 rng(1202);
  std::uniform_real_distribution<double> base_radius(0.3, 0.4), platform_radius(0.06, 0.14), phi(-30.0, 30.0),
      reaction(130.0, 300.0), alpha(40.0, 70.0);
  const double pi = std::acos(-1.0);
  for (int design = 0; design < 3; ++design) {
    const double rb = base_radius(rng), rp = platform_radius(rng), orientation = phi(rng);
    std::string base, platform;
    for (int i = 0; i < 3; ++i) {
      const double t = (-90.0 + 120.0 * i) * pi / 180.0;
      base += std::string(i ? ", " : "") + "[" + num(rb * std::cos(t)) + ", " + num(rb * std::sin(t)) + "]";
      platform += std::string(i ? ", " : "") + "[" + num(rp * std::cos(t)) + ", " + num(rp * std::sin(t)) + "]";
    }
    const bool by_reaction = design != 1;
    const double limit = by_reaction ? reaction(rng) : alpha(rng);
    const std::string criteria =
        by_reaction ? R"({"load": {"force_N": 100.0, "moment_Nm": 5.0}, "max_reaction_N": )" + num(limit) +
                          R"(, "reaction_legs": [1]})"
                    : R"({"max_pressure_angle_deg": )" + num(limit) + "}";
    const std::string text = R"({"name": "random 3-RPR", "mechanism": "three_rpr", "units": "m", "base": [)" + base +
                             R"(], "platform": [)" + platform + R"(], "actuation": "revolute", "orientation_deg": )" +
                             num(orientation) + R"(, "criteria": )" + criteria +
                             R"(, "analysis_window": [[-0.3, -0.3], [0.3, 0.3]]})";
    const io::MechanismFile f = io::parse_mechanism_text(text, "random_three_rpr.json");
    const std::string name = by_reaction ? "reaction" : "pressure_angle";
    const auto fields = criteria::fields_for(f, name);
    const auto& m = *f.model;
    const Box b = m.bounds();
    const int n = 700;
    // The criterion as pkmws eval gives it, in the assembly mode of the
    // window's centre (the fields' last one for the reaction, see fields.hpp).
    const double grid = test::grid_area(b, n, [&](Point p) {
      if (!m.reachable({p.x, p.y, m.orientation()})) return false;
      for (const auto& c : fields) {
        const double bound = c.name == "assembly_mode" ? c.level(0.0) : limit;
        if (!(c.value(p) <= bound)) return false;
      }
      return true;
    });
    const double h = std::max(b.width(), b.height()) / n;
    const double slack = (b.width() + b.height()) * h;  // as for the five-bar
    check(f, 1e-4, grid, slack, "3-RPR " + text);
  }
}

}  // namespace
