// 3-RPR criterion fields ([Briot]): reactions and pressure angles per leg from
// the platform twists, the velocity ratio and condition number of the
// homogenised Jacobian dq/dx, and the assembly-mode constraint (docs/theory/three_dof.md).
#include "mechanisms/three_rpr/criteria.hpp"

#include <type_traits>

#include "criteria/singular3.hpp"
#include "criteria/support.hpp"

namespace pkmws::criteria {

namespace {

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
  // the assembly mode of the reference point: no type-2 singularity crossed),
  // 3 = σ_max² of dq/dx', 4 = -σ_min² / σ_max² of dq/dx' (x' = (x, y, L φ)).
  int what = 0;
  double length = 1.0;  // L of x'
  double det_sign = 1.0;
  // what == 0 over boxes: only the assembly mode det_sign det > 0 counts (the
  // field comes with that mode's constraint, three_rpr_assembly_mode).
  bool assembly_only = false;
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
  // What fixes jacobian_cubic (the roots' cache key; `length` may be set later).
  detail::CubicKey cubic_key() const {
    detail::CubicKey k{};
    for (std::size_t j = 0; j < 3; ++j) {
      k[4 * j] = c[j].x;
      k[4 * j + 1] = c[j].y;
      k[4 * j + 2] = e[j].x;
      k[4 * j + 3] = e[j].y;
    }
    k[12] = length;
    k[13] = revolute ? 1.0 : 0.0;
    return k;
  }

