// 3-RPR ([Briot]; docs/theory/three_dof.md): inverse kinematics, direct kinematics (the
// sextic for leg lengths, the sinusoid for base angles), [Briot] transmission
// (A matrix, twists, pressure angles, reactions), exact constant-orientation
// workspace with leg limits. Derivations in docs/theory/three_dof.md.
#include "mechanisms/three_rpr/three_rpr.hpp"

#include "mechanisms/contour.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>

#include "mechanisms/common.hpp"
#include "pkmws/geometry/primitives.hpp"

namespace pkmws::mechanisms {

namespace {

constexpr double pi = std::numbers::pi;
constexpr double two_pi = 2.0 * pi;
constexpr double rad2deg = 180.0 / pi;
constexpr double inf = std::numeric_limits<double>::infinity();
constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double eps = std::numeric_limits<double>::epsilon();
constexpr double singular_tol = 1e-9;

using LD = long double;
using Poly = std::vector<LD>;  // ascending powers of t
using detail::format_number;
using detail::unit;
using detail::rotate;
using detail::wrap_pi;


Poly padd(const Poly& a, const Poly& b, LD sb = 1.0L) {
  Poly r(std::max(a.size(), b.size()), 0.0L);
  for (std::size_t i = 0; i < a.size(); ++i) r[i] += a[i];
  for (std::size_t i = 0; i < b.size(); ++i) r[i] += sb * b[i];
  return r;
}
Poly pmul(const Poly& a, const Poly& b) {
  Poly r(a.size() + b.size() - 1, 0.0L);
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) r[i + j] += a[i] * b[j];
  return r;
}
Poly pscale(const Poly& a, LD k) {
  Poly r = a;
  for (auto& c : r) c *= k;
  return r;
}
LD pmax(const Poly& a) {
  LD m = 0.0L;
  for (LD c : a) m = std::max(m, std::fabs(c));
  return m;
}

// The degree-8 polynomial in t = tan(psi / 2) of the prismatic DK with the
// platform offsets e_i already rotated by phi0 (docs/theory/three_dof.md), and
// the size of its terms before cancellation.
struct Octic {
  Poly f;
  LD term_size = 0.0L;
};

Octic prismatic_octic(const std::array<std::array<LD, 2>, 3>& a, const std::array<std::array<LD, 2>, 3>& e,
                      const std::array<LD, 3>& r) {
  // D = 1 + t^2, D cos = 1 - t^2, D sin = 2t.
  const Poly d{1.0L, 0.0L, 1.0L}, dc{1.0L, 0.0L, -1.0L}, ds{0.0L, 2.0L};
  std::array<std::array<Poly, 2>, 3> m;
  std::array<Poly, 3> k;
  for (std::size_t i = 1; i < 3; ++i) {
    // D R e_i, then M_i = 2 (D R e_i - D a_i), k_i = D (r_i^2 - r_0^2 - |e_i|^2 - |a_i|^2) + 2 a_i . D R e_i.
    const Poly rex = padd(pscale(dc, e[i][0]), pscale(ds, e[i][1]), -1.0L);
    const Poly rey = padd(pscale(ds, e[i][0]), pscale(dc, e[i][1]));
    m[i][0] = pscale(padd(rex, pscale(d, a[i][0]), -1.0L), 2.0L);
    m[i][1] = pscale(padd(rey, pscale(d, a[i][1]), -1.0L), 2.0L);
    const LD c = r[i] * r[i] - r[0] * r[0] - (e[i][0] * e[i][0] + e[i][1] * e[i][1]) - (a[i][0] * a[i][0] + a[i][1] * a[i][1]);
    k[i] = padd(pscale(d, c), padd(pscale(rex, 2.0L * a[i][0]), pscale(rey, 2.0L * a[i][1])));
  }
  const Poly det = padd(pmul(m[1][0], m[2][1]), pmul(m[1][1], m[2][0]), -1.0L);
  const Poly yx = padd(pmul(k[1], m[2][1]), pmul(k[2], m[1][1]), -1.0L);
  const Poly yy = padd(pmul(m[1][0], k[2]), pmul(m[2][0], k[1]), -1.0L);
  // Y = (yx, yy) / det on |Y|^2 = r_0^2:  yx^2 + yy^2 - r_0^2 det^2 = 0.
  const Poly sq = padd(pmul(yx, yx), pmul(yy, yy));
  const Poly dd = pscale(pmul(det, det), r[0] * r[0]);
  Octic o;
  o.f = padd(sq, dd, -1.0L);
  o.term_size = std::max(pmax(sq), pmax(dd));
  return o;
}

// Quotient and remainder of f by 1 + t^2.
std::pair<Poly, std::array<LD, 2>> divide_circular(Poly f) {
  Poly q(f.size() > 2 ? f.size() - 2 : 1, 0.0L);
  for (std::size_t k = f.size(); k-- > 2;) {
    q[k - 2] = f[k];
    f[k - 2] -= f[k];
    f[k] = 0.0L;
  }
  return {q, {f.size() > 0 ? f[0] : 0.0L, f.size() > 1 ? f[1] : 0.0L}};
}

}  // namespace

