// The zero set of a smooth field traced with a certified chord error (see
// zero_set.hpp and docs/theory/level_sets.md, "Distance to the type-2
// singularity", for why the bounds hold).
#include "pkmws/certified/zero_set.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include "detail/parallel.hpp"
#include "certified/box.hpp"

namespace pkmws::certified {

using geometry::Box;
using geometry::Point;

double ZeroSetResult::length() const {
  double s = 0.0;
  for (const auto& p : pieces) {
    for (std::size_t k = 1; k < p.size(); ++k) s += std::hypot(p[k].x - p[k - 1].x, p[k].y - p[k - 1].y);
  }
  return s;
}

namespace {

// One box in graph coordinates: u along the graph's axis, v across it.
struct Frame {
  bool swap = false;  // false: u = x, v = y; true: u = y, v = x
  Point point(double u, double v) const { return swap ? Point{v, u} : Point{u, v}; }
  Box box(double u0, double u1, double v0, double v1) const {
    return swap ? make_box(v0, u0, v1, u1) : make_box(u0, v0, u1, v1);
  }
};

// The sign of g at a point, certified (0: not decided).
int certified_sign(const ScalarField& g, Point p) {
  const Interval v = g.enclose(make_box(p.x, p.y, p.x, p.y));
  if (v.lo > 0.0) return 1;
  if (v.hi < 0.0) return -1;
  return 0;
}

struct Bracket {
  double lo = 0.0, hi = 0.0;  // the root of v -> g(u, v) is in [lo, hi]
  double mid() const { return 0.5 * (lo + hi); }
};

enum class Root { none, found, failed };

class CellTracer {
 public:
  CellTracer(const ScalarField& g, const WithinTest& within, double max_error)
      : g_(g), within_(within), max_error_(max_error) {}

  // Traces Z in box B. nullopt: not traceable here (split the box). Otherwise
  // the pieces of Z ∩ B (possibly none) with their error.
  struct Traced {
    std::vector<std::vector<Point>> pieces;
    double error = 0.0;
    std::uint64_t samples = 0;
  };
  std::optional<Traced> trace(const Box& b) const {
    if (g_.domain(b) != CellState::inside) return std::nullopt;
    const Grad<Interval> gb = g_.grad(b);
    // Try the axis with the larger lower bound of |∂g/∂v| first.
    const bool prefer_x_graph = gb.dx.mig() > gb.dy.mig();  // |g_x| > 0: x = φ(y)
    for (int attempt = 0; attempt < 2; ++attempt) {
      Frame f;
      f.swap = (attempt == 0) == prefer_x_graph;
      std::optional<Traced> t = trace_in(b, f);
      if (t) return t;
    }
    return std::nullopt;
  }

 private:
  const ScalarField& g_;
  const WithinTest& within_;
  double max_error_;

  // Root of v -> g(u, v) in [lo, hi]; `up` the sign of g at hi (g increasing if +1).
  Root root(const Frame& f, double u, double lo, double hi, Bracket& out, std::uint64_t& samples) const {
    ++samples;
    const int s_lo = certified_sign(g_, f.point(u, lo)), s_hi = certified_sign(g_, f.point(u, hi));
    if (s_lo != 0 && s_lo == s_hi) return Root::none;
    if (s_lo == 0 || s_hi == 0) return Root::failed;
    const double up = s_hi;
    // Newton in double from the secant guess.
    const auto gval = [&](double v) { return g_.value(f.point(u, v)); };
    double a = lo, b = hi;
    double ga = gval(a), gb = gval(b);
    double v = (std::isfinite(ga) && std::isfinite(gb) && gb != ga) ? a - ga * (b - a) / (gb - ga) : 0.5 * (a + b);
    if (!(v > a && v < b)) v = 0.5 * (a + b);
    for (int it = 0; it < 12; ++it) {
      const Grad<double> d = g_.grad(f.point(u, v));
      const double dv = f.swap ? d.dx : d.dy;
      if (!(std::isfinite(d.v) && std::isfinite(dv)) || dv == 0.0) break;
      double next = v - d.v / dv;
      if (!(next > a && next < b)) next = 0.5 * (a + b);
      if (up * d.v > 0.0) b = v; else a = v;  // keep a (double) bracket of the sign change
      if (next == v) break;
      v = next;
    }
    // A certified bracket around v: widen until both signs are proved.
    const double scale = std::max({std::abs(v), std::abs(u), std::abs(lo), std::abs(hi)});
    double d = 4.0 * scale * std::numeric_limits<double>::epsilon();
    double cl = lo, ch = hi;  // certified: sign(lo) = -up, sign(hi) = up
    for (int it = 0; it < 60; ++it) {
      const double l = std::max(lo, v - d), h = std::min(hi, v + d);
      const int sl = l == lo ? -static_cast<int>(up) : certified_sign(g_, f.point(u, l));
      const int sh = h == hi ? static_cast<int>(up) : certified_sign(g_, f.point(u, h));
      if (sl == -up) cl = std::max(cl, l);
      if (sh == up) ch = std::min(ch, h);
      if (sl == -up && sh == up) break;
      if (l == lo && h == hi) break;
      d *= 4.0;
    }
    // Bisection of what is left, on certified signs only.
    for (int it = 0; it < 200 && ch - cl > 64.0 * scale * std::numeric_limits<double>::epsilon(); ++it) {
      const double m = 0.5 * (cl + ch);
      if (m <= cl || m >= ch) break;
      const int sm = certified_sign(g_, f.point(u, m));
      if (sm == 0) break;
      if (sm == up) ch = m; else cl = m;
    }
    out = {cl, ch};
    return Root::found;
  }

