// 3-RRP and 3-PRP ([Mitsi]; docs/theory/three_dof.md): inverse kinematics per working mode,
// direct kinematics through the Assur group RP-RP-RP (closed form, and the
// paper's elimination as a cross-check), Jacobians, [Briot] transmission, and
// the exact constant-orientation workspace (intersection of three strips).
// Derivations in docs/theory/three_dof.md.
#include "mechanisms/three_rrp/three_rrp.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include <Eigen/LU>
#include <Eigen/SVD>

#include "mechanisms/common.hpp"
#include "pkmws/geometry/primitives.hpp"

namespace pkmws::mechanisms {

namespace {

constexpr double pi = std::numbers::pi;
constexpr double two_pi = 2.0 * pi;
constexpr double rad2deg = 180.0 / pi;
constexpr double inf = std::numeric_limits<double>::infinity();
constexpr double singular_tol = 1e-9;

using detail::format_number;
using detail::unit;
using detail::rotate;
using detail::wrap_pi;
using detail::wrap_from;




std::string label(const std::array<int, 3>& sigma) {
  return {detail::mode_sign(sigma[0]), detail::mode_sign(sigma[1]), detail::mode_sign(sigma[2])};
}

}  // namespace

ThreeRrp::ThreeRrp(ThreeRrpDrive drive, std::array<ThreeRrpChain, 3> chains, std::array<Point, 3> platform,
                   double orientation)
    : drive_(drive), chains_(chains), triangle_(AssurTriangle::from_vertices(platform)), orientation_(orientation) {
  if (!std::isfinite(orientation)) throw std::invalid_argument("non-finite orientation");
  for (std::size_t i = 0; i < 3; ++i) {
    const ThreeRrpChain& c = chains_[i];
    const std::string name = "chain " + std::to_string(i + 1) + ": ";
    if (!std::isfinite(c.base.x) || !std::isfinite(c.base.y)) throw std::invalid_argument(name + "non-finite base point");
    if (drive_ == ThreeRrpDrive::crank) {
      if (!(c.crank_length > 0.0) || !std::isfinite(c.crank_length)) {
        throw std::invalid_argument(name + "crank length must be positive");
      }
    } else if (!std::isfinite(c.direction)) {
      throw std::invalid_argument(name + "non-finite slider direction");
    }
    if (c.limits) {
      const auto& l = *c.limits;
      if (!std::isfinite(l[0]) || !std::isfinite(l[1]) || !(l[0] < l[1])) {
        throw std::invalid_argument(name + "limits must be [min, max] with min < max");
      }
      if (drive_ == ThreeRrpDrive::crank && l[1] - l[0] > two_pi * (1.0 + 1e-15)) {
        throw std::invalid_argument(name + "crank limits must span at most 360 degrees");
      }
    }
  }
  // Circumradius abc / (4 area).
  characteristic_length_ = triangle_.side[0] * triangle_.side[1] * triangle_.side[2] / (4.0 * triangle_.area);
}

// ---------------------------------------------------------------------------
// Kinematics

Point ThreeRrp::external_joint(int chain, double joint) const {
  const ThreeRrpChain& c = chains_[static_cast<std::size_t>(chain)];
  if (drive_ == ThreeRrpDrive::crank) return c.base + c.crank_length * unit(joint);  // [Mitsi] eq. 1
  return c.base + joint * unit(c.direction);                                          // [Mitsi] eq. 2
}

std::array<Point, 3> ThreeRrp::external_joints(std::span<const double> joints) const {
  if (joints.size() != 3) throw std::invalid_argument(std::string(kind()) + ": three joint values are needed");
  return {external_joint(0, joints[0]), external_joint(1, joints[1]), external_joint(2, joints[2])};
}

std::array<Point, 3> ThreeRrp::platform_points(const Pose& pose) const {
  const Point p{pose.x, pose.y};
  std::array<Point, 3> b;
  for (std::size_t i = 0; i < 3; ++i) b[i] = p + rotate(triangle_.vertices[i], pose.phi);
  return b;
}

std::vector<ThreeRrpChainSolution> ThreeRrp::inverse_chain(int chain, const Pose& pose) const {
  const auto i = static_cast<std::size_t>(chain);
  const ThreeRrpChain& c = chains_[i];
  const Point n = rotate(triangle_.normal[i], pose.phi);
  const Point b = Point{pose.x, pose.y} + rotate(triangle_.vertices[i], pose.phi);
  const double level = dot(n, b - c.base);  // side line i: n . (X - O_i) = level
  std::vector<ThreeRrpChainSolution> out;
  if (drive_ == ThreeRrpDrive::crank) {
    // n . (O + r u(q) - O) = level: r cos(q - θ_n) = level, q = θ_n + σ acos(κ);
    // then (A - O) . u_i = r sin(q - θ_n) has the sign σ.
    const double kappa = level / c.crank_length;
    if (!(std::abs(kappa) <= 1.0 + 1e-12)) return out;
    const double beta = std::acos(std::clamp(kappa, -1.0, 1.0));
    const double theta_n = std::atan2(n.y, n.x);
    for (int sigma : {1, -1}) {
      const double q = theta_n + sigma * beta;
      const double joint = c.limits ? wrap_from(q, (*c.limits)[0]) : wrap_pi(q);
      out.push_back({sigma, joint, external_joint(chain, joint)});
    }
  } else {
    const Point d = unit(c.direction);
    const double nd = dot(n, d);
    if (!(std::abs(nd) > singular_tol)) return out;  // guide parallel to the side line
    const double s = level / nd;
    out.push_back({1, s, external_joint(chain, s)});
  }
  return out;
}

std::string ThreeRrp::limit_problem(int chain, double joint) const {
  const ThreeRrpChain& c = chains_[static_cast<std::size_t>(chain)];
  if (!c.limits) return "";
  const auto& l = *c.limits;
  const std::string i = std::to_string(chain + 1);
  if (drive_ == ThreeRrpDrive::crank) {
    const double q = wrap_from(joint, l[0]);
    const double tol = singular_tol * (l[1] - l[0]);
    if (q <= l[1] + tol || q >= l[0] + two_pi - tol) return "";
    return "phi" + i + " = " + format_number(q * rad2deg) + " deg outside [" + format_number(l[0] * rad2deg) + ", " +
           format_number(l[1] * rad2deg) + "] deg";
  }
  const double tol = singular_tol * std::max(1.0, l[1] - l[0]);
  if (joint >= l[0] - tol && joint <= l[1] + tol) return "";
  return "s" + i + " = " + format_number(joint) + " outside stroke [" + format_number(l[0]) + ", " +
         format_number(l[1]) + "]";
}

std::vector<AssurAssembly> ThreeRrp::direct_closed_form(std::span<const double> joints) const {
  return assur_closed_form(triangle_, external_joints(joints));
}

AssurElimination ThreeRrp::direct_elimination(std::span<const double> joints) const {
  return assur_elimination(triangle_, external_joints(joints));
}

ThreeRrpJacobians ThreeRrp::jacobians(const Pose& pose, std::span<const double> joints) const {
  const std::array<Point, 3> a = external_joints(joints);
  const Point p{pose.x, pose.y};
  ThreeRrpJacobians j;
  j.B.setZero();
  for (int r = 0; r < 3; ++r) {
    const auto i = static_cast<std::size_t>(r);
    const Point n = rotate(triangle_.normal[i], pose.phi);
    // d/dt [n_i . (A_i - P)] = 0 with dn_i/dt = ω J n_i (docs/theory/three_dof.md).
    j.A(r, 0) = n.x;
    j.A(r, 1) = n.y;
    j.A(r, 2) = cross(a[i] - p, n);
    j.B(r, r) = drive_ == ThreeRrpDrive::crank ? chains_[i].crank_length * cross(unit(joints[i]), n)
                                               : dot(n, unit(chains_[i].direction));
  }
  return j;
}

Transmission ThreeRrp::transmission(const Pose& pose, std::span<const double> joints) const {
  const std::array<Point, 3> a = external_joints(joints);
  std::array<ActuationLine, 3> lines;
  for (std::size_t i = 0; i < 3; ++i) lines[i] = {a[i], rotate(triangle_.normal[i], pose.phi)};
  return analyse_transmission({pose.x, pose.y}, lines);
}

std::vector<JointInfo> ThreeRrp::joints() const {
  std::vector<JointInfo> out;
  for (int i = 1; i <= 3; ++i) {
    out.push_back(drive_ == ThreeRrpDrive::crank ? JointInfo{"phi" + std::to_string(i), true, std::nullopt}
                                                 : JointInfo{"s" + std::to_string(i), false, std::nullopt});
  }
  return out;
}

std::vector<JointSolution> ThreeRrp::inverse(const Pose& pose) const {
  std::array<std::vector<ThreeRrpChainSolution>, 3> per_chain;
  for (int i = 0; i < 3; ++i) per_chain[static_cast<std::size_t>(i)] = inverse_chain(i, pose);
  std::vector<std::array<int, 3>> modes;
  if (drive_ == ThreeRrpDrive::crank) {
    for (int s1 : {1, -1})
      for (int s2 : {1, -1})
        for (int s3 : {1, -1}) modes.push_back({s1, s2, s3});
  } else {
    modes.push_back({1, 1, 1});
  }
  std::vector<JointSolution> out;
  for (const auto& m : modes) {
    JointSolution s;
    s.mode = drive_ == ThreeRrpDrive::crank ? label(m) : "000";  // sliders: one solution per leg
    std::vector<double> q;
    for (std::size_t i = 0; i < 3 && s.reason.empty(); ++i) {
      const auto it = std::find_if(per_chain[i].begin(), per_chain[i].end(),
                                   [&](const ThreeRrpChainSolution& c) { return c.sigma == m[i]; });
      if (it == per_chain[i].end()) {
        s.reason = drive_ == ThreeRrpDrive::crank
                       ? "crank " + std::to_string(i + 1) + " cannot reach side line " + std::to_string(i + 1)
                       : "guide " + std::to_string(i + 1) + " is parallel to side line " + std::to_string(i + 1);
      } else {
        q.push_back(it->joint);
      }
    }
    if (s.reason.empty()) {
      s.joints = q;
      for (int i = 0; i < 3 && s.reason.empty(); ++i) s.reason = limit_problem(i, q[static_cast<std::size_t>(i)]);
    }
    s.valid = s.reason.empty();
    out.push_back(s);
  }
  return out;
}

std::vector<PoseSolution> ThreeRrp::direct(std::span<const double> joints) const {
  const std::vector<AssurAssembly> assemblies = direct_closed_form(joints);
  std::string limits;
  for (int i = 0; i < 3 && limits.empty(); ++i) limits = limit_problem(i, joints[static_cast<std::size_t>(i)]);
  std::vector<PoseSolution> out;
  for (const AssurAssembly& as : assemblies) {
    PoseSolution s;
    s.pose = {as.origin.x, as.origin.y, as.phi};
    s.platform_points = {as.vertices[0], as.vertices[1], as.vertices[2]};
    if (assemblies.size() == 1) {
      s.mode = "0";  // the two assembly modes meet: a type-2 singularity
    } else {
      const double det = jacobians(s.pose, joints).A.determinant();
      s.mode = std::string(1, detail::mode_sign(det));
    }
    s.reason = limits;
    s.valid = s.reason.empty();
    out.push_back(s);
  }
  return out;
}

std::vector<Evaluation> ThreeRrp::evaluate(const Pose& pose, const Criteria& criteria) const {
  std::vector<Evaluation> out;
  const double length = criteria.characteristic_length.value_or(characteristic_length_);
  for (const JointSolution& s : inverse(pose)) {
    Evaluation e = detail::start_evaluation(s, 3);
    if (s.joints.size() != 3) {
      out.push_back(e);
      continue;
    }
    const ThreeRrpJacobians j = jacobians(pose, s.joints);
    bool type1 = false;
    for (std::size_t i = 0; i < 3; ++i) {
      const double scale = drive_ == ThreeRrpDrive::crank ? chains_[i].crank_length : 1.0;
      const int r = static_cast<int>(i);
      type1 = type1 || !(std::abs(j.B(r, r)) > singular_tol * scale);
    }
    const Transmission t = transmission(pose, s.joints);
    const bool type2 = t.singular;
    e.singular = type1 || type2;
    e.singularity = type1 && type2 ? "both" : type1 ? "type1" : type2 ? "type2" : "";
    if (type1) {
      e.jacobian_det = inf;
      e.condition_number = inf;
    } else {
      // dq/dx = B^-1 A, x = (x, y, phi); for conditioning the angular column is
      // scaled by the characteristic length L (x' = (x, y, L phi)).
      const Eigen::Matrix3d jq = j.B.inverse() * j.A;
      e.jacobian_det = jq.determinant();
      Eigen::Matrix3d scaled = jq;
      scaled.col(2) /= length;
      const Eigen::JacobiSVD<Eigen::Matrix3d> svd(scaled);
      const auto sv = svd.singularValues();
      e.condition_number = type2 || sv(2) == 0.0 ? inf : sv(0) / sv(2);
      e.velocity_ratio = sv(0);  // |dq| / |dx'| in the worst direction
    }
    for (double a : t.pressure_angle) e.pressure_angle_deg.push_back(a * rad2deg);
    if (criteria.load) {
      for (double r : reaction_max(t, *criteria.load)) e.reactions_N.push_back(r);
    }
    e.extra.push_back({"transmission_det", t.determinant});
    e.extra.push_back({"characteristic_length", length});
    out.push_back(e);
  }
  return out;
}

// ---------------------------------------------------------------------------
// Constant-orientation workspace: three strips

std::optional<std::array<double, 2>> ThreeRrp::strip_range(int chain, double phi) const {
  const auto i = static_cast<std::size_t>(chain);
  const ThreeRrpChain& c = chains_[i];
  const Point n = rotate(triangle_.normal[i], phi);
  // n_i . (A_i - P) = h_i  =>  n_i . P = n_i . A_i(q) - h_i.
  const double base = dot(n, c.base) - triangle_.offset[i];
  if (drive_ == ThreeRrpDrive::crank) {
    const double r = c.crank_length;
    if (!c.limits || (*c.limits)[1] - (*c.limits)[0] >= two_pi) return std::array<double, 2>{base - r, base + r};
    const double lo = (*c.limits)[0], hi = (*c.limits)[1];
    const double theta_n = std::atan2(n.y, n.x);
    // n . A = n . O + r cos(q - θ_n) over q in [lo, hi]: the ends, and the
    // extremes at q = θ_n (max) and θ_n + pi (min) when inside.
    double vmin = std::min(std::cos(lo - theta_n), std::cos(hi - theta_n));
    double vmax = std::max(std::cos(lo - theta_n), std::cos(hi - theta_n));
    if (wrap_from(theta_n, lo) <= hi) vmax = 1.0;
    if (wrap_from(theta_n + pi, lo) <= hi) vmin = -1.0;
    return std::array<double, 2>{base + r * vmin, base + r * vmax};
  }
  const double nd = dot(n, unit(c.direction));
  if (!c.limits) {
    if (nd == 0.0) return std::array<double, 2>{base, base};
    return std::nullopt;
  }
  const double v0 = base + (*c.limits)[0] * nd, v1 = base + (*c.limits)[1] * nd;
  return std::array<double, 2>{std::min(v0, v1), std::max(v0, v1)};
}

geometry::Box ThreeRrp::bounds_at(double phi) const {
  std::array<std::array<double, 2>, 3> range;
  std::array<Point, 3> normal;
  for (std::size_t i = 0; i < 3; ++i) {
    const auto r = strip_range(static_cast<int>(i), phi);
    if (!r) {
      throw std::runtime_error(
          "three_prp: without strokes an actuated slider moves its joint along a whole line, so the "
          "constant-orientation workspace is unbounded; give `strokes` [[min, max] x 3] in the file");
    }
    range[i] = *r;
    normal[i] = rotate(triangle_.normal[i], phi);
  }
  // The parallelogram of the two strips whose normals are the most transverse
  // holds the intersection of all three.
  std::size_t bi = 0, bj = 1;
  double best = -1.0;
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = i + 1; j < 3; ++j) {
      const double c = std::abs(cross(normal[i], normal[j]));
      if (c > best) { best = c; bi = i; bj = j; }
    }
  }
  geometry::Box box;
  const Point ni = normal[bi], nj = normal[bj];
  const double det = cross(ni, nj);
  for (double u : range[bi]) {
    for (double v : range[bj]) {
      // n_i . P = u, n_j . P = v (Cramer).
      box.expand(Point{(u * nj.y - v * ni.y) / det, (ni.x * v - nj.x * u) / det});
    }
  }
  double scale = std::max(box.width(), box.height());
  for (const auto& c : chains_) scale = std::max({scale, std::abs(c.base.x), std::abs(c.base.y)});
  const double pad = 0.01 * std::max(box.width(), box.height()) + 1e-9 * scale + std::numeric_limits<double>::min();
  box.min = {box.min.x - pad, box.min.y - pad};
  box.max = {box.max.x + pad, box.max.y + pad};
  return box;
}

