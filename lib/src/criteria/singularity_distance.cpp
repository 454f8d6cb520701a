// The distance to the type-2 singularity (singularity_distance.hpp; the
// bounds in docs/theory/level_sets.md, "Distance to the type-2 singularity").
#include "criteria/singularity_distance.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <map>
#include <numbers>
#include <stdexcept>

#include "detail/parallel.hpp"
#include "pkmws/certified/zero_set.hpp"
#include "pkmws/core/error.hpp"
#include "pkmws/geometry/primitives.hpp"

namespace pkmws::criteria {

// The default of the capability: no singular determinant (a module that has
// one overrides it).
CriterionField CriterionFields::singular_determinant(const mechanisms::Criteria& /*criteria*/) const {
  throw std::invalid_argument("this mechanism gives no type-2 singular determinant field");
}

namespace detail {

using geometry::Box;
using geometry::Point;
using geometry::Region;

CriterionField singular_field(const mechanisms::Design& file) {
  const auto capability = file.model->capability<CriterionFields>();
  if (!capability) throw InputError(file.path + ": criteria.min_singularity_distance: " + capability.reason());
  try {
    return capability->singular_determinant(file.criteria);
  } catch (const std::invalid_argument& e) {
    throw InputError(file.path + ": criteria.min_singularity_distance: " + e.what());
  }
}

namespace {

Point add(Point a, Point b, double s) { return {a.x + s * b.x, a.y + s * b.y}; }

// The union of the segments' stadiums (directions rounded to rational ones,
// ~1e-16 rad: covered by the callers' radius margins).
void stadium_parts(const std::vector<Point>& v, double r, std::vector<Region>& parts) {
  for (std::size_t k = 0; k + 1 < v.size(); ++k) parts.push_back(geometry::stadium(v[k], v[k + 1], r));
}

// The polyline without repeated points in `v`, and r moved by a margin that
// covers the rounding of the offsets (a few ulps of the coordinates).
double prepared(const std::vector<Point>& piece, double r, bool superset, std::vector<Point>& v) {
  v.clear();
  for (const Point& p : piece) {
    if (v.empty() || v.back().x != p.x || v.back().y != p.y) v.push_back(p);
  }
  double scale = r;
  for (const Point& p : v) scale = std::max({scale, std::abs(p.x), std::abs(p.y)});
  const double margin = 1e-12 * scale;
  return superset ? r + margin : r - margin;
}

// The tube of a prepared polyline as one polygon and its end disks; false,
// with nothing added, where that polygon cannot be made (a sharp turn, or
// offset chains that cross).
bool tube_polygon(const std::vector<Point>& v, double r, bool superset, std::vector<Region>& parts);

// Chains of pieces: a piece whose first or last point lies within `join` of a
// chain's free end continues it (turned round if need be; the lowest index
// first), the chain keeping its own end point. That moves the polyline by at
// most the distance between the two points, the largest of which is `gap`.
// A chain that comes back to its start is cut in two (a closed loop's tube is
// no simple polygon). With `join` 0 every piece is a chain of its own.
struct Chain {
  std::vector<Point> points;
  std::vector<std::size_t> members;  // indices into the pieces, in chain order
};
std::vector<Chain> chain_pieces(const std::vector<const std::vector<Point>*>& pieces, double join, double& gap) {
  gap = 0.0;
  std::vector<Chain> chains;
  if (!(join > 0.0)) {  // nothing joins: each piece is a chain of its own
    for (std::size_t k = 0; k < pieces.size(); ++k) chains.push_back({*pieces[k], {k}});
    return chains;
  }
  // Ends are bucketed by a grid of side >= join (so the ends within join of a
  // point lie in its bucket's 3 x 3 block), coarse enough that the buckets'
  // indices stay small.
  double scale = 0.0;
  for (const auto* piece : pieces) {
    for (const Point& p : {piece->front(), piece->back()}) scale = std::max({scale, std::abs(p.x), std::abs(p.y)});
  }
  const double side = std::max(join, 1e-9 * scale);
  const auto cell = [side](Point p) {
    return std::make_pair(static_cast<long long>(std::floor(p.x / side)), static_cast<long long>(std::floor(p.y / side)));
  };
  std::map<std::pair<long long, long long>, std::vector<std::size_t>> ends;  // piece indices by end cell
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    ends[cell(pieces[k]->front())].push_back(k);
    ends[cell(pieces[k]->back())].push_back(k);
  }
  std::vector<bool> used(pieces.size(), false);
  // The unused piece with an end within `join` of p (lowest index), and
  // whether it is its back that meets p.
  const auto next_to = [&](Point p, bool& at_back) {
    std::size_t best = pieces.size();
    const auto [cx, cy] = cell(p);
    for (long long i = cx - 1; i <= cx + 1; ++i) {
      for (long long j = cy - 1; j <= cy + 1; ++j) {
        const auto it = ends.find({i, j});
        if (it == ends.end()) continue;
        for (const std::size_t k : it->second) {
          if (used[k] || k >= best) continue;
          const Point a = pieces[k]->front(), b = pieces[k]->back();
          if (std::hypot(a.x - p.x, a.y - p.y) <= join) {
            best = k;
            at_back = false;
          } else if (std::hypot(b.x - p.x, b.y - p.y) <= join) {
            best = k;
            at_back = true;
          }
        }
      }
    }
    return best;
  };
  for (std::size_t first = 0; first < pieces.size(); ++first) {
    if (used[first]) continue;
    used[first] = true;
    std::deque<Point> pts(pieces[first]->begin(), pieces[first]->end());
    std::deque<std::size_t> members{first};
    for (const bool forward : {true, false}) {
      for (;;) {
        const Point end = forward ? pts.back() : pts.front();
        bool at_back = false;
        const std::size_t k = next_to(end, at_back);
        if (k == pieces.size()) break;
        used[k] = true;
        std::vector<Point> add(pieces[k]->begin(), pieces[k]->end());
        // Oriented to leave from `end`: forward, its meeting point first.
        if (at_back == forward) std::reverse(add.begin(), add.end());
        const Point meet = forward ? add.front() : add.back();
        gap = std::max(gap, std::hypot(meet.x - end.x, meet.y - end.y));
        if (forward) {
          pts.insert(pts.end(), add.begin() + 1, add.end());
          members.push_back(k);
        } else {
          pts.insert(pts.begin(), add.begin(), add.end() - 1);
          members.push_front(k);
        }
      }
    }
    Chain c{{pts.begin(), pts.end()}, {members.begin(), members.end()}};
    const Point a = c.points.front(), b = c.points.back();
    if (c.members.size() >= 2 && std::hypot(a.x - b.x, a.y - b.y) <= join) {
      // Closed: two halves, each ending at the first piece's start or at the cut.
      std::size_t cut = 0;
      for (std::size_t m = 0; m < c.members.size() / 2; ++m) cut += pieces[c.members[m]]->size() - 1;
      Chain second{{c.points.begin() + static_cast<std::ptrdiff_t>(cut), c.points.end()},
                   {c.members.begin() + static_cast<std::ptrdiff_t>(c.members.size() / 2), c.members.end()}};
      c.points.resize(cut + 1);
      c.members.resize(c.members.size() / 2);
      chains.push_back(std::move(c));
      chains.push_back(std::move(second));
    } else {
      chains.push_back(std::move(c));
    }
  }
  return chains;
}

}  // namespace

Region polyline_tube(const std::vector<Point>& piece, double r, bool superset) {
  std::vector<Region> parts;
  polyline_tube_parts(piece, r, superset, parts);
  return Region::unite_all(parts);
}

void polyline_tube_parts(const std::vector<Point>& piece, double r, bool superset, std::vector<Region>& parts) {
  std::vector<Point> v;
  r = prepared(piece, r, superset, v);
  if (v.empty() || !(r > 0.0)) return;
  if (!tube_polygon(v, r, superset, parts)) stadium_parts(v, r, parts);
}

namespace {

bool tube_polygon(const std::vector<Point>& v, double r, bool superset, std::vector<Region>& parts) {
  if (v.size() == 1) {
    parts.push_back(geometry::disk(v[0], r));
    return true;
  }
  const std::size_t n = v.size() - 1;  // segments
  std::vector<Point> normal(n);
  std::vector<double> length(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double dx = v[k + 1].x - v[k].x, dy = v[k + 1].y - v[k].y;
    length[k] = std::hypot(dx, dy);
    normal[k] = {-dy / length[k], dx / length[k]};
  }
  // Left and right offset chains. Each edge of a chain lies on the offset
  // line of its segment: the polygon holds the segments' rectangles. At a
  // joint, the concave side takes the miter point (the offset lines'
  // intersection, inside both rectangles when r tan(θ/2) <= both lengths);
  // the convex side takes the miter point too when `superset` (the kite holds
  // the disk's wedge), else the two points on the circle (their chord lies in
  // the disk).
  std::vector<Point> left{add(v[0], normal[0], r)}, right{add(v[0], normal[0], -r)};
  for (std::size_t k = 1; k < n; ++k) {
    const Point a = normal[k - 1], b = normal[k];
    const double dot = a.x * b.x + a.y * b.y, cross = a.x * b.y - a.y * b.x;
    if (!(1.0 + dot > 0.5)) return false;  // a turn over 120°
    const double tan_half = std::abs(cross) / (1.0 + dot);
    if (r * tan_half > 0.999 * std::min(length[k - 1], length[k])) return false;
    const Point m{(a.x + b.x) / (1.0 + dot), (a.y + b.y) / (1.0 + dot)};
    if (cross == 0.0) {
      left.push_back(add(v[k], a, r));
      right.push_back(add(v[k], a, -r));
    } else if (superset) {
      left.push_back(add(v[k], m, r));
      right.push_back(add(v[k], m, -r));
    } else if (cross > 0.0) {  // turning left: the left side is concave
      left.push_back(add(v[k], m, r));
      right.push_back(add(v[k], a, -r));
      right.push_back(add(v[k], b, -r));
    } else {
      right.push_back(add(v[k], m, -r));
      left.push_back(add(v[k], a, r));
      left.push_back(add(v[k], b, r));
    }
  }
  left.push_back(add(v[n], normal[n - 1], r));
  right.push_back(add(v[n], normal[n - 1], -r));
  std::vector<Point> ring = left;
  ring.insert(ring.end(), right.rbegin(), right.rend());
  try {
    parts.push_back(geometry::polygon(ring));
  } catch (const std::invalid_argument&) {
    return false;  // the offset chains cross (the piece bends back within 2r)
  }
  parts.push_back(geometry::disk(v.front(), r));
  parts.push_back(geometry::disk(v.back(), r));
  return true;
}

}  // namespace

double distance_to_curves(const std::vector<std::vector<Point>>& curves, Point p) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& c : curves) {
    if (c.size() == 1) best = std::min(best, std::hypot(p.x - c[0].x, p.y - c[0].y));
    for (std::size_t k = 0; k + 1 < c.size(); ++k) {
      const double dx = c[k + 1].x - c[k].x, dy = c[k + 1].y - c[k].y;
      const double l2 = dx * dx + dy * dy;
      double t = l2 > 0.0 ? ((p.x - c[k].x) * dx + (p.y - c[k].y) * dy) / l2 : 0.0;
      t = std::clamp(t, 0.0, 1.0);
      best = std::min(best, std::hypot(p.x - (c[k].x + t * dx), p.y - (c[k].y + t * dy)));
    }
  }
  return best;
}

