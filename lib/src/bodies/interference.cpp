// Interference regions and the real workspace (docs/format.md (bodies); [Vasilic] §4 end):
// exact Minkowski sums for the platform joint against fixed parts, certified
// quadtree enclosures (pkmws::certified) for every other pair and for the
// minimum angle between the links meeting at the platform joint.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "pkmws/bodies/bodies.hpp"
#include "pkmws/geometry/primitives.hpp"

namespace pkmws::bodies {

namespace {

constexpr double pi = std::numbers::pi;
using certified::CellState;

double wrap(double a) {
  while (a > pi) a -= 2 * pi;
  while (a <= -pi) a += 2 * pi;
  return a;
}

// Polar-angle range [lo, hi] (hi − lo < pi) of the set hull ⊕ disk(radius),
// or nullopt when it comes within `margin` of the origin.
std::optional<std::array<double, 2>> angle_range(const Shape& s, double margin) {
  const double d = core_distance({Point{0.0, 0.0}}, s.core);
  if (!(d > s.radius + margin)) return std::nullopt;
  const double ref = std::atan2(s.core[0].y, s.core[0].x);
  double lo = 0.0, hi = 0.0;
  for (Point v : s.core) {
    const double a = wrap(std::atan2(v.y, v.x) - ref);
    lo = std::min(lo, a);
    hi = std::max(hi, a);
  }
  // Every point of the disk around a hull point q (|q| >= d) is within asin(r / d) of q's direction.
  const double spread = std::asin(std::min(1.0, s.radius / d)) + 1e-12;
  return std::array<double, 2>{ref + lo - spread, ref + hi + spread};
}

}  // namespace

bool PoseCheck::collides() const {
  return std::any_of(contacts.begin(), contacts.end(), [](const Contact& c) { return c.collides; });
}

PoseCheck check_pose(const BodyRig& rig, Point p) {
  PoseCheck out;
  const auto shapes = rig.shapes_at(p);
  if (!shapes) return out;
  out.reachable = true;
  const BodyModel& m = rig.model();
  for (const PartPair& pr : m.pairs()) {
    const Shape& a = (*shapes)[static_cast<std::size_t>(pr.a)];
    const Shape& b = (*shapes)[static_cast<std::size_t>(pr.b)];
    Contact c{m.parts[static_cast<std::size_t>(pr.a)].name, m.parts[static_cast<std::size_t>(pr.b)].name, "overlap",
              clearance(a, b), false};
    c.collides = c.clearance <= 0.0;
    out.contacts.push_back(std::move(c));
  }
  if (m.min_link_angle > 0.0) {
    const auto v = rig.link_vectors_at(p);
    const auto names = rig.joint_links();
    Contact c{names[0], names[1], "link_angle", 0.0, false};
    c.clearance = unsigned_angle((*v)[0], (*v)[1]) - m.min_link_angle;
    c.collides = c.clearance < 0.0;
    out.contacts.push_back(std::move(c));
  }
  return out;
}

certified::CellTest interference_test(const BodyRig& rig, const PartPair& pair, double margin) {
  return [&rig, pair, margin](const Box& box) {
    const auto e = rig.enclose(box);
    if (!e) return CellState::outside;  // no reachable point in the box
    const auto& a = e->parts[static_cast<std::size_t>(pair.a)];
    const auto& b = e->parts[static_cast<std::size_t>(pair.b)];
    if (clearance(a.outer, b.outer) > margin) return CellState::outside;
    if (a.inner && b.inner && clearance(*a.inner, *b.inner) < -margin) return CellState::inside;
    return CellState::undecided;
  };
}

certified::CellTest link_angle_test(const BodyRig& rig, double margin) {
  const double theta = rig.model().min_link_angle;
  return [&rig, margin, theta](const Box& box) {
    const auto e = rig.enclose(box);
    if (!e) return CellState::outside;
    const auto r1 = angle_range(e->link_vectors[0], margin);
    const auto r2 = angle_range(e->link_vectors[1], margin);
    if (!r1 || !r2) return CellState::undecided;
    // delta = angle(u2) − angle(u1); the links collide iff |delta mod 2pi| < theta.
    double lo = (*r2)[0] - (*r1)[1], hi = (*r2)[1] - (*r1)[0];
    if (hi - lo >= 2 * pi - 2 * theta) return CellState::undecided;
    const double shift = wrap(0.5 * (lo + hi)) - 0.5 * (lo + hi);
    lo += shift;
    hi += shift;
    const double eps = 1e-12;
    bool meets = false;
    for (int k = -1; k <= 1; ++k) {
      const double c = 2 * pi * k;
      if (lo > c - theta + eps && hi < c + theta - eps) return CellState::inside;
      if (!(hi < c - theta - eps || lo > c + theta + eps)) meets = true;
    }
    return meets ? CellState::undecided : CellState::outside;
  };
}

geometry::Region minkowski_with_disk(const Shape& part, double r) {
  const double rr = r + part.radius;
  std::vector<geometry::Region> pieces;
  const auto& c = part.core;
  if (c.size() >= 3) pieces.push_back(geometry::polygon(c));
  if (!(rr > 0.0)) return c.size() >= 3 ? pieces.front() : geometry::Region{};  // no thickness: the polygon itself
  if (c.size() == 1) {
    pieces.push_back(geometry::disk(c[0], rr));
  } else {
    const std::size_t edges = c.size() == 2 ? 1 : c.size();
    // polygon ⊕ disk = polygon ∪ stadiums on its edges (each with the disks at its end points)
    for (std::size_t i = 0; i < edges; ++i) pieces.push_back(geometry::stadium(c[i], c[(i + 1) % c.size()], rr));
  }
  return geometry::Region::unite_all(pieces);
}

RealWorkspace real_workspace(const BodyRig& rig, const geometry::Region& reachable,
                             const InterferenceOptions& options) {
  RealWorkspace out;
  out.reachable = certified::from_exact(reachable);
  const BodyModel& m = rig.model();
  const Box bb = reachable.bbox();
  const double margin = bb.empty() ? 0.0 : 1e-9 * std::hypot(bb.width(), bb.height());
  certified::CellOptions cell;
  cell.base = options.base;
  cell.max_depth = options.max_depth;
  cell.threads = options.threads;
  std::optional<certified::CertifiedRegion> all;
  auto add = [&](Interference i) {
    all = all ? certified::unite(*all, i.region) : i.region;
    out.interference.push_back(std::move(i));
  };
  for (const PartPair& pr : m.pairs()) {
    const Part& a = m.parts[static_cast<std::size_t>(pr.a)];
    const Part& b = m.parts[static_cast<std::size_t>(pr.b)];
    Interference i{a.name, b.name, "overlap", {}};
    const Part* platform = a.kind == PartKind::platform_joint ? &a : (b.kind == PartKind::platform_joint ? &b : nullptr);
    const Part* other = platform == &a ? &b : &a;
    if (platform && other->fixed() && !reachable.empty()) {
      // Exact: the platform disk meets the fixed part iff P ∈ part ⊕ disk(r).
      const Shape fixed = rig.fixed_part(static_cast<std::size_t>(platform == &a ? pr.b : pr.a));
      i.region = certified::from_exact(reachable.intersect(minkowski_with_disk(fixed, platform->radius)));
    } else {
      i.region = certified::certify(interference_test(rig, pr, margin), reachable, cell);
    }
    add(std::move(i));
  }
  if (m.min_link_angle > 0.0) {
    const auto names = rig.joint_links();
    add(Interference{names[0], names[1], "link_angle", certified::certify(link_angle_test(rig, margin), reachable, cell)});
  }
  out.real = all ? certified::subtract(out.reachable, *all) : out.reachable;
  return out;
}

}  // namespace pkmws::bodies
