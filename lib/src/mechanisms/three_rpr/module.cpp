// The 3-RPR module's capabilities: constant-orientation slices and the
// direct-kinematics eliminant (the sextic, or the base-angle method), and
// criterion fields (criteria.cpp).
#include <numbers>

#include "mechanisms/three_rpr/criteria.hpp"
#include "mechanisms/three_rpr/three_rpr.hpp"

namespace pkmws::mechanisms {

Offer ThreeRpr::provide(std::type_index which) const {
  if (Offer::asks<PoseSlice>(which)) return Offer::of<PoseSlice>(this);
  if (Offer::asks<Elimination>(which)) return Offer::of<Elimination>(this);
  if (Offer::asks<criteria::CriterionFields>(which)) return Offer::owned(criteria::three_rpr_fields(*this));
  return Mechanism::provide(which);
}

std::string ThreeRpr::workspace_label() const {
  return !leg_limits_ && window_ ? "analysis window (no leg limits)" : Mechanism::workspace_label();
}

Elimination::Report ThreeRpr::elimination(std::span<const double> q) const {
  const std::array<double, 3> v{q[0], q[1], q[2]};
  Elimination::Report r;
  if (actuation() == ThreeRprActuation::revolute) {
    const auto d = direct_from_angles(v);
    r.method = "base angles: linear in the platform position, one trigonometric equation in phi";
    r.poses = d.poses.size();
    r.continuum = d.continuum;
    return r;
  }
  const auto d = direct_from_lengths(v);
  r.method = "sextic in t = tan((phi - phi0) / 2) ([Briot])";
  r.variable = "t = tan((phi - phi0) / 2)";
  r.nominal_degree = 6;
  r.degree = d.roots.degree;
  for (long double c : d.eliminant) r.coefficients_ascending.push_back(static_cast<double>(c));
  for (const auto& root : d.roots.real) r.real_roots.push_back(root.value);
  for (const auto& z : d.roots.complex) r.complex_roots.push_back({z.real(), z.imag()});
  r.poses = d.poses.size();
  r.continuum = d.continuum;
  r.figures = {{"phi0_deg", d.phi_offset * 180.0 / std::numbers::pi}, {"length_scale", d.length_scale}};
  return r;
}

}  // namespace pkmws::mechanisms