ThreeRpr::ThreeRpr(std::array<Point, 3> base, std::array<Point, 3> platform, ThreeRprActuation actuation,
                   double orientation, std::optional<std::array<std::array<double, 2>, 3>> leg_limits,
                   std::optional<geometry::Box> analysis_window)
    : base_(base), platform_(platform), actuation_(actuation), orientation_(orientation), leg_limits_(leg_limits),
      window_(analysis_window) {
  if (!std::isfinite(orientation)) throw std::invalid_argument("non-finite orientation");
  if (window_ && (!(window_->min.x < window_->max.x) || !(window_->min.y < window_->max.y) ||
                  !std::isfinite(window_->width()) || !std::isfinite(window_->height()))) {
    throw std::invalid_argument("analysis window must be [[xmin, ymin], [xmax, ymax]] with min < max");
  }
  for (std::size_t i = 0; i < 3; ++i) {
    for (const Point p : {base_[i], platform_[i]}) {
      if (!std::isfinite(p.x) || !std::isfinite(p.y)) throw std::invalid_argument("non-finite base or platform point");
    }
  }
  for (std::size_t i = 0; i < 3; ++i) {
    const std::size_t j = (i + 1) % 3;
    if (base_[i] == base_[j]) throw std::invalid_argument("base points must be distinct");
    if (platform_[i] == platform_[j]) throw std::invalid_argument("platform points must be distinct");
  }
  if (leg_limits_) {
    for (std::size_t i = 0; i < 3; ++i) {
      const auto& l = (*leg_limits_)[i];
      if (!std::isfinite(l[0]) || !std::isfinite(l[1]) || !(l[0] >= 0.0) || !(l[0] < l[1])) {
        throw std::invalid_argument("leg " + std::to_string(i + 1) + ": limits must be [min, max] with 0 <= min < max");
      }
    }
  }
  const Point centroid = (1.0 / 3.0) * (platform_[0] + platform_[1] + platform_[2]);
  characteristic_length_ = 0.0;
  for (const Point& b : platform_) characteristic_length_ = std::max(characteristic_length_, norm(b - centroid));
}

ThreeRpr ThreeRpr::symmetric(double base_radius, double platform_radius, ThreeRprActuation actuation,
                             double orientation, std::optional<std::array<std::array<double, 2>, 3>> leg_limits) {
  std::array<Point, 3> a, b;
  const double theta[3] = {-pi / 2.0, pi / 6.0, 5.0 * pi / 6.0};  // [Briot]: θ_i = -90°, 30°, 150°
  for (std::size_t i = 0; i < 3; ++i) {
    a[i] = base_radius * unit(theta[i]);
    b[i] = platform_radius * unit(theta[i]);
  }
  return ThreeRpr(a, b, actuation, orientation, leg_limits);
}

// ---------------------------------------------------------------------------
// Inverse kinematics and transmission

