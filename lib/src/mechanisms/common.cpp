#include "mechanisms/common.hpp"

#include <Eigen/LU>
#include <Eigen/SVD>

namespace pkmws::mechanisms::detail {

void set_velocity_figures(Evaluation& e, const Eigen::Matrix2d& dq_dx, bool type1, bool type2) {
  if (type1 || !dq_dx.allFinite()) {
    e.jacobian_det = infinity;
    e.condition_number = infinity;
    e.velocity_ratio = infinity;
    return;
  }
  e.jacobian_det = dq_dx.determinant();
  const Eigen::JacobiSVD<Eigen::Matrix2d> svd(dq_dx);
  const auto sv = svd.singularValues();
  e.condition_number = type2 || sv(1) == 0.0 ? infinity : sv(0) / sv(1);
  e.velocity_ratio = sv(0);
}

void set_point_platform_transmission(Evaluation& e, double abs_sin_eps, const Criteria& criteria) {
  const double alpha = std::acos(std::min(1.0, abs_sin_eps)) * 180.0 / std::numbers::pi;
  e.pressure_angle_deg = {alpha, alpha};
  if (criteria.load) {
    const double r = abs_sin_eps > 0.0 ? criteria.load->force_N / abs_sin_eps : infinity;
    e.reactions_N = {r, r};
  }
}

}  // namespace pkmws::mechanisms::detail

namespace pkmws::mechanisms {

certified::CertifiedRegion Mechanism::workspace_enclosure(int /*max_depth*/) const {
  return certified::from_exact(workspace());
}

Drawing Mechanism::draw_with_joints(const Pose& pose, std::span<const double> /*joints*/) const { return draw(pose); }

Offer Mechanism::provide(std::type_index /*which*/) const { return {}; }

}  // namespace pkmws::mechanisms