  template <class T> struct Parts {
    T det, w0, w1, w2, rho2;
  };
  // Row j of A' at P, (n_j, c_j x n_j), and ρ_j² = |d_j|².
  template <class T> std::array<T, 4> row(std::size_t j, const T& x, const T& y) const {
    const T dx = x - e[j].x, dy = y - e[j].y;
    T nx = dx, ny = dy;
    if (revolute) {
      nx = -dy;
      ny = dx;
    }
    return {nx, ny, c[j].x * ny - c[j].y * nx, certified::sqr(dx) + certified::sqr(dy)};  // (B_j - P) x n_j = c_j x n_j
  }
  template <class T> Parts<T> parts(const T& x, const T& y) const {
    std::array<std::array<T, 3>, 3> a;
    std::array<T, 3> rho2;
    for (std::size_t j = 0; j < 3; ++j) {
      const std::array<T, 4> r = row(j, x, y);
      a[j] = {r[0], r[1], r[2]};
      rho2[j] = r[3];
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
  // p(μ) = det(μ I - MᵀM) for M = dq/dx' at P: row j of dq/dx is a_j / ρ_j²
  // (leg angle: dq_j = (J d_j) . dB_j / ρ_j²) or a_j / ρ_j (leg length:
  // dρ_j = d_j . dB_j / ρ_j), dB_j = dP + dφ J c_j, i.e. [Briot]'s A' rows
  // divided by the diagonal B (ρ_j or 1), as ThreeRpr::evaluate's B⁻¹A;
  // x' = (x, y, L φ) divides the third column by L (criteria/singular3.hpp).
  template <class T> detail::Cubic<T> jacobian_cubic(const T& x, const T& y) const {
    if constexpr (std::is_same_v<T, certified::Grad<Interval>> || std::is_same_v<T, certified::Jet<Interval>>) {
      // Leg angles over a box: row j is (J d_j, c_j . d_j / L) / ρ_j², linear in
      // the inverted point u_j = d_j / ρ_j² (dq_j/dφ = (J d_j).(J c_j) / ρ_j²),
      // whose derivatives have closed forms (detail::inverted_point).
      if (revolute && detail::plain_coordinates(x, y)) {
        const Interval inv_length = Interval(1.0) / Interval(length);
        T a[3][3];
        for (std::size_t j = 0; j < 3; ++j) {
          const auto [ux, uy] = detail::inverted_point<T>(x.v, y.v, e[j].x, e[j].y);
          a[j][0] = -uy;
          a[j][1] = ux;
          a[j][2] = (Interval(c[j].x) * inv_length) * ux + (Interval(c[j].y) * inv_length) * uy;
        }
        return detail::gram_invariants(a);
      }
    }
    T a[3][3], w[3];
    for (std::size_t j = 0; j < 3; ++j) {
      const std::array<T, 4> r = row(j, x, y);
      a[j][0] = r[0];
      a[j][1] = r[1];
      a[j][2] = r[2] / length;
      w[j] = revolute ? r[3] * r[3] : r[3];
    }
    return detail::gram_invariants(a, w);
  }
  template <class T> T eval(const T& x, const T& y) const {
    if (what >= 3) {
      const auto cubic = [this](const auto& u, const auto& v) { return jacobian_cubic(u, v); };
      const detail::CubicKey key = cubic_key();
      const auto [l1, l3] = detail::cubic_roots_field(cubic, x, y, what == 4, &key);
      if (what == 3) return l1;
      return -(l3 / l1);
    }
    using certified::sqr;
    using certified::sqrt;
    using std::abs;
    using std::sqrt;
    using certified::abs;
    using certified::max;
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
    if constexpr (!std::is_same_v<T, double>) {
      // Restricted to one assembly mode, |det| = det_sign det there: over a box
      // across the singular curve it is [0, hi], so the bound is a half-line
      // [R_lo, inf) (the reaction grows without bound towards the curve) instead
      // of the whole line, and such boxes away from the 0/0 points are decided.
      if (assembly_only) return sqrt(p.rho2) * num / max(det_sign * p.det, 0.0);
    }
    return sqrt(p.rho2) * num / abs(p.det);
  }
  // ScalarField::side: the conditioning fields' sign tests (criteria/singular3.hpp).
  CellState side(const Box& b, double level) const {
    if (what < 3) return CellState::undecided;
    return detail::conditioning_side(*this, Interval(b.min.x, b.max.x), Interval(b.min.y, b.max.y), what == 4, level);
  }
  // ScalarField::enclose_cheap: the conditioning fields' rows' bound
  // (detail::conditioning_from_rows), which decides the boxes about the base
  // joint points e_j, where a leg has zero length and the roots' enclosures
  // (and the side test) fail at every scale; the others' natural enclosure is
  // cheap already.
  Interval enclose_cheap(const Box& b) const {
    if (what < 3) return Interval::whole();
    return detail::conditioning_from_rows(row_norms(Interval(b.min.x, b.max.x), Interval(b.min.y, b.max.y)), what == 4);
  }
  // |m_j|², row j of dq/dx' squared, over a box: with |n_j|² = ρ_j² it is
  // 1/ρ_j² + ((c_j x n_j)/L)²/ρ_j⁴ (leg angle) or 1 + ((c_j x n_j)/L)²/ρ_j²
  // (leg length), which keeps the lower bound 1/ρ_j² (or 1) where ρ_j's
  // enclosure reaches 0.
  std::array<Interval, 3> row_norms(const Interval& x, const Interval& y) const {
    std::array<Interval, 3> n;
    for (std::size_t j = 0; j < 3; ++j) {
      const std::array<Interval, 4> r = row(j, x, y);
      const Interval moment = certified::sqr(r[2] / length), rho2 = certified::max(r[3], 0.0);  // ρ² >= 0
      n[j] = revolute ? Interval(1.0) / rho2 + moment / certified::sqr(rho2) : Interval(1.0) + moment / rho2;
    }
    return n;
  }
  // ScalarField::excluded: the conditioning fields are defined everywhere but
  // at the base joints (points), so only their smoothness test (the roots'
  // enclosures) can say anything, and it never says `outside`.
  bool excluded(const Box& b) const { return what < 3 && domain(b) == CellState::outside; }
  CellState domain(const Box& b) const {
    if (what == 2) return CellState::inside;  // a polynomial
    if (what >= 3) {
      // No leg of zero length; the roots used are simple (λ_1 > λ_2, and λ_3 < λ_2 for κ).
      for (const Point& ej : e) {
        if (dist2(b, ej).lo <= 0.0) return CellState::undecided;
      }
      const auto cubic = [this](const auto& u, const auto& v) { return jacobian_cubic(u, v); };
      const Interval x(b.min.x, b.max.x), y(b.min.y, b.max.y);
      const detail::CubicKey key = cubic_key();
      const bool simple = detail::simple_roots_over_box(cubic, x, y, what == 4, &key);
      return simple ? CellState::inside : CellState::undecided;
    }
    const Parts<Interval> p = parts(Interval(b.min.x, b.max.x), Interval(b.min.y, b.max.y));
    if (assembly_only && (det_sign * p.det).hi <= 0.0) return CellState::outside;  // the other mode
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

// The sign of det A' at the reference point (det is the same for every leg
// index up to the cyclic order of the rows, i.e. identical).
double reference_det_sign(const ThreeRprTwist& t, Point reference) {
  const double d = t.parts<double>(reference.x, reference.y).det;
  if (!(d != 0.0) || !std::isfinite(d)) {
    throw std::invalid_argument("three_rpr_assembly_mode: the reference point is type-2 singular");
  }
  return d > 0.0 ? 1.0 : -1.0;
}
}  // namespace

CriterionField three_rpr_reaction(const mechanisms::ThreeRpr& mechanism, const mechanisms::Load& load, int leg,
                                  std::optional<Point> assembly_reference) {
  if (leg < 0 || leg > 2) throw std::invalid_argument("three_rpr_reaction: leg must be 0, 1 or 2");
  ThreeRprTwist impl(mechanism, leg, 0, load);
  if (assembly_reference) {
    impl.assembly_only = true;
    impl.det_sign = reference_det_sign(impl, *assembly_reference);
  }
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
  impl.det_sign = reference_det_sign(impl, reference);
  return zero_level_field(impl, "assembly_mode", "", "three_rpr.assembly",
                          [impl](const Box& b) { return impl.within(b); });
}

double three_rpr_characteristic_length(const mechanisms::ThreeRpr& mechanism, const mechanisms::Criteria& criteria) {
  return criteria.characteristic_length.value_or(mechanism.characteristic_length());
}

namespace {

// σ_max² (velocity ratio, level t²) or -σ_min²/σ_max² (condition number: κ <= t
// <=> σ_min²/σ_max² >= 1/t², level -1/t²) of dq/dx' with the file's L.
CriterionField three_rpr_conditioning(const mechanisms::ThreeRpr& mechanism, const mechanisms::Criteria& criteria,
                                      bool kappa) {
  ThreeRprTwist impl(mechanism, 0, kappa ? 4 : 3, mechanisms::Load{});
  impl.length = three_rpr_characteristic_length(mechanism, criteria);
  CriterionField c;
  c.name = kappa ? "condition_number" : "velocity_ratio";
  c.unit = kappa ? "" : "|dq|/|dx'|";
  c.key = kappa ? "three_rpr.kappa" : "three_rpr.vratio";
  c.characteristic_length = impl.length;
  c.surrogate = std::make_shared<certified::TemplateField<ThreeRprTwist>>(impl);
  if (kappa) {
    c.threshold_min = 1.0;
    c.level = [](double t) { return t >= 1.0 ? -1.0 / (t * t) : -std::numeric_limits<double>::infinity(); };
  } else {
    c.level = [](double t) { return t * t; };
  }
  // The criterion as pkmws eval gives it (with the same L).
  const mechanisms::ThreeRpr* m = &mechanism;
  mechanisms::Criteria with_length;
  with_length.characteristic_length = impl.length;
  c.value = [m, with_length, kappa](Point p) {
    const auto e = m->evaluate({p.x, p.y, m->orientation()}, with_length);
    if (e.empty()) return nan;
    if (kappa) return e.front().condition_number;
    return e.front().velocity_ratio ? *e.front().velocity_ratio : nan;
  };
  c.within_test = [impl](const Box& b) { return impl.within(b); };
  return c;
}

}  // namespace

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


CriterionField three_rpr_velocity_ratio(const mechanisms::ThreeRpr& mechanism, const mechanisms::Criteria& criteria) {
  return three_rpr_conditioning(mechanism, criteria, false);
}

CriterionField three_rpr_condition_number(const mechanisms::ThreeRpr& mechanism, const mechanisms::Criteria& criteria) {
  return three_rpr_conditioning(mechanism, criteria, true);
}

namespace {

// Capability criteria::CriterionFields of the 3-RPR at its file orientation.
class ThreeRprFields final : public CriterionFields {
 public:
  explicit ThreeRprFields(const mechanisms::ThreeRpr* m) : m_(m) {}
  std::vector<CriterionField> fields(const std::string& name, const mechanisms::Criteria& criteria,
                                     const std::vector<int>& reaction_legs) const override {
    const mechanisms::ThreeRpr& rpr = *m_;
    if (!rpr.leg_limits() && !rpr.analysis_window()) {
      throw std::invalid_argument("three_rpr level sets need leg_limits or an analysis_window");
    }
    const geometry::Box b = rpr.bounds();
    const Point centre{0.5 * (b.min.x + b.max.x), 0.5 * (b.min.y + b.max.y)};
    std::vector<int> legs = reaction_legs;
    if (legs.empty()) legs = {1, 2, 3};
    std::vector<CriterionField> out;
    // One field for the whole Jacobian; the others one per limited leg.
    if (name == "velocity_ratio") out.push_back(three_rpr_velocity_ratio(rpr, criteria));
    if (name == "condition_number") out.push_back(three_rpr_condition_number(rpr, criteria));
    if (!out.empty()) legs.clear();
    for (int leg : legs) {
      if (name == "reaction") {
        if (!criteria.load) throw std::invalid_argument("the reaction criterion needs criteria.load");
        out.push_back(three_rpr_reaction(rpr, *criteria.load, leg - 1, centre));
      } else {
        out.push_back(three_rpr_pressure_angle(rpr, leg - 1));
      }
    }
    // The platform stays in the assembly mode of the workspace's centre (it
    // cannot cross the type-2 singularity, [Briot] fig. 12's dashed curve).
    if (singular_everywhere(ThreeRprTwist(rpr, 0, 2, mechanisms::Load{}), b)) {
      // Reactions and pressure angles are infinite at every position: every
      // sub-level set is empty, known without refining anything.
      for (auto& f : out) {
        if (f.name == "velocity_ratio") continue;  // dq/dx' stays finite (σ_min = 0 there)
        f.nowhere = "the 3-RPR is type-2 singular at every position at this orientation (cos phi = R_p / R_b): " +
                    f.name + " is infinite everywhere";
      }
      return out;
    }
    out.push_back(three_rpr_assembly_mode(rpr, centre));
    return out;
  }
  // det A' at the file's orientation, a cubic in P ([Briot]'s rows a_j; zero
  // on the type-2 singular curve: a circle for PAMINSA, docs/theory/three_dof.md).
  CriterionField singular_determinant(const mechanisms::Criteria& /*criteria*/) const override {
    const mechanisms::ThreeRpr& rpr = *m_;
    if (!rpr.leg_limits() && !rpr.analysis_window()) {
      throw std::invalid_argument("three_rpr needs leg_limits or an analysis_window for its workspace");
    }
    ThreeRprTwist impl(rpr, 0, 2, mechanisms::Load{});
    impl.det_sign = 1.0;
    CriterionField c;
    c.name = "singularity_distance";
    c.unit = "length";
    c.key = "three_rpr.det";
    c.surrogate = std::make_shared<certified::TemplateField<ThreeRprTwist>>(impl);
    c.level = [](double) { return 0.0; };
    c.value = [impl](Point p) { return impl.eval<double>(p.x, p.y); };
    c.within_test = [impl](const Box& b) { return impl.within(b); };
    if (singular_everywhere(impl, rpr.bounds())) {
      c.nowhere = "the 3-RPR is type-2 singular at every position at this orientation (cos phi = R_p / R_b): the "
                  "distance to the singularity is 0 everywhere";
    }
    return c;
  }

 private:
  const mechanisms::ThreeRpr* m_;
};

}  // namespace

std::shared_ptr<const CriterionFields> three_rpr_fields(const mechanisms::ThreeRpr& mechanism) {
  return std::make_shared<ThreeRprFields>(&mechanism);
}

}  // namespace pkmws::criteria
