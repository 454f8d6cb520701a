// MOMA ([Vasilic]): inverse kinematics eq. 5-6, robust direct kinematics, the
// paper's closed form eq. 9-12 as a cross-check, Jacobians, singularities,
// pressure angle and the exact workspace (intersection of two leg bands).
#include "mechanisms/common.hpp"
#include "mechanisms/moma/moma.hpp"

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
using detail::mode_label;

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();
constexpr double rad2deg = 180.0 / std::numbers::pi;
// Relative tolerance of the singularity tests (|B_ii| <= tol l_i, |det A| <= tol l1 l2)
// and of the branch side in direct() (|a_i . (P - S_i)| <= tol l_i counts as either side).
constexpr double singular_tol = 1e-9;
// inverse() accepts p_i up to this fraction of the stroke outside it, so that a
// DK pose at p = stroke_min round-trips; reachable() (the grid test) is strict.
constexpr double stroke_tol = 1e-12;

}  // namespace

Moma::Moma(std::array<MomaLeg, 2> legs) : legs_(legs) {
  for (int i = 0; i < 2; ++i) {
    const MomaLeg& l = legs_[i];
    const std::string leg = "leg " + std::to_string(i + 1) + ": ";
    if (!(l.rod_length > 0.0) || !std::isfinite(l.rod_length)) {
      throw std::invalid_argument(leg + "rod length must be positive");
    }
    if (!(l.stroke_min < l.stroke_max) || !std::isfinite(l.stroke_min) || !std::isfinite(l.stroke_max)) {
      throw std::invalid_argument(leg + "stroke must be [min, max] with min < max");
    }
    if (l.branch != 1 && l.branch != -1) throw std::invalid_argument(leg + "branch must be -1 or 1");
    if (!std::isfinite(l.guide_angle) || !std::isfinite(l.reference.x) || !std::isfinite(l.reference.y)) {
      throw std::invalid_argument(leg + "non-finite guide");
    }
  }
}

Point Moma::guide_direction(int leg) const {
  // The same rational direction the exact workspace uses (docs/theory/regions.md).
  return geometry::rational_direction(legs_[leg].guide_angle).unit();
}

Point Moma::slider(int leg, double p) const {
  return legs_[leg].reference + p * guide_direction(leg);
}

std::optional<double> Moma::inverse_leg(int leg, Point p, int branch) const {
  const MomaLeg& l = legs_[leg];
  const Point a = guide_direction(leg);
  const Point w = p - l.reference;
  const double b = dot(a, w);  // [Vasilic] eq. 6: B_i = a_i . (P - R_i)
  // B^2 - C = l^2 - (a x w)^2 (eq. 5's discriminant, in a cancellation-free form)
  const double across = std::abs(cross(a, w));
  const double disc = (l.rod_length - across) * (l.rod_length + across);
  if (disc < 0.0) return std::nullopt;
  return b + branch * std::sqrt(disc);  // [Vasilic] eq. 5 (branch -1), other root (+1)
}

std::vector<MomaAssembly> Moma::direct_all(double p1, double p2) const {
  // Circle-circle intersection of |P - S1| = l1 and |P - S2| = l2 ([Vasilic]
  // eq. 7-8 are these two circles). No division by v4 - v1: the construction
  // works along the centre line S1S2 in its own frame (e, n).
  const Point s1 = slider(0, p1), s2 = slider(1, p2);
  const double l1 = legs_[0].rod_length, l2 = legs_[1].rod_length;
  const Point d = s2 - s1;
  const double dist = norm(d);
  std::vector<MomaAssembly> out;
  // Coincident centres: no solution (l1 != l2) or a whole circle of them
  // (l1 == l2, the rods can spin together): no isolated assembly mode either way.
  if (!(dist > 0.0) || !std::isfinite(dist)) return out;
  const Point e = (1.0 / dist) * d;
  const Point n{-e.y, e.x};  // left of S1 -> S2: cross(S2 - S1, n) > 0
  // Foot of the common chord on S1S2 and the squared half chord (mm, mm^2).
  const double along = (l1 * l1 - l2 * l2 + dist * dist) / (2.0 * dist);
  const double h2 = (l1 - along) * (l1 + along);
  // h2 carries a rounding error of a few ulp of l1^2 + l2^2 + dist^2; within
  // that the circles are tangent (rods aligned: a type-2 singular pose).
  const double tangency = 16.0 * std::numeric_limits<double>::epsilon() * (l1 * l1 + l2 * l2 + dist * dist);
  if (h2 < -tangency) return out;
  if (h2 <= tangency) {
    out.push_back({s1 + along * e, 0});
    return out;
  }
  const double h = std::sqrt(h2);
  out.push_back({s1 + along * e + h * n, 1});
  out.push_back({s1 + along * e - h * n, -1});
  return out;
}

