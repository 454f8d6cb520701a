// Biglide velocity-ratio fields ([Strutynskyi] fig. 8), one per leg, the
// condition number of dq/dP, and (simplified scheme) the pressure angle and
// reaction of the two rods ([Briot]'s two-force members, as the five-bar's).
#include "mechanisms/biglide/criteria.hpp"

#include <Eigen/SVD>

#include "criteria/support.hpp"

namespace pkmws::criteria {

namespace {

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
    T w1, w2;  // sqrt(max(w_i², 0))
  };
  template <class T> Parts<T> parts(const T& x, const T& y) const {
    using certified::max;
    using certified::sqr;
    using certified::sqrt;
    using std::sqrt;
    using S = certified::scalar_t<T>;
    Parts<T> r;
    r.h1 = y + S(b);
    r.w1sq = S(l3 * l3) - sqr(r.h1);
    r.w1 = sqrt(max(r.w1sq, 0.0));
    const T& w1 = r.w1;
    r.dq1 = S(-b1) * r.h1 / w1;
    const T dvx = S(b1) * r.h1 / w1;
    const T jy = S(-b) - S(b1 * m10) * w1 + S(m11) * r.h1;
    const T djx = r.dq1 + S(m00) * dvx + S(m01);
    const T djy = S(m10) * dvx + S(m11);
    r.h2 = S(b) - jy;
    r.w2sq = S(l2 * l2) - sqr(r.h2);
    r.w2 = sqrt(max(r.w2sq, 0.0));
    r.dq2 = djx + S(b2) * r.h2 * djy / r.w2;
    (void)x;
    return r;
  }
  bool kappa = false;  // eval() gives the condition-number surrogate of dq/dP instead
  template <class T> T eval(const T& x, const T& y) const {
    const Parts<T> p = parts(x, y);
    // dq/dP has rows (1, ∂q_i/∂y): both sliders follow x one to one (q_1 = x + b_1 w_1, q_2 = J_x + b_2 w_2).
    if (kappa) return kappa_surrogate(Rows2<T>{T(1.0), p.dq1, T(1.0), p.dq2});
    return certified::sqr(leg == 0 ? p.dq1 : p.dq2);
  }
  // Smooth where both rods are strictly off the perpendicular (w_i > 0).
  CellState domain(const Box& box) const {
    const Parts<Interval> p = parts(Interval(box.min.x, box.max.x), Interval(box.min.y, box.max.y));
    if (p.w1sq.hi <= 0.0 || p.w2sq.hi <= 0.0) return CellState::outside;
    return p.w1sq.lo > 0.0 && p.w2sq.lo > 0.0 ? CellState::inside : CellState::undecided;
  }
  // Slider 2's position q_2 = J_x + b_2 w_2 for the tool at (x, y), J_x = x +
  // b_1 w_1 (1 - M00) + M01 h_1 (J = S_1 + M (T - S_1), S_1 = (x + b_1 w_1, -B)).
  template <class T> T slider2(const T& x, const Parts<T>& p) const {
    using S = certified::scalar_t<T>;
    const T jx = x + S(b1 * (1.0 - m00)) * p.w1 + S(m01) * p.h1;
    return jx + S(b2) * p.w2;
  }
  // Box ⊆ workspace: the chain closes with both sliders inside their strokes.
  CellState within(const Box& box) const {
    const Interval x(box.min.x, box.max.x), y(box.min.y, box.max.y);
    const Parts<Interval> p = parts(x, y);
    if (p.w1sq.hi < 0.0 || p.w2sq.hi < 0.0) return CellState::outside;
    const Interval q1 = x + Interval(b1) * p.w1;
    const Interval q2 = slider2(x, p);
    if (q1.hi < stroke[0][0] || q1.lo > stroke[0][1] || q2.hi < stroke[1][0] || q2.lo > stroke[1][1])
      return CellState::outside;
    const bool inside = p.w1sq.lo > 0.0 && p.w2sq.lo > 0.0 && q1.lo >= stroke[0][0] && q1.hi <= stroke[0][1] &&
                        q2.lo >= stroke[1][0] && q2.hi <= stroke[1][1];
    return inside ? CellState::inside : CellState::undecided;
  }
};