SingularTubes singular_tubes(const mechanisms::Design& file, const Region& within, double delta, double area_estimate,
                             const certified::LevelSetOptions& options, bool build_tubes) {
  const CriterionField field = singular_field(file);
  SingularTubes t;
  if (!field.nowhere.empty()) {
    t.nowhere = field.nowhere;
    return t;
  }
  if (within.empty()) {
    t.empty_set = true;
    return t;
  }
  const Box window = within.bbox();
  const double diag = std::hypot(window.width(), window.height());
  certified::ZeroSetOptions zo;
  zo.threads = options.threads;
  zo.deadline = options.deadline;
  // A coarse pass for the length of S.
  zo.max_error = 1e-3 * diag;
  zo.max_depth = 10;
  const certified::ZeroSetResult coarse = certified::trace_zero_set(*field.surrogate, window, field.within_test, zo);
  if (coarse.pieces.empty() && coarse.undecided.empty()) {
    t.empty_set = true;
    return t;
  }
  double length = coarse.length();
  for (const Box& b : coarse.undecided) length += std::hypot(b.width(), b.height());
  // The bounds' width is about 4 w length (two sides of the tube, each 2 w thick).
  double w = 0.9 * options.relative_tolerance * std::max(area_estimate, 0.0) / (4.0 * std::max(length, 1e-300));
  w = std::min({w, 0.25 * delta, 1e-3 * diag});
  if (!(w > 0.0)) w = 1e-9 * diag;
  zo.max_error = w;
  zo.max_depth = 16;
  certified::ZeroSetResult fine = certified::trace_zero_set(*field.surrogate, window, field.within_test, zo);
  // A box left undecided at the depth limit (where S crosses W's boundary,
  // or the tracer fails at a point) widens the bounds by about the rim of its
  // disk, π δ diag(box) (below). Such boxes are traced again 4 levels deeper
  // while that exceeds a tenth of the target width: a crossing leaves one to
  // three boxes per level, so a round divides the sum by 5 to 16. Where the
  // boxes multiply instead (S along W's boundary, a singular point: the
  // DexTAR's 9 500 boxes became 30 000) deeper levels buy little for their
  // cost, so rounds are tried only on up to 1 024 boxes, and one is kept only
  // when it at least halves the sum.
  const double budget = 0.1 * options.relative_tolerance * std::max(area_estimate, 0.0);
  const auto rims = [delta](const std::vector<Box>& boxes) {
    double sum = 0.0;
    for (const Box& b : boxes) sum += std::numbers::pi * delta * std::hypot(b.width(), b.height());
    return sum;
  };
  certified::ZeroSetOptions deeper = zo;
  deeper.base = 2;
  deeper.max_depth = 3;
  deeper.min_trace_depth = 0;
  double rim = rims(fine.undecided);
  for (int depth = zo.max_depth; rim > budget && depth + 4 <= 30 && !fine.stopped && fine.undecided.size() <= 1024;
       depth += 4) {
    certified::ZeroSetResult round;
    for (const Box& b : fine.undecided) {
      round.append(certified::trace_zero_set(*field.surrogate, b, field.within_test, deeper));
    }
    const double next = rims(round.undecided);
    if (!(next <= 0.5 * rim)) break;
    // The deeper boxes replace the ones they split; pieces and counts add up.
    fine.undecided.clear();
    fine.append(std::move(round));
    rim = next;
  }
  t.curves = std::move(fine.pieces);
  t.undecided = std::move(fine.undecided);
  t.error = fine.error;
  t.stopped = fine.stopped;
  if (t.curves.empty() && t.undecided.empty()) {
    t.empty_set = true;
    return t;
  }
  if (!build_tubes) return t;
  std::vector<Region> in_parts, out_parts;
  // Where S cannot be traced (it meets W's boundary tangentially at a leg's
  // type-1 singularity, or runs into a point where g is undefined) the
  // quadtree leaves many tiny boxes and tiny traced pieces. They are grouped
  // by a grid of side c: each group's bounding box B (boxes, and pieces
  // widened by w) gives one disk of radius δ + ½ diag(B) ⊇ B ⊕ disk(δ) in the
  // inner tube; the pieces grouped so are left out of the outer tube (a
  // subset of it stays a subset).
  // c grows (by 2) until at most max_parts pieces and groups are left, which
  // bounds the exact Boolean work; the width a group adds is about that of
  // the S it stands for (its disk's rim), whatever c.
  constexpr std::size_t max_parts = 3000;
  std::vector<double> piece_size;
  for (const auto& piece : t.curves) {
    Box bb;
    for (const Point& p : piece) bb.expand(p);
    piece_size.push_back(std::max(bb.width(), bb.height()));
  }
  // The grid starts no coarser than what keeps the groups' rims (about
  // π δ diag each, one group per undecided box where S crosses W's boundary)
  // within the budget (halving 1e-5 δ, so that where the parts' bound below
  // decides, the grid is the one it was).
  const double finest =
      budget / (std::numbers::pi * delta * static_cast<double>(std::max<std::size_t>(t.undecided.size(), 4)));
  double c = 1e-5 * delta;
  for (int it = 0; it < 40 && c > finest && c > 1e-12 * diag; ++it) c *= 0.5;
  for (int it = 0; it < 80; ++it) {
    std::size_t parts = 0;
    std::map<std::pair<long long, long long>, int> cells;
    const auto key_of = [&](const Box& b) {
      return std::make_pair(static_cast<long long>(std::floor((0.5 * (b.min.x + b.max.x) - window.min.x) / c)),
                            static_cast<long long>(std::floor((0.5 * (b.min.y + b.max.y) - window.min.y) / c)));
    };
    for (std::size_t k = 0; k < t.curves.size(); ++k) {
      if (piece_size[k] >= c) {
        ++parts;
      } else {
        Box bb;
        for (const Point& p : t.curves[k]) bb.expand(p);
        cells[key_of(bb)] = 1;
      }
    }
    for (const Box& b : t.undecided) cells[key_of(b)] = 1;
    if (parts + cells.size() <= max_parts || c > 0.25 * delta) break;
    c *= 2.0;
  }
  struct Group {
    Box box;
    std::vector<Point> on_curve;  // chord points (each within w of S)
  };
  std::map<std::pair<long long, long long>, Group> groups;
  const auto group = [&](const Box& b, const Point* on_curve) {
    const Point m{0.5 * (b.min.x + b.max.x), 0.5 * (b.min.y + b.max.y)};
    const auto key = std::make_pair(static_cast<long long>(std::floor((m.x - window.min.x) / c)),
                                    static_cast<long long>(std::floor((m.y - window.min.y) / c)));
    Group& g = groups[key];
    g.box.expand(b);
    if (on_curve) g.on_curve.push_back(*on_curve);
  };
  std::vector<std::size_t> long_pieces;
  for (std::size_t k = 0; k < t.curves.size(); ++k) {
    const auto& piece = t.curves[k];
    Box bb;
    for (const Point& p : piece) bb.expand(p);
    if (std::max(bb.width(), bb.height()) < c) {
      bb.min = {bb.min.x - t.error, bb.min.y - t.error};
      bb.max = {bb.max.x + t.error, bb.max.y + t.error};
      group(bb, &piece.front());
      continue;
    }
    long_pieces.push_back(k);
  }
  // The long pieces joined where they meet (each traced cell's piece ends
  // on the cell's edge, where its neighbour's starts, to rounding): one
  // polygon and two disks per chain instead of per cell, for the unions below
  // (the biglide's straight S: 60 pieces, 184 parts, became 1 chain). A
  // chain's polygon has the radius margin of the points it moved; where it
  // cannot be made, its pieces' tubes are taken.
  std::vector<const std::vector<Point>*> long_curves;
  for (const std::size_t k : long_pieces) long_curves.push_back(&t.curves[k]);
  double gap = 0.0;
  const std::vector<Chain> chains = chain_pieces(long_curves, t.error, gap);
  const auto add_tube = [&](const Chain& chain, double r, bool superset, std::vector<Region>& parts) {
    if (chain.members.size() >= 2) {
      std::vector<Point> v;
      const double rc = prepared(chain.points, superset ? r + gap : r - gap, superset, v);
      if (!(rc > 0.0) || tube_polygon(v, rc, superset, parts)) return;
    }
    for (const std::size_t m : chain.members) polyline_tube_parts(*long_curves[m], r, superset, parts);
  };
  // The chains' tubes (exact polygons and disks) are built as parallel tasks
  // over fixed blocks of chains and kept in chain order, so the parts do not
  // depend on the number of threads.
  pkmws::detail::ParallelPolicy policy;
  policy.threads = options.threads;
  policy.serial_threshold = 32;  // chains; each tube takes tens of microseconds
  constexpr std::size_t per_block = 8;
  const std::size_t blocks = pkmws::detail::block_count(chains.size(), per_block);
  std::vector<std::vector<Region>> block_in(blocks), block_out(blocks);
  pkmws::detail::for_each_block(policy, blocks, chains.size(), [&](std::size_t b) {
    for (std::size_t i = b * per_block; i < std::min(chains.size(), (b + 1) * per_block); ++i) {
      add_tube(chains[i], delta + t.error, true, block_in[b]);
      if (delta - t.error > 0.0) add_tube(chains[i], delta - t.error, false, block_out[b]);
    }
  });
  for (std::size_t b = 0; b < blocks; ++b) {
    in_parts.insert(in_parts.end(), block_in[b].begin(), block_in[b].end());
    out_parts.insert(out_parts.end(), block_out[b].begin(), block_out[b].end());
  }
  for (const Box& b : t.undecided) group(b, nullptr);
  for (const auto& [key, g] : groups) {
    const Box& b = g.box;
    const Point m{0.5 * (b.min.x + b.max.x), 0.5 * (b.min.y + b.max.y)};
    const double r = (delta + 0.5 * std::hypot(b.width(), b.height())) * (1.0 + 1e-12);
    in_parts.push_back(geometry::disk(m, r));
    // The outer tube keeps a disk of radius δ − w about the grouped chord
    // point nearest the middle: within δ of S, so a subset of {d < δ}.
    if (!g.on_curve.empty() && delta - t.error > 0.0) {
      Point best = g.on_curve.front();
      for (const Point& p : g.on_curve) {
        if (std::hypot(p.x - m.x, p.y - m.y) < std::hypot(best.x - m.x, best.y - m.y)) best = p;
      }
      const double scale = std::max({delta, std::abs(best.x), std::abs(best.y)});
      const double ro = (delta - t.error) - 1e-12 * scale;
      if (ro > 0.0) out_parts.push_back(geometry::disk(best, ro));
    }
  }
  // The two unions are independent: two tasks.
  policy.serial_threshold = 64;  // parts
  pkmws::detail::for_each_block(policy, 2, in_parts.size() + out_parts.size(), [&](std::size_t k) {
    if (k == 0) t.inner_tube = Region::unite_all(in_parts);
    else t.outer_tube = Region::unite_all(out_parts);
  });
  return t;
}

}  // namespace detail
}  // namespace pkmws::criteria
