// Five-bar 5R ([Briot], DexTAR): inverse kinematics per working mode, robust
// direct kinematics (both assembly modes), Jacobians, transmission and
// pressure angles ([Briot]: α = acos|sin ε|), reactions, the exact reachable
// workspace (annuli, or with crank limits the region swept by each distal
// circle; docs/theory/five_bar.md), Π-joint drives ([Milutinovic] figure 5) and the
// type-2 singularity curves.
#include "mechanisms/common.hpp"
#include "mechanisms/five_bar/five_bar.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include <Eigen/LU>

#include "pkmws/geometry/primitives.hpp"

namespace pkmws::mechanisms {

using detail::format_number;
using detail::unit;
using detail::wrap_pi;
using detail::wrap_from;
using detail::mode_label;

namespace {

constexpr double pi = std::numbers::pi;
constexpr double two_pi = 2.0 * std::numbers::pi;
constexpr double rad2deg = 180.0 / pi;
constexpr double inf = std::numeric_limits<double>::infinity();
// Relative tolerance of the singularity, working-mode and limit tests.
constexpr double singular_tol = 1e-9;




PiJointKinematics pi_kinematics(const FiveBarLeg& leg) { return {leg.proximal, leg.pi_joint->k}; }

// t1' within a few ulps of t1 with fl(t0 + fl(t1' - t0)) == t1': then
// annulus_sector(c, ., ., t0, t1' - t0) ends exactly on rational_direction(t1'),
// the ray a sector or half-disk starting at t1' begins on (docs/theory/five_bar.md).
double snap_end(double t0, double t1) {
  double t = t1;
  for (int i = 0; i < 8; ++i) {
    const double sweep = t - t0;
    const double end = t0 + sweep;
    if (end == t) return t;
    t = end;
  }
  double up = t1, down = t1;
  for (int i = 0; i < 256; ++i) {
    up = std::nextafter(up, inf);
    if (t0 + (up - t0) == up) return up;
    down = std::nextafter(down, -inf);
    if (t0 + (down - t0) == down) return down;
  }
  throw std::logic_error("five_bar: cannot snap a crank limit angle");
}

}  // namespace

// ---------------------------------------------------------------------------
// Construction

FiveBar::FiveBar(std::array<FiveBarLeg, 2> legs) : legs_(legs) {
  for (int i = 0; i < 2; ++i) {
    const FiveBarLeg& l = legs_[i];
    const std::string leg = "leg " + std::to_string(i + 1) + ": ";
    if (!std::isfinite(l.base.x) || !std::isfinite(l.base.y)) throw std::invalid_argument(leg + "non-finite base");
    if (!(l.proximal > 0.0) || !std::isfinite(l.proximal)) throw std::invalid_argument(leg + "proximal length must be positive");
    if (!(l.distal > 0.0) || !std::isfinite(l.distal)) throw std::invalid_argument(leg + "distal length must be positive");
    if (l.working_mode != 1 && l.working_mode != -1) throw std::invalid_argument(leg + "working mode must be -1 or 1");
    if (l.crank_limits && l.pi_joint) {
      throw std::invalid_argument(leg + "give either crank limits or a Π-joint drive, not both");
    }
    if (l.crank_limits) {
      const auto& c = *l.crank_limits;
      if (!std::isfinite(c[0]) || !std::isfinite(c[1]) || !(c[0] < c[1]) || c[1] - c[0] > two_pi * (1 + 1e-15)) {
        throw std::invalid_argument(leg + "crank limits must be [min, max] with 0 < max - min <= 360 degrees");
      }
      limits_[i] = c;
    }
    if (l.pi_joint) {
      const FiveBarPiDrive& p = *l.pi_joint;
      if (!(p.k > 0.0) || !std::isfinite(p.k)) throw std::invalid_argument(leg + "Π-joint k must be positive");
      if (p.sense != 1 && p.sense != -1) throw std::invalid_argument(leg + "Π-joint sense must be -1 or 1");
      if (!std::isfinite(p.base_angle)) throw std::invalid_argument(leg + "non-finite Π-joint base angle");
      const PiJointKinematics kin = pi_kinematics(l);
      if (!(p.stroke_min < p.stroke_max) || !(p.stroke_min > kin.length_min()) || !(p.stroke_max < kin.length_max())) {
        throw std::invalid_argument(leg + "Π-joint stroke [" + format_number(p.stroke_min) + ", " + format_number(p.stroke_max) +
                                    "] must lie strictly inside the parallelogram's d range (" +
                                    format_number(kin.length_min()) + ", " + format_number(kin.length_max()) +
                                    ") = (a|1 - k|, a(1 + k)), i.e. -90 < theta < 90 degrees");
      }
      // [Milutinovic] eq. 3-5 at both ends of the stroke; q = base + sense * theta.
      const double t_lo = *kin.angle(p.stroke_min), t_hi = *kin.angle(p.stroke_max);
      limits_[i] = p.sense > 0 ? std::array<double, 2>{p.base_angle + t_lo, p.base_angle + t_hi}
                               : std::array<double, 2>{p.base_angle - t_hi, p.base_angle - t_lo};
    }
  }
}

std::optional<std::array<double, 2>> FiveBar::crank_limits(int leg) const { return limits_[leg]; }

// ---------------------------------------------------------------------------
// Kinematics

Point FiveBar::elbow(int leg, double q) const { return legs_[leg].base + legs_[leg].proximal * unit(q); }

int FiveBar::working_mode_sign(Point base, Point elbow, Point tool) {
  const double c = cross(tool - base, elbow - base);  // docs/theory/five_bar.md
  return c > 0.0 ? 1 : (c < 0.0 ? -1 : 0);
}

std::optional<double> FiveBar::inverse_leg(int leg, Point c, int s) const {
  const FiveBarLeg& l = legs_[leg];
  const Point w = c - l.base;
  const double rho = norm(w);
  const double l1 = l.proximal, l2 = l.distal;
  double beta;
  if (rho == 0.0) {
    if (l1 != l2) return std::nullopt;
    beta = pi / 2;  // C = A_i with l1 = l2: every crank angle reaches it
  } else {
    // Law of cosines in triangle A_i B_i C: cos β = (ρ² + l1² - l2²) / (2 ρ l1).
    const double cb = (rho * rho + (l1 - l2) * (l1 + l2)) / (2.0 * rho * l1);
    if (!(std::abs(cb) <= 1.0 + 1e-12)) return std::nullopt;
    beta = std::acos(std::clamp(cb, -1.0, 1.0));
  }
  // s = sign(w x (B - A)) = sign(sin(q - ψ)) (docs/theory/five_bar.md), so q = ψ + s β.
  const double q = std::atan2(w.y, w.x) + s * beta;
  return limits_[leg] ? wrap_from(q, (*limits_[leg])[0]) : wrap_pi(q);
}

std::vector<FiveBarAssembly> FiveBar::direct_all(double q1, double q2) const {
  const Point b = elbow(0, q1), d = elbow(1, q2);
  const double l1 = legs_[0].distal, l2 = legs_[1].distal;
  const Point bd = d - b;
  const double dist = norm(bd);
  std::vector<FiveBarAssembly> out;
  if (dist == 0.0) return out;  // B = D: C anywhere on a circle (type-2 singular)
  const Point e = (1.0 / dist) * bd;
  const Point n{-e.y, e.x};
  const double along = (l1 * l1 - l2 * l2 + dist * dist) / (2.0 * dist);
  const double h2 = (l1 - along) * (l1 + along);
  const double scale = std::max(l1, l2);
  if (h2 < -singular_tol * scale * scale) return out;
  if (h2 <= singular_tol * scale * scale) {
    out.push_back({b + along * e, {b, d}, 0});
    return out;
  }
  const double h = std::sqrt(h2);
  out.push_back({b + along * e + h * n, {b, d}, 1});
  out.push_back({b + along * e - h * n, {b, d}, -1});
  return out;
}

FiveBarJacobians FiveBar::jacobians(Point c, double q1, double q2) const {
  // d/dt |C - B_i|² = 0 with Ḃ_i = l_i1 (-sin q_i, cos q_i) q̇_i.
  FiveBarJacobians j;
  j.B.setZero();
  const double q[2] = {q1, q2};
  for (int i = 0; i < 2; ++i) {
    const Point w = c - elbow(i, q[i]);
    j.A(i, 0) = w.x;
    j.A(i, 1) = w.y;
    j.B(i, i) = legs_[i].proximal * cross(unit(q[i]), w);
  }
  return j;
}

double FiveBar::transmission_angle(Point c, double q1, double q2) const {
  const Point u1 = c - elbow(0, q1), u2 = c - elbow(1, q2);
  return std::atan2(cross(u1, u2), dot(u1, u2));
}

std::optional<double> FiveBar::pi_length(int leg, double q) const {
  const FiveBarLeg& l = legs_[leg];
  if (!l.pi_joint) return std::nullopt;
  const double theta = wrap_pi(l.pi_joint->sense * (q - l.pi_joint->base_angle));
  if (!(std::abs(theta) < pi / 2)) return std::nullopt;
  return pi_kinematics(l).length(theta);  // [Milutinovic] eq. 2
}

std::optional<double> FiveBar::crank_from_pi_length(int leg, double d) const {
  const FiveBarLeg& l = legs_[leg];
  if (!l.pi_joint || !(d >= 0.0)) return std::nullopt;
  const auto theta = pi_kinematics(l).angle(d);  // [Milutinovic] eq. 3-5
  if (!theta) return std::nullopt;
  return l.pi_joint->base_angle + l.pi_joint->sense * *theta;
}

std::optional<double> FiveBar::joint_from_crank(int leg, double q) const {
  if (legs_[leg].pi_joint) return pi_length(leg, q);
  return q;
}

std::optional<double> FiveBar::crank_from_joint(int leg, double value) const {
  if (legs_[leg].pi_joint) return crank_from_pi_length(leg, value);
  return value;
}

std::string FiveBar::limit_problem(int leg, double q) const {
  if (!limits_[leg]) return "";
  const auto& lim = *limits_[leg];
  const double qq = wrap_from(q, lim[0]);
  const double tol = singular_tol * (lim[1] - lim[0]);
  // Within [min, max], also just below min (wrapped to min + 2 pi).
  if (qq <= lim[1] + tol || qq >= lim[0] + two_pi - tol) return "";
  const std::string i = std::to_string(leg + 1);
  if (legs_[leg].pi_joint) {
    const auto d = pi_length(leg, q);
    const FiveBarPiDrive& p = *legs_[leg].pi_joint;
    if (d) return "d" + i + " = " + format_number(*d) + " outside stroke [" + format_number(p.stroke_min) + ", " + format_number(p.stroke_max) + "]";
    return "crank " + i + " at " + format_number(qq * rad2deg) + " deg puts its Π-joint outside (-90, 90) deg";
  }
  return "theta" + i + " = " + format_number(qq * rad2deg) + " deg outside [" + format_number(lim[0] * rad2deg) + ", " +
         format_number(lim[1] * rad2deg) + "] deg";
}

std::vector<JointInfo> FiveBar::joints() const {
  std::vector<JointInfo> out;
  for (int i = 0; i < 2; ++i) {
    const std::string n = std::to_string(i + 1);
    if (const auto& pi = legs_[i].pi_joint) {
      out.push_back(JointInfo{"d" + n, false, std::array{pi->stroke_min, pi->stroke_max}});
    } else {
      out.push_back(JointInfo{"theta" + n, true, crank_limits(i)});
    }
  }
  return out;
}

std::vector<JointSolution> FiveBar::inverse(const Pose& pose) const {
  const Point c{pose.x, pose.y};
  const int f1 = legs_[0].working_mode, f2 = legs_[1].working_mode;
  const int combos[4][2] = {{f1, f2}, {f1, -f2}, {-f1, f2}, {-f1, -f2}};
  std::vector<JointSolution> out;
  for (const auto& m : combos) {
    JointSolution s;
    s.mode = mode_label(m[0], m[1]);
    std::optional<double> q[2];
    for (int i = 0; i < 2 && s.reason.empty(); ++i) {
      q[i] = inverse_leg(i, c, m[i]);
      if (!q[i]) s.reason = "leg " + std::to_string(i + 1) + " cannot reach the point (outside its annulus)";
    }
    if (s.reason.empty()) {
      for (int i = 0; i < 2; ++i) {
        const auto v = joint_from_crank(i, *q[i]);
        s.joints.push_back(v ? *v : std::numeric_limits<double>::quiet_NaN());
      }
      for (int i = 0; i < 2 && s.reason.empty(); ++i) s.reason = limit_problem(i, *q[i]);
      if (s.reason.empty() && (m[0] != f1 || m[1] != f2)) {
        s.reason = "reachable, but not the file's working mode " + mode_label(f1, f2);
      }
    }
    s.valid = s.reason.empty();
    out.push_back(s);
  }
  return out;
}

std::vector<PoseSolution> FiveBar::direct(std::span<const double> joints) const {
  if (joints.size() != 2) throw std::invalid_argument("five_bar: direct kinematics needs two joint values");
  std::optional<double> q[2];
  for (int i = 0; i < 2; ++i) {
    q[i] = crank_from_joint(i, joints[i]);
    if (!q[i]) return {};  // d outside the parallelogram's range: no assembly
  }
  std::vector<PoseSolution> out;
  for (const FiveBarAssembly& a : direct_all(*q[0], *q[1])) {
    PoseSolution s;
    s.mode = std::string(1, detail::mode_sign(a.sign));
    s.pose = {a.tool.x, a.tool.y, 0.0};
    s.platform_points = {a.elbows[0], a.elbows[1]};
    for (int i = 0; i < 2 && s.reason.empty(); ++i) s.reason = limit_problem(i, *q[i]);
    for (int i = 0; i < 2 && s.reason.empty(); ++i) {
      const FiveBarLeg& l = legs_[i];
      const double c = cross(a.tool - l.base, a.elbows[i] - l.base);
      if (c * l.working_mode < -singular_tol * l.proximal * (l.proximal + l.distal)) {
        s.reason = "leg " + std::to_string(i + 1) + " is in working mode " + std::to_string(-l.working_mode) +
                   ", the file's is " + std::to_string(l.working_mode);
      }
    }
    s.valid = s.reason.empty();
    out.push_back(s);
  }
  return out;
}

std::vector<Evaluation> FiveBar::evaluate(const Pose& pose, const Criteria& criteria) const {
  const Point c{pose.x, pose.y};
  std::vector<Evaluation> out;
  const int f1 = legs_[0].working_mode, f2 = legs_[1].working_mode;
  const int combos[4][2] = {{f1, f2}, {f1, -f2}, {-f1, f2}, {-f1, -f2}};  // the order of inverse()
  const auto solutions = inverse(pose);
  for (std::size_t k = 0; k < solutions.size(); ++k) {
    const JointSolution& s = solutions[k];
    Evaluation e = detail::start_evaluation(s, 2);
    if (s.joints.size() != 2) {
      out.push_back(e);
      continue;
    }
    const double q1 = *inverse_leg(0, c, combos[k][0]), q2 = *inverse_leg(1, c, combos[k][1]);
    const FiveBarJacobians j = jacobians(c, q1, q2);
    const double l11 = legs_[0].proximal, l12 = legs_[0].distal;
    const double l21 = legs_[1].proximal, l22 = legs_[1].distal;
    const bool type1 = std::abs(j.B(0, 0)) <= singular_tol * l11 * l12 || std::abs(j.B(1, 1)) <= singular_tol * l21 * l22;
    const double det_a = j.A.determinant();  // = l12 l22 sin ε
    const bool type2 = std::abs(det_a) <= singular_tol * l12 * l22;
    e.singular = type1 || type2;
    e.singularity = type1 && type2 ? "both" : type1 ? "type1" : type2 ? "type2" : "";
    // Joint rates dq = B⁻¹ A dC; a Π-driven leg's row is scaled by dd/dq = sense J_Π(θ_Π).
    Eigen::Matrix2d scale = Eigen::Matrix2d::Identity();
    const double q[2] = {q1, q2};
    for (int i = 0; i < 2; ++i) {
      if (const auto& p = legs_[i].pi_joint) {
        const double theta = wrap_pi(p->sense * (q[i] - p->base_angle));
        scale(i, i) = p->sense * pi_kinematics(legs_[i]).jacobian(theta);  // [Milutinovic] eq. 7
        e.extra.push_back({"crank" + std::to_string(i + 1) + "_deg", wrap_pi(q[i]) * rad2deg});
        e.extra.push_back({"theta_pi" + std::to_string(i + 1) + "_deg", theta * rad2deg});
      }
    }
    detail::set_velocity_figures(e, scale * j.B.inverse() * j.A, type1, type2);  // worst |dq| / |dC|
    // [Briot]: cos α_i = |sin ε| for both legs (the force of leg i is along its
    // distal link; with actuator j locked C moves perpendicular to distal link j).
    detail::set_point_platform_transmission(e, std::abs(det_a) / (l12 * l22), criteria);
    // [Briot] Table 2, chain R̲RR: the elbow and base joints carry the distal
    // force R_i; the actuator torque is its moment about A_i,
    // |τ_i| = l_i1 R_i |sin(angle between proximal and distal link)| = R_i |B_ii| / l_i2
    // (N times the file's length unit; the Π-joint's own force is not included).
    for (int i = 0; i < 2 && static_cast<std::size_t>(i) < e.reactions_N.size(); ++i) {
      const double distal = legs_[i].distal;
      e.extra.push_back({"actuator_torque" + std::to_string(i + 1),
                         e.reactions_N[static_cast<std::size_t>(i)] * std::abs(j.B(i, i)) / distal});
    }
    e.extra.push_back({"transmission_angle_deg", transmission_angle(c, q1, q2) * rad2deg});
    out.push_back(e);
  }
  return out;
}

// ---------------------------------------------------------------------------
// Exact workspace

geometry::Region FiveBar::leg_workspace(int leg) const {
  const FiveBarLeg& l = legs_[leg];
  const Point a = l.base;
  const double l1 = l.proximal, l2 = l.distal;
  const double r_out = l1 + l2, r_in = std::abs(l1 - l2);
  const geometry::Region ring = geometry::annulus(a, r_in, r_out);
  if (!limits_[leg]) return ring;
  const double lo = (*limits_[leg])[0], hi = (*limits_[leg])[1];
  if (hi - lo >= two_pi) return ring;
  // In polar coordinates (ρ, ψ) about A the leg reaches C in working mode s with
  // the crank at q = ψ + s β(ρ) (inverse_leg), so with q in [lo, hi] the region is
  // ψ in [lo - s β, hi - s β]: bounded by the outer and inner circles and by the
  // half circles of radius l2 about B(lo), B(hi) on the side s of the crank line
  // (docs/theory/five_bar.md):
  //   s = +1: (S ∪ HD(lo)) − HD(hi),  s = −1: (S ∪ HD(hi)) − HD(lo),
  // S the annulus sector [lo, hi], HD(t) the half disk of radius l2 about B(t)
  // on side s of the ray at t, then ∩ the annulus. Valid while the span plus
  // β_max (the largest β over the annulus) stays within a turn; a longer span
  // is the annulus minus the complementary span [hi, lo + 2π], which is shorter
  // than β_max <= π.
  const int s = l.working_mode;
  const double big = 2.0 * r_out;
  const double beta_max = l1 > l2 ? std::asin(l2 / l1) : (l1 == l2 ? pi / 2 : pi);
  auto half_disk = [&](double t) {
    const Point b = a + l1 * geometry::rational_direction(t).unit();
    const geometry::Region d = geometry::disk(b, l2);
    const geometry::Region side = geometry::annulus_sector(a, 0.0, big, t, pi);  // ψ in [t, t + π]: s = -1
    return s > 0 ? d.subtract(side) : d.intersect(side);
  };
  auto swept = [&](double t0, double t1) {
    t1 = snap_end(t0, t1);  // the sector's end ray is exactly HD(t1)'s ray
    const geometry::Region sector = geometry::annulus_sector(a, r_in, r_out, t0, t1 - t0);
    const geometry::Region h0 = half_disk(t0), h1 = half_disk(t1);
    return s > 0 ? sector.unite(h0).subtract(h1) : sector.unite(h1).subtract(h0);
  };
  if (hi - lo + beta_max <= two_pi) return swept(lo, hi).intersect(ring);
  return ring.subtract(swept(hi, lo + two_pi));
}

geometry::Region FiveBar::workspace() const { return leg_workspace(0).intersect(leg_workspace(1)); }

bool FiveBar::reachable(const Pose& pose) const {
  const Point c{pose.x, pose.y};
  for (int i = 0; i < 2; ++i) {
    const auto q = inverse_leg(i, c, legs_[i].working_mode);
    if (!q || !limit_problem(i, *q).empty()) return false;
  }
  return true;
}

Drawing FiveBar::draw(const Pose& pose) const {
  Drawing d;
  const Point c{pose.x, pose.y};
  d.tool = c;
  d.singular_curves = type2_singularity_curves(*this);
  d.guides.push_back({legs_[0].base, legs_[1].base});
  d.guides_legend = "base line";
  for (int i = 0; i < 2; ++i) {
    const FiveBarLeg& l = legs_[i];
    d.base_points.push_back(l.base);
    d.joints.push_back(l.base);
    auto q = inverse_leg(i, c, l.working_mode);
    const bool reach = q.has_value();
    if (!q) q = limits_[i] ? 0.5 * ((*limits_[i])[0] + (*limits_[i])[1]) : pi / 2;
    const Point b = elbow(i, *q);
    d.links.push_back({l.base, b});
    d.joints.push_back(b);
    if (reach) d.links.push_back({b, c});
    if (l.pi_joint) {
      // The Π-joint's fixed link A O' points along the crank at θ_Π = 90°; its
      // second crank O' A' and coupler B A' stay parallel to A B and A O'.
      const PiJointKinematics kin = pi_kinematics(l);
      const Point o2 = l.base + kin.b() * unit(l.pi_joint->base_angle + l.pi_joint->sense * pi / 2);
      const Point a2 = o2 + (b - l.base);
      d.guides.push_back({l.base, o2});
      d.guides_legend = "base line / fixed link";
      d.links.push_back({o2, a2});
      d.links.push_back({b, a2});
      d.links.push_back({l.base, a2});  // the telescopic diagonal
      d.joints.push_back(o2);
      d.joints.push_back(a2);
      d.base_points.push_back(o2);
    }
  }
  d.joints.push_back(c);
  return d;
}

geometry::Box FiveBar::bounds() const {
  geometry::Box boxes[2];
  for (int i = 0; i < 2; ++i) {
    const FiveBarLeg& l = legs_[i];
    const double r = l.proximal + l.distal;
    boxes[i].expand(Point{l.base.x - r, l.base.y - r});
    boxes[i].expand(Point{l.base.x + r, l.base.y + r});
  }
  geometry::Box b;
  b.min = {std::max(boxes[0].min.x, boxes[1].min.x), std::max(boxes[0].min.y, boxes[1].min.y)};
  b.max = {std::min(boxes[0].max.x, boxes[1].max.x), std::min(boxes[0].max.y, boxes[1].max.y)};
  if (b.empty()) {
    b = boxes[0];
    b.expand(boxes[1]);
  }
  return b;
}

// ---------------------------------------------------------------------------
// Type-2 singularity curves

namespace {

struct Sample {
  Point c;
  bool keep = true;
};

// Splits a closed loop into the runs of kept samples (joining the run that
// wraps around the loop's start).
void split_closed(const std::vector<Sample>& loop, std::vector<std::vector<Point>>& out) {
  const std::size_t n = loop.size();
  if (n < 2) return;
  std::size_t start = n;
  for (std::size_t i = 0; i < n; ++i) {
    if (!loop[i].keep) { start = i; break; }
  }
  if (start == n) {  // all kept: the closed loop itself
    std::vector<Point> pts;
    for (const Sample& s : loop) pts.push_back(s.c);
    pts.push_back(loop.front().c);
    out.push_back(std::move(pts));
    return;
  }
  std::vector<Point> run;
  for (std::size_t k = 1; k <= n; ++k) {
    const Sample& s = loop[(start + k) % n];
    if (s.keep) {
      run.push_back(s.c);
    } else if (!run.empty()) {
      if (run.size() >= 2) out.push_back(run);
      run.clear();
    }
  }
  if (run.size() >= 2) out.push_back(run);
}

}  // namespace

std::vector<std::vector<Point>> type2_singularity_curves(const FiveBar& m, bool all_modes, int samples) {
  if (samples < 8) throw std::invalid_argument("type2_singularity_curves: samples must be >= 8");
  const auto& legs = m.legs();
  const Point a = legs[0].base, e = legs[1].base;
  const double l11 = legs[0].proximal, l12 = legs[0].distal;
  const double l21 = legs[1].proximal, l22 = legs[1].distal;
  std::vector<std::vector<Point>> out;

  auto keep = [&](Point c, double q1, double q2) {
    if (all_modes) return true;
    const Point b = m.elbow(0, q1), d = m.elbow(1, q2);
    const double scale1 = l11 * (l11 + l12), scale2 = l21 * (l21 + l22);
    if (cross(c - a, b - a) * legs[0].working_mode < -singular_tol * scale1) return false;
    if (cross(c - e, d - e) * legs[1].working_mode < -singular_tol * scale2) return false;
    const Pose pose{c.x, c.y, 0.0};
    return m.reachable(pose);
  };

  // Distal links aligned: |B - D| = L with C between B and D (L = l12 + l22,
  // ε = π) or beyond them (L = |l12 - l22| > 0, ε = 0). For each crank angle q1,
  // D lies on circle(E, l21) ∩ circle(B, L): two branches that meet where
  // |B - E| = |L ± l21| (turning points).
  auto trace = [&](double L, bool between) {
    const Point ae = a - e;
    const double c0 = dot(ae, ae) + l11 * l11, c1 = 2.0 * l11 * norm(ae);
    if (c1 == 0.0) return;
    const double r_lo = std::abs(L - l21), r_hi = L + l21;
    const double clo = (r_lo * r_lo - c0) / c1, chi = (r_hi * r_hi - c0) / c1;
    // |B - E|² = c0 + c1 cos(q1 - ang), ang the angle of A - E.
    const double ang = std::atan2(ae.y, ae.x);
    auto point_at = [&](double q1, int branch, Point& c, double& q2) {
      const Point b = m.elbow(0, q1);
      const Point eb = b - e;
      const double dist = norm(eb);
      if (dist == 0.0) return false;
      const Point u = (1.0 / dist) * eb;
      const Point n{-u.y, u.x};
      const double along = (l21 * l21 - L * L + dist * dist) / (2.0 * dist);
      const double h = std::sqrt(std::max(0.0, (l21 - along) * (l21 + along)));
      const Point d = e + along * u + (branch * h) * n;
      q2 = std::atan2(d.y - e.y, d.x - e.x);
      if (between || l12 > l22) {
        c = b + (l12 / L) * (d - b);
      } else {
        c = d + (l22 / L) * (b - d);
      }
      return true;
    };
    auto loop_over = [&](double lo, double hi, bool turning) {
      std::vector<Sample> loop;
      const int n = samples / (turning ? 2 : 1);
      for (int branch : {1, -1}) {
        std::vector<Sample> half;
        for (int k = 0; k < n; ++k) {
          double q1;
          if (turning) {
            // Cluster samples at the turning points (where dq2/dq1 is infinite).
            const double s = static_cast<double>(k) / (n - 1);
            q1 = 0.5 * (lo + hi) - 0.5 * (hi - lo) * std::cos(pi * s);
          } else {
            q1 = lo + (hi - lo) * k / n;
          }
          Point c;
          double q2;
          if (point_at(q1, branch, c, q2)) half.push_back({c, keep(c, q1, q2)});
        }
        if (!turning) {
          split_closed(half, out);
          continue;
        }
        if (branch < 0) std::reverse(half.begin(), half.end());
        // Drop the duplicated turning points when joining the two branches.
        if (branch < 0 && !half.empty()) half.erase(half.begin());
        if (branch < 0 && !half.empty()) half.pop_back();
        loop.insert(loop.end(), half.begin(), half.end());
      }
      if (turning) split_closed(loop, out);
    };
    if (chi < -1.0 || clo > 1.0) return;
    if (clo <= -1.0 && chi >= 1.0) {
      loop_over(0.0, two_pi, false);
    } else if (clo <= -1.0) {
      const double t = std::acos(chi);
      loop_over(ang + t, ang + two_pi - t, true);
    } else if (chi >= 1.0) {
      const double t = std::acos(clo);
      loop_over(ang - t, ang + t, true);
    } else {
      const double t1 = std::acos(chi), t2 = std::acos(clo);
      loop_over(ang + t1, ang + t2, true);
      loop_over(ang - t2, ang - t1, true);
    }
  };
  trace(l12 + l22, true);
  if (l12 != l22) {
    trace(std::abs(l12 - l22), false);
  } else {
    // Equal distal links folded onto each other: B = D at an intersection P of
    // the crank circles, and C anywhere on the circle of radius l12 about P.
    const Point ea = e - a;
    const double dist = norm(ea);
    if (dist > 0.0) {
      const Point u = (1.0 / dist) * ea;
      const Point n{-u.y, u.x};
      const double along = (l11 * l11 - l21 * l21 + dist * dist) / (2.0 * dist);
      const double h2 = (l11 - along) * (l11 + along);
      if (h2 >= 0.0) {
        for (int branch : {1, -1}) {
          const Point p = a + along * u + (branch * std::sqrt(h2)) * n;
          const double q1 = std::atan2(p.y - a.y, p.x - a.x), q2 = std::atan2(p.y - e.y, p.x - e.x);
          std::vector<Sample> loop;
          for (int k = 0; k < samples; ++k) {
            const Point c = p + l12 * unit(two_pi * k / samples);
            loop.push_back({c, keep(c, q1, q2)});
          }
          split_closed(loop, out);
          if (h2 == 0.0) break;
        }
      }
    }
  }
  return out;
}

}  // namespace pkmws::mechanisms