// The simplified scheme as a point platform (criteria/support.hpp): the rods
// are two-force members meeting at the tool, u_1 = P - S_1 = (w_1, h_1) and
// u_2 = P - S_2 = (w_2, y - B) on the paper's branches (q_i = x - w_i,
// [Strutynskyi] eq. 5-6), so cos ε = u_1 . u_2 / (l_1 l_2) as in Biglide::evaluate.
struct BiglideRods {
  BiglideVelocityRatio legs;
  double l1 = 0.0, l2 = 0.0;
  explicit BiglideRods(const mechanisms::Biglide& m)
      : legs(m, 0), l1(m.params().rods[0]), l2(m.params().rods[1]) {}
  template <class T> T cos_eps(const T& x, const T& y) const {
    const auto p = legs.parts(x, y);
    return (p.w1 * p.w2 - p.h1 * p.h2) / (l1 * l2);  // u_1 . u_2 with u_2,y = y - B = -h_2
  }
  double eps_scale() const { return l1 * l2; }  // sin ε = singular_det / (l_1 l_2)
  template <class T> Rows2<T> rows(const T& x, const T& y) const {
    const auto p = legs.parts(x, y);
    return {T(1.0), p.dq1, T(1.0), p.dq2};
  }
  // det A = u_1 x u_2 = -(w_1 h_2 + h_1 w_2) (u_1 = (w_1, h_1), u_2 = (w_2, -h_2);
  // derived from [Strutynskyi] eq. 5-6): zero where the rods are aligned.
  template <class T> T singular_det(const T& x, const T& y) const {
    const auto p = legs.parts(x, y);
    return -(p.w1 * p.h2 + p.h1 * p.w2);
  }
  CellState domain(const Box& b) const { return legs.domain(b); }
  CellState within(const Box& b) const { return legs.within(b); }
};

// The real scheme's leg 2 as fields over the tool position T = (x, y)
// (docs/theory/biglide.md): its chain closes where h_2² <= l_2², and slider 2
// stands at q_2 = J_x + b_2 w_2 (BiglideVelocityRatio::slider2, as in its cell test),
// which must lie in its stroke. With leg 1 exact (Biglide::tool_band), these
// three sub-level sets cut the workspace out of the band.
struct BiglideChain {
  enum class What { h2sq, q2, minus_q2 };
  BiglideVelocityRatio legs;
  What what = What::q2;
  template <class T> T eval(const T& x, const T& y) const {
    const auto p = legs.parts(x, y);
    if (what == What::h2sq) return certified::sqr(p.h2);
    const T q2 = legs.slider2(x, p);
    return what == What::q2 ? q2 : -q2;
  }
  // h_2² is smooth where leg 1 is off its type-1 singularity (w_1 > 0); q_2
  // also needs w_2 > 0 (leg 2's).
  CellState domain(const Box& box) const {
    if (what != What::h2sq) return legs.domain(box);
    const auto p = legs.parts(Interval(box.min.x, box.max.x), Interval(box.min.y, box.max.y));
    if (p.w1sq.hi <= 0.0) return CellState::outside;
    return p.w1sq.lo > 0.0 ? CellState::inside : CellState::undecided;
  }
};

// The real scheme's type-2 singular determinant (q_i from [Strutynskyi] eq.
// 5-8, docs/references.md; derived here): dq/dP has rows (1, ∂q_1/∂y)
// and (1, ∂q_2/∂y), singular where ∂q_2/∂y = ∂q_1/∂y; times w_1 w_2 (to clear
// the denominators, with w_1 ∂v_x/∂y = b_1 h_1): w_2 (M00 b_1 h_1 + M01 w_1) +
// b_2 h_2 (M10 b_1 h_1 + M11 w_1). With M = I it is the simplified scheme's
// -(w_1 h_2 + h_1 w_2) (BiglideRods::singular_det): the rods aligned.
struct BiglideRealSingular {
  BiglideVelocityRatio legs;
  template <class T> T eval(const T& x, const T& y) const {
    using S = certified::scalar_t<T>;
    const auto p = legs.parts(x, y);
    const double b1 = BiglideVelocityRatio::b1, b2 = BiglideVelocityRatio::b2;
    return p.w2 * (S(legs.m00 * b1) * p.h1 + S(legs.m01) * p.w1) +
           S(b2) * p.h2 * (S(legs.m10 * b1) * p.h1 + S(legs.m11) * p.w1);
  }
  CellState domain(const Box& b) const { return legs.domain(b); }
};

}  // namespace

