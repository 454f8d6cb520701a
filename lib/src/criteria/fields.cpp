// Criterion fields (see criteria/fields.hpp; derivations in docs/theory/level_sets.md).
#include "pkmws/criteria/fields.hpp"

#include "pkmws/certified/template_field.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <stdexcept>

namespace pkmws::criteria {

using certified::CellState;
using certified::Interval;
using certified::Jet;
using geometry::Box;
using geometry::Point;

namespace {

constexpr double pi = std::numbers::pi;
constexpr double deg = pi / 180.0;
constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// |p - c|² over a box (tight: separable).
Interval dist2(const Box& b, Point c) {
  return certified::sqr(Interval(b.min.x, b.max.x) - Interval(c.x)) +
         certified::sqr(Interval(b.min.y, b.max.y) - Interval(c.y));
}

// ---------------------------------------------------------------------------
// Five-bar: cos ε from the inverse kinematics in closed form.
//
// Leg i, w = C - A_i, r² = |w|²: the elbow is B_i = A_i + a w + s b J w with
// a = 1/2 + (l1² - l2²) / (2 r²), b = sqrt(D) / (2 r²),
// D = ((l1 + l2)² - r²)(r² - (l1 - l2)²) (law of cosines, docs/theory/five_bar.md
// eq. IK: cos β = (r² + l1² - l2²) / (2 r l1)), J the rotation by +90°, and
// s the working mode (s = sign(w x (B_i - A_i))). Distal vector
// u_i = C - B_i = (1 - a) w - s b J w; cos ε = u_1 . u_2 / (l12 l22).
struct FiveBarCosEps {
  std::array<Point, 2> base;
  std::array<double, 2> l1, l2, s;
  std::array<double, 2> r_out2, r_in2;

  explicit FiveBarCosEps(const mechanisms::FiveBar& m) {
    for (std::size_t i = 0; i < 2; ++i) {
      const auto& leg = m.legs()[i];
      base[i] = leg.base;
      l1[i] = leg.proximal;
      l2[i] = leg.distal;
      s[i] = leg.working_mode;
      r_out2[i] = (l1[i] + l2[i]) * (l1[i] + l2[i]);
      r_in2[i] = (l1[i] - l2[i]) * (l1[i] - l2[i]);
    }
  }
  template <class T> T cos_eps(const T& x, const T& y) const {
    using certified::max;
    using certified::sqr;
    using std::sqrt;
    using certified::sqrt;
    std::array<T, 2> ux, uy;
    for (std::size_t i = 0; i < 2; ++i) {
      // Derived constants in T arithmetic, so that interval evaluations enclose
      // their rounding too.
      const T p = T(l1[i]), q = T(l2[i]);
      const T wx = x - base[i].x, wy = y - base[i].y;
      const T r2 = sqr(wx) + sqr(wy);
      const T inv2r2 = 0.5 / r2;
      const T one_minus_a = 0.5 - (p - q) * (p + q) * inv2r2;
      const T d = (sqr(p + q) - r2) * (r2 - sqr(p - q));
      const T b = sqrt(max(d, 0.0)) * inv2r2;
      ux[i] = one_minus_a * wx + s[i] * (b * wy);
      uy[i] = one_minus_a * wy - s[i] * (b * wx);
    }
    return (ux[0] * ux[1] + uy[0] * uy[1]) / (T(l2[0]) * T(l2[1]));
  }
  template <class T> T eval(const T& x, const T& y) const { return certified::sqr(cos_eps(x, y)); }
  // Smooth where every leg is strictly inside its annulus (D > 0, r > 0).
  CellState domain(const Box& b) const {
    bool inside = true;
    for (std::size_t i = 0; i < 2; ++i) {
      const Interval r2 = dist2(b, base[i]);
      if (r2.lo > r_out2[i] || r2.hi < r_in2[i]) return CellState::outside;
      inside = inside && r2.hi < r_out2[i] && r2.lo > r_in2[i] && r2.lo > 0.0;
    }
    return inside ? CellState::inside : CellState::undecided;
  }
};

// ---------------------------------------------------------------------------
// 3-RPR at a fixed orientation φ: B_j = P + c_j, c_j = R(φ) b'_j; leg vector
// d_j = B_j - A_j = P - e_j, e_j = A_j - c_j. Unnormalised force direction n_j:
// J d_j (revolute actuation: perpendicular to the leg) or d_j (prismatic).
// Rows a_j = [n_j, c_j x n_j] (moments about P, [Briot]'s f_i), linear in P.
// Column i of A^{-1} is (a_j x a_k) / det(a_0, a_1, a_2) ((i, j, k) cyclic), and
// normalising row i by |n_i| = |d_i| = ρ_i multiplies it by ρ_i, so the twist
// with only actuator i free is t_i = ρ_i (a_j x a_k) / det: v_P,i = its first two
// components, ω_i the third (planar_transmission.hpp).
struct ThreeRprTwist {
  std::array<Point, 3> c, e;
  bool revolute = true;
  int leg = 0;
  // Which quantity: 0 = R_i,max, 1 = |v_B_i|², 2 = -det_sign det A' (<= 0 in
  // the assembly mode of the reference point: no type-2 singularity crossed).
  int what = 0;
  double det_sign = 1.0;
  double f = 0.0, m = 0.0;
  std::optional<Box> window;
  std::optional<std::array<std::array<double, 2>, 3>> limits;