std::optional<Point> Moma::direct_closed_form(double p1, double p2, int sign) const {
  const Point a1 = guide_direction(0), a2 = guide_direction(1);
  const Point r1 = legs_[0].reference, r2 = legs_[1].reference;
  const double l1 = legs_[0].rod_length, l2 = legs_[1].rod_length;
  // [Vasilic] eq. 11
  const double v1 = 2.0 * (p1 * a1.x + r1.x);
  const double v2 = 2.0 * (p1 * a1.y + r1.y);
  const double v3 = p1 * p1 + 2.0 * p1 * (a1.x * r1.x + a1.y * r1.y) - l1 * l1 + r1.x * r1.x + r1.y * r1.y;
  const double v4 = 2.0 * (p2 * a2.x + r2.x);
  const double v5 = 2.0 * (p2 * a2.y + r2.y);
  const double v6 = p2 * p2 + 2.0 * p2 * (a2.x * r2.x + a2.y * r2.y) - l2 * l2 + r2.x * r2.x + r2.y * r2.y;
  // [Vasilic] eq. 12: undefined where v4 = v1 (sliders on one vertical line)
  const double denom = v4 - v1;
  if (std::abs(denom) <= 1e-12 * (std::abs(v4) + std::abs(v1) + 1.0)) return std::nullopt;
  const double v7 = (v6 - v3) / denom;
  const double v8 = (v2 - v5) / denom;
  const double v9 = 1.0 + v8 * v8;
  const double v10 = 2.0 * v7 * v8 - v1 * v8 - v2;
  const double v11 = v7 * v7 - v1 * v7 + v3;
  const double disc = v10 * v10 - 4.0 * v9 * v11;
  if (disc < 0.0) return std::nullopt;
  const double y = (-v10 + sign * std::sqrt(disc)) / (2.0 * v9);  // [Vasilic] eq. 10
  return Point{v7 + y * v8, y};                                   // [Vasilic] eq. 9
}

MomaJacobians Moma::jacobians(Point p, double p1, double p2) const {
  // d/dt of [Vasilic] eq. 3: (P - S_i) . dP = ((P - S_i) . a_i) dp_i
  MomaJacobians j;
  for (int i = 0; i < 2; ++i) {
    const Point w = p - slider(i, i == 0 ? p1 : p2);
    j.A(i, 0) = w.x;
    j.A(i, 1) = w.y;
  }
  j.B.setZero();
  j.B(0, 0) = dot(p - slider(0, p1), guide_direction(0));
  j.B(1, 1) = dot(p - slider(1, p2), guide_direction(1));
  return j;
}

std::vector<JointInfo> Moma::joints() const {
  return {{"p1", false, std::array{legs_[0].stroke_min, legs_[0].stroke_max}},
          {"p2", false, std::array{legs_[1].stroke_min, legs_[1].stroke_max}}};
}

namespace {

struct ModeIk {
  int b1, b2;
  std::optional<double> p1, p2;
};

}  // namespace

std::vector<JointSolution> Moma::inverse(const Pose& pose) const {
  const Point p{pose.x, pose.y};
  const int f1 = legs_[0].branch, f2 = legs_[1].branch;
  // The file's working mode first, then the other three branch combinations.
  const int combos[4][2] = {{f1, f2}, {f1, -f2}, {-f1, f2}, {-f1, -f2}};
  std::vector<JointSolution> out;
  for (const auto& c : combos) {
    JointSolution s;
    s.mode = mode_label(c[0], c[1]);
    const auto q1 = inverse_leg(0, p, c[0]);
    const auto q2 = inverse_leg(1, p, c[1]);
    if (!q1 || !q2) {
      s.reason = std::string("rod ") + (!q1 ? "1" : "2") + " cannot reach the point";
      out.push_back(s);
      continue;
    }
    s.joints = {*q1, *q2};
    for (int i = 0; i < 2; ++i) {
      const MomaLeg& l = legs_[i];
      const double tol = stroke_tol * std::max(l.stroke_max - l.stroke_min, std::abs(l.stroke_max) + std::abs(l.stroke_min));
      if (s.joints[i] < l.stroke_min - tol || s.joints[i] > l.stroke_max + tol) {
        s.reason = "p" + std::to_string(i + 1) + " = " + format_number(s.joints[i]) + " outside stroke [" +
                   format_number(l.stroke_min) + ", " + format_number(l.stroke_max) + "]";
        break;
      }
    }
    if (s.reason.empty() && (c[0] != f1 || c[1] != f2)) {
      s.reason = "within the strokes, but another working mode than the file's branches " + mode_label(f1, f2);
    }
    s.valid = s.reason.empty();
    out.push_back(s);
  }
  return out;
}