CriterionField biglide_pressure_angle(const mechanisms::Biglide& mechanism) {
  return point_platform_field(BiglideRods(mechanism), mechanism, "biglide", "pressure_angle");
}

CriterionField biglide_reaction(const mechanisms::Biglide& mechanism, double force_N) {
  return point_platform_field(BiglideRods(mechanism), mechanism, "biglide", "reaction", force_N);
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


CriterionField biglide_condition_number(const mechanisms::Biglide& mechanism) {
  BiglideVelocityRatio impl(mechanism, 0);
  impl.kappa = true;
  CriterionField c;
  c.name = "condition_number";
  c.unit = "";  // dimensionless
  c.key = "biglide.kappa";
  c.threshold_min = 1.0;
  c.surrogate = std::make_shared<certified::TemplateField<BiglideVelocityRatio>>(impl);
  c.level = kappa_level;
  const mechanisms::Biglide* m = &mechanism;
  c.value = [m](Point p) {
    if (!m->reachable({p.x, p.y, 0.0})) return nan;
    const Eigen::JacobiSVD<Eigen::Matrix2d> svd(m->inverse_jacobian(p));  // the paper's branches
    const auto sv = svd.singularValues();
    return sv(1) > 0.0 ? sv(0) / sv(1) : std::numeric_limits<double>::infinity();
  };
  c.within_test = [impl](const Box& b) { return impl.within(b); };
  return c;
}

namespace {

// Capability criteria::CriterionFields of the biglide: the velocity ratio, the
// condition number, and the pressure angle and reaction of the rods.
class BiglideFields final : public CriterionFields {
 public:
  explicit BiglideFields(const mechanisms::Biglide* m) : m_(m) {}
  std::vector<CriterionField> fields(const std::string& name, const mechanisms::Criteria& criteria,
                                     const std::vector<int>& /*reaction_legs*/) const override {
    if (name == "condition_number") return {biglide_condition_number(*m_)};
    if (name == "velocity_ratio") return {biglide_velocity_ratio(*m_, 0), biglide_velocity_ratio(*m_, 1)};
    if (m_->real_scheme()) {
      throw std::invalid_argument("the real-scheme biglide's rods do not meet at the tool (it sits on link 1's "
                                  "triangle), so " + name + " as the angle between two-force rods is defined for "
                                  "the simplified scheme only; velocity_ratio and condition_number hold for both");
    }
    if (name == "reaction") {
      if (!criteria.load) throw std::invalid_argument("the reaction criterion needs criteria.load");
      return {biglide_reaction(*m_, criteria.load->force_N)};
    }
    return {biglide_pressure_angle(*m_)};
  }
  // The real scheme: leg 1's band cut by leg 2's chain (BiglideChain).
  std::optional<WorkspaceSets> workspace_sets() const override {
    if (!m_->real_scheme()) return std::nullopt;
    const BiglideVelocityRatio legs(*m_, 1);
    const auto& stroke = m_->params().strokes[1];
    const double l2 = m_->params().rods[1];
    const auto cut = [&](BiglideChain::What what, double level) {
      return WorkspaceCut{std::make_shared<certified::TemplateField<BiglideChain>>(BiglideChain{legs, what}), level};
    };
    WorkspaceSets sets;
    sets.within = m_->tool_band();
    sets.within_test = [legs](const Box& b) { return legs.within(b); };
    sets.cuts = {cut(BiglideChain::What::h2sq, l2 * l2), cut(BiglideChain::What::q2, stroke[1]),
                 cut(BiglideChain::What::minus_q2, -stroke[0])};
    return sets;
  }
  CriterionField singular_determinant(const mechanisms::Criteria& /*criteria*/) const override {
    if (!m_->real_scheme()) return point_platform_singular(BiglideRods(*m_), "biglide");
    const BiglideRealSingular field{BiglideVelocityRatio(*m_, 1)};
    return zero_level_field(field, "singularity_distance", "length", "biglide_real.det",
                            [legs = field.legs](const Box& b) { return legs.within(b); });
  }

 private:
  const mechanisms::Biglide* m_;
};

}  // namespace

std::shared_ptr<const CriterionFields> biglide_fields(const mechanisms::Biglide& mechanism) {
  return std::make_shared<BiglideFields>(&mechanism);
}

}  // namespace pkmws::criteria
