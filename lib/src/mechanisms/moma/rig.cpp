// Part shapes of MOMA at a pose, and their enclosures over a
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
#include "mechanisms/moma/moma.hpp"

namespace pkmws::bodies {

namespace {

using namespace detail;
using mechanisms::Moma;

// Shapes of the fixed parts (the same at every pose).
Shape fixed_shape(const Part& part, const Moma* moma) {
  if (part.kind == PartKind::obstacle) return Shape{part.polygon, 0.0};
  const int i = part.leg;
  const Point a = moma->guide_direction(i);
  return Shape{guide_rectangle(moma->legs()[static_cast<std::size_t>(i)].reference, a, part.from, part.to,
                               0.5 * part.width),
               0.0};
}


// ---------------------------------------------------------------- MOMA
class MomaRig final : public BodyRig {
 public:
  std::string link_noun() const override { return "rod"; }
  MomaRig(std::shared_ptr<const Moma> m, BodyModel model) : BodyRig(std::move(model)), m_(std::move(m)) {
    for (const Part& p : model_.parts) {
      if (p.fixed()) fixed_.push_back(fixed_shape(p, m_.get()));
      else fixed_.push_back({});
    }
  }

  std::optional<std::vector<Shape>> shapes_at(Point p) const override {
    std::array<Point, 2> s;
    for (int i = 0; i < 2; ++i) {
      const auto& leg = m_->legs()[static_cast<std::size_t>(i)];
      const auto q = m_->inverse_leg(i, p, leg.branch);  // [Vasilic] eq. 5
      if (!q || *q < leg.stroke_min || *q > leg.stroke_max) return std::nullopt;
      s[static_cast<std::size_t>(i)] = m_->slider(i, *q);
    }
    std::vector<Shape> out;
    for (std::size_t k = 0; k < model_.parts.size(); ++k) {
      const Part& part = model_.parts[k];
      const auto leg = static_cast<std::size_t>(std::max(part.leg, 0));
      switch (part.kind) {
        case PartKind::platform_joint: out.push_back({{p}, part.radius}); break;
        case PartKind::link: out.push_back({{s[leg], p}, part.radius}); break;
        case PartKind::slider_block:
          out.push_back({guide_rectangle(s[leg], m_->guide_direction(part.leg), -0.5 * part.length,
                                         0.5 * part.length, 0.5 * part.width),
                         0.0});
          break;
        default: out.push_back(fixed_[k]);
      }
    }
    return out;
  }

  std::optional<BoxParts> enclose(const Box& box) const override {
    const Point c = centre(box);
    const double h = half_diagonal(box);
    const auto cs = corners(box);
    std::array<double, 2> plo{}, phi{};
    for (int i = 0; i < 2; ++i) {
      const auto& leg = m_->legs()[static_cast<std::size_t>(i)];
      const Point a = m_->guide_direction(i);
      // [Vasilic] eq. 6: B = a·(P − R); the rod reaches P iff l² − (a × (P − R))² >= 0.
      const auto b = linear_range(box, [&](Point q) { return dot(a, q - leg.reference); });
      const auto x = linear_range(box, [&](Point q) { return cross(a, q - leg.reference); });
      const double x2_lo = (x[0] <= 0.0 && x[1] >= 0.0) ? 0.0 : std::min(x[0] * x[0], x[1] * x[1]);
      const double x2_hi = std::max(x[0] * x[0], x[1] * x[1]);
      const double l2 = leg.rod_length * leg.rod_length;
      const double scale = leg.rod_length + std::abs(b[0]) + std::abs(b[1]);
      const double tiny = 1e-12 * scale;
      if (l2 - x2_lo < -tiny * scale) return std::nullopt;  // the rod cannot reach any point of X
      const double sq_lo = std::sqrt(std::max(0.0, l2 - x2_hi)), sq_hi = std::sqrt(std::max(0.0, l2 - x2_lo));
      // [Vasilic] eq. 5: p = B + branch sqrt(l² − (a × w)²)
      double lo = leg.branch < 0 ? b[0] - sq_hi : b[0] + sq_lo;
      double hi = leg.branch < 0 ? b[1] - sq_lo : b[1] + sq_hi;
      lo = std::max(lo - tiny, leg.stroke_min);
      hi = std::min(hi + tiny, leg.stroke_max);
      if (lo > hi) return std::nullopt;  // out of stroke everywhere in X
      plo[static_cast<std::size_t>(i)] = lo;
      phi[static_cast<std::size_t>(i)] = hi;
    }
    BoxParts out;
    for (int i = 0; i < 2; ++i) {
      const auto k = static_cast<std::size_t>(i);
      std::vector<Point> v;
      for (Point q : cs) {
        v.push_back(m_->slider(i, plo[k]) - q);
        v.push_back(m_->slider(i, phi[k]) - q);
      }
      out.link_vectors[k] = hull_of(std::move(v), 0.0);
    }
    for (std::size_t k = 0; k < model_.parts.size(); ++k) {
      const Part& part = model_.parts[k];
      const auto leg = static_cast<std::size_t>(std::max(part.leg, 0));
      const double pm = 0.5 * (plo[leg] + phi[leg]), dp = 0.5 * (phi[leg] - plo[leg]);
      switch (part.kind) {
        case PartKind::platform_joint:
          out.parts.push_back({{{c}, part.radius + h}, witness({c}, part.radius - h)});
          break;
        case PartKind::link: {
          std::vector<Point> v(cs.begin(), cs.end());
          v.push_back(m_->slider(part.leg, plo[leg]));
          v.push_back(m_->slider(part.leg, phi[leg]));
          out.parts.push_back({hull_of(std::move(v), part.radius),
                               witness({m_->slider(part.leg, pm), c}, part.radius - std::max(h, dp))});
          break;
        }
        case PartKind::slider_block: {
          const Point a = m_->guide_direction(part.leg);
          const Point r = m_->legs()[leg].reference;
          const double hl = 0.5 * part.length, hw = 0.5 * part.width;
          Enclosure e{{guide_rectangle(r, a, plo[leg] - hl, phi[leg] + hl, hw), 0.0}, std::nullopt};
          // Common to every slider position: [phi - hl, plo + hl].
          const double in_half = hl - dp;
          if (in_half > 0.0) {
            // A thin rounding (radius rho > 0) makes overlap of two witnesses a strict test.
            const double rho = 1e-3 * std::min(in_half, hw);
            e.inner = Shape{guide_rectangle(r, a, pm - in_half + rho, pm + in_half - rho, hw - rho), rho};
          }
          out.parts.push_back(std::move(e));
          break;
        }
        default: out.parts.push_back({fixed_[k], fixed_[k]});
      }
    }
    return out;
  }