  ThreeRprTwist(const mechanisms::ThreeRpr& mech, int leg_index, int quantity, const mechanisms::Load& load)
      : revolute(mech.actuation() == mechanisms::ThreeRprActuation::revolute), leg(leg_index), what(quantity),
        f(load.force_N), m(std::abs(load.moment_Nm)), window(mech.analysis_window()), limits(mech.leg_limits()) {
    const double phi = mech.orientation();
    for (std::size_t j = 0; j < 3; ++j) {
      const Point b = mech.platform()[j];
      c[j] = {std::cos(phi) * b.x - std::sin(phi) * b.y, std::sin(phi) * b.x + std::cos(phi) * b.y};
      e[j] = mech.base()[j] - c[j];
    }
  }

  template <class T> struct Parts {
    T det, w0, w1, w2, rho2;
  };
  template <class T> Parts<T> parts(const T& x, const T& y) const {
    std::array<std::array<T, 3>, 3> a;
    std::array<T, 3> rho2;
    for (std::size_t j = 0; j < 3; ++j) {
      const T dx = x - e[j].x, dy = y - e[j].y;
      T nx = dx, ny = dy;
      if (revolute) {
        nx = -dy;
        ny = dx;
      }
      a[j][0] = nx;
      a[j][1] = ny;
      a[j][2] = c[j].x * ny - c[j].y * nx;  // (B_j - P) x n_j = c_j x n_j
      rho2[j] = certified::sqr(dx) + certified::sqr(dy);
    }
    const auto i = static_cast<std::size_t>(leg);
    const std::size_t j = (i + 1) % 3, k = (i + 2) % 3;
    Parts<T> p;
    p.w0 = a[j][1] * a[k][2] - a[j][2] * a[k][1];
    p.w1 = a[j][2] * a[k][0] - a[j][0] * a[k][2];
    p.w2 = a[j][0] * a[k][1] - a[j][1] * a[k][0];
    p.det = a[i][0] * p.w0 + a[i][1] * p.w1 + a[i][2] * p.w2;
    p.rho2 = rho2[i];
    return p;
  }
  template <class T> T eval(const T& x, const T& y) const {
    using certified::sqr;
    using certified::sqrt;
    using std::abs;
    using std::sqrt;
    using certified::abs;
    const Parts<T> p = parts(x, y);
    if (what == 2) return -det_sign * p.det;
    if (what == 1) {
      // v_B_i = v_P + ω J c_i: |v_B_i|² = ρ_i² |(w0 - w2 c_iy, w1 + w2 c_ix)|² / det².
      const Point ci = c[static_cast<std::size_t>(leg)];
      const T vx = p.w0 - ci.y * p.w2, vy = p.w1 + ci.x * p.w2;
      return p.rho2 * (sqr(vx) + sqr(vy)) / sqr(p.det);
    }
    // docs/theory/three_dof.md: R_i,max = f |v_P,i| + |m| |ω_i|.
    const T num = f * sqrt(sqr(p.w0) + sqr(p.w1)) + m * abs(p.w2);
    return sqrt(p.rho2) * num / abs(p.det);
  }
  CellState domain(const Box& b) const {
    if (what == 2) return CellState::inside;  // a polynomial
    const Parts<Interval> p = parts(Interval(b.min.x, b.max.x), Interval(b.min.y, b.max.y));
    if (p.det.contains_zero() || p.rho2.lo <= 0.0) return CellState::undecided;
    return CellState::inside;
  }
  // Box ⊆ workspace: inside the window and the leg annuli.
  CellState within(const Box& b) const {
    bool inside = true;
    if (window) {
      if (b.max.x < window->min.x || b.min.x > window->max.x || b.max.y < window->min.y || b.min.y > window->max.y)
        return CellState::outside;
      inside = b.min.x >= window->min.x && b.max.x <= window->max.x && b.min.y >= window->min.y && b.max.y <= window->max.y;
    }
    if (limits) {
      for (std::size_t j = 0; j < 3; ++j) {
        const Interval r2 = dist2(b, e[j]);
        const double lo2 = (*limits)[j][0] * (*limits)[j][0], hi2 = (*limits)[j][1] * (*limits)[j][1];
        if (r2.lo > hi2 || r2.hi < lo2) return CellState::outside;
        inside = inside && r2.hi < hi2 && r2.lo > lo2;
      }
    }
    return inside ? CellState::inside : CellState::undecided;
  }
};

// True when det A' vanishes to rounding at every position (the PAMINSA at
// cos phi = R_p / R_b, docs/theory/three_dof.md): a cubic in (x, y) that is
// below 1e-9 of Hadamard's bound (product of the row norms) at 25 points in
// general position over `box` is the zero polynomial up to rounding.
bool singular_everywhere(const ThreeRprTwist& t, const Box& box) {
  for (int i = 0; i < 5; ++i) {
    for (int j = 0; j < 5; ++j) {
      const double x = box.min.x + box.width() * (i + 0.31831) / 5.0;
      const double y = box.min.y + box.height() * (j + 0.57722) / 5.0;
      double bound = 1.0;
      for (std::size_t k = 0; k < 3; ++k) {
        const double n = std::hypot(x - t.e[k].x, y - t.e[k].y);
        bound *= n * std::sqrt(1.0 + t.c[k].x * t.c[k].x + t.c[k].y * t.c[k].y);
      }
      if (!(std::abs(t.parts<double>(x, y).det) <= 1e-9 * bound)) return false;
    }
  }
  return true;
}

// ---------------------------------------------------------------------------
// Biglide velocity ratio V_i / V_y = |∂q_i/∂y| ([Strutynskyi] fig. 8) for the
// paper's branches b_1 = b_2 = -1 (eq. 5-8), docs/theory/biglide.md:
//   h1 = y + B, w1 = sqrt(l3² - h1²), ∂q1/∂y = -b1 h1 / w1,
//   ∂v/∂y = (b1 h1 / w1, 1), ∂J/∂y = (∂q1/∂y, 0) + M ∂v/∂y,
//   J_y = -B - b1 w1 M10 + M11 h1, h2 = B - J_y, w2 = sqrt(l2² - h2²),
//   ∂q2/∂y = ∂J_x/∂y + b2 h2 ∂J_y/∂y / w2,
// M = (l1 / l3) R(γ) (identity for the simplified scheme). Surrogate:
// s_i = (∂q_i/∂y)², level(t) = t².
struct BiglideVelocityRatio {
  double b = 0.0, l2 = 0.0, l3 = 0.0;
  double m00 = 1.0, m01 = 0.0, m10 = 0.0, m11 = 1.0;
  std::array<std::array<double, 2>, 2> stroke{};
  int leg = 0;
  static constexpr double b1 = -1.0, b2 = -1.0;  // [Strutynskyi] eq. 5-8: minus roots

