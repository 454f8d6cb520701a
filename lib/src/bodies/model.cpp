// Which pairs of parts may collide (docs/format.md (bodies)): every pair with at least one
// moving part, both solid, not joined by a joint and not listed as allowed.
#include "pkmws/bodies/bodies.hpp"

namespace pkmws::bodies {

int BodyModel::find(const std::string& name) const {
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (parts[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

namespace {
// A link ending at the platform joint: a MOMA rod or a five-bar distal link.
bool platform_link(const Part& p) { return p.kind == PartKind::link && !p.proximal; }
}  // namespace

bool BodyModel::joined(int ia, int ib) const {
  const Part& a = parts[static_cast<std::size_t>(ia)];
  const Part& b = parts[static_cast<std::size_t>(ib)];
  auto is = [](const Part& p, PartKind k) { return p.kind == k; };
  auto either = [&](auto&& f) { return f(a, b) || f(b, a); };
  return either([&](const Part& x, const Part& y) {
    // The platform joint carries the links that meet at it.
    if (is(x, PartKind::platform_joint) && platform_link(y)) return true;
    // The two links meeting at the platform (their angle is checked separately).
    if (platform_link(x) && platform_link(y)) return true;
    // Same leg: rod on its slider, slider on its housing, distal on its proximal link.
    if (x.leg >= 0 && x.leg == y.leg) {
      if (is(x, PartKind::link) && is(y, PartKind::slider_block)) return true;
      if (is(x, PartKind::slider_block) && is(y, PartKind::housing)) return true;
      if (is(x, PartKind::link) && is(y, PartKind::link)) return true;
    }
    return false;
  });
}

bool BodyModel::allowed(int ia, int ib) const {
  const std::string& a = parts[static_cast<std::size_t>(ia)].name;
  const std::string& b = parts[static_cast<std::size_t>(ib)].name;
  for (const auto& [x, y] : allowed_contacts) {
    if ((x == a && y == b) || (x == b && y == a)) return true;
  }
  return false;
}

std::vector<PartPair> BodyModel::pairs() const {
  std::vector<PartPair> out;
  const int n = static_cast<int>(parts.size());
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      const Part& a = parts[static_cast<std::size_t>(i)];
      const Part& b = parts[static_cast<std::size_t>(j)];
      if (a.fixed() && b.fixed()) continue;
      if (!a.solid() || !b.solid()) continue;
      if (joined(i, j) || allowed(i, j)) continue;
      out.push_back({i, j});
    }
  }
  return out;
}

}  // namespace pkmws::bodies
