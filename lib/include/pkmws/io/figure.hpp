// The paper-style figure of a workspace (docs/format.md (command line)):
// white page, the region filled with its outline (true arcs), frame with 1-2-5
// ticks in the file's unit, light grid, axes through the origin, scale bar,
// overlays (criterion bands, interference regions, the real workspace), the
// parts of a machine with bodies, the mechanism at a pose, a legend and a
// caption. `pkmws export -f svg`, `batch`, `dk --svg` and `levels --svg` all
// draw through workspace_figure, so every figure has the same axes and legend.
//
// Machine-readable marks for tests and tools: the plot group carries
// data-transform="X0 Y0 S" (a point (x, y) of the file's frame is drawn at
// px = X0 + S x, py = Y0 - S y); elements carry classes (workspace, overlay,
// band, interference, part, singular, link, platform, slider, joint, tool,
// caption, legend).
#pragma once

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "pkmws/certified/level_set.hpp"
#include "pkmws/geometry/region.hpp"
#include "pkmws/io/mechanism_file.hpp"

namespace pkmws::io {

struct FigureOptions {
  std::string title;
  std::string caption;  // e.g. "exact workspace area = 36202.18 mm²"
  bool draw_mechanism = true;
  /// The main region: fill, outline and legend entry (empty legend: none).
  std::string region_fill = "#f4a3a3";
  std::string region_stroke = "#8b1a1a";
  std::string region_legend = "workspace";
  /// Regions drawn over the main one in order (criterion bands, interference
  /// regions, the real workspace outlined in black; [Vasilic] figs. 5-11).
  struct Overlay {
    geometry::Region region;
    /// Instead of `region`: closed rings (nonzero fill; outer loops
    /// counter-clockwise, holes clockwise) drawn clipped to the main region.
    std::vector<std::vector<geometry::Point>> rings;
    std::string fill = "none";      // SVG colour or "none"
    double fill_opacity = 1.0;
    /// Finite: the fill is hatching at this angle (degrees) in `fill` instead of
    /// a flat colour, so that overlapping overlays stay readable.
    double hatch_deg = std::numeric_limits<double>::quiet_NaN();
    std::string stroke = "black";   // SVG colour or "none"
    double stroke_px = 2.0;
    std::string label;              // short tag drawn inside its largest component (empty: none)
    std::string legend;             // legend entry (empty: none)
    std::string css_class = "overlay";
    int legend_rank = 0;            // legend entries are sorted by rank (stable)
  };
  std::vector<Overlay> overlays;
  /// Solid parts drawn over the regions and under the mechanism: the set of
  /// points within `radius` of `core` (1 point: a disk, 2: a capsule, >= 3: a
  /// polygon grown by radius). Parts with the same legend share one entry.
  struct Part {
    std::vector<geometry::Point> core;
    double radius = 0.0;
    std::string fill = "#b0bec5";
    std::string stroke = "#37474f";
    std::string legend;
    std::string css_class = "part";
  };
  std::vector<Part> parts;
  /// Legend entries of the main region and the mechanism come first (rank 0).
  int region_legend_rank = 0;
};

/// The figure of `region` with the mechanism drawn at `pose`.
std::string workspace_figure(const MechanismFile& file, const geometry::Region& region,
                             const mechanisms::Pose& pose, const FigureOptions& options);
/// The same with the mechanism already drawn (e.g. at the joint values of an
/// assembly mode: Mechanism::draw_with_joints).
std::string workspace_figure(const MechanismFile& file, const geometry::Region& region,
                             const mechanisms::Drawing& drawing, const FigureOptions& options);

/// The part of a certified sub-level set drawn in figures: the union of the
/// cells certified in it and, in each traced cell, the polygon on the inner
/// side of the traced level curve, as closed rings (counter-clockwise outer
/// loops, clockwise holes). Shared cell edges cancel (coordinates snapped to
/// 2^-26 of the pieces' extent), so a band is a few loops that follow the
/// traced curve: no staircase, no seams. Not clipped: draw it clipped to the
/// workspace (FigureOptions::Overlay::rings).
std::vector<std::vector<geometry::Point>> traced_inner_rings(const certified::LevelSetResult& result);
/// The signed area of closed rings (their union when they do not overlap).
double rings_area(const std::vector<std::vector<geometry::Point>>& rings);
/// A region for placing the mechanism: the largest ring (simplified) ∩ `within`.
geometry::Region largest_ring_region(const std::vector<std::vector<geometry::Point>>& rings,
                                     const geometry::Region& within);

/// "[lo, hi]" with the fewest significant digits (at least `min_digits`)
/// that print the two bounds differently.
std::string interval_text(double lo, double hi, int min_digits = 6);

/// The paper keys ("[Briot]", ...) and figure of a file's `source`, for
/// captions: e.g. "[Briot] Fig. 10"; empty when the file names none.
std::string source_citation(const MechanismFile& file);

}  // namespace pkmws::io
