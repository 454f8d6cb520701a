// Line charts of data series as SVG (the paper papers' x-y plots: Π-joint
// figures 8-12 and 15-17, velocity ratios, ...). Plain data, no CGAL.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace pkmws::io {

/// One curve: points (x[i], y[i]); a non-finite y breaks the line there.
struct PlotSeries {
  std::string label;
  std::vector<double> x;
  std::vector<double> y;
  bool dashed = false;
};

struct LineChart {
  std::string title;
  std::string x_label;  // with its unit, e.g. "θ [°]"
  std::string y_label;
  std::vector<PlotSeries> series;
  /// Axis ranges; default: the finite data range, widened to whole ticks.
  std::optional<std::array<double, 2>> x_range;
  std::optional<std::array<double, 2>> y_range;
  /// Tick spacing on x (e.g. 30 for degrees); default: 1-2-5 steps.
  std::optional<double> x_tick_step;
  std::string caption;  // one line under the plot (source, parameters)
};

/// "Nice" tick values (steps 1, 2, 5 x 10^n) covering [lo, hi], about
/// `target` of them; lo < hi.
std::vector<double> nice_ticks(double lo, double hi, int target = 6);

/// The chart as a standalone SVG document: axes with ticks and tick labels,
/// grid, axis labels, title, legend (in the corner that hides the fewest data
/// points) and caption. `width` x `height` pixels.
/// Throws std::invalid_argument when no series has two finite points or a
/// series' x and y sizes differ.
std::string line_chart_svg(const LineChart& chart, int width = 760, int height = 500);

/// A chart with the file stem it is written under.
struct NamedChart {
  std::string stem;  // e.g. "pi_joint_fig08_length"
  LineChart chart;
};

/// Capability (Mechanism::capability): a mechanism whose study is a set of
/// curves rather than a workspace (`pkmws plot`: the Π-joint's figures).
struct Charts {
  static constexpr std::string_view capability_name = "curve charts (pkmws plot draws the Pi-joint's)";
  virtual ~Charts() = default;
  virtual std::vector<NamedChart> charts() const = 0;
};

}  // namespace pkmws::io
