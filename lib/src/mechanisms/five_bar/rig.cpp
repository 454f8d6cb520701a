// Part shapes of the five-bar at a pose, and their enclosures over a
// box of platform positions (docs/theory/interference.md).
//
// Over a box X (centre c, half-diagonal h) the joint values of a leg lie in an
// interval obtained by interval arithmetic on the inverse kinematics: a moving
// point then stays in a small convex set (a segment of the guide, or an arc of
// the crank circle enclosed by its chord ⊕ the sagitta), so a link lies in the
// convex hull of its two end sets (outer enclosure), and the part at every p
// in X contains the part at the reference pose eroded by the largest
// displacement of its end points (inner witness).

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>

#include "io/load_bodies.hpp"
#include "bodies/rig_support.hpp"
#include "mechanisms/five_bar/five_bar.hpp"

namespace pkmws::bodies {

namespace {

using namespace detail;
using mechanisms::FiveBar;
constexpr double pi = std::numbers::pi;

// ---------------------------------------------------------------- five-bar
double wrap(double a) {
  while (a > pi) a -= 2 * pi;
  while (a <= -pi) a += 2 * pi;
  return a;
}

class FiveBarRig final : public BodyRig {
 public:
  FiveBarRig(std::shared_ptr<const FiveBar> m, BodyModel model) : BodyRig(std::move(model)), m_(std::move(m)) {}

  std::optional<std::array<Point, 2>> elbows(Point c) const {
    if (!m_->reachable(mechanisms::Pose{c.x, c.y, 0.0})) return std::nullopt;
    std::array<Point, 2> e;
    for (int i = 0; i < 2; ++i) {
      const auto q = m_->inverse_leg(i, c, m_->legs()[static_cast<std::size_t>(i)].working_mode);
      if (!q) return std::nullopt;
      e[static_cast<std::size_t>(i)] = m_->elbow(i, *q);
    }
    return e;
  }

  std::optional<std::vector<Shape>> shapes_at(Point p) const override {
    const auto e = elbows(p);
    if (!e) return std::nullopt;
    std::vector<Shape> out;
    for (const Part& part : model_.parts) {
      const auto leg = static_cast<std::size_t>(std::max(part.leg, 0));
      switch (part.kind) {
        case PartKind::platform_joint: out.push_back({{p}, part.radius}); break;
        case PartKind::link:
          if (part.proximal) out.push_back({{m_->legs()[leg].base, (*e)[leg]}, part.radius});
          else out.push_back({{(*e)[leg], p}, part.radius});
          break;
        default: out.push_back({part.polygon, 0.0});
      }
    }
    return out;
  }

  // The elbow of leg i over the box: chord end points, sagitta, mid point, displacement bound.
  struct ElbowSet {
    bool coarse = true;  // true: only |B − A| = l1 is known
    Point lo, hi, mid;
    double sagitta = 0.0, displacement = 0.0;
  };

  std::optional<ElbowSet> elbow_set(int i, const Box& box) const {
    const auto& leg = m_->legs()[static_cast<std::size_t>(i)];
    const Point a = leg.base;
    const double l1 = leg.proximal, l2 = leg.distal;
    ElbowSet out;
    const double tiny = 1e-12 * (l1 + l2);
    // rho range: distance from A to the box (0 inside) .. farthest corner.
    const double dx = std::max({box.min.x - a.x, 0.0, a.x - box.max.x});
    const double dy = std::max({box.min.y - a.y, 0.0, a.y - box.max.y});
    const double rho_lo = std::hypot(dx, dy);
    double rho_hi = 0.0;
    for (Point q : corners(box)) rho_hi = std::max(rho_hi, norm(q - a));
    // Reachable only in the annulus |l1 − l2| <= rho <= l1 + l2.
    if (rho_lo > l1 + l2 + tiny || rho_hi < std::abs(l1 - l2) - tiny) return std::nullopt;
    if (rho_lo <= tiny) return out;  // A in (or at) the box: the direction is unknown
    const Point c = centre(box);
    const double psi_c = std::atan2(c.y - a.y, c.x - a.x);
    double d_lo = 0.0, d_hi = 0.0;
    for (Point q : corners(box)) {
      const double d = wrap(std::atan2(q.y - a.y, q.x - a.x) - psi_c);
      d_lo = std::min(d_lo, d);
      d_hi = std::max(d_hi, d);
    }
    // Law of cosines (docs/theory/five_bar.md): cos beta = (rho² + l1² − l2²) / (2 rho l1).
    auto f = [&](double rho) { return (rho * rho + (l1 - l2) * (l1 + l2)) / (2.0 * rho * l1); };
    double f_lo = std::min(f(rho_lo), f(rho_hi)), f_hi = std::max(f(rho_lo), f(rho_hi));
    if (l1 > l2) {
      const double r_star = std::sqrt((l1 - l2) * (l1 + l2));  // minimum of f
      if (r_star > rho_lo && r_star < rho_hi) f_lo = std::min(f_lo, f(r_star));
    }
    if (f_lo > 1.0 + 1e-12 || f_hi < -1.0 - 1e-12) return std::nullopt;
    const double beta_lo = std::acos(std::clamp(f_hi, -1.0, 1.0)), beta_hi = std::acos(std::clamp(f_lo, -1.0, 1.0));
    const int s = leg.working_mode;
    // q = psi + s beta (docs/theory/five_bar.md working mode)
    const double q_lo = psi_c + d_lo + (s > 0 ? beta_lo : -beta_hi) - 1e-12;
    const double q_hi = psi_c + d_hi + (s > 0 ? beta_hi : -beta_lo) + 1e-12;
    const double span = q_hi - q_lo;
    if (span > 0.5 * pi) return out;
    out.coarse = false;
    out.lo = m_->elbow(i, q_lo);
    out.hi = m_->elbow(i, q_hi);
    out.mid = m_->elbow(i, 0.5 * (q_lo + q_hi));
    out.sagitta = l1 * (1.0 - std::cos(0.5 * span)) * (1.0 + 1e-12) + tiny;
    out.displacement = 2.0 * l1 * std::sin(0.25 * span) + tiny;
    return out;
  }