  explicit BiglideVelocityRatio(const mechanisms::Biglide& m, int leg_index) : leg(leg_index) {
    const auto& p = m.params();
    b = p.half_width;
    l2 = p.rods[1];
    l3 = m.tool_distance();
    const double k = p.rods[0] / l3, c = std::cos(m.gamma()), s = std::sin(m.gamma());
    m00 = k * c;
    m01 = -k * s;
    m10 = k * s;
    m11 = k * c;
    stroke = p.strokes;
  }
  template <class T> struct Parts {
    T h1, w1sq, dq1, h2, w2sq, dq2;
  };
  template <class T> Parts<T> parts(const T& x, const T& y) const {
    using certified::max;
    using certified::sqr;
    using certified::sqrt;
    using std::sqrt;
    Parts<T> r;
    r.h1 = y + T(b);
    r.w1sq = T(l3 * l3) - sqr(r.h1);
    const T w1 = sqrt(max(r.w1sq, 0.0));
    r.dq1 = T(-b1) * r.h1 / w1;
    const T dvx = T(b1) * r.h1 / w1;
    const T jy = T(-b) - T(b1 * m10) * w1 + T(m11) * r.h1;
    const T djx = r.dq1 + T(m00) * dvx + T(m01);
    const T djy = T(m10) * dvx + T(m11);
    r.h2 = T(b) - jy;
    r.w2sq = T(l2 * l2) - sqr(r.h2);
    const T w2 = sqrt(max(r.w2sq, 0.0));
    r.dq2 = djx + T(b2) * r.h2 * djy / w2;
    (void)x;
    return r;
  }
  template <class T> T eval(const T& x, const T& y) const {
    const Parts<T> p = parts(x, y);
    return certified::sqr(leg == 0 ? p.dq1 : p.dq2);
  }
  // Smooth where both rods are strictly off the perpendicular (w_i > 0).
  CellState domain(const Box& box) const {
    const Parts<Interval> p = parts(Interval(box.min.x, box.max.x), Interval(box.min.y, box.max.y));
    if (p.w1sq.hi <= 0.0 || p.w2sq.hi <= 0.0) return CellState::outside;
    return p.w1sq.lo > 0.0 && p.w2sq.lo > 0.0 ? CellState::inside : CellState::undecided;
  }
  // Box ⊆ workspace: the chain closes with both sliders inside their strokes.
  CellState within(const Box& box) const {
    using certified::max;
    using certified::sqr;
    using certified::sqrt;
    const Interval x(box.min.x, box.max.x), y(box.min.y, box.max.y);
    const Parts<Interval> p = parts(x, y);
    if (p.w1sq.hi < 0.0 || p.w2sq.hi < 0.0) return CellState::outside;
    const Interval w1 = sqrt(max(p.w1sq, 0.0));
    const Interval q1 = x + Interval(b1) * w1;
    const Interval jx = x + Interval(b1 * (1.0 - m00)) * w1 + Interval(m01) * p.h1;
    const Interval q2 = jx + Interval(b2) * sqrt(max(p.w2sq, 0.0));
    if (q1.hi < stroke[0][0] || q1.lo > stroke[0][1] || q2.hi < stroke[1][0] || q2.lo > stroke[1][1])
      return CellState::outside;
    const bool inside = p.w1sq.lo > 0.0 && p.w2sq.lo > 0.0 && q1.lo >= stroke[0][0] && q1.hi <= stroke[0][1] &&
                        q2.lo >= stroke[1][0] && q2.hi <= stroke[1][1];
    return inside ? CellState::inside : CellState::undecided;
  }
};

const mechanisms::FiveBar* as_five_bar(const io::MechanismFile& file) {
  return dynamic_cast<const mechanisms::FiveBar*>(file.model.get());
}
const mechanisms::ThreeRpr* as_three_rpr(const io::MechanismFile& file) {
  return dynamic_cast<const mechanisms::ThreeRpr*>(file.model.get());
}

double five_bar_alpha_deg(const FiveBarCosEps& f, Point p) {
  if (f.domain(Box{p, p}) == CellState::outside) return nan;
  const double ce = std::clamp(f.cos_eps<double>(p.x, p.y), -1.0, 1.0);
  // α = acos|sin ε| = asin|cos ε| ([Briot]).
  return std::asin(std::abs(ce)) / deg;
}

}  // namespace

CriterionField five_bar_pressure_angle(const mechanisms::FiveBar& mechanism) {
  const FiveBarCosEps impl(mechanism);
  CriterionField c;
  c.name = "pressure_angle";
  c.unit = "deg";
  c.threshold_max = 90.0;
  c.key = "five_bar.cos2eps";
  c.surrogate = std::make_shared<certified::TemplateField<FiveBarCosEps>>(impl);
  // α <= α_max  <=>  |cos ε| <= sin α_max  <=>  cos²ε <= sin²α_max.
  c.level = [](double alpha_deg) {
    const double a = std::clamp(alpha_deg, 0.0, 90.0) * deg;
    return std::sin(a) * std::sin(a);
  };
  c.value = [impl](Point p) { return five_bar_alpha_deg(impl, p); };
  c.within_test = [impl](const Box& b) { return impl.domain(b); };
  return c;
}

CriterionField biglide_velocity_ratio(const mechanisms::Biglide& mechanism, int leg) {
  const BiglideVelocityRatio impl(mechanism, leg);
  CriterionField c;
  c.name = "velocity_ratio";
  c.unit = "V_i/V_y";
  c.key = "biglide.vratio" + std::to_string(leg + 1);
  c.surrogate = std::make_shared<certified::TemplateField<BiglideVelocityRatio>>(impl);
  c.level = [](double ratio) { return ratio * ratio; };  // V_i/V_y <= t  <=>  (∂q_i/∂y)² <= t²
  const mechanisms::Biglide* m = &mechanism;
  c.value = [m, leg](Point p) {
    if (!m->reachable({p.x, p.y, 0.0})) return nan;
    return m->velocity_ratio_y(p)[static_cast<std::size_t>(leg)];
  };
  c.within_test = [impl](const Box& b) { return impl.within(b); };
  return c;
}

CriterionField five_bar_reaction(const mechanisms::FiveBar& mechanism, double force_N) {
  const FiveBarCosEps impl(mechanism);
  CriterionField c = five_bar_pressure_angle(mechanism);
  c.name = "reaction";
  c.unit = "N";
  c.threshold_max = std::numeric_limits<double>::infinity();
  // R = f / |sin ε| <= R_max  <=>  cos²ε <= 1 - (f / R_max)² (docs/theory/five_bar.md).
  c.level = [force_N](double r_max) {
    if (!(r_max > 0.0)) return -1.0;
    const double q = force_N / r_max;
    return q >= 1.0 ? (q == 1.0 ? 0.0 : -1.0) : 1.0 - q * q;
  };
  c.value = [impl, force_N](Point p) {
    const double a = five_bar_alpha_deg(impl, p);
    if (std::isnan(a)) return nan;
    const double sin_eps = std::cos(a * deg);
    return sin_eps > 0.0 ? force_N / sin_eps : std::numeric_limits<double>::infinity();
  };
  return c;
}

CriterionField three_rpr_reaction(const mechanisms::ThreeRpr& mechanism, const mechanisms::Load& load, int leg) {
  if (leg < 0 || leg > 2) throw std::invalid_argument("three_rpr_reaction: leg must be 0, 1 or 2");
  const ThreeRprTwist impl(mechanism, leg, 0, load);
  CriterionField c;
  c.name = "reaction";
  c.unit = "N";
  c.key = "three_rpr.reaction" + std::to_string(leg);
  c.surrogate = std::make_shared<certified::TemplateField<ThreeRprTwist>>(impl);
  c.level = [](double r) { return r; };
  c.value = [impl](Point p) { return impl.eval<double>(p.x, p.y); };
  c.within_test = [impl](const Box& b) { return impl.within(b); };
  return c;
}

CriterionField three_rpr_assembly_mode(const mechanisms::ThreeRpr& mechanism, Point reference) {
  ThreeRprTwist impl(mechanism, 0, 2, mechanisms::Load{});
  const double d = impl.parts<double>(reference.x, reference.y).det;
  if (!(d != 0.0) || !std::isfinite(d)) {
    throw std::invalid_argument("three_rpr_assembly_mode: the reference point is type-2 singular");
  }
  impl.det_sign = d > 0.0 ? 1.0 : -1.0;
  CriterionField c;
  c.name = "assembly_mode";
  c.unit = "";
  c.key = "three_rpr.assembly";
  c.surrogate = std::make_shared<certified::TemplateField<ThreeRprTwist>>(impl);
  c.level = [](double) { return 0.0; };
  c.value = [impl](Point p) { return impl.eval<double>(p.x, p.y); };
  c.within_test = [impl](const Box& b) { return impl.within(b); };
  return c;
}

CriterionField three_rpr_pressure_angle(const mechanisms::ThreeRpr& mechanism, int leg) {
  if (leg < 0 || leg > 2) throw std::invalid_argument("three_rpr_pressure_angle: leg must be 0, 1 or 2");
  const ThreeRprTwist impl(mechanism, leg, 1, mechanisms::Load{});
  CriterionField c;
  c.name = "pressure_angle";
  c.unit = "deg";
  c.threshold_max = 90.0;
  c.key = "three_rpr.vb2_" + std::to_string(leg);
  c.surrogate = std::make_shared<certified::TemplateField<ThreeRprTwist>>(impl);
  // [Briot]: cos α_i = |r_i . v_i| / |v_i| = 1 / |v_i|  =>  α_i <= α  <=>  |v_i|² <= 1 / cos²α.
  c.level = [](double alpha_deg) {
    const double ca = std::cos(std::clamp(alpha_deg, 0.0, 90.0) * deg);
    return ca > 0.0 ? 1.0 / (ca * ca) : std::numeric_limits<double>::infinity();
  };
  c.value = [impl](Point p) {
    const double v2 = impl.eval<double>(p.x, p.y);
    if (!std::isfinite(v2)) return 90.0;
    return std::acos(std::min(1.0, 1.0 / std::sqrt(v2))) / deg;
  };
  c.within_test = [impl](const Box& b) { return impl.within(b); };
  return c;
}

std::vector<CriterionField> fields_for(const io::MechanismFile& file, const std::string& name) {
  if (name != "pressure_angle" && name != "reaction" && name != "velocity_ratio") {
    throw io::InputError("unknown criterion \"" + name + "\" (expected pressure_angle, reaction or velocity_ratio)");
  }
  if (const auto* bg = dynamic_cast<const mechanisms::Biglide*>(file.model.get())) {
    if (name != "velocity_ratio") {
      throw io::InputError(file.path + ": for the biglide the certified level sets are of the velocity ratio "
                           "(criteria.max_velocity_ratio); pkmws eval gives pressure angles and reactions at a pose");
    }
    if (bg->real_scheme()) {
      throw io::InputError(file.path + ": velocity-ratio level sets need the exact workspace of the simplified "
                           "scheme; the real scheme's workspace is itself certified (coupler-curve boundary)");
    }
    return {biglide_velocity_ratio(*bg, 0), biglide_velocity_ratio(*bg, 1)};
  }
  if (name == "velocity_ratio") {
    throw io::InputError(file.path + ": velocity-ratio level sets are implemented for the biglide ([Strutynskyi]), not " +
                         file.mechanism);
  }
  if (const auto* fb = as_five_bar(file)) {
    for (int i = 0; i < 2; ++i) {
      if (fb->crank_limits(i)) {
        throw io::InputError(file.path + ": level sets of five-bars with crank limits are not supported "
                             "(the criterion fields assume freely rotating cranks)");
      }
    }
    if (name == "pressure_angle") return {five_bar_pressure_angle(*fb)};
    if (!file.criteria.load) throw io::InputError(file.path + ": the reaction criterion needs criteria.load");
    return {five_bar_reaction(*fb, file.criteria.load->force_N)};
  }
  if (const auto* rpr = as_three_rpr(file)) {
    if (!rpr->leg_limits() && !rpr->analysis_window()) {
      throw io::InputError(file.path + ": three_rpr level sets need leg_limits or an analysis_window");
    }
    std::vector<int> legs = file.reaction_legs;
    if (legs.empty()) legs = {1, 2, 3};
    std::vector<CriterionField> out;
    for (int leg : legs) {
      if (name == "reaction") {
        if (!file.criteria.load) throw io::InputError(file.path + ": the reaction criterion needs criteria.load");
        out.push_back(three_rpr_reaction(*rpr, *file.criteria.load, leg - 1));
      } else {
        out.push_back(three_rpr_pressure_angle(*rpr, leg - 1));
      }
    }
    // The platform stays in the assembly mode of the workspace's centre (it
    // cannot cross the type-2 singularity, [Briot] fig. 12's dashed curve).
    const geometry::Box b = rpr->bounds();
    if (singular_everywhere(ThreeRprTwist(*rpr, 0, 2, mechanisms::Load{}), b)) {
      // Reactions and pressure angles are infinite at every position: every
      // sub-level set is empty, known without refining anything.
      for (auto& f : out) {
        f.nowhere = "the 3-RPR is type-2 singular at every position at this orientation (cos phi = R_p / R_b): " +
                    f.name + " is infinite everywhere";
      }
      return out;
    }
    out.push_back(three_rpr_assembly_mode(*rpr, {0.5 * (b.min.x + b.max.x), 0.5 * (b.min.y + b.max.y)}));
    return out;
  }
  throw io::InputError(file.path + ": certified level sets are implemented for five_bar and three_rpr, not " +
                       file.mechanism);
}

std::vector<Limit> file_limits(const io::MechanismFile& file) {
  std::vector<Limit> out;
  const auto& c = file.criteria;
  if (c.max_pressure_angle_deg) out.push_back({"pressure_angle", *c.max_pressure_angle_deg});
  if (c.max_reaction_N) out.push_back({"reaction", *c.max_reaction_N});
  if (c.max_velocity_ratio) out.push_back({"velocity_ratio", *c.max_velocity_ratio});
  return out;
}

namespace {

class LimitedMechanism final : public mechanisms::Mechanism {
 public:
  LimitedMechanism(std::shared_ptr<const mechanisms::Mechanism> base, std::vector<std::pair<CriterionField, double>> f)
      : base_(std::move(base)), fields_(std::move(f)) {}
  std::string_view kind() const override { return base_->kind(); }
  int dof() const override { return base_->dof(); }
  std::vector<mechanisms::JointInfo> joints() const override { return base_->joints(); }
  std::vector<mechanisms::JointSolution> inverse(const mechanisms::Pose& p) const override { return base_->inverse(p); }
  std::vector<mechanisms::PoseSolution> direct(std::span<const double> q) const override { return base_->direct(q); }
  std::vector<mechanisms::Evaluation> evaluate(const mechanisms::Pose& p, const mechanisms::Criteria& c) const override {
    return base_->evaluate(p, c);
  }
  geometry::Region workspace() const override {
    throw std::runtime_error("a criteria-limited workspace is certified, not exact (pkmws area gives its bounds)");
  }
  bool reachable(const mechanisms::Pose& pose) const override {
    if (!base_->reachable(pose)) return false;
    for (const auto& [field, level] : fields_) {
      const double v = field.surrogate->value({pose.x, pose.y});
      if (!(v <= level)) return false;  // NaN (undefined) counts as outside
    }
    return true;
  }
  mechanisms::Drawing draw(const mechanisms::Pose& p) const override { return base_->draw(p); }
  geometry::Box bounds() const override { return base_->bounds(); }

