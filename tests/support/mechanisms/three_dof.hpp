// Test fixtures shared by the 3-DOF mechanisms (3-RRP / 3-PRP, the Assur group
// RP-RP-RP, 3-RPR): plane rotation, angle differences, assembly lookup.
#pragma once

#include <cmath>
#include <numbers>
#include <vector>

#include "pkmws/geometry/primitives.hpp"
#include "mechanisms/three_rrp/assur_rprprp.hpp"

namespace pkmws::test::three_dof {

/// a - b reduced to [-pi, pi] (signed).
inline double angle_diff(double a, double b) { return std::remainder(a - b, 2.0 * std::numbers::pi); }

/// p rotated by phi about the origin.
inline geometry::Point rot(double phi, geometry::Point p) {
  return {std::cos(phi) * p.x - std::sin(phi) * p.y, std::sin(phi) * p.x + std::cos(phi) * p.y};
}

/// Whether `v` holds the assembly (origin, phi) within `tol`.
inline bool has_assembly(const std::vector<mechanisms::AssurAssembly>& v, geometry::Point origin, double phi, double tol) {
  for (const auto& as : v)
    if (std::hypot(as.origin.x - origin.x, as.origin.y - origin.y) < tol && std::abs(angle_diff(as.phi, phi)) < tol) return true;
  return false;
}

}  // namespace pkmws::test::three_dof
