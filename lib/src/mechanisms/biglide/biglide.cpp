// Biglide ([Strutynskyi]): simplified and real schemes; IK eq. 5-8, DK eq. 1-4,
// zero position eq. 9, velocity ratio V/V_y (fig. 8), Jacobians, statics, and
// the exact workspace of the simplified scheme (two leg bands).
#include "mechanisms/common.hpp"
#include "mechanisms/biglide/biglide.hpp"

#include <boost/numeric/interval.hpp>

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
using detail::rotate;
using detail::mode_label;

namespace {

constexpr double pi = std::numbers::pi;
constexpr double rad2deg = 180.0 / pi;
constexpr double inf = std::numeric_limits<double>::infinity();
constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double singular_tol = 1e-9;
constexpr int paper_branch = -1;  // eq. 5-8 take the minus roots


// sqrt(l² - h²) without cancellation; negative when |h| > l.
double leg_reach(double l, double h) {
  const double ah = std::abs(h);
  const double disc = (l - ah) * (l + ah);
  return disc < 0.0 ? -1.0 : std::sqrt(disc);
}

}  // namespace

Biglide::Biglide(BiglideParams p) : params_(p) {
  const double b = params_.half_width;
  if (!(b > 0.0) || !std::isfinite(b)) throw std::invalid_argument("biglide: half width B must be positive");
  if (!(params_.meters_per_unit > 0.0)) throw std::invalid_argument("biglide: bad length unit");
  for (int i = 0; i < 2; ++i) {
    const std::string leg = "biglide: leg " + std::to_string(i + 1) + ": ";
    const double l = params_.rods[i];
    if (!(l > 0.0) || !std::isfinite(l)) throw std::invalid_argument(leg + "rod length must be positive");
    const auto& s = params_.strokes[i];
    if (!std::isfinite(s[0]) || !std::isfinite(s[1]) || !(s[0] < s[1])) {
      throw std::invalid_argument(leg + "stroke must be [min, max] with min < max");
    }
  }
  if (params_.tool) {
    const double l1 = params_.rods[0], l3 = params_.tool->l3, l4 = params_.tool->l4;
    if (!(l3 > 0.0) || !std::isfinite(l3)) throw std::invalid_argument("biglide: tool l3 must be positive");
    if (!(l4 >= 0.0) || !std::isfinite(l4)) throw std::invalid_argument("biglide: tool l4 must not be negative");
    const double slack = 1e-12 * (l1 + l3 + l4);
    if (l4 > l1 + l3 + slack || l4 < std::abs(l1 - l3) - slack) {
      throw std::invalid_argument("biglide: the tool triangle needs |l1 - l3| <= l4 <= l1 + l3");
    }
  }
}

double Biglide::tool_distance() const { return params_.tool ? params_.tool->l3 : params_.rods[0]; }

double Biglide::gamma() const {
  if (!params_.tool) return 0.0;
  const double l1 = params_.rods[0], l3 = params_.tool->l3, l4 = params_.tool->l4;
  // Law of cosines in the triangle S_1 J T ([Strutynskyi] eq. 3-4, 9).
  return std::acos(std::clamp((l1 * l1 + l3 * l3 - l4 * l4) / (2.0 * l1 * l3), -1.0, 1.0));
}

Point Biglide::slider(int i, double q) const { return {q, i == 0 ? -params_.half_width : params_.half_width}; }

Point Biglide::joint_of(Point tool, double q1) const {
  // J is T turned by +γ (counter-clockwise) about S_1 and scaled by l_1 / l_3:
  // eq. 3-4 put T at the paper's angle φ + γ (clockwise from +y) when J is at φ.
  const Point s1 = slider(0, q1);
  return s1 + (params_.rods[0] / tool_distance()) * rotate(tool - s1, gamma());
}

std::optional<std::array<double, 2>> Biglide::inverse_joints(Point t, int b1, int b2) const {
  const double b = params_.half_width;
  const double w1 = leg_reach(tool_distance(), t.y + b);
  if (w1 < 0.0) return std::nullopt;
  const double q1 = t.x + b1 * w1;  // [Strutynskyi] eq. 5 / eq. 7 (b1 = -1)
  const Point j = joint_of(t, q1);
  const double w2 = leg_reach(params_.rods[1], b - j.y);
  if (w2 < 0.0) return std::nullopt;
  const double q2 = j.x + b2 * w2;  // [Strutynskyi] eq. 6 / eq. 8 (b2 = -1)
  return std::array<double, 2>{q1, q2};
}

