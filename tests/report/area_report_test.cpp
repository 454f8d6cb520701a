// The area report (pkmws/report/area.hpp) against closed forms (the toy
// annulus), its JSON text parsed back, its text form, the budget of a
// criteria-limited area, and its errors.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>

#include "pkmws/io/mechanism_file.hpp"
#include "pkmws/pkmws.hpp"
#include "pkmws/report/area.hpp"
#include "support/fixtures.hpp"
#include "support/report_fixtures.hpp"

namespace pkmws {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(ReportArea, AnnulusMatchesItsClosedForm) {
  const io::MechanismFile f = test::toy_annulus_file();
  const report::AreaReport r = report::area(f);
  EXPECT_EQ(r.method, "exact");
  EXPECT_TRUE(r.enclosure.exact);
  EXPECT_FALSE(r.limited);
  EXPECT_FALSE(r.real);
  EXPECT_NEAR(r.area, 40 * kPi, 1e-12 * 40 * kPi);
  EXPECT_LT(r.area_lower, r.area);
  EXPECT_GT(r.area_upper, r.area);
  const double width = 128 * std::numeric_limits<double>::epsilon() * r.area;
  EXPECT_NEAR(r.area_upper - r.area_lower, width, 0.01 * width);
  ASSERT_EQ(r.components.size(), 1u);
  const auto& c = r.components[0];
  EXPECT_EQ(c.holes, 1u);
  EXPECT_NEAR(c.perimeter, 20 * kPi, 1e-9);
  EXPECT_NEAR(c.centroid.x, 1.0, 1e-9);
  EXPECT_NEAR(c.centroid.y, 2.0, 1e-9);
  EXPECT_NEAR(c.bbox.min.x, -6.0, 1e-12);
  EXPECT_NEAR(c.bbox.max.y, 9.0, 1e-12);
  // The ring is 4 wide: the largest inscribed circle has radius 2.
  EXPECT_LE(c.inscribed_circle.radius, 2.0 + 1e-12);
  EXPECT_NEAR(c.inscribed_circle.radius, 2.0, report::inscribed_circle_precision(c.bbox));
  EXPECT_NEAR(std::hypot(c.inscribed_circle.center.x - 1.0, c.inscribed_circle.center.y - 2.0), 5.0, 1e-3);
  // The rectangle: corners within the ring, certified area bounds.
  const auto& rect = c.inscribed_rectangle;
  EXPECT_TRUE(rect.verified);
  EXPECT_GT(rect.area, 0.0);
  EXPECT_LE(rect.area, rect.area_upper);
  EXPECT_LE(rect.area_upper, rect.area * (1 + 2e-6));
  for (const geometry::Point p : {rect.box.min, rect.box.max, geometry::Point{rect.box.min.x, rect.box.max.y},
                                  geometry::Point{rect.box.max.x, rect.box.min.y}}) {
    const double d = std::hypot(p.x - 1.0, p.y - 2.0);
    EXPECT_GE(d, 3.0 - 1e-9);
    EXPECT_LE(d, 7.0 + 1e-9);
  }
  ASSERT_TRUE(r.bbox);
  EXPECT_NEAR(r.bbox->max.x, 8.0, 1e-12);
  EXPECT_GT(r.boundary_curves, 0u);
}

TEST(ReportArea, JsonTextParsesBackToTheReport) {
  const report::AreaReport r = report::area(test::toy_annulus_file());
  const auto j = test::parsed(report::to_json_text(r));
  EXPECT_EQ(j["name"], "toy annulus");
  EXPECT_EQ(j["mechanism"], "toy_rp");
  EXPECT_EQ(j["units"], "mm");
  EXPECT_EQ(j["method"], "exact");
  // Doubles survive the text exactly (shortest round-trip digits).
  EXPECT_EQ(j["area"].get<double>(), r.area);
  EXPECT_EQ(j["area_lower"].get<double>(), r.area_lower);
  EXPECT_EQ(j["area_upper"].get<double>(), r.area_upper);
  EXPECT_EQ(j["time_ms"].get<double>(), r.time_ms);
  EXPECT_EQ(j["boundary_curves"].get<std::size_t>(), r.boundary_curves);
  EXPECT_EQ(j["bbox"]["max"][1].get<double>(), r.bbox->max.y);
  ASSERT_EQ(j["components"].size(), 1u);
  const auto& c = j["components"][0];
  EXPECT_EQ(c["holes"], 1);
  EXPECT_EQ(c["centroid"][0].get<double>(), r.components[0].centroid.x);
  EXPECT_EQ(c["inscribed_circle"]["radius"].get<double>(), r.components[0].inscribed_circle.radius);
  EXPECT_EQ(c["inscribed_rectangle"]["width"].get<double>(), r.components[0].inscribed_rectangle.box.width());
  EXPECT_EQ(c["inscribed_rectangle"]["verified"], true);
  // Exact and without criteria or bodies: none of their keys.
  for (const char* key : {"components_of", "criteria", "traced_cells", "stopped", "note", "real_area", "interference"}) {
    EXPECT_FALSE(j.contains(key)) << key;
  }
  EXPECT_EQ(report::to_json_text(r).find('\n'), 1u) << "indented by 2";
}

TEST(ReportArea, TextStatesTheAreaWithItsUnit) {
  report::AreaReport r = report::area(test::toy_annulus_file());
  r.time_ms = 1.5;
  const std::string t = report::to_text(r);
  EXPECT_EQ(t.rfind("toy annulus (toy_rp)\narea       125.663706143", 0), 0u) << t;
  EXPECT_NE(t.find(" mm²  (exact, 1 component)\n"), std::string::npos) << t;
  EXPECT_NE(t.find("  [0] area 125.663706143"), std::string::npos) << t;
  EXPECT_NE(t.find("inscribed circle r = 2"), std::string::npos) << t;
  EXPECT_NE(t.find(std::string("time       1.500 ms  (") + report::kComputeTimeMeaning + ")\n"), std::string::npos);
  EXPECT_EQ(test::count_of(t, "\n"), 4u);
}

TEST(ReportArea, ExactBoundsAreTheRoundingOfGreensTheorem) {
  const report::AreaBounds b = report::exact_area_bounds(1.0);
  EXPECT_EQ(b.lower, 1.0 - 64 * std::numeric_limits<double>::epsilon());
  EXPECT_EQ(b.upper, 1.0 + 64 * std::numeric_limits<double>::epsilon());
  // The front door's workspace is the report's enclosure.
  const io::MechanismFile f = test::toy_annulus_file();
  EXPECT_EQ(pkmws::workspace(f).inner.area(), report::area(f).enclosure.inner.area());
}

TEST(ReportArea, ANonPlanarFileIsAnErrorNamingIt) {
  const io::MechanismFile f = io::load_mechanism(test::dataset("pi_joint_prototype"));
  try {
    report::area(f);
    FAIL() << "a lone Π-joint has no workspace";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(f.path + ": pi_joint: ", 0), 0u) << e.what();
  }
}