std::vector<PoseSolution> Moma::direct(std::span<const double> q) const {
  if (q.size() != 2) throw std::invalid_argument("moma: direct kinematics needs p1 and p2");
  std::vector<PoseSolution> out;
  for (const MomaAssembly& a : direct_all(q[0], q[1])) {
    PoseSolution s;
    s.mode = std::string(1, detail::mode_sign(a.sign));
    s.pose = {a.platform.x, a.platform.y, 0.0};
    // Strokes first (they do not depend on the assembly mode), then the branch side.
    for (int i = 0; i < 2 && s.reason.empty(); ++i) {
      const MomaLeg& l = legs_[i];
      if (!(q[i] >= l.stroke_min && q[i] <= l.stroke_max)) {
        s.reason = "p" + std::to_string(i + 1) + " = " + format_number(q[i]) + " outside stroke [" +
                   format_number(l.stroke_min) + ", " + format_number(l.stroke_max) + "]";
      }
    }
    for (int i = 0; i < 2 && s.reason.empty(); ++i) {
      const MomaLeg& l = legs_[i];
      // Branch -1 (eq. 5) keeps P ahead of the slider, a . (P - S) >= 0; +1 behind.
      const double ahead = dot(a.platform - slider(i, q[i]), guide_direction(i));
      if (-l.branch * ahead < -singular_tol * l.rod_length) {
        s.reason = "rod " + std::to_string(i + 1) + " is on the other branch than the file's (" +
                   std::to_string(l.branch) + "): the platform is " + (ahead > 0 ? "ahead of" : "behind") +
                   " slider " + std::to_string(i + 1);
      }
    }
    s.valid = s.reason.empty();
    out.push_back(s);
  }
  return out;
}

std::vector<Evaluation> Moma::evaluate(const Pose& pose, const Criteria& criteria) const {
  const Point p{pose.x, pose.y};
  std::vector<Evaluation> out;
  for (const JointSolution& s : inverse(pose)) {
    Evaluation e = detail::start_evaluation(s, 2);
    if (s.joints.size() != 2) {
      out.push_back(e);
      continue;
    }
    const MomaJacobians j = jacobians(p, s.joints[0], s.joints[1]);
    const double l1 = legs_[0].rod_length, l2 = legs_[1].rod_length;
    const bool type1 = std::abs(j.B(0, 0)) <= singular_tol * l1 || std::abs(j.B(1, 1)) <= singular_tol * l2;
    const double det_a = j.A.determinant();
    const bool type2 = std::abs(det_a) <= singular_tol * l1 * l2;
    e.singular = type1 || type2;
    e.singularity = type1 && type2 ? "both" : type1 ? "type1" : type2 ? "type2" : "";
    // dq = B^-1 A dP: the inverse-kinematic Jacobian.
    detail::set_velocity_figures(e, j.B.inverse() * j.A, type1, type2);
    const double sin_eps = std::abs(det_a) / (l1 * l2);
    detail::set_point_platform_transmission(e, sin_eps, criteria);
    e.extra.push_back({"transmission_angle_deg", std::asin(std::min(1.0, sin_eps)) * rad2deg});
    out.push_back(e);
  }
  return out;
}

geometry::Region Moma::workspace() const {
  geometry::Region ws;
  for (int i = 0; i < 2; ++i) {
    const MomaLeg& l = legs_[i];
    // Branch -1 (eq. 5) puts P ahead of the slider: band side +1.
    const geometry::Region band = geometry::band(slider(i, l.stroke_min), l.guide_angle,
                                                 l.stroke_max - l.stroke_min, l.rod_length, -l.branch);
    ws = i == 0 ? band : ws.intersect(band);
  }
  return ws;
}

bool Moma::reachable(const Pose& pose) const {
  const Point p{pose.x, pose.y};
  for (int i = 0; i < 2; ++i) {
    const MomaLeg& l = legs_[i];
    const auto q = inverse_leg(i, p, l.branch);
    if (!q || *q < l.stroke_min || *q > l.stroke_max) return false;
  }
  return true;
}