std::optional<std::array<double, 2>> Biglide::inverse_closed_form(Point t, bool as_printed) const {
  const double b = params_.half_width, x = t.x, y = t.y;
  const double l1 = params_.rods[0], l2 = params_.rods[1];
  if (!params_.tool) {
    const double r1 = l1 * l1 - (b + y) * (b + y), r2 = l2 * l2 - (b - y) * (b - y);
    if (r1 < 0.0 || r2 < 0.0) return std::nullopt;
    return std::array<double, 2>{x - std::sqrt(r1), x - std::sqrt(r2)};  // [Strutynskyi] eq. 5-6
  }
  const double l3 = params_.tool->l3, l4 = params_.tool->l4;
  if (!(l4 > 0.0)) return std::nullopt;
  const double r1 = l3 * l3 - (b + y) * (b + y);
  if (r1 < 0.0 || std::abs((b + y) / l3) > 1.0) return std::nullopt;
  const double q1 = x - std::sqrt(r1);  // [Strutynskyi] eq. 7
  const double psi = std::acos((b + y) / l3);
  const double delta = std::acos(std::clamp((l3 * l3 + l4 * l4 - l1 * l1) / (2.0 * l3 * l4), -1.0, 1.0));
  // [Strutynskyi] eq. 8: q2 = x - sqrt(l2² - [B - y - l4 sin(ψ - π/2 + δ)]²) - l4 cos(ψ ∓ δ - π/2),
  // printed with -δ in the last term; the geometry of eq. 3-4 gives +δ.
  const double h = b - y - l4 * std::sin(psi - pi / 2 + delta);
  const double r2 = l2 * l2 - h * h;
  if (r2 < 0.0) return std::nullopt;
  const double last = as_printed ? l4 * std::cos(psi - delta - pi / 2) : l4 * std::cos(psi + delta - pi / 2);
  return std::array<double, 2>{q1, x - std::sqrt(r2) - last};
}

std::vector<BiglideAssembly> Biglide::direct_all(double q1, double q2) const {
  const Point s1 = slider(0, q1), s2 = slider(1, q2);
  const double l1 = params_.rods[0], l2 = params_.rods[1];
  const Point d = s2 - s1;
  const double dist = norm(d);  // >= 2B > 0
  const Point e = (1.0 / dist) * d;
  const Point n{-e.y, e.x};
  const double along = (l1 * l1 - l2 * l2 + dist * dist) / (2.0 * dist);
  const double h2 = (l1 - along) * (l1 + along);
  const double scale = std::max(l1, l2);
  std::vector<BiglideAssembly> out;
  if (h2 < -singular_tol * scale * scale) return out;
  // T from J on the rigid triangle: T - S_1 = (l_3 / l_1) R(-γ) (J - S_1).
  auto tool_of = [&](Point j) { return s1 + (tool_distance() / l1) * rotate(j - s1, -gamma()); };
  if (h2 <= singular_tol * scale * scale) {
    const Point j = s1 + along * e;
    out.push_back({tool_of(j), j, 0});
    return out;
  }
  const double h = std::sqrt(h2);
  for (int sign : {-1, 1}) {  // the paper's assembly mode (J on the +x side of S_1 S_2) first
    const Point j = s1 + along * e + (sign * h) * n;
    out.push_back({tool_of(j), j, sign});
  }
  return out;
}

std::optional<Point> Biglide::direct_closed_form(double q1, double q2) const {
  const double b = params_.half_width, l1 = params_.rods[0], l2 = params_.rods[1];
  const double dq = q1 - q2;
  const double dist2 = 4.0 * b * b + dq * dq;
  const double c = (dist2 + l1 * l1 - l2 * l2) / (2.0 * l1 * std::sqrt(dist2));
  if (!(std::abs(c) <= 1.0)) return std::nullopt;
  const double phi = std::acos(c) - std::atan(dq / (2.0 * b)) + gamma();
  const double l = tool_distance();
  return Point{l * std::sin(phi) + q1, l * std::cos(phi) - b};  // [Strutynskyi] eq. 1-2 (γ = 0) / eq. 3-4
}