std::array<Point, 3> ThreeRpr::platform_points(const Pose& pose) const {
  std::array<Point, 3> b;
  for (std::size_t i = 0; i < 3; ++i) b[i] = Point{pose.x, pose.y} + rotate(platform_[i], pose.phi);
  return b;
}

std::array<double, 3> ThreeRpr::leg_lengths(const Pose& pose) const {
  const auto b = platform_points(pose);
  return {norm(b[0] - base_[0]), norm(b[1] - base_[1]), norm(b[2] - base_[2])};
}

std::array<double, 3> ThreeRpr::leg_angles(const Pose& pose) const {
  const auto b = platform_points(pose);
  std::array<double, 3> q{};
  for (std::size_t i = 0; i < 3; ++i) q[i] = std::atan2(b[i].y - base_[i].y, b[i].x - base_[i].x);
  return q;
}

std::array<ActuationLine, 3> ThreeRpr::actuation_lines(const Pose& pose) const {
  const auto b = platform_points(pose);
  const auto q = leg_angles(pose);
  std::array<ActuationLine, 3> lines;
  for (std::size_t i = 0; i < 3; ++i) {
    const Point u = unit(q[i]);
    // [Briot]: f_i = [-sin q_i, cos q_i] for the actuated base revolute.
    lines[i] = {b[i], actuation_ == ThreeRprActuation::revolute ? Point{-u.y, u.x} : u};
  }
  return lines;
}

Eigen::Matrix3d ThreeRpr::wrench_matrix(const Pose& pose, Point reference) const {
  return mechanisms::wrench_matrix(reference, actuation_lines(pose));
}

Transmission ThreeRpr::transmission(const Pose& pose) const {
  return analyse_transmission({pose.x, pose.y}, actuation_lines(pose));
}

std::array<double, 3> ThreeRpr::reaction_max(const Pose& pose, const Load& load) const {
  return mechanisms::reaction_max(transmission(pose), load);
}

ThreeRprJacobians ThreeRpr::jacobians(const Pose& pose) const {
  ThreeRprJacobians j;
  j.A = wrench_matrix(pose, {pose.x, pose.y});
  j.B.setIdentity();
  if (actuation_ == ThreeRprActuation::revolute) {
    const auto rho = leg_lengths(pose);
    for (int i = 0; i < 3; ++i) j.B(i, i) = rho[static_cast<std::size_t>(i)];
  }
  return j;
}

bool ThreeRpr::type2_singular(const Pose& pose) const { return transmission(pose).singular; }

std::string ThreeRpr::leg_problem(int leg, double length) const {
  const std::string i = std::to_string(leg + 1);
  if (!leg_limits_) return "";
  const auto& l = (*leg_limits_)[static_cast<std::size_t>(leg)];
  const double tol = singular_tol * std::max(1.0, l[1]);
  if (length >= l[0] - tol && length <= l[1] + tol) return "";
  return "rho" + i + " = " + format_number(length) + " outside [" + format_number(l[0]) + ", " + format_number(l[1]) + "]";
}

std::vector<JointInfo> ThreeRpr::joints() const {
  std::vector<JointInfo> out;
  for (int i = 1; i <= 3; ++i) {
    out.push_back(actuation_ == ThreeRprActuation::revolute ? JointInfo{"q" + std::to_string(i), true, std::nullopt}
                                                            : JointInfo{"rho" + std::to_string(i), false, std::nullopt});
  }
  return out;
}

std::vector<JointSolution> ThreeRpr::inverse(const Pose& pose) const {
  JointSolution s;
  s.mode = "000";  // one inverse solution per leg (docs/format.md (modes))
  const auto rho = leg_lengths(pose);
  const auto q = leg_angles(pose);
  for (std::size_t i = 0; i < 3; ++i) s.joints.push_back(actuation_ == ThreeRprActuation::revolute ? q[i] : rho[i]);
  for (int i = 0; i < 3 && s.reason.empty(); ++i) {
    if (rho[static_cast<std::size_t>(i)] == 0.0) s.reason = "B" + std::to_string(i + 1) + " is on its base joint";
  }
  for (int i = 0; i < 3 && s.reason.empty(); ++i) s.reason = leg_problem(i, rho[static_cast<std::size_t>(i)]);
  s.valid = s.reason.empty();
  return {s};
}

