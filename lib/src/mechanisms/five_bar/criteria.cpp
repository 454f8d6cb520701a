// Five-bar criterion fields ([Briot]): the pressure angle and the reaction as
// cos²ε from the closed-form inverse kinematics (docs/theory/level_sets.md).
#include "mechanisms/five_bar/criteria.hpp"

#include "criteria/support.hpp"

namespace pkmws::criteria {

namespace {

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
  std::array<std::optional<std::array<double, 2>>, 2> limits;  // crank angles (explicit or from a Π-joint)

  explicit FiveBarCosEps(const mechanisms::FiveBar& m) {
    for (std::size_t i = 0; i < 2; ++i) {
      const auto& leg = m.legs()[i];
      limits[i] = m.crank_limits(static_cast<int>(i));
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
  // Rows of dq/dC: differentiating |C - B_i|² = l_i2² with B_i - A_i = w - u_i
  // gives dq_i = u_i . dC / (w_i x u_i) (the eval's B⁻¹A, docs/theory/five_bar.md).
  template <class T> Rows2<T> rows(const T& x, const T& y) const {
    using certified::max;
    using certified::sqr;
    using certified::sqrt;
    using std::sqrt;
    std::array<T, 2> mx, my;
    for (std::size_t i = 0; i < 2; ++i) {
      const T p = T(l1[i]), q = T(l2[i]);
      const T wx = x - base[i].x, wy = y - base[i].y;
      const T r2 = sqr(wx) + sqr(wy);
      const T inv2r2 = 0.5 / r2;
      const T one_minus_a = 0.5 - (p - q) * (p + q) * inv2r2;
      const T d = (sqr(p + q) - r2) * (r2 - sqr(p - q));
      const T b = sqrt(max(d, 0.0)) * inv2r2;
      const T ux = one_minus_a * wx + s[i] * (b * wy), uy = one_minus_a * wy - s[i] * (b * wx);
      const T cross = wx * uy - wy * ux;
      mx[i] = ux / cross;
      my[i] = uy / cross;
    }
    return {mx[0], my[0], mx[1], my[1]};
  }
  enum class What { cos2eps, ratio2, kappa };
  What what = What::cos2eps;
  template <class T> T eval(const T& x, const T& y) const {
    if (what == What::ratio2) return sigma_max2(rows(x, y));
    if (what == What::kappa) return kappa_surrogate(rows(x, y));
    return certified::sqr(cos_eps(x, y));
  }
  // Smooth where every leg is strictly inside its annulus (D > 0, r > 0).
  CellState domain(const Box& b) const {
    bool inside = true;
    for (std::size_t i = 0; i < 2; ++i) {
      const Interval r2 = dist2(b, base[i]);
      if (r2.lo > r_out2[i] || r2.hi < r_in2[i]) return CellState::outside;
      inside = inside && r2.hi < r_out2[i] && r2.lo > r_in2[i] && r2.lo > 0.0;
    }
    if (inside && what == What::ratio2 &&
        !detail::distinct_singular_values(rows(Interval(b.min.x, b.max.x), Interval(b.min.y, b.max.y)))) {
      return CellState::undecided;  // near an isotropic point
    }
    return inside ? CellState::inside : CellState::undecided;
  }
  // Box ⊆ workspace: inside both annuli and, with crank limits, every crank
  // direction B_i - A_i = a w + s b J w over the box (interval arithmetic)
  // inside the allowed sector of angles.
  CellState within(const Box& box) const {
    FiveBarCosEps plain = *this;
    plain.what = What::cos2eps;  // the annuli alone (no smoothness condition of the field)
    const CellState annuli = plain.domain(box);
    if (annuli == CellState::outside) return annuli;
    bool inside = annuli == CellState::inside;
    const Interval x(box.min.x, box.max.x), y(box.min.y, box.max.y);
    for (std::size_t i = 0; i < 2; ++i) {
      if (!limits[i]) continue;
      const Interval p(l1[i]), q(l2[i]);
      const Interval wx = x - base[i].x, wy = y - base[i].y;
      const Interval r2 = certified::sqr(wx) + certified::sqr(wy);
      if (!(r2.lo > 0.0)) return CellState::undecided;
      const Interval inv2r2 = 0.5 / r2;
      const Interval a = 0.5 + (p - q) * (p + q) * inv2r2;
      const Interval d = (certified::sqr(p + q) - r2) * (r2 - certified::sqr(p - q));
      const Interval b = certified::sqrt(certified::max(d, 0.0)) * inv2r2;
      const Interval dx = a * wx - s[i] * (b * wy), dy = a * wy + s[i] * (b * wx);
      const CellState sector = in_sector(dx, dy, (*limits[i])[0], (*limits[i])[1]);
      if (sector == CellState::outside) return sector;
      inside = inside && sector == CellState::inside;
    }
    return inside ? CellState::inside : CellState::undecided;
  }
  // Position of the directions of the vector box (dx, dy) against the angle
  // sector [lo, hi] (hi - lo <= 2 pi): the box's extreme directions are at its
  // corners (when it misses the origin); atan2's rounding is covered by a margin.
  static CellState in_sector(const Interval& dx, const Interval& dy, double lo, double hi) {
    if (dx.contains_zero() && dy.contains_zero()) return CellState::undecided;
    const double ref = std::atan2(0.5 * (dy.lo + dy.hi), 0.5 * (dx.lo + dx.hi));
    double amin = inf_angle, amax = -inf_angle;
    for (double cx : {dx.lo, dx.hi}) {
      for (double cy : {dy.lo, dy.hi}) {
        double t = std::atan2(cy, cx);
        while (t > ref + pi) t -= 2 * pi;
        while (t <= ref - pi) t += 2 * pi;
        amin = std::min(amin, t);
        amax = std::max(amax, t);
      }
    }
    constexpr double margin = 1e-12;
    amin -= margin;
    amax += margin;
    // Shift the directions' range next to the sector.
    const double shift = 2 * pi * std::floor((amin - lo) / (2 * pi));
    amin -= shift;
    amax -= shift;  // now lo <= amin < lo + 2 pi
    if (amax <= hi) return CellState::inside;
    if (amin > hi && amax < lo + 2 * pi) return CellState::outside;
    return CellState::undecided;
  }
  static constexpr double inf_angle = std::numeric_limits<double>::infinity();
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


CriterionField five_bar_velocity_ratio(const mechanisms::FiveBar& mechanism) {
  FiveBarCosEps impl(mechanism);
  impl.what = FiveBarCosEps::What::ratio2;
  CriterionField c;
  c.name = "velocity_ratio";
  c.unit = "|dq|/|dP|";
  c.key = "five_bar.vratio";
  c.surrogate = std::make_shared<certified::TemplateField<FiveBarCosEps>>(impl);
  c.level = [](double ratio) { return ratio * ratio; };
  const mechanisms::FiveBar* m = &mechanism;
  c.value = [m](Point p) {
    const auto e = m->evaluate({p.x, p.y, 0.0}, {});
    return !e.empty() && e.front().reachable && e.front().velocity_ratio ? *e.front().velocity_ratio : nan;
  };
  c.within_test = [impl](const Box& b) { return impl.within(b); };
  return c;
}

CriterionField five_bar_condition_number(const mechanisms::FiveBar& mechanism) {
  FiveBarCosEps impl(mechanism);
  impl.what = FiveBarCosEps::What::kappa;
  CriterionField c;
  c.name = "condition_number";
  c.unit = "";  // dimensionless
  c.key = "five_bar.kappa";
  c.threshold_min = 1.0;
  c.surrogate = std::make_shared<certified::TemplateField<FiveBarCosEps>>(impl);
  c.level = kappa_level;
  const mechanisms::FiveBar* m = &mechanism;
  c.value = [m](Point p) {
    const auto e = m->evaluate({p.x, p.y, 0.0}, {});
    return !e.empty() && e.front().reachable ? e.front().condition_number : nan;
  };
  c.within_test = [impl](const Box& b) { return impl.within(b); };
  return c;
}

namespace {

// Capability criteria::CriterionFields of a five-bar (crank limits and Π-joint
// drives bound the workspace W, which the level sets are restricted to).
class FiveBarFields final : public CriterionFields {
 public:
  explicit FiveBarFields(const mechanisms::FiveBar* m) : m_(m) {}
  std::vector<CriterionField> fields(const std::string& name, const mechanisms::Criteria& criteria,
                                     const std::vector<int>& /*reaction_legs*/) const override {
    if (name == "velocity_ratio") return {five_bar_velocity_ratio(*m_)};
    if (name == "condition_number") return {five_bar_condition_number(*m_)};
    if (name == "pressure_angle") return {five_bar_pressure_angle(*m_)};
    if (!criteria.load) throw std::invalid_argument("the reaction criterion needs criteria.load");
    return {five_bar_reaction(*m_, criteria.load->force_N)};
  }

 private:
  const mechanisms::FiveBar* m_;
};

}  // namespace

std::shared_ptr<const CriterionFields> five_bar_fields(const mechanisms::FiveBar& mechanism) {
  return std::make_shared<FiveBarFields>(&mechanism);
}

}  // namespace pkmws::criteria