Eigen::Matrix2d Biglide::inverse_jacobian(Point t, int b1, int b2) const {
  const double b = params_.half_width;
  const double h1 = t.y + b;
  const double w1 = leg_reach(tool_distance(), h1);
  Eigen::Matrix2d jq;
  jq.setConstant(nan);
  if (w1 < 0.0) return jq;
  // Leg 1: q1 = x + b1 w1, w1 = sqrt(l3² - (y + B)²).
  const double dq1_dy = w1 > 0.0 ? -b1 * h1 / w1 : inf;
  // v = T - S_1 = (-b1 w1, y + B): dv/dx = 0, dv/dy = (b1 h1 / w1, 1).
  const Point dv_dy{w1 > 0.0 ? b1 * h1 / w1 : inf, 1.0};
  const Point m_dv = (params_.rods[0] / tool_distance()) * rotate(dv_dy, gamma());
  // J = S_1 + M v: dJ/dx = (1, 0); dJ/dy = (dq1/dy, 0) + M dv/dy.
  const Point dj_dy{dq1_dy + m_dv.x, m_dv.y};
  const double q1 = t.x + b1 * w1;
  const Point j = joint_of(t, q1);
  const double h2 = b - j.y;
  const double w2 = leg_reach(params_.rods[1], h2);
  if (w2 < 0.0) return jq;
  // Leg 2: q2 = J_x + b2 w2, w2 = sqrt(l2² - (B - J_y)²), dw2 = (B - J_y) dJ_y / w2.
  jq(0, 0) = 1.0;
  jq(0, 1) = dq1_dy;
  jq(1, 0) = 1.0;
  jq(1, 1) = w2 > 0.0 ? dj_dy.x + b2 * h2 * dj_dy.y / w2 : inf;
  return jq;
}

std::array<double, 2> Biglide::velocity_ratio_y(Point t) const {
  const Eigen::Matrix2d jq = inverse_jacobian(t, paper_branch, paper_branch);
  return {std::abs(jq(0, 1)), std::abs(jq(1, 1))};
}

double Biglide::zero_position_rod_length(double b, double l1, double l3, double l4) {
  const double gamma = std::acos(std::clamp((l1 * l1 + l3 * l3 - l4 * l4) / (2.0 * l1 * l3), -1.0, 1.0));
  // Angle at S_1 between S_1 S_2 (+y) and S_1 J at q1 = q2 with T on y = 0:
  // T is at acos(B / l3) from +y, J at acos(B / l3) - γ ([Strutynskyi] eq. 9, corrected sign).
  const double phi0 = std::acos(b / l3) - gamma;
  return std::sqrt(4.0 * b * b + l1 * l1 - 4.0 * b * l1 * std::cos(phi0));
}

double Biglide::zero_position_rod_length_as_printed(double b, double l1, double l3, double l4) {
  const double gamma = std::acos(std::clamp((l1 * l1 + l3 * l3 - l4 * l4) / (2.0 * l1 * l3), -1.0, 1.0));
  return std::sqrt(4.0 * b * b + l1 * l1 - 4.0 * b * l1 * std::cos(pi / 2 - (gamma - std::asin(b / l3))));  // eq. 9
}

// ---------------------------------------------------------------------------
// Mechanism

std::vector<JointInfo> Biglide::joints() const {
  return {{"q1", false, params_.strokes[0]}, {"q2", false, params_.strokes[1]}};
}

std::string Biglide::stroke_problem(int i, double q) const {
  const auto& s = params_.strokes[i];
  const double tol = singular_tol * (s[1] - s[0]);
  if (q < s[0] - tol || q > s[1] + tol) {
    return "q" + std::to_string(i + 1) + " = " + format_number(q) + " outside stroke [" + format_number(s[0]) + ", " + format_number(s[1]) + "]";
  }
  return "";
}

std::vector<JointSolution> Biglide::inverse(const Pose& pose) const {
  const Point t{pose.x, pose.y};
  const int f = paper_branch;
  const int combos[4][2] = {{f, f}, {f, -f}, {-f, f}, {-f, -f}};
  std::vector<JointSolution> out;
  for (const auto& c : combos) {
    JointSolution s;
    s.mode = mode_label(c[0], c[1]);
    const auto q = inverse_joints(t, c[0], c[1]);
    if (!q) {
      s.reason = "a link cannot reach the point";
    } else {
      s.joints = {(*q)[0], (*q)[1]};
      for (int i = 0; i < 2 && s.reason.empty(); ++i) s.reason = stroke_problem(i, (*q)[i]);
      if (s.reason.empty() && (c[0] != f || c[1] != f)) {
        s.reason = "within the strokes, but not the paper's working mode " + mode_label(f, f) + " (eq. 5-8)";
      }
    }
    s.valid = s.reason.empty();
    out.push_back(s);
  }
  return out;
}