geometry::Region ThreeRrp::workspace_at(double phi) const {
  const geometry::Box clip = bounds_at(phi);
  geometry::Region ws;
  for (std::size_t i = 0; i < 3; ++i) {
    const auto r = *strip_range(static_cast<int>(i), phi);
    if (!(r[1] > r[0])) return geometry::Region();  // a line: no area (a 3-PRP guide along its side)
    const Point n = rotate(triangle_.normal[i], phi);
    const geometry::Region strip = geometry::strip(r[0] * n, std::atan2(n.y, n.x), r[1] - r[0], clip);
    ws = i == 0 ? strip : ws.intersect(strip);
  }
  return ws;
}

geometry::Region ThreeRrp::workspace() const { return workspace_at(orientation_); }

geometry::Box ThreeRrp::bounds() const { return bounds_at(orientation_); }

bool ThreeRrp::reachable(const Pose& pose) const {
  for (int i = 0; i < 3; ++i) {
    bool ok = false;
    for (const auto& c : inverse_chain(i, pose)) ok = ok || limit_problem(i, c.joint).empty();
    if (!ok) return false;
  }
  return true;
}

Drawing ThreeRrp::draw(const Pose& pose) const {
  // One working mode: the first valid one, else the first with joint values.
  const std::vector<JointSolution> solutions = inverse(pose);
  const JointSolution* chosen = nullptr;
  for (const auto& s : solutions) {
    if (s.valid) { chosen = &s; break; }
  }
  if (!chosen) {
    for (const auto& s : solutions) {
      if (s.joints.size() == 3) { chosen = &s; break; }
    }
  }
  return draw_with_joints(pose, chosen ? std::span<const double>(chosen->joints) : std::span<const double>());
}