  std::optional<Traced> trace_in(const Box& b, const Frame& f) const {
    const double u0 = f.swap ? b.min.y : b.min.x, u1 = f.swap ? b.max.y : b.max.x;
    const double v0 = f.swap ? b.min.x : b.min.y, v1 = f.swap ? b.max.x : b.max.y;
    const double du = u1 - u0;
    // The extended box B' = [u0, u1] x [v0 - E, v1 + E] with 2 L du <= E.
    double e = 0.5 * std::max(v1 - v0, du);
    double lip = 0.0;
    bool ok = false;
    for (int it = 0; it < 4 && !ok; ++it) {
      const Box ext = f.box(u0, u1, v0 - e, v1 + e);
      if (within_ && within_(ext) != CellState::inside) return std::nullopt;
      if (g_.domain(ext) != CellState::inside) return std::nullopt;
      const Grad<Interval> gr = g_.grad(ext);
      const Interval gu = f.swap ? gr.dy : gr.dx, gv = f.swap ? gr.dx : gr.dy;
      if (!(gu.finite() && gv.finite()) || gv.contains_zero()) return std::nullopt;
      lip = gu.mag() / gv.mig();
      lip = lip * (1.0 + 1e-12) + 1e-300;
      if (2.0 * lip * du <= e) {
        ok = true;
      } else {
        e = 2.5 * lip * du;
      }
    }
    if (!ok) return std::nullopt;
    const double lo = v0 - e, hi = v1 + e;
    Traced out;
    Bracket ba, bb;
    const Root ra = root(f, u0, lo, hi, ba, out.samples);
    if (ra == Root::failed) return std::nullopt;
    if (ra == Root::none) return out;  // Z misses B (it would be a graph over all of [u0, u1])
    const Root rb = root(f, u1, lo, hi, bb, out.samples);
    if (rb == Root::failed) return std::nullopt;
    if (rb == Root::none) return out;
    // Chords, halved until their bound holds.
    struct Item {
      double a, b;
      Bracket ba, bb;
      int depth;
    };
    std::vector<Item> stack{{u0, u1, ba, bb, 0}};
    std::vector<std::pair<Point, Point>> segments;  // in u order
    int splits = 0;
    std::vector<double> seg_u;
    while (!stack.empty()) {
      const Item it = stack.back();
      stack.pop_back();
      const double delta = it.b - it.a;
      // If Z meets B over [a, b], its branch is a graph over [u0, u1] in B'
      // and φ(a) is within L Δ of [v0, v1], so the cone φ(a) ± L Δ lies in
      // B' (2 L du <= E). Contrapositive: a cone from a's bracket that leaves
      // B' says Z ∩ B is empty over [a, b]. Otherwise the branch through a is
      // a graph over [a, b] inside the cone (its only root at b is b's), and
      // it stays in the tent (Lipschitz from both ends).
      const double cone_lo = it.ba.lo - lip * delta, cone_hi = it.ba.hi + lip * delta;
      if (cone_lo < lo || cone_hi > hi) continue;
      double tlo = std::min(it.ba.lo, it.bb.lo) - 0.5 * lip * delta;
      double thi = std::max(it.ba.hi, it.bb.hi) + 0.5 * lip * delta;
      tlo = std::max(tlo, cone_lo);
      thi = std::min(thi, cone_hi);
      if (thi < v0 || tlo > v1) continue;  // this part of Z lies outside B (another box has it)
      const Jet<Interval> j = g_.jet(f.box(it.a, it.b, tlo, thi));
      const Interval gu = f.swap ? j.dy : j.dx, gv = f.swap ? j.dx : j.dy;
      const Interval guu = f.swap ? j.dyy : j.dxx, gvv = f.swap ? j.dxx : j.dyy, guv = j.dxy;
      // φ' = -g_u / g_v, φ'' = -(g_uu + 2 g_uv φ' + g_vv φ'²) / g_v (implicit differentiation).
      const Interval p1 = -(gu / gv);
      const Interval p2 = -((guu + Interval(2.0) * guv * p1 + gvv * sqr(p1)) / gv);
      const double m = p2.mag();
      double err = m * delta * delta / 8.0 + 0.5 * std::max(it.ba.hi - it.ba.lo, it.bb.hi - it.bb.lo);
      err = err * (1.0 + 1e-9);
      if (std::isfinite(err) && err <= max_error_) {
        out.error = std::max(out.error, err);
        segments.push_back({f.point(it.a, it.ba.mid()), f.point(it.b, it.bb.mid())});
        seg_u.push_back(it.a);
        continue;
      }
      // Not smooth enough here (an enclosure too wide, or a point where the
      // bound blows up): let the quadtree split the box instead.
      if (!std::isfinite(err) || it.depth >= 16 || ++splits > 4096) return std::nullopt;
      const double mid = 0.5 * (it.a + it.b);
      Bracket bm;
      const Root rm = root(f, mid, lo, hi, bm, out.samples);
      if (rm == Root::failed) return std::nullopt;
      if (rm == Root::none) return std::nullopt;  // cannot happen on a graph over [a, b]
      stack.push_back({mid, it.b, bm, it.bb, it.depth + 1});
      stack.push_back({it.a, mid, it.ba, bm, it.depth + 1});
    }
    // The stack pops in u order: chain consecutive segments.
    for (std::size_t k = 0; k < segments.size(); ++k) {
      const auto& [p, q] = segments[k];
      if (out.pieces.empty() || !(out.pieces.back().back().x == p.x && out.pieces.back().back().y == p.y)) {
        out.pieces.push_back({p});
      }
      out.pieces.back().push_back(q);
    }
    return out;
  }
};

struct Work {
  const ScalarField& g;
  const WithinTest& within;
  const ZeroSetOptions& o;
  CellTracer tracer;
  std::atomic<std::size_t>& undecided_count;
  bool over_time() const {
    return o.deadline != std::chrono::steady_clock::time_point::max() && std::chrono::steady_clock::now() >= o.deadline;
  }