  std::optional<std::array<Point, 2>> link_vectors_at(Point p) const override {
    std::array<Point, 2> out;
    for (int i = 0; i < 2; ++i) {
      const auto& leg = m_->legs()[static_cast<std::size_t>(i)];
      const auto q = m_->inverse_leg(i, p, leg.branch);
      if (!q || *q < leg.stroke_min || *q > leg.stroke_max) return std::nullopt;
      out[static_cast<std::size_t>(i)] = m_->slider(i, *q) - p;
    }
    return out;
  }
  std::array<std::string, 2> joint_links() const override { return {"rod1", "rod2"}; }
  Shape fixed_part(std::size_t index) const override { return fixed_.at(index); }

 private:
  std::shared_ptr<const Moma> m_;
  std::vector<Shape> fixed_;
};


// Capability RigFactory: rods, slider blocks and housings.
class MomaRigFactory final : public RigFactory {
 public:
  std::vector<std::string> part_fields() const override { return {"rods", "slider_blocks", "housings"}; }
  void read_parts(io::detail::JsonReader& r, BodyModel& model) const override {
    using io::detail::leg_part;
    using io::detail::part_length;
    io::detail::read_capsules(r, "rods", "rod", false, model);
    if (r.has("slider_blocks")) {
      auto items = r.objects("slider_blocks", 2);
      for (int i = 0; i < 2; ++i) {
        auto& it = items[static_cast<std::size_t>(i)];
        it.declare_fields({"length", "width"});
        Part part = leg_part("slider" + std::to_string(i + 1), PartKind::slider_block, i);
        part.length = part_length(it, "length", false);
        part.width = part_length(it, "width", false);
        it.finish();
        model.parts.push_back(part);
      }
    }
    if (r.has("housings")) {
      auto items = r.objects("housings", 2);
      for (int i = 0; i < 2; ++i) {
        auto& it = items[static_cast<std::size_t>(i)];
        it.declare_fields({"extent", "width"});
        Part part = leg_part("housing" + std::to_string(i + 1), PartKind::housing, i);
        const auto e = it.interval("extent");
        if (!(std::abs(e[0]) <= 1e15 && std::abs(e[1]) <= 1e15)) it.fail("extent", "magnitude must not exceed 1e15");
        part.from = e[0];
        part.to = e[1];
        part.width = part_length(it, "width", false);
        it.finish();
        model.parts.push_back(part);
      }
    }
  }
  std::shared_ptr<const BodyRig> make(std::shared_ptr<const mechanisms::Mechanism> self,
                                      BodyModel model) const override {
    // The mechanism that offered this capability is a Moma (its own module).
    return std::make_shared<MomaRig>(std::static_pointer_cast<const Moma>(std::move(self)), std::move(model));
  }
};

}  // namespace

std::shared_ptr<const RigFactory> moma_rig_factory() { return std::make_shared<MomaRigFactory>(); }

}  // namespace pkmws::bodies