std::vector<PoseSolution> Biglide::direct(std::span<const double> q) const {
  if (q.size() != 2) throw std::invalid_argument("biglide: direct kinematics needs q1 and q2");
  std::vector<PoseSolution> out;
  for (const BiglideAssembly& a : direct_all(q[0], q[1])) {
    PoseSolution s;
    s.mode = std::string(1, detail::mode_sign(a.sign));
    s.pose = {a.tool.x, a.tool.y, 0.0};
    s.platform_points = {a.joint};
    for (int i = 0; i < 2 && s.reason.empty(); ++i) s.reason = stroke_problem(i, q[i]);
    // The paper's branches: the tool ahead of slider 1, J ahead of slider 2.
    const double scale = singular_tol * std::max(tool_distance(), params_.rods[1]);
    if (s.reason.empty() && a.tool.x - q[0] < -scale) s.reason = "the tool is behind slider 1 (not eq. 5/7's branch)";
    if (s.reason.empty() && a.joint.x - q[1] < -scale) s.reason = "rod 2 points behind slider 2 (not eq. 6/8's branch)";
    s.valid = s.reason.empty();
    out.push_back(s);
  }
  return out;
}

std::vector<Evaluation> Biglide::evaluate(const Pose& pose, const Criteria& criteria) const {
  const Point t{pose.x, pose.y};
  const int f = paper_branch;
  const int combos[4][2] = {{f, f}, {f, -f}, {-f, f}, {-f, -f}};
  const auto solutions = inverse(pose);
  std::vector<Evaluation> out;
  for (std::size_t k = 0; k < solutions.size(); ++k) {
    const JointSolution& s = solutions[k];
    Evaluation e = detail::start_evaluation(s, 2);
    if (s.joints.size() != 2) {
      out.push_back(e);
      continue;
    }
    const int b1 = combos[k][0], b2 = combos[k][1];
    const double b = params_.half_width;
    const double l3 = tool_distance(), l2 = params_.rods[1];
    const Point s1 = slider(0, s.joints[0]), s2 = slider(1, s.joints[1]);
    const Point j = joint_of(t, s.joints[0]);
    const double w1 = leg_reach(l3, t.y + b), w2 = leg_reach(l2, b - j.y);
    const bool type1 = w1 <= singular_tol * l3 || w2 <= singular_tol * l2;
    // Rod 2 is a two-force member acting at J; with slider 1 locked J moves
    // perpendicular to S_1 J. ε: angle from S_1 J to rod 2 (S_2 J); for the
    // simplified scheme S_1 J is rod 1 and ε the angle between the rods.
    const Point u1 = j - s1, u2 = j - s2;
    const double sin_eps = cross(u1, u2) / (norm(u1) * norm(u2));
    const bool type2 = std::abs(sin_eps) <= singular_tol;
    e.singular = type1 || type2;
    e.singularity = type1 && type2 ? "both" : type1 ? "type1" : type2 ? "type2" : "";
    const Eigen::Matrix2d jq = inverse_jacobian(t, b1, b2);
    const std::array<double, 2> vy{std::abs(jq(0, 1)), std::abs(jq(1, 1))};
    detail::set_velocity_figures(e, jq, type1, type2);
    if (std::isfinite(*e.velocity_ratio)) {
      e.extra.push_back({"velocity_ratio_worst_direction", *e.velocity_ratio});
      e.velocity_ratio = std::max(vy[0], vy[1]);  // [Strutynskyi] fig. 8: V / V_y
    }
    e.extra.push_back({"V1_over_Vy", vy[0]});
    e.extra.push_back({"V2_over_Vy", vy[1]});
    const double alpha = std::acos(std::min(1.0, std::abs(sin_eps))) * rad2deg;
    e.pressure_angle_deg = {alpha, alpha};
    e.extra.push_back({"transmission_angle_deg", std::asin(std::clamp(sin_eps, -1.0, 1.0)) * rad2deg});
    if (criteria.load) {
      const double f_n = criteria.load->force_N, m = criteria.load->moment_Nm;
      if (!real_scheme()) {
        // Point tool on two two-force rods: R_i = f / |sin ε|; no moment reaches P.
        const double r = std::abs(sin_eps) > 0.0 ? f_n / std::abs(sin_eps) : inf;
        e.reactions_N = {r, r};
      } else {
        // Statics of the triangle S_1 J T (docs/theory/biglide.md): rod 2 carries
        // λ r_2 (r_2 = unit(J - S_2)), the slider joint S_1 the rest. Moments
        // about S_1: λ (J - S_1) x r_2 + (T - S_1) x w + m = 0, with m converted
        // to N x the file's length unit. Reactions in N.
        const double m_unit = m / params_.meters_per_unit;
        const Point r2 = (1.0 / norm(u2)) * u2;
        const double den = cross(u1, r2);
        if (std::abs(den) <= singular_tol * norm(u1)) {
          e.reactions_N = {inf, inf};
        } else {
          const Point ts = t - s1;
          const Point n{-ts.y, ts.x};  // (T - S_1) x w = n . w
          const double rod = (f_n * norm(ts) + std::abs(m_unit)) / std::abs(den);
          // |R_1(w)| = |w - r_2 (n . w ± m) / den|: maximise over the direction of w.
          double best = 0.0;
          for (int sgn : {-1, 1}) {
            auto value = [&](double a) {
              const Point w{f_n * std::cos(a), f_n * std::sin(a)};
              const double lambda = -(dot(n, w) + sgn * m_unit) / den;
              return norm(w + lambda * r2);
            };
            const int steps = 720;
            int arg = 0;
            for (int i = 0; i < steps; ++i) {
              if (value(2 * pi * i / steps) > value(2 * pi * arg / steps)) arg = i;
            }
            double lo = 2 * pi * (arg - 1) / steps, hi = 2 * pi * (arg + 1) / steps;
            for (int it = 0; it < 80; ++it) {  // golden-section refinement
              const double m1 = hi - (hi - lo) * 0.6180339887498949, m2 = lo + (hi - lo) * 0.6180339887498949;
              if (value(m1) < value(m2)) lo = m1; else hi = m2;
            }
            best = std::max(best, value(0.5 * (lo + hi)));
          }
          e.reactions_N = {best, rod};
        }
      }
    }
    out.push_back(e);
  }
  return out;
}

