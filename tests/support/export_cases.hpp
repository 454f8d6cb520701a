// The regions the export tests write (closed forms where known) and small
// readers of what the writers produce.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "pkmws/geometry/region.hpp"

namespace pkmws::test {

struct Case {
  std::string name;
  geometry::Region region;
  double closed_form;  // exact area, or NaN if none
};

/// Disks, annuli, rectangles, stadiums, bands, several components with holes,
/// a region far from the origin.
std::vector<Case> cases();

/// Curves of the components of `r` (holes included) at least `min_area` large.
std::size_t curve_total(const geometry::Region& r, double min_area = 0.0);

/// The value of attribute `name` of the first `element` in `text` ("" when absent).
std::string attribute(const std::string& text, const std::string& element, const std::string& name);

/// The z component of a x b.
double cross2(geometry::Point a, geometry::Point b);

/// |a - b| / |b|.
double rel(double a, double b);

}  // namespace pkmws::test
