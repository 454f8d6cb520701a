// The largest all-inside rectangle of a raster: an estimate of the largest
// inscribed axis-aligned rectangle independent of the branch and bound.
#pragma once

#include <vector>

#include "pkmws/geometry/inscribed.hpp"
#include "pkmws/geometry/types.hpp"

namespace pkmws::test {

// Maximal all-inside rectangle of a raster (cells whose four corners and
// centre are inside), by the histogram method: an estimate independent of the
// branch and bound, within about one cell of the truth.
inline double raster_rectangle(const geometry::Component& c, int n) {
  const geometry::Box b = c.outer.bbox();
  const double dx = b.width() / n, dy = b.height() / n;
  std::vector<std::vector<char>> corner(n + 1, std::vector<char>(n + 1));
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) corner[i][j] = geometry::inside(c, {b.min.x + i * dx, b.min.y + j * dy});
  }
  std::vector<int> height(n, 0);
  double best = 0.0;
  for (int j = 0; j < n; ++j) {  // rows bottom to top
    for (int i = 0; i < n; ++i) {
      const bool in = corner[i][j] && corner[i + 1][j] && corner[i][j + 1] && corner[i + 1][j + 1] &&
                      geometry::inside(c, {b.min.x + (i + 0.5) * dx, b.min.y + (j + 0.5) * dy});
      height[i] = in ? height[i] + 1 : 0;
    }
    std::vector<int> stack;
    for (int i = 0; i <= n; ++i) {
      const int h = i < n ? height[i] : 0;
      while (!stack.empty() && height[stack.back()] >= h) {
        const int top = height[stack.back()];
        stack.pop_back();
        const int left = stack.empty() ? 0 : stack.back() + 1;
        best = std::max(best, top * dy * (i - left) * dx);
      }
      stack.push_back(i);
    }
  }
  return best;
}

}  // namespace pkmws::test