geometry::Region Biglide::workspace() const {
  if (real_scheme()) {
    throw std::runtime_error(
        "biglide (real scheme): the tool workspace is not bounded by arcs and segments only: where "
        "slider 2 stops at a stroke end and slider 1 moves, the tool traces a coupler curve of the "
        "slider-crank formed by rod 2 and the tool triangle (a quartic, neither circle nor line; "
        "docs/theory/biglide.md); its area is certified (workspace_enclosure), and criteria trace it as level sets");
  }
  geometry::Region ws;
  for (int i = 0; i < 2; ++i) {
    const auto& s = params_.strokes[i];
    // The paper's branch (eq. 5-6, minus roots) puts the tool ahead (+x) of the
    // slider: a half circle of radius l_i on the +x side swept along the guide.
    const geometry::Region band =
        geometry::band(slider(i, s[0]), 0.0, s[1] - s[0], params_.rods[i], -paper_branch);
    ws = i == 0 ? band : ws.intersect(band);
  }
  return ws;
}

geometry::Region Biglide::tool_band() const {
  const auto& s = params_.strokes[0];
  return geometry::band(slider(0, s[0]), 0.0, s[1] - s[0], tool_distance(), -paper_branch);
}

certified::CertifiedRegion Biglide::workspace_enclosure(int max_depth) const {
  if (!real_scheme()) return certified::from_exact(workspace());
  using I = boost::numeric::interval<double>;
  const double b = params_.half_width, l2 = params_.rods[1], l3 = tool_distance();
  const auto& st1 = params_.strokes[0];
  const auto& st2 = params_.strokes[1];
  const double bb = static_cast<double>(paper_branch);
  // J = S_1 + M (T - S_1), M = (l_1 / l_3) R(γ); with T - S_1 = (-b1 w1, h1):
  //   J_x = x + b1 w1 (1 - M00) + M01 h1,   J_y = -B - b1 w1 M10 + M11 h1.
  const double k = params_.rods[0] / l3, c = std::cos(gamma()), s = std::sin(gamma());
  const double m00 = k * c, m01 = -k * s, m10 = k * s, m11 = k * c;
  // Leg 1 exactly: T within l_3 of slider 1, ahead of it (the paper's branch).
  const geometry::Region band1 = tool_band();
  // The cell test: for every T in the box, is the chain closed with q_2 in its
  // stroke? (Leg 1's own conditions are exact in band1; they are re-checked
  // here only to bound w1.)
  auto test = [=](const geometry::Box& box) {
    const I x(box.min.x, box.max.x), y(box.min.y, box.max.y);
    const I h1 = y + b;
    if (h1.lower() > l3 || h1.upper() < -l3) return certified::CellState::outside;
    bool partial = !(h1.lower() >= -l3 && h1.upper() <= l3);
    const I h1c = boost::numeric::intersect(h1, I(-l3, l3));
    I r1 = I(l3) * I(l3) - boost::numeric::square(h1c);
    r1 = I(std::max(0.0, r1.lower()), std::max(0.0, r1.upper()));
    const I w1 = boost::numeric::sqrt(r1);
    const I q1 = x + bb * w1;
    if (q1.upper() < st1[0] || q1.lower() > st1[1]) return certified::CellState::outside;
    const I jx = x + (bb * (1.0 - m00)) * w1 + m01 * h1c;
    const I jy = -b - (bb * m10) * w1 + m11 * h1c;
    const I h2 = b - jy;
    if (h2.lower() > l2 || h2.upper() < -l2) return certified::CellState::outside;
    partial = partial || !(h2.lower() >= -l2 && h2.upper() <= l2);
    const I h2c = boost::numeric::intersect(h2, I(-l2, l2));
    I r2 = I(l2) * I(l2) - boost::numeric::square(h2c);
    r2 = I(std::max(0.0, r2.lower()), std::max(0.0, r2.upper()));
    const I q2 = jx + bb * boost::numeric::sqrt(r2);
    if (q2.upper() < st2[0] || q2.lower() > st2[1]) return certified::CellState::outside;
    const bool inside = !partial && q1.lower() >= st1[0] && q1.upper() <= st1[1] && q2.lower() >= st2[0] &&
                        q2.upper() <= st2[1];
    return inside ? certified::CellState::inside : certified::CellState::undecided;
  };
  certified::CellOptions options;
  options.window = bounds();
  options.base = 16;
  options.max_depth = max_depth;
  return certified::certify(test, band1, options);
}

