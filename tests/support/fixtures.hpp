// Fixtures shared by the unit tests: the bundled datasets, file contents, text
// counts, grid counts of a predicate.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "pkmws/geometry/primitives.hpp"

namespace pkmws::test {

/// datasets/ of the source tree.
std::filesystem::path datasets_dir();

/// datasets/<stem>.json.
std::string dataset(const std::string& stem);

/// The bundled datasets/*.json whose file name starts with `prefix`, sorted.
std::vector<std::filesystem::path> dataset_files(const std::string& prefix = "");

/// The contents of file `p` ("" when it cannot be read).
std::string slurp(const std::filesystem::path& p);

/// How many times `what` occurs in `text` (overlapping occurrences count).
std::size_t count_of(const std::string& text, const std::string& what);

/// Area of {p in box : in(p)} counted at the centres of an n x n grid.
template <class Predicate>
double grid_area(const geometry::Box& box, int n, Predicate in) {
  const double dx = box.width() / n, dy = box.height() / n;
  long count = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) count += in(geometry::Point{box.min.x + (i + 0.5) * dx, box.min.y + (j + 0.5) * dy}) ? 1 : 0;
  return static_cast<double>(count) * dx * dy;
}

}  // namespace pkmws::test