 private:
  std::shared_ptr<const mechanisms::Mechanism> base_;
  std::vector<std::pair<CriterionField, double>> fields_;
};

}  // namespace

std::shared_ptr<const mechanisms::Mechanism> limited_mechanism(const io::MechanismFile& file) {
  std::vector<std::pair<CriterionField, double>> fields;
  for (const Limit& l : file_limits(file)) {
    for (CriterionField& f : fields_for(file, l.name)) {
      const double level = f.level(l.threshold);
      fields.emplace_back(std::move(f), level);
    }
  }
  return std::make_shared<LimitedMechanism>(file.model, std::move(fields));
}

geometry::Region criteria_domain(const io::MechanismFile& file) { return file.model->workspace(); }

LimitedWorkspace limited_workspace(const io::MechanismFile& file, const std::vector<Limit>& limits,
                                   const certified::LevelSetOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  LimitedWorkspace out;
  const geometry::Region within = criteria_domain(file);
  // Group by surrogate: the stricter level per key.
  std::map<std::string, std::pair<CriterionField, double>> by_key;
  for (const Limit& l : limits) {
    for (CriterionField& f : fields_for(file, l.name)) {
      const double level = f.level(l.threshold);
      auto it = by_key.find(f.key);
      if (it == by_key.end()) {
        by_key.emplace(f.key, std::make_pair(f, level));
      } else {
        it->second.second = std::min(it->second.second, level);
      }
    }
  }
  std::string nowhere;
  for (const auto& [key, entry] : by_key) {
    if (nowhere.empty()) nowhere = entry.first.nowhere;
  }
  if (by_key.empty()) {
    out.region = certified::from_exact(within);
  } else if (!nowhere.empty()) {
    out.region = certified::from_exact(geometry::Region{});
    out.note = nowhere;
  } else {
    std::vector<certified::Constraint> cs;
    certified::WithinTest within_test;
    for (auto& [key, entry] : by_key) {
      cs.push_back({entry.first.surrogate.get(), entry.second});
      if (!within_test) within_test = entry.first.within_test;  // one mechanism: one workspace test
    }
    certified::LevelSetResult r = certified::sublevel_set(cs, within, within_test, options);
    out.region = std::move(r.region);
    out.curves = std::move(r.curves);
    out.detail = std::move(r);
  }
  out.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace pkmws::criteria
