// [Briot] ("Определение критерия"): w = -A^T R, R = -A^{-T} w, twists with
// one actuator free, pressure angles and the largest reactions (docs/theory/three_dof.md).
#include "pkmws/mechanisms/planar_transmission.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/LU>

namespace pkmws::mechanisms {

namespace {
constexpr double inf = std::numeric_limits<double>::infinity();
constexpr double singular_tol = 1e-9;
}  // namespace

Eigen::Matrix3d wrench_matrix(Point reference, const std::array<ActuationLine, 3>& lines) {
  Eigen::Matrix3d a;
  for (int i = 0; i < 3; ++i) {
    const ActuationLine& l = lines[static_cast<std::size_t>(i)];
    // [Briot]: f_i = [r_i; d_{P Q_i}^T r_i], d^T = [-y, x]: the moment (Q_i - P) x r_i.
    a(i, 0) = l.direction.x;
    a(i, 1) = l.direction.y;
    a(i, 2) = cross(l.point - reference, l.direction);
  }
  return a;
}

Transmission analyse_transmission(Point reference, const std::array<ActuationLine, 3>& lines) {
  Transmission t;
  t.reference = reference;
  t.lines = lines;
  t.A = wrench_matrix(reference, lines);
  t.determinant = t.A.determinant();
  const Point centroid = (1.0 / 3.0) * (lines[0].point + lines[1].point + lines[2].point);
  double scale = 0.0;
  for (const auto& l : lines) scale = std::max(scale, norm(l.point - centroid));
  if (scale == 0.0) scale = 1.0;
  t.singular = !(std::abs(t.determinant) > singular_tol * scale);
  if (t.singular) {
    for (int i = 0; i < 3; ++i) {
      t.twists[static_cast<std::size_t>(i)] = {{inf, inf}, inf};
      t.pressure_angle[static_cast<std::size_t>(i)] = std::acos(0.0);
      t.lever[static_cast<std::size_t>(i)] = inf;
      t.lever_ratio[static_cast<std::size_t>(i)] = inf;
    }
    return t;
  }
  const Eigen::Matrix3d inv = t.A.inverse();
  for (std::size_t i = 0; i < 3; ++i) {
    const int c = static_cast<int>(i);
    PlanarTwist tw{{inv(0, c), inv(1, c)}, inv(2, c)};
    t.twists[i] = tw;
    const Point q = lines[i].point;
    const Point vq = tw.velocity_at(reference, q);
    // r_i . v_i = 1 by construction (A A^{-1} = I); |r_i| = 1.
    const double vn = norm(vq);
    t.pressure_angle[i] = std::acos(std::min(1.0, std::abs(dot(lines[i].direction, vq)) / vn));
    if (tw.omega != 0.0) {
      // Instantaneous centre: v_P + ω J (I - P) = 0  =>  I = P + J v_P / ω.
      const Point centre{reference.x - tw.velocity.y / tw.omega, reference.y + tw.velocity.x / tw.omega};
      t.lever[i] = norm(q - centre);
      t.lever_ratio[i] = norm(reference - centre) / t.lever[i];
    } else {
      t.lever[i] = inf;
      t.lever_ratio[i] = 1.0;
    }
  }
  return t;
}

std::array<double, 3> reaction_max(const Transmission& t, const Load& load) {
  std::array<double, 3> r{};
  for (std::size_t i = 0; i < 3; ++i) {
    if (t.singular) {
      r[i] = inf;
      continue;
    }
    // docs/theory/three_dof.md: R_i,max = f |v_P,i| + |m| |ω_i|.
    r[i] = load.force_N * norm(t.twists[i].velocity) + std::abs(load.moment_Nm) * std::abs(t.twists[i].omega);
  }
  return r;
}

std::array<double, 3> reactions(const Transmission& t, Point force, double moment) {
  std::array<double, 3> r{};
  for (std::size_t i = 0; i < 3; ++i) {
    // [Briot]: R = -A^{-T} w, row i of A^{-T} is t_i^T.
    r[i] = t.singular ? std::numeric_limits<double>::quiet_NaN()
                      : -(dot(t.twists[i].velocity, force) + t.twists[i].omega * moment);
  }
  return r;
}

}  // namespace pkmws::mechanisms