// ---------------------------------------------------------------------------
// Direct kinematics

ThreeRprDirect ThreeRpr::direct_from_lengths(const std::array<double, 3>& lengths) const {
  ThreeRprDirect out;
  for (double r : lengths) {
    if (!(r >= 0.0) || !std::isfinite(r)) return out;
  }
  // Work in Y = (B_1 - A_1) / L with e_i = b'_i - b'_1 and a_i = A_i - A_1.
  double length = 0.0;
  for (std::size_t i = 0; i < 3; ++i) {
    length = std::max({length, norm(base_[i] - base_[0]), norm(platform_[i] - platform_[0]), lengths[i]});
  }
  out.length_scale = length;
  const LD ll = length;
  std::array<std::array<LD, 2>, 3> a{}, e0{};
  std::array<LD, 3> r{};
  for (std::size_t i = 0; i < 3; ++i) {
    a[i] = {(static_cast<LD>(base_[i].x) - base_[0].x) / ll, (static_cast<LD>(base_[i].y) - base_[0].y) / ll};
    e0[i] = {(static_cast<LD>(platform_[i].x) - platform_[0].x) / ll,
             (static_cast<LD>(platform_[i].y) - platform_[0].y) / ll};
    r[i] = lengths[i] / ll;
  }
  auto rotated = [&](LD phi) {
    std::array<std::array<LD, 2>, 3> e{};
    const LD c = std::cos(phi), s = std::sin(phi);
    for (std::size_t i = 0; i < 3; ++i) e[i] = {c * e0[i][0] - s * e0[i][1], s * e0[i][0] + c * e0[i][1]};
    return e;
  };
  // t = tan((phi - phi0) / 2) misses phi = phi0 + pi, where the sextic's degree
  // drops: choose phi0 so that its leading coefficient is not small.
  Poly sextic;
  std::array<LD, 2> remainder{};
  LD best = -1.0L, term_size = 0.0L;
  for (double phi0 : {0.0, 1.0, 2.2, -1.4, 0.5}) {
    const Octic o = prismatic_octic(a, rotated(phi0), r);
    auto [q, rem] = divide_circular(o.f);  // the factor 1 + t^2 (circular points)
    const LD m = pmax(q);
    const LD lead = m > 0.0L ? std::fabs(q.back()) / m : 0.0L;
    if (lead > best) {
      best = lead;
      sextic = q;
      remainder = rem;
      term_size = o.term_size;
      out.phi_offset = phi0;
    }
    if (best > 1e-3L) break;
  }
  out.eliminant = sextic;
  out.circular_remainder = remainder;
  if (!(pmax(sextic) > 1e-12L * term_size)) {
    out.continuum = true;  // the eliminant vanishes: a continuum of poses (self-motion)
    return out;
  }
  out.roots = polynomial_roots(sextic);
  const std::array<std::array<LD, 2>, 3> e_unrotated = e0;
  auto residuals = [&](LD yx, LD yy, LD phi, Eigen::Matrix<LD, 3, 3>* jac) {
    Eigen::Matrix<LD, 3, 1> g;
    const LD c = std::cos(phi), s = std::sin(phi);
    for (int i = 0; i < 3; ++i) {
      const auto k = static_cast<std::size_t>(i);
      const LD ex = c * e_unrotated[k][0] - s * e_unrotated[k][1], ey = s * e_unrotated[k][0] + c * e_unrotated[k][1];
      const LD dx = yx + ex - a[k][0], dy = yy + ey - a[k][1];
      g(i) = dx * dx + dy * dy - r[k] * r[k];
      if (jac) {
        (*jac)(i, 0) = 2.0L * dx;
        (*jac)(i, 1) = 2.0L * dy;
        (*jac)(i, 2) = 2.0L * (dx * -ey + dy * ex);  // d(R e)/dphi = J R e
      }
    }
    return g;
  };
  std::vector<Pose> poses;
  for (const RealRoot& root : out.roots.real) {
    const LD phi = out.phi_offset + 2.0L * std::atan(static_cast<LD>(root.value));
    const LD c = std::cos(phi), s = std::sin(phi);
    // Back-substitution: B_1 on circle 1 (centre 0, radius r_0) and circle 2
    // (centre a_2 - R e_2, radius r_1); of the (up to) two points keep the one on circle 3.
    std::array<std::array<LD, 2>, 3> centre{};
    for (std::size_t i = 0; i < 3; ++i) {
      centre[i] = {a[i][0] - (c * e0[i][0] - s * e0[i][1]), a[i][1] - (s * e0[i][0] + c * e0[i][1])};
    }
    std::size_t j = 1;  // the farther of circles 2 and 3 from circle 1's centre
    if (std::hypot(centre[2][0], centre[2][1]) > std::hypot(centre[1][0], centre[1][1])) j = 2;
    const std::size_t other = 3 - j;
    const LD dist = std::hypot(centre[j][0], centre[j][1]);
    std::vector<std::array<LD, 2>> candidates;
    if (dist > 0.0L) {
      const LD ux = centre[j][0] / dist, uy = centre[j][1] / dist;
      const LD along = (r[0] * r[0] - r[j] * r[j] + dist * dist) / (2.0L * dist);
      const LD h = std::sqrt(std::max(0.0L, r[0] * r[0] - along * along));
      candidates.push_back({along * ux - h * uy, along * uy + h * ux});
      candidates.push_back({along * ux + h * uy, along * uy - h * ux});
    }
    for (auto y : candidates) {
      LD yx = y[0], yy = y[1], ph = phi;
      const LD misfit = std::fabs(std::hypot(yx - centre[other][0], yy - centre[other][1]) - r[other]);
      if (!(misfit <= 1e-6L)) continue;
      // Newton on the three circle equations in (Y, phi).
      Eigen::Matrix<LD, 3, 3> jac;
      LD res = residuals(yx, yy, ph, &jac).cwiseAbs().maxCoeff();
      for (int it = 0; it < 8 && res > 0.0L; ++it) {
        const Eigen::Matrix<LD, 3, 1> step = jac.fullPivLu().solve(residuals(yx, yy, ph, nullptr));
        if (!step.allFinite()) break;
        Eigen::Matrix<LD, 3, 3> next_jac;
        const LD next = residuals(yx - step(0), yy - step(1), ph - step(2), &next_jac).cwiseAbs().maxCoeff();
        if (!(next < res)) break;
        yx -= step(0);
        yy -= step(1);
        ph -= step(2);
        res = next;
        jac = next_jac;
      }
      if (!(res <= 1e-12L)) continue;
      const double phi_d = wrap_pi(static_cast<double>(ph));
      const Point b1{static_cast<double>(base_[0].x + ll * yx), static_cast<double>(base_[0].y + ll * yy)};
      const Point p = b1 - rotate(platform_[0], phi_d);
      bool duplicate = false;
      for (const Pose& q : poses) {
        duplicate = duplicate || (std::abs(wrap_pi(q.phi - phi_d)) <= 1e-9 && std::hypot(q.x - p.x, q.y - p.y) <= 1e-9 * length);
      }
      if (!duplicate) poses.push_back({p.x, p.y, phi_d});
    }
  }
  std::sort(poses.begin(), poses.end(), [](const Pose& u, const Pose& v) { return u.phi < v.phi; });
  out.poses = poses;
  return out;
}

