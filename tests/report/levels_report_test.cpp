// The levels report (pkmws/report/levels.hpp): the biglide's velocity-ratio
// bands against the README's certified area and a grid of the mechanism's own
// evaluate, the bands' arithmetic, the JSON text parsed back, the text form,
// the curves and the figure, and the refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "pkmws/io/mechanism_file.hpp"
#include "pkmws/report/area.hpp"
#include "pkmws/report/levels.hpp"
#include "support/fixtures.hpp"
#include "support/report_fixtures.hpp"

namespace pkmws {
namespace {

report::LevelsReport biglide_bands(const io::MechanismFile& f) {
  report::LevelsOptions o;
  o.criterion = "velocity_ratio";
  o.levels = {1.5, 2.0};
  o.tolerance = 1e-4;
  return report::levels(f, o);
}

TEST(ReportLevels, BandsBracketTheCertifiedAreaAndAGrid) {
  const io::MechanismFile f = io::load_mechanism(test::dataset("biglide_simplified"));
  const report::LevelsReport r = biglide_bands(f);
  EXPECT_EQ(r.criterion, "velocity_ratio");
  EXPECT_FALSE(r.stopped);
  ASSERT_EQ(r.bands.size(), 2u);
  ASSERT_EQ(r.sublevel_sets.size(), 2u);
  // Both velocity ratios <= 2: the exact area is 932941.5282957 mm² (W cut by
  // the strips where both hold, test LevelSetsSingular).
  const auto& s2 = r.sublevel_sets[1].region;
  EXPECT_LE(s2.area_lower, 932941.5282958);
  EXPECT_GE(s2.area_upper, 932941.5282957);
  EXPECT_LE(s2.area_upper - s2.area_lower, 1e-4 * s2.area_upper);
  // A grid of the mechanism's own velocity ratios (the file's working mode).
  const double grid = test::grid_area(f.model->bounds(), 400, [&](geometry::Point p) {
    const auto ev = f.model->evaluate({p.x, p.y, 0.0}, f.criteria);
    if (ev.empty() || !ev.front().reachable || !ev.front().velocity_ratio) return false;
    return *ev.front().velocity_ratio <= 2.0;
  });
  EXPECT_NEAR(0.5 * (s2.area_lower + s2.area_upper), grid, 1e-2 * grid);
  // Band 1 = S(2) minus S(1.5): its bounds from the sub-level sets' bounds.
  const auto& s1 = r.sublevel_sets[0].region;
  EXPECT_EQ(r.bands[0].area_lower, s1.area_lower);
  EXPECT_NEAR(r.bands[1].area_lower, std::max(0.0, s2.area_lower - s1.area_upper), 1e-6 * s2.area_upper);
  EXPECT_NEAR(r.bands[1].area_upper, s2.area_upper - s1.area_lower, 1e-6 * s2.area_upper);
  EXPECT_EQ(r.bands[1].lower_level, 1.5);
  EXPECT_EQ(r.bands[1].upper_level, 2.0);
}

TEST(ReportLevels, EachLevelIsTheLimitedWorkspaceAreaCertifies) {
  // DexTAR (+1, -1) at 40 deg: the sub-level set of `levels` is the
  // criteria-limited workspace `pkmws area` certifies for the file with
  // that limit (charts included): the same bounds, bit for bit.
  const io::MechanismFile f = io::load_mechanism(test::dataset("five_bar_dextar_pm"));
  report::LevelsOptions o;
  o.criterion = "pressure_angle";
  o.levels = {20.0, 40.0};
  const report::LevelsReport r = report::levels(f, o);
  ASSERT_EQ(r.sublevel_sets.size(), 2u);
  const io::MechanismFile limited = io::load_mechanism(test::dataset("five_bar_dextar_pm_alpha40"));
  const auto lw = report::limited_workspace(limited, {});
  ASSERT_TRUE(lw.charted);
  EXPECT_EQ(r.sublevel_sets[1].region.area_lower, lw.region.area_lower);
  EXPECT_EQ(r.sublevel_sets[1].region.area_upper, lw.region.area_upper);
  EXPECT_LE(r.sublevel_sets[1].region.width(), 1e-6 * lw.region.area_upper);
  // The traced curves (the charts' mapped to the plane, not the charts'
  // cuts) lie on their level: the mechanism's own pressure angle there (the
  // larger of the legs'). Every level curve ends at the base joints
  // (±0.1375, 0), where the angle is 0/0: the base charts' curves reach them.
  std::size_t checked = 0;
  for (std::size_t k = 0; k < 2; ++k) {
    for (const auto& piece : r.sublevel_sets[k].curves) {
      for (std::size_t i = 0; i < piece.size(); i += 5) {
        if (std::abs(std::abs(piece[i].x) - 0.1375) < 1e-12 && std::abs(piece[i].y) < 1e-12) continue;
        const auto ev = f.model->evaluate({piece[i].x, piece[i].y, 0.0}, f.criteria);
        ASSERT_FALSE(ev.empty());
        ASSERT_TRUE(ev.front().reachable) << piece[i].x << ", " << piece[i].y;
        const double alpha = std::max(ev.front().pressure_angle_deg[0], ev.front().pressure_angle_deg[1]);
        EXPECT_NEAR(alpha, o.levels[k], 1e-6) << piece[i].x << ", " << piece[i].y;
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 1000u);
  // The band figure has its pieces in (x, y) (the charts give none).
  o.figure_pieces = true;
  const report::LevelsReport drawn = report::levels(f, o);
  EXPECT_EQ(drawn.sublevel_sets[1].region.area_lower, lw.region.area_lower);
  EXPECT_GT(drawn.sublevel_sets[1].inner_polygons.size(), r.sublevel_sets[1].inner_polygons.size());
}

TEST(ReportLevels, JsonTextTextCurvesAndFigure) {
  const io::MechanismFile f = io::load_mechanism(test::dataset("biglide_simplified"));
  const report::LevelsReport r = biglide_bands(f);
  const auto j = test::parsed(report::to_json_text(r));
  EXPECT_EQ(j["criterion"], "velocity_ratio");
  EXPECT_EQ(j["criterion_units"], r.criterion_units);
  EXPECT_EQ(j["units"], "mm");
  EXPECT_EQ(j["method"], "certified");
  ASSERT_EQ(j["bands"].size(), 2u);
  EXPECT_TRUE(j["bands"][0]["from"].is_null());
  EXPECT_TRUE(j["bands"][0].contains("from_reason"));
  EXPECT_EQ(j["bands"][1]["from"].get<double>(), 1.5);
  EXPECT_EQ(j["bands"][1]["area_upper"].get<double>(), r.bands[1].area_upper);
  EXPECT_EQ(j["bands"][1]["sublevel_area_lower"].get<double>(), r.sublevel_sets[1].region.area_lower);
  EXPECT_FALSE(j.contains("stopped"));
  const std::string t = report::to_text(r);
  EXPECT_EQ(t.rfind("Biglide", 0), 0u) << t;
  EXPECT_NE(t.find(": velocity_ratio bands ("), std::string::npos) << t;
  EXPECT_NE(t.find("areas in mm², certified\n"), std::string::npos) << t;
  EXPECT_NE(t.find("\n<= 1.5 "), std::string::npos) << t;
  EXPECT_NE(t.find("\n1.5 .. 2 "), std::string::npos) << t;
  const std::string csv = report::level_curves_csv(r);
  EXPECT_EQ(csv.rfind("level,piece,x,y\n", 0), 0u);
  EXPECT_GT(test::count_of(csv, "\n2,"), 10u) << "traced points of the level 2 curves";
  const std::string svg = report::band_figure(f, r);
  EXPECT_EQ(test::count_of(svg, "class=\"band\""), 2u);
}

TEST(ReportLevels, BadLevelsAreRefusedNamingTheOption) {
  EXPECT_THROW(report::check_levels({}), InputError);
  try {
    report::check_levels({2.0, 2.0});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "--levels: values must increase");
  }
  const io::MechanismFile f = io::load_mechanism(test::dataset("five_bar_dextar_pp"));
  report::LevelsOptions o;
  o.criterion = "pressure_angle";
  o.levels = {40.0, 95.0};
  try {
    report::levels(f, o);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "--levels: 95 is outside the range of pressure_angle, (0, 90) deg");
  }
}

}  // namespace
}  // namespace pkmws