Drawing ThreeRrp::draw_with_joints(const Pose& pose, std::span<const double> joints) const {
  Drawing d;
  const Point p{pose.x, pose.y};
  d.tool = p;
  const std::array<Point, 3> b = platform_points(pose);
  d.platform.assign(b.begin(), b.end());
  for (std::size_t i = 0; i < 3; ++i) d.links.push_back({b[i], b[(i + 1) % 3]});
  const bool legs = joints.size() == 3;
  for (std::size_t i = 0; i < 3; ++i) {
    const ThreeRrpChain& c = chains_[i];
    d.base_points.push_back(c.base);
    if (drive_ == ThreeRrpDrive::slider) {
      const Point u = unit(c.direction);
      if (c.limits) {
        d.guides.push_back({c.base + (*c.limits)[0] * u, c.base + (*c.limits)[1] * u});
      } else if (legs) {
        d.guides.push_back({c.base, external_joint(static_cast<int>(i), joints[i])});
      }
    }
    if (!legs) continue;
    const Point a = external_joint(static_cast<int>(i), joints[i]);
    if (drive_ == ThreeRrpDrive::crank) {
      d.links.push_back({c.base, a});
      d.joints.push_back(c.base);
    }
    d.sliders.push_back(a);
    d.joints.push_back(a);
    // The slider's rail: side line i, drawn from the nearer end of the side to A_i.
    const Point near = norm(a - b[i]) <= norm(a - b[(i + 1) % 3]) ? b[i] : b[(i + 1) % 3];
    d.guides.push_back({near, a});
  }
  return d;
}

}  // namespace pkmws::mechanisms