  std::optional<BoxParts> enclose(const Box& box) const override {
    const Point c = centre(box);
    const double h = half_diagonal(box);
    const auto cs = corners(box);
    std::array<ElbowSet, 2> e;
    for (int i = 0; i < 2; ++i) {
      const auto s = elbow_set(i, box);
      if (!s) return std::nullopt;
      e[static_cast<std::size_t>(i)] = *s;
    }
    BoxParts out;
    for (std::size_t i = 0; i < 2; ++i) {
      const Point a = m_->legs()[i].base;
      const double l1 = m_->legs()[i].proximal;
      std::vector<Point> v;
      for (Point q : cs) {
        if (e[i].coarse) {
          v.push_back(a - q);
        } else {
          v.push_back(e[i].lo - q);
          v.push_back(e[i].hi - q);
        }
      }
      out.link_vectors[i] = hull_of(std::move(v), e[i].coarse ? l1 : e[i].sagitta);
    }
    auto push = [&out](Shape outer, std::optional<Shape> inner) {
      Enclosure part;
      part.outer = std::move(outer);
      part.inner = std::move(inner);
      out.parts.push_back(std::move(part));
    };
    for (const Part& part : model_.parts) {
      const auto leg = static_cast<std::size_t>(std::max(part.leg, 0));
      const ElbowSet& el = e[leg];
      const Point a = m_->legs()[leg].base;
      const double l1 = m_->legs()[leg].proximal;
      if (part.kind == PartKind::platform_joint) {
        push(Shape{{c}, part.radius + h}, witness({c}, part.radius - h));
      } else if (part.kind == PartKind::link && part.proximal) {
        if (el.coarse) push(Shape{{a}, l1 + part.radius}, std::nullopt);
        else push(hull_of({a, el.lo, el.hi}, part.radius + el.sagitta), witness({a, el.mid}, part.radius - el.displacement));
      } else if (part.kind == PartKind::link) {
        std::vector<Point> v(cs.begin(), cs.end());
        if (el.coarse) {
          v.push_back(a);
          push(hull_of(std::move(v), part.radius + l1), std::nullopt);
        } else {
          v.push_back(el.lo);
          v.push_back(el.hi);
          push(hull_of(std::move(v), part.radius + el.sagitta),
               witness({el.mid, c}, part.radius - std::max(el.displacement, h)));
        }
      } else {
        push(Shape{part.polygon, 0.0}, Shape{part.polygon, 0.0});
      }
    }
    return out;
  }

  std::optional<std::array<Point, 2>> link_vectors_at(Point p) const override {
    const auto e = elbows(p);
    if (!e) return std::nullopt;
    return std::array<Point, 2>{(*e)[0] - p, (*e)[1] - p};
  }
  std::array<std::string, 2> joint_links() const override { return {"distal1", "distal2"}; }
  Shape fixed_part(std::size_t index) const override { return {model_.parts.at(index).polygon, 0.0}; }

 private:
  std::shared_ptr<const FiveBar> m_;
};


// Capability RigFactory: proximal and distal links.
class FiveBarRigFactory final : public RigFactory {
 public:
  std::vector<std::string> part_fields() const override { return {"proximal", "distal"}; }
  void read_parts(io::detail::JsonReader& r, BodyModel& model) const override {
    io::detail::read_capsules(r, "proximal", "proximal", true, model);
    io::detail::read_capsules(r, "distal", "distal", false, model);
  }
  std::shared_ptr<const BodyRig> make(std::shared_ptr<const mechanisms::Mechanism> self,
                                      BodyModel model) const override {
    // The mechanism that offered this capability is a FiveBar (its own module).
    return std::make_shared<FiveBarRig>(std::static_pointer_cast<const FiveBar>(std::move(self)), std::move(model));
  }
};

}  // namespace

std::shared_ptr<const RigFactory> five_bar_rig_factory() { return std::make_shared<FiveBarRigFactory>(); }

}  // namespace pkmws::bodies