  void run(const Box& b, int depth, ZeroSetResult& r) const {
    ++r.cell_tests;
    if (within) {
      const CellState w = within(b);
      if (w == CellState::outside) return;
    }
    const Interval v = g.enclose(b);
    if (v.lo > 0.0 || v.hi < 0.0) return;
    if (depth >= o.min_trace_depth) {
      if (auto t = tracer.trace(b)) {
        ++r.traced_cells;
        r.samples += t->samples;
        r.error = std::max(r.error, t->error);
        for (auto& p : t->pieces) r.pieces.push_back(std::move(p));
        return;
      }
    }
    if (depth >= o.max_depth || undecided_count.load(std::memory_order_relaxed) >= o.max_undecided || over_time()) {
      if (depth < o.max_depth) r.stopped = true;
      undecided_count.fetch_add(1, std::memory_order_relaxed);
      r.undecided.push_back(b);
      return;
    }
    const double xm = 0.5 * (b.min.x + b.max.x), ym = 0.5 * (b.min.y + b.max.y);
    run(make_box(b.min.x, b.min.y, xm, ym), depth + 1, r);
    run(make_box(xm, b.min.y, b.max.x, ym), depth + 1, r);
    run(make_box(b.min.x, ym, xm, b.max.y), depth + 1, r);
    run(make_box(xm, ym, b.max.x, b.max.y), depth + 1, r);
  }
};

}  // namespace

ZeroSetResult trace_zero_set(const ScalarField& g, const Box& window, const WithinTest& within,
                             const ZeroSetOptions& options) {
  if (window.empty() || !(window.width() > 0.0) || !(window.height() > 0.0)) {
    throw std::invalid_argument("trace_zero_set: empty window");
  }
  if (!(options.max_error > 0.0)) throw std::invalid_argument("trace_zero_set: max_error must be positive");
  if (options.base < 1 || options.max_depth < 0 || options.max_depth > 30) {
    throw std::invalid_argument("trace_zero_set: base >= 1 and max_depth in [0, 30]");
  }
  const int n = options.base;
  std::vector<ZeroSetResult> per(static_cast<std::size_t>(n) * static_cast<std::size_t>(n));
  std::atomic<std::size_t> undecided{0};
  const Work work{g, within, options, CellTracer(g, within, options.max_error), undecided};
  const double hx = window.width() / n, hy = window.height() / n;
  detail::ParallelPolicy policy;
  policy.threads = options.threads;
  policy.serial_threshold = 1;
  detail::for_each_block(policy, per.size(), per.size() * 64, [&](std::size_t k) {
    const int i = static_cast<int>(k % static_cast<std::size_t>(n)), j = static_cast<int>(k / static_cast<std::size_t>(n));
    const double x0 = window.min.x + i * hx, y0 = window.min.y + j * hy;
    const double x1 = i + 1 == n ? window.max.x : window.min.x + (i + 1) * hx;
    const double y1 = j + 1 == n ? window.max.y : window.min.y + (j + 1) * hy;
    work.run(make_box(x0, y0, x1, y1), 0, per[k]);
  });
  ZeroSetResult out;
  for (auto& r : per) out.append(std::move(r));
  return out;
}

void ZeroSetResult::append(ZeroSetResult&& other) {
  cell_tests += other.cell_tests;
  traced_cells += other.traced_cells;
  samples += other.samples;
  error = std::max(error, other.error);
  stopped = stopped || other.stopped;
  for (auto& p : other.pieces) pieces.push_back(std::move(p));
  undecided.insert(undecided.end(), other.undecided.begin(), other.undecided.end());
}

}  // namespace pkmws::certified