Drawing Moma::draw(const Pose& pose) const {
  // Each slider where the file's branch puts it; if that is off the stroke,
  // where the other root of the leg's equation puts it (a pose of another
  // assembly mode), so that the rod drawn has the rod's length.
  const Point p{pose.x, pose.y};
  std::array<double, 2> q{};
  for (int i = 0; i < 2; ++i) {
    const MomaLeg& l = legs_[i];
    auto in_stroke = [&](const std::optional<double>& v) { return v && *v >= l.stroke_min && *v <= l.stroke_max; };
    const auto own = inverse_leg(i, p, l.branch);
    const auto other = inverse_leg(i, p, -l.branch);
    q[static_cast<std::size_t>(i)] = in_stroke(own) ? *own
                                     : in_stroke(other) ? *other
                                     : own ? std::clamp(*own, l.stroke_min, l.stroke_max)
                                           : 0.5 * (l.stroke_min + l.stroke_max);
  }
  return draw_with_joints(pose, q);
}

Drawing Moma::draw_with_joints(const Pose& pose, std::span<const double> joints) const {
  Drawing d;
  const Point p{pose.x, pose.y};
  d.tool = p;
  for (int i = 0; i < 2; ++i) {
    const MomaLeg& l = legs_[i];
    d.guides.push_back({slider(i, l.stroke_min), slider(i, l.stroke_max)});
    d.base_points.push_back(l.reference);
    const double at = static_cast<std::size_t>(i) < joints.size() ? joints[static_cast<std::size_t>(i)]
                                                                   : 0.5 * (l.stroke_min + l.stroke_max);
    const Point s = slider(i, at);
    d.sliders.push_back(s);
    d.joints.push_back(s);
    // The rod only when it closes (|P - S| = l to 1e-7 of the rod).
    if (std::abs(norm(p - s) - l.rod_length) <= 1e-7 * l.rod_length) d.links.push_back({s, p});
  }
  d.joints.push_back(p);
  return d;
}

geometry::Box Moma::bounds() const {
  // Box of each leg's band: the half disk of radius l on the side v = -branch a
  // of the slider has, per coordinate k, the extent S_k + l if v_k >= 0 else
  // S_k + l |n_k| upwards (n the normal to v; v_k^2 + n_k^2 = 1), and the mirror
  // downwards. The band is the union over the slider positions, i.e. over the
  // two ends. The workspace lies in the intersection of the two legs' boxes,
  // padded by a few ulp-scale units for the rounding of the exact boundary.
  geometry::Box boxes[2];
  double scale = 0.0;
  for (int i = 0; i < 2; ++i) {
    const MomaLeg& l = legs_[i];
    const Point a = guide_direction(i);
    const Point v = double(-l.branch) * a;
    const double up_x = v.x >= 0.0 ? l.rod_length : l.rod_length * std::abs(v.y);
    const double down_x = v.x <= 0.0 ? l.rod_length : l.rod_length * std::abs(v.y);
    const double up_y = v.y >= 0.0 ? l.rod_length : l.rod_length * std::abs(v.x);
    const double down_y = v.y <= 0.0 ? l.rod_length : l.rod_length * std::abs(v.x);
    for (const Point s : {slider(i, l.stroke_min), slider(i, l.stroke_max)}) {
      boxes[i].expand(Point{s.x - down_x, s.y - down_y});
      boxes[i].expand(Point{s.x + up_x, s.y + up_y});
      scale = std::max({scale, std::abs(s.x) + l.rod_length, std::abs(s.y) + l.rod_length});
    }
  }
  geometry::Box b;
  b.min = {std::max(boxes[0].min.x, boxes[1].min.x), std::max(boxes[0].min.y, boxes[1].min.y)};
  b.max = {std::min(boxes[0].max.x, boxes[1].max.x), std::min(boxes[0].max.y, boxes[1].max.y)};
  if (b.empty()) {
    // Disjoint bands: empty workspace; still return a box that shows both legs.
    b = boxes[0];
    b.expand(boxes[1]);
  }
  const double pad = 1e-9 * scale;
  b.min = {b.min.x - pad, b.min.y - pad};
  b.max = {b.max.x + pad, b.max.y + pad};
  return b;
}

std::vector<GuidedRodLegs::Leg> Moma::guided_rod_legs() const {
  std::vector<GuidedRodLegs::Leg> out;
  for (int i = 0; i < 2; ++i) {
    const MomaLeg& leg = legs_[static_cast<std::size_t>(i)];
    // the rational direction the exact workspace uses
    out.push_back({leg.reference, guide_direction(i), leg.rod_length, leg.branch, leg.stroke_min, leg.stroke_max});
  }
  return out;
}

}  // namespace pkmws::mechanisms