ThreeRprDirect ThreeRpr::direct_from_angles(const std::array<double, 3>& angles) const {
  ThreeRprDirect out;
  // Leg i is the fixed line through A_i with direction w_i = u(q_i); B_i on it:
  // m_i . P = m_i . A_i - m_i . R(phi) b'_i, m_i = J w_i. With the cofactors
  // κ = (m_2 x m_3, m_3 x m_1, m_1 x m_2), Σ κ_i m_i = 0, so the three are
  // consistent iff Σ κ_i (m_i . A_i - m_i . R(phi) b'_i) = 0:
  //   C cos phi + S sin phi = E.
  std::array<Point, 3> m;
  for (std::size_t i = 0; i < 3; ++i) {
    if (!std::isfinite(angles[i])) return out;
    const Point w = unit(angles[i]);
    m[i] = {-w.y, w.x};
  }
  const std::array<double, 3> kappa = {cross(m[1], m[2]), cross(m[2], m[0]), cross(m[0], m[1])};
  double scale = 0.0;
  for (std::size_t i = 0; i < 3; ++i) scale = std::max({scale, norm(base_[i]), norm(platform_[i])});
  double c = 0.0, s = 0.0, e = 0.0;
  for (std::size_t i = 0; i < 3; ++i) {
    e += kappa[i] * dot(m[i], base_[i]);
    c += kappa[i] * dot(m[i], platform_[i]);             // m . R b' = cos phi m . b' + sin phi m . J b'
    s += kappa[i] * dot(m[i], Point{-platform_[i].y, platform_[i].x});
  }
  const double kmax = std::max({std::abs(kappa[0]), std::abs(kappa[1]), std::abs(kappa[2])});
  const double amplitude = std::hypot(c, s);
  if (!(kmax > 1e-12)) {
    out.continuum = true;  // all legs parallel: the platform can slide along them
    return out;
  }
  if (!(amplitude > 1e-12 * kmax * scale)) {
    if (std::abs(e) <= 1e-12 * kmax * scale) out.continuum = true;  // every phi: self-motion
    return out;
  }
  const double ratio = e / amplitude;
  const double delta = std::atan2(s, c);
  std::vector<double> phis;
  if (std::abs(ratio) > 1.0 + 8.0 * eps) return out;
  if (std::abs(ratio) >= 1.0 - 8.0 * eps) {
    phis.push_back(ratio > 0.0 ? delta : delta + pi);
  } else {
    const double beta = std::acos(ratio);
    phis = {delta - beta, delta + beta};
  }
  for (double phi : phis) {
    Eigen::Matrix2d nn = Eigen::Matrix2d::Zero();
    Eigen::Vector2d nr = Eigen::Vector2d::Zero();
    for (std::size_t i = 0; i < 3; ++i) {
      const double rhs = dot(m[i], base_[i]) - dot(m[i], rotate(platform_[i], phi));
      nn(0, 0) += m[i].x * m[i].x; nn(0, 1) += m[i].x * m[i].y; nn(1, 1) += m[i].y * m[i].y;
      nr(0) += m[i].x * rhs; nr(1) += m[i].y * rhs;
    }
    nn(1, 0) = nn(0, 1);
    const Eigen::Vector2d p = nn.ldlt().solve(nr);
    out.poses.push_back({p(0), p(1), wrap_pi(phi)});
  }
  std::sort(out.poses.begin(), out.poses.end(), [](const Pose& u, const Pose& v) { return u.phi < v.phi; });
  return out;
}

