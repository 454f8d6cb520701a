// Side-by-side line-chart panels sharing one legend below them (the design
// studies' "metric vs parameter, one line per configuration" figures, e.g.
// the MOMA program of building in docs/design_space.md). Plain data, no CGAL.
//
// Machine-readable marks for tests and tools: each panel's plot group has
// class "panel" and data-transform="X0 Y0 SX SY" (a point (x, y) is drawn at
// px = X0 + SX x, py = Y0 - SY y); each curve is a polyline of class
// "series" with data-label; legend entries are in the group of class "legend".
#pragma once

#include <string>
#include <vector>

namespace pkmws::io {

struct PanelSeries {
  std::string label;
  std::vector<double> x;
  std::vector<double> y;  // a non-finite y breaks the line
  std::string colour = "#000000";
  std::string dash;       // SVG stroke-dasharray ("" solid)
};

struct Panel {
  std::string title;
  std::string x_label;  // with unit, e.g. "rod length l (mm)"
  std::string y_label;
  std::vector<PanelSeries> series;
};

struct PanelFigure {
  std::string title;
  std::vector<Panel> panels;
  /// x values drawn as light vertical guides labelled `marks_label` (e.g. the bundled rod lengths).
  std::vector<double> x_marks;
  std::string marks_label;
  std::string caption;  // wrapped under the legend
};

/// The figure as a standalone SVG document. Series with the same label in
/// several panels share one legend entry (taken from the first panel that has
/// it). Throws std::invalid_argument when there is no panel, a series' x and
/// y sizes differ, or a panel has no finite point.
std::string panel_chart_svg(const PanelFigure& figure);

/// Colour-blind-safe line styles for series grouped by the first word of their
/// label ("M1 γ = 0°", "M1 γ = 5°" share the colour of "M1" and differ in
/// dash): sets `colour` and `dash` of every series of every panel.
void style_by_group(PanelFigure& figure);

}  // namespace pkmws::io
