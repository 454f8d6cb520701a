// Design atlases: a metric over two design parameters as a filled contour
// map (bands between "nice" levels, labelled isolines, the best design
// marked), in the manner of the published five-bar atlases.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace pkmws::io {

struct AtlasData {
  std::vector<double> xs;                 // increasing
  std::vector<double> ys;                 // increasing
  std::vector<std::optional<double>> z;   // z[j * xs.size() + i] at (xs[i], ys[j]); nullopt: no design
  std::string x_label, y_label;           // axis titles with units, e.g. "rod length l (mm)"
  std::string metric_label;               // e.g. "inscribed rectangle area (mm²)"
  std::string title;
  bool maximize = true;                   // mark the largest (else the smallest) value
};

/// The atlas as an SVG document; throws std::invalid_argument when the grid
/// is smaller than 2 x 2 or holds no finite value.
std::string atlas_figure(const AtlasData& data);

}  // namespace pkmws::io
