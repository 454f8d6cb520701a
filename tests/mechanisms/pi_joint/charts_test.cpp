// Active Π-joint charts ([Milutinovic]): the figure data, the SVG line chart,
// nice ticks.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "pkmws/io/mechanism_file.hpp"
#include "pkmws/io/plot.hpp"
#include "mechanisms/pi_joint/charts.hpp"
#include "support/fixtures.hpp"
#include "support/mechanisms/pi_joint.hpp"

using namespace pkmws;
using namespace pkmws::test::pi_joint;
using mechanisms::PiJoint;

namespace {

constexpr double pi = std::numbers::pi;
constexpr double deg = pi / 180.0;

using pkmws::test::count_of;

}  // namespace

TEST(PiJointFigures, SeriesFollowThePapersFormulas) {
  const auto figures = mechanisms::pi_joint_figures(prototype(), 121);
  std::vector<int> numbers;
  for (const auto& f : figures) numbers.push_back(f.number);
  EXPECT_EQ(numbers, (std::vector<int>{8, 9, 10, 11, 12, 15, 16, 17}));
  auto value_at = [](const io::PlotSeries& s, double x) {
    for (std::size_t i = 0; i < s.x.size(); ++i) if (std::abs(s.x[i] - x) < 1e-9) return s.y[i];
    ADD_FAILURE() << "no sample at " << x;
    return 0.0;
  };
  // Figure 8: a = 1 m; d(90°) = 1 + k, d(-90°) = |1 - k|.
  const auto& f8 = figures[0].chart;
  ASSERT_EQ(f8.series.size(), 5u);
  EXPECT_NEAR(value_at(f8.series[1], 90.0), 1.4, 1e-12);
  EXPECT_NEAR(value_at(f8.series[4], -90.0), 0.5, 1e-12);
  // Figure 11: J(0) = k / sqrt(1 + k²) for a = 1 m.
  EXPECT_NEAR(value_at(figures[3].chart.series[1], 0.0), 0.4 / std::sqrt(1.16), 1e-12);
  // Figure 12: J⁻¹ = 1 / J.
  EXPECT_NEAR(value_at(figures[4].chart.series[2], 0.0), std::sqrt(1.25) / 0.5, 1e-12);
  // Figures 15-17 over the prototype's ±60°.
  const double j60 = 170.0 * 0.4 * 0.5 / std::sqrt(1.16 + 0.8 * std::sin(60 * deg));
  EXPECT_NEAR(value_at(figures[5].chart.series[0], 60.0), 0.0127 / j60 / deg, 1e-12);
  EXPECT_NEAR(value_at(figures[6].chart.series[0], 60.0), 50.0 / j60 / deg, 1e-10);
  EXPECT_NEAR(value_at(figures[7].chart.series[0], 60.0), 130.0 * j60 * 1e-3, 1e-12);
  EXPECT_NEAR(figures[7].chart.series[0].x.front(), -60.0, 1e-12);
  EXPECT_NEAR(figures[7].chart.series[0].x.back(), 60.0, 1e-12);
  // Without an actuator only figures 8-12.
  mechanisms::PiJointParams p = prototype().params();
  p.actuator.reset();
  EXPECT_EQ(mechanisms::pi_joint_figures(PiJoint(p)).size(), 5u);
}

TEST(PiJointFigures, LineChartSvgHasAxesTicksLegend) {
  const auto figures = mechanisms::pi_joint_figures(prototype(), 61);
  for (const auto& f : figures) {
    const std::string svg = io::line_chart_svg(f.chart);
    EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
    EXPECT_EQ(count_of(svg, "<svg"), 1u);
    EXPECT_EQ(count_of(svg, "</svg>"), 1u);
    EXPECT_EQ(count_of(svg, "<g"), count_of(svg, "</g>"));
    // One path per series, one legend entry per series.
    EXPECT_EQ(count_of(svg, "<path"), f.chart.series.size()) << f.stem;
    for (const auto& s : f.chart.series) EXPECT_NE(svg.find(">" + s.label + "<"), std::string::npos) << s.label;
    EXPECT_NE(svg.find(f.chart.x_label), std::string::npos);
    EXPECT_NE(svg.find("θ [°]"), std::string::npos);
  }
  // Figure 12's J⁻¹ stays finite over ±75°; a NaN breaks the line into two subpaths.
  io::LineChart c;
  c.series.push_back({"a", {0, 1, 2, 3, 4}, {0, 1, std::nan(""), 3, 4}, false});
  const std::string svg = io::line_chart_svg(c);
  EXPECT_EQ(count_of(svg, " M"), 1u);
  EXPECT_THROW(io::line_chart_svg(io::LineChart{}), std::invalid_argument);
}

TEST(PiJointFigures, NiceTicks) {
  EXPECT_EQ(io::nice_ticks(-60, 60), (std::vector<double>{-60, -40, -20, 0, 20, 40, 60}));
  EXPECT_EQ(io::nice_ticks(0, 1, 5), (std::vector<double>{0, 0.2, 0.4, 0.6000000000000001, 0.8, 1}));
  const auto t = io::nice_ticks(0.011, 0.029);
  ASSERT_GE(t.size(), 3u);
  EXPECT_GE(t.front(), 0.011);
  EXPECT_LE(t.back(), 0.029);
}