bool Biglide::reachable(const Pose& pose) const {
  const auto q = inverse_joints({pose.x, pose.y}, paper_branch, paper_branch);
  return q && stroke_problem(0, (*q)[0]).empty() && stroke_problem(1, (*q)[1]).empty();
}

Drawing Biglide::draw(const Pose& pose) const {
  Drawing d;
  const Point t{pose.x, pose.y};
  d.tool = t;
  for (int i = 0; i < 2; ++i) {
    const auto& s = params_.strokes[i];
    d.guides.push_back({slider(i, s[0]), slider(i, s[1])});
  }
  const auto q = inverse_joints(t, paper_branch, paper_branch);
  double q1 = 0.5 * (params_.strokes[0][0] + params_.strokes[0][1]);
  double q2 = 0.5 * (params_.strokes[1][0] + params_.strokes[1][1]);
  if (q) {
    q1 = std::clamp((*q)[0], params_.strokes[0][0], params_.strokes[0][1]);
    q2 = std::clamp((*q)[1], params_.strokes[1][0], params_.strokes[1][1]);
  }
  const Point s1 = slider(0, q1), s2 = slider(1, q2);
  d.sliders = {s1, s2};
  d.joints = {s1, s2};
  if (q) {
    const Point j = joint_of(t, (*q)[0]);
    d.links.push_back({s1, j});
    d.links.push_back({s2, j});
    if (real_scheme()) {
      d.links.push_back({s1, t});
      d.links.push_back({j, t});
      d.joints.push_back(j);
    }
  }
  d.joints.push_back(t);
  return d;
}

geometry::Box Biglide::bounds() const {
  const double b = params_.half_width, l2 = params_.rods[1];
  const auto& s1 = params_.strokes[0];
  const auto& s2 = params_.strokes[1];
  // Tool ahead of slider 1 within l3; J ahead of slider 2 within l2, T within l4 of J.
  const double l3 = tool_distance(), l4 = real_scheme() ? params_.tool->l4 : 0.0;
  geometry::Box box1, box2;
  box1.expand(Point{s1[0], -b - l3});
  box1.expand(Point{s1[1] + l3, -b + l3});
  box2.expand(Point{s2[0] - l4, b - l2 - l4});
  box2.expand(Point{s2[1] + l2 + l4, b + l2 + l4});
  geometry::Box out;
  out.min = {std::max(box1.min.x, box2.min.x), std::max(box1.min.y, box2.min.y)};
  out.max = {std::min(box1.max.x, box2.max.x), std::min(box1.max.y, box2.max.y)};
  if (out.empty()) {
    out = box1;
    out.expand(box2);
  }
  return out;
}

}  // namespace pkmws::mechanisms