std::vector<PoseSolution> ThreeRpr::direct(std::span<const double> joints) const {
  if (joints.size() != 3) throw std::invalid_argument("three_rpr: three joint values are needed");
  const std::array<double, 3> q = {joints[0], joints[1], joints[2]};
  const ThreeRprDirect d = actuation_ == ThreeRprActuation::revolute ? direct_from_angles(q) : direct_from_lengths(q);
  std::vector<PoseSolution> out;
  for (std::size_t k = 0; k < d.poses.size(); ++k) {
    PoseSolution s;
    s.pose = d.poses[k];
    const auto b = platform_points(s.pose);
    s.platform_points = {b[0], b[1], b[2]};
    const double det = transmission(s.pose).determinant;
    s.mode = std::string(1, detail::mode_sign(det));
    const auto rho = leg_lengths(s.pose);
    if (actuation_ == ThreeRprActuation::revolute) {
      for (int i = 0; i < 3 && s.reason.empty(); ++i) {
        const auto k3 = static_cast<std::size_t>(i);
        if (dot(unit(q[k3]), b[k3] - base_[k3]) < 0.0) {
          s.reason = "leg " + std::to_string(i + 1) + " would need a negative length (B" + std::to_string(i + 1) +
                     " lies behind A" + std::to_string(i + 1) + " on the leg's line)";
        }
      }
    }
    for (int i = 0; i < 3 && s.reason.empty(); ++i) s.reason = leg_problem(i, rho[static_cast<std::size_t>(i)]);
    s.valid = s.reason.empty();
    out.push_back(s);
  }
  return out;
}