// A deadline already past: the limited area stops at once with certified
// (wide) bounds, says so with the budget's note, and the budget was asked.
TEST(ReportArea, CriteriaAreaFollowsItsBudget) {
  const io::MechanismFile f = io::load_mechanism(test::dataset("five_bar_dextar_pp_alpha40"));
  report::AreaOptions o;
  int asked = 0;
  o.budget.bound = [&asked](certified::LevelSetOptions lo, const std::string& stage) {
    ++asked;
    EXPECT_EQ(stage, "");
    lo.deadline = std::chrono::steady_clock::now();
    return lo;
  };
  o.budget.stopped_note = "stopped by the test";
  const report::AreaReport r = report::area(f, o);
  EXPECT_EQ(asked, 1);
  EXPECT_EQ(r.method, "certified");
  ASSERT_TRUE(r.limited);
  EXPECT_EQ(r.stopped, "stopped by the test");
  // README: the certified limited area of DexTAR (++) at 40°.
  EXPECT_LE(r.area_lower, 0.2246441686 + 1e-9);
  EXPECT_GE(r.area_upper, 0.2246443091 - 1e-9);
  ASSERT_EQ(r.criteria.size(), 1u);
  EXPECT_EQ(r.criteria[0].criterion, "pressure_angle");
  EXPECT_EQ(r.criteria[0].threshold, 40.0);
  const auto j = test::parsed(report::to_json_text(r));
  EXPECT_EQ(j["stopped"], "stopped by the test");
  EXPECT_EQ(j["components"].size(), 0u);
  EXPECT_FALSE(j.contains("bbox"));
  EXPECT_EQ(j["criteria"][0]["threshold"].get<double>(), 40.0);
  EXPECT_EQ(j["traced_cells"].get<std::uint64_t>(), r.limited->detail.traced_cells);
  const std::string t = report::to_text(r);
  EXPECT_NE(t.find("           limited by pressure_angle <= 40\n"), std::string::npos) << t;
  EXPECT_NE(t.find("STOPPED    stopped by the test\n"), std::string::npos) << t;
}

// The 3-DOF condition number depends on the characteristic length L of
// x' = (x, y, L phi): the report states the one it used, the platform's
// circumradius (0.1 m) by default, the file's when it gives one.
TEST(ReportArea, ConditionNumberLimitStatesItsCharacteristicLength) {
  const auto stopped_at_once = [](report::AreaOptions& o) {
    o.budget.bound = [](certified::LevelSetOptions lo, const std::string&) {
      lo.deadline = std::chrono::steady_clock::now();
      return lo;
    };
  };
  report::AreaOptions o;
  stopped_at_once(o);
  const auto path = test::dataset("three_rpr_paminsa_phi0_kappa4");
  const report::AreaReport r = report::area(io::load_mechanism(path), o);
  ASSERT_EQ(r.criteria.size(), 1u);
  EXPECT_EQ(r.criteria[0].criterion, "condition_number");
  EXPECT_NEAR(r.criteria[0].characteristic_length, 0.1, 1e-15);
  EXPECT_NE(report::to_text(r).find("limited by condition_number <= 4 (characteristic length L = 0.1 m)\n"),
            std::string::npos)
      << report::to_text(r);
  EXPECT_NEAR(test::parsed(report::to_json_text(r))["criteria"][0]["characteristic_length"].get<double>(), 0.1, 1e-15);

  std::string text = test::slurp(path);
  const std::string key = "\"max_condition_number\": 4.0";
  ASSERT_NE(text.find(key), std::string::npos);
  text.replace(text.find(key), key.size(), key + ", \"characteristic_length\": 0.25");
  const report::AreaReport given = report::area(io::parse_mechanism_text(text, "given_L.json"), o);
  ASSERT_EQ(given.criteria.size(), 1u);
  EXPECT_EQ(given.criteria[0].characteristic_length, 0.25);

  // A pressure-angle limit has no length: none is stated.
  const report::AreaReport alpha = report::area(io::load_mechanism(test::dataset("five_bar_dextar_pp_alpha40")), o);
  ASSERT_EQ(alpha.criteria.size(), 1u);
  EXPECT_EQ(alpha.criteria[0].characteristic_length, 0.0);
  EXPECT_FALSE(test::parsed(report::to_json_text(alpha))["criteria"][0].contains("characteristic_length"));
}

}  // namespace
}  // namespace pkmws
