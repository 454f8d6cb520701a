// The 3-RRP / 3-PRP module's capabilities: constant-orientation slices, the
// paper's eliminant next to the closed form ([Mitsi] eq. 9-18), and criterion
// fields (criteria.cpp).
#include <algorithm>
#include <cmath>
#include <limits>

#include "mechanisms/three_rrp/criteria.hpp"
#include "mechanisms/three_rrp/three_rrp.hpp"

namespace pkmws::mechanisms {

Offer ThreeRrp::provide(std::type_index which) const {
  if (Offer::asks<PoseSlice>(which)) return Offer::of<PoseSlice>(this);
  if (Offer::asks<Elimination>(which)) return Offer::of<Elimination>(this);
  if (Offer::asks<criteria::CriterionFields>(which)) return Offer::owned(criteria::three_rrp_fields(*this));
  return Mechanism::provide(which);
}

// The elimination so a user sees the eliminant, its true degree, every root
// and how far it is from the closed form.
Elimination::Report ThreeRrp::elimination(std::span<const double> q) const {
  const auto e = direct_elimination(q);
  const auto closed = direct_closed_form(q);
  Elimination::Report r;
  r.method = "Sylvester elimination of s2, s3 ([Mitsi] eq. 12-13)";
  r.variable = "sigma = s1 / L";
  r.nominal_degree = 8;
  r.degree = e.roots.degree;
  int computed = 0;
  for (int k = 8; k >= 0; --k) {
    if (e.eliminant[static_cast<std::size_t>(k)] != 0.0L) {
      computed = k;
      break;
    }
  }
  for (long double c : e.eliminant) r.coefficients_ascending.push_back(static_cast<double>(c));
  for (double s1 : e.real_s1) r.real_roots.push_back(s1 / e.length_scale);
  for (const auto& z : e.complex_s1) r.complex_roots.push_back({z.real() / e.length_scale, z.imag() / e.length_scale});
  r.solution_values = "s (s1, s2, s3: positions of the external joints on the side lines)";
  for (const auto& root : e.real_roots) {
    r.solutions.push_back({{root.s[0], root.s[1], root.s[2]}, root.assembled ? "platform" : "mirror image", root.residual});
  }
  r.poses = e.assemblies.size();
  double difference = 0.0;
  const bool same_count = closed.size() == e.assemblies.size();
  if (same_count) {
    for (std::size_t k = 0; k < closed.size(); ++k)
      for (std::size_t i = 0; i < 3; ++i)
        difference = std::max(difference, geometry::norm(closed[k].vertices[i] - e.assemblies[k].vertices[i]));
  } else {
    difference = std::numeric_limits<double>::quiet_NaN();
    r.note = "max_vertex_difference: the two methods found different numbers of assemblies";
  }
  r.figures = {{"length_scale_L", e.length_scale},
               {"computed_degree", computed},
               {"closed_form_assemblies", static_cast<double>(closed.size())},
               {"max_vertex_difference", difference}};
  return r;
}

}  // namespace pkmws::mechanisms