std::vector<Evaluation> ThreeRpr::evaluate(const Pose& pose, const Criteria& criteria) const {
  const JointSolution s = inverse(pose).front();
  Evaluation e = detail::start_evaluation(s, 3);  // the 3-RPR's IK always gives three values
  const auto rho = leg_lengths(pose);
  const double length = criteria.characteristic_length.value_or(characteristic_length_);
  const double scale = std::max(characteristic_length_, 1e-300);
  bool type1 = false;
  for (double r : rho) type1 = type1 || !(r > singular_tol * scale);
  const Transmission t = transmission(pose);
  const bool type2 = t.singular;
  e.singular = type1 || type2;
  e.singularity = type1 && type2 ? "both" : type1 ? "type1" : type2 ? "type2" : "";
  if (type1) {
    e.jacobian_det = inf;
    e.condition_number = inf;
  } else {
    const ThreeRprJacobians j = jacobians(pose);
    const Eigen::Matrix3d jq = j.B.inverse() * j.A;  // dq/dx, x = (x, y, phi)
    e.jacobian_det = jq.determinant();
    Eigen::Matrix3d scaled = jq;
    scaled.col(2) /= length;  // x' = (x, y, L phi)
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(scaled);
    const auto sv = svd.singularValues();
    e.condition_number = type2 || sv(2) == 0.0 ? inf : sv(0) / sv(2);
    e.velocity_ratio = sv(0);  // |dq| / |dx'| in the worst direction
  }
  for (double a : t.pressure_angle) e.pressure_angle_deg.push_back(a * rad2deg);
  if (criteria.load) {
    for (double r : mechanisms::reaction_max(t, *criteria.load)) e.reactions_N.push_back(r);
    // [Briot] Table 2, chain RPR: the base and slider joints carry the same
    // force |f_A| = |f_C| = R_i; the actuator's effort is the torque
    // |τ| = ρ_i R_i (R̲PR: the force acts at B_i perpendicular to the leg) or
    // the force |τ| = R_i (RP̲R). Torques in N times the file's length unit.
    for (std::size_t i = 0; i < 3 && i < e.reactions_N.size(); ++i) {
      const double tau = actuation_ == ThreeRprActuation::revolute ? rho[i] * e.reactions_N[i] : e.reactions_N[i];
      e.extra.push_back({"actuator_effort" + std::to_string(i + 1), tau});
    }
  }
  e.extra.push_back({"transmission_det", t.determinant});
  e.extra.push_back({"characteristic_length", length});
  for (std::size_t i = 0; i < 3; ++i) e.extra.push_back({"leg_length" + std::to_string(i + 1), rho[i]});
  return {e};
}

// ---------------------------------------------------------------------------
// Workspace

geometry::Region ThreeRpr::workspace_at(double phi) const {
  if (!leg_limits_ && !window_) {
    throw std::runtime_error(
        "three_rpr: without leg limits every position is reachable at any orientation (the workspace is "
        "the whole plane); give `leg_limits` [[min, max] x 3] or an `analysis_window` in the file");
  }
  if (!leg_limits_) return geometry::rectangle(*window_);
  geometry::Region ws;
  for (std::size_t i = 0; i < 3; ++i) {
    // |P + R b'_i - A_i| in [ρ_min, ρ_max]: an annulus about A_i - R(phi) b'_i.
    const Point centre = base_[i] - rotate(platform_[i], phi);
    const auto& l = (*leg_limits_)[i];
    const geometry::Region ring = geometry::annulus(centre, l[0], l[1]);
    ws = i == 0 ? ring : ws.intersect(ring);
  }
  return window_ ? ws.intersect(geometry::rectangle(*window_)) : ws;
}

geometry::Region ThreeRpr::workspace() const { return workspace_at(orientation_); }

bool ThreeRpr::reachable(const Pose& pose) const {
  if (window_ && !window_->contains({pose.x, pose.y})) return false;
  const auto rho = leg_lengths(pose);
  for (int i = 0; i < 3; ++i) {
    if (!leg_problem(i, rho[static_cast<std::size_t>(i)]).empty()) return false;
  }
  return true;
}

geometry::Box ThreeRpr::bounds() const {
  if (!leg_limits_ && window_) return *window_;
  if (!leg_limits_) {
    throw std::runtime_error("three_rpr: the workspace is unbounded without leg limits; give `leg_limits`");
  }
  geometry::Box box;
  double scale = 0.0;
  for (std::size_t i = 0; i < 3; ++i) {
    const Point c = base_[i] - rotate(platform_[i], orientation_);
    const double r = (*leg_limits_)[i][1];
    scale = std::max({scale, std::abs(c.x) + r, std::abs(c.y) + r});
    geometry::Box b;
    b.min = {c.x - r, c.y - r};
    b.max = {c.x + r, c.y + r};
    if (i == 0) {
      box = b;
    } else {
      box.min = {std::max(box.min.x, b.min.x), std::max(box.min.y, b.min.y)};
      box.max = {std::min(box.max.x, b.max.x), std::min(box.max.y, b.max.y)};
    }
  }
  if (box.empty()) {  // disjoint disks: empty workspace; show the base instead
    box = geometry::Box();
    for (const Point& a : base_) box.expand(a);
  }
  const double pad = 1e-9 * scale;
  box.min = {box.min.x - pad, box.min.y - pad};
  box.max = {box.max.x + pad, box.max.y + pad};
  if (window_) {
    box.min = {std::max(box.min.x, window_->min.x), std::max(box.min.y, window_->min.y)};
    box.max = {std::min(box.max.x, window_->max.x), std::min(box.max.y, window_->max.y)};
    if (box.empty()) box = *window_;
  }
  return box;
}

Drawing ThreeRpr::draw(const Pose& pose) const {
  Drawing d;
  d.tool = {pose.x, pose.y};
  const auto b = platform_points(pose);
  d.platform.assign(b.begin(), b.end());
  for (std::size_t i = 0; i < 3; ++i) {
    d.base_points.push_back(base_[i]);
    d.links.push_back({base_[i], b[i]});
    d.links.push_back({b[i], b[(i + 1) % 3]});
    d.joints.push_back(base_[i]);
    d.joints.push_back(b[i]);
    d.sliders.push_back(0.5 * (base_[i] + b[i]));
  }
  // Type-2 singularity at this orientation: det A = 0 (A's rows are normalised
  // by positive factors, so its sign changes only there). Window: the
  // workspace's box with leg limits, else the base enlarged by the platform.
  geometry::Box window;
  if (leg_limits_) {
    window = bounds();
  } else {
    double reach = 0.0;
    for (const Point& p : platform_) reach = std::max(reach, norm(p));
    for (const Point& a : base_) window.expand(a);
    const double pad = 0.25 * std::max(window.width(), window.height()) + 2.0 * reach;
    window.min = {window.min.x - pad, window.min.y - pad};
    window.max = {window.max.x + pad, window.max.y + pad};
  }
  d.singular_curves = zero_contours(
      [&](Point p) { return transmission(Pose{p.x, p.y, pose.phi}).determinant; }, window, 160);
  return d;
}

}  // namespace pkmws::mechanisms
