// The global conditioning index (docs/design_space.md, "The global
// conditioning index"): a midpoint rule over grid cells clipped to the exact
// workspace. Cells the boundary cannot reach (the distance from the cell's
// centre to every boundary curve exceeds its half-diagonal) are whole, inside
// or outside as one exact membership test per run of such cells in a row
// says; the others are clipped exactly (Region booleans). Each piece carries
// its exact area and centroid, and 1/κ is evaluated at the centroid. The
// coarse rule sums the same pieces over 2x2 blocks (their union's centroid),
// so the two resolutions differ only in where 1/κ is sampled.
#include "pkmws/design/gci.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <vector>

#include "detail/parallel.hpp"
#include "pkmws/criteria/fields.hpp"
#include "pkmws/geometry/primitives.hpp"

namespace pkmws::design {

namespace {

using geometry::Box;
using geometry::Curve;
using geometry::Point;

// Distance from p to a boundary curve (segment or arc).
double distance_to(const Curve& c, Point p) {
  if (c.kind == Curve::Kind::segment) {
    const Point d = c.target - c.source;
    const double len2 = geometry::dot(d, d);
    const double t = len2 > 0.0 ? std::clamp(geometry::dot(p - c.source, d) / len2, 0.0, 1.0) : 0.0;
    return geometry::norm(p - (c.source + t * d));
  }
  const double sweep = c.sweep();
  const double ends = std::min(geometry::norm(p - c.source), geometry::norm(p - c.target));
  const Point v = p - c.center;
  if (std::abs(sweep) >= 2.0 * std::numbers::pi || geometry::norm(v) == 0.0) {
    return std::abs(geometry::norm(v) - c.radius);
  }
  const double a0 = std::atan2(c.source.y - c.center.y, c.source.x - c.center.x);
  const double a = std::atan2(v.y, v.x);
  const double turn = 2.0 * std::numbers::pi;
  const double rel = sweep > 0 ? std::fmod(a - a0 + 2.0 * turn, turn) : std::fmod(a0 - a + 2.0 * turn, turn);
  if (rel <= std::abs(sweep)) return std::min(ends, std::abs(geometry::norm(v) - c.radius));
  return ends;
}

// 1/κ at p for the file's working mode (the first evaluation), or nothing when
// the mechanism gives no condition number there (κ is NaN, or below 1: unset).
// κ comes from the mechanism's condition-number criterion field when it has
// one (for a point platform the closed form of the same κ in the file's
// working mode, without every mode's joints, SVDs and reasons: a 48-design
// MOMA GCI sweep went from 4.4 s to 2.7 s), else from evaluate().
using Kappa = std::function<double(Point)>;

Kappa condition_number_of(const mechanisms::Mechanism& m) {
  if (const auto fields = m.capability<criteria::CriterionFields>()) {
    try {
      for (criteria::CriterionField& f : fields->fields("condition_number", {}, {})) {
        if (f.name == "condition_number" && f.value && f.nowhere.empty()) return std::move(f.value);
      }
    } catch (const std::exception&) {
      // no field for this mechanism (e.g. a scheme without closed forms): evaluate() below
    }
  }
  return [&m](Point p) {
    const auto ev = m.evaluate({p.x, p.y, m.orientation()}, {});
    return ev.empty() ? std::numeric_limits<double>::quiet_NaN() : ev.front().condition_number;
  };
}

std::optional<double> inverse_condition(const Kappa& kappa, Point p) {
  try {
    const double k = kappa(p);
    if (std::isnan(k) || k < 1.0 - 1e-9) return std::nullopt;
    return std::isinf(k) ? 0.0 : std::min(1.0, 1.0 / k);
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

struct Piece {
  double area = 0.0;
  Point centroid;
  std::optional<double> f;  // 1/κ at the centroid (or a fallback point of the piece)
};

}  // namespace

GciResult global_conditioning_index(const mechanisms::Mechanism& mechanism,
                                    const certified::CertifiedRegion& workspace, const GciOptions& options) {
  GciResult out;
  const geometry::Region& region = workspace.inner;
  if (region.empty()) {
    out.reason = workspace.exact ? "the workspace is empty" : "the certified workspace has an empty inner enclosure";
    return out;
  }
  const Box bb = region.bbox();
  const int cells = std::max(2, options.cells + (options.cells % 2));
  const double h = std::max(bb.width(), bb.height()) / cells;
  if (!(h > 0.0)) {
    out.reason = "the workspace has no extent";
    return out;
  }
  const int nx = std::max(2, 2 * static_cast<int>(std::ceil(bb.width() / h / 2.0)));
  const int ny = std::max(2, 2 * static_cast<int>(std::ceil(bb.height() / h / 2.0)));
  // Centre the grid on the bounding box.
  const Point origin{bb.min.x - 0.5 * (nx * h - bb.width()), bb.min.y - 0.5 * (ny * h - bb.height())};
  out.cell_size = h;

  std::vector<Curve> curves;
  for (const auto& loop : region.loops()) curves.insert(curves.end(), loop.curves.begin(), loop.curves.end());
  const double reach = 0.5 * std::sqrt(2.0) * h * (1.0 + 1e-9) + 1e-12 * std::max(bb.width(), bb.height());
  // A curve within `reach` of a cell centre of row j has a point in the row's
  // band widened by `reach`: each row tests only those (boxes of arcs: their circle's).
  std::vector<std::array<double, 2>> y_extent;
  for (const Curve& c : curves) {
    if (c.kind == Curve::Kind::segment) {
      y_extent.push_back({std::min(c.source.y, c.target.y), std::max(c.source.y, c.target.y)});
    } else {
      y_extent.push_back({c.center.y - c.radius, c.center.y + c.radius});
    }
  }

  // The region cut into row strips by halving (about log2(ny) Booleans of the
  // whole region's size instead of one per row: staircase boundaries of
  // certified regions have thousands of curves).
  std::vector<geometry::Region> strips(static_cast<std::size_t>(ny));
  const auto rows_box = [&](int lo, int hi) {
    return geometry::rectangle({{origin.x - h, origin.y + lo * h}, {origin.x + (nx + 1) * h, origin.y + hi * h}});
  };
  const std::function<void(const geometry::Region&, int, int)> split = [&](const geometry::Region& part, int lo,
                                                                          int hi) {
    if (part.empty()) return;
    if (hi - lo == 1) {
      strips[static_cast<std::size_t>(lo)] = part;
      return;
    }
    const int mid = (lo + hi) / 2;
    split(part.intersect(rows_box(lo, mid)), lo, mid);
    split(part.intersect(rows_box(mid, hi)), mid, hi);
  };
  split(region, 0, ny);

  const Kappa kappa = condition_number_of(mechanism);
  std::vector<Piece> pieces(static_cast<std::size_t>(nx) * ny);
  std::vector<std::size_t> inside_count(ny, 0), boundary_count(ny, 0);
  detail::ParallelPolicy policy;
  policy.threads = options.threads;
  policy.serial_threshold = 8;
  detail::for_each_block(policy, static_cast<std::size_t>(ny), static_cast<std::size_t>(ny), [&](std::size_t row) {
    const int j = static_cast<int>(row);
    const double y0 = origin.y + j * h, y1 = origin.y + (j + 1) * h;  // as rows_box: cells tile exactly
    const geometry::Region& strip = strips[row];  // region ∩ the row
    std::optional<bool> run_inside;  // status of the current run of boundary-free cells
    std::vector<const Curve*> near;
    for (std::size_t k = 0; k < curves.size(); ++k) {
      if (y_extent[k][1] >= y0 - reach && y_extent[k][0] <= y1 + reach) near.push_back(&curves[k]);
    }
    for (int i = 0; i < nx; ++i) {
      const double x0 = origin.x + i * h, x1 = origin.x + (i + 1) * h;
      const Point c{0.5 * (x0 + x1), 0.5 * (y0 + y1)};
      double d = std::numeric_limits<double>::infinity();
      for (const Curve* curve : near) {
        d = std::min(d, distance_to(*curve, c));
        if (d <= reach) break;
      }
      Piece& piece = pieces[static_cast<std::size_t>(j) * nx + i];
      if (d > reach) {
        if (!run_inside) run_inside = !strip.empty() && strip.contains(c);  // c is inside the row
        if (*run_inside) {
          piece.area = (x1 - x0) * (y1 - y0);
          piece.centroid = c;
          ++inside_count[row];
        }
        continue;
      }
      run_inside.reset();
      const geometry::Region clip = strip.intersect(geometry::rectangle({{x0, y0}, {x1, y1}}));
      double a = 0.0;
      Point m{0.0, 0.0};
      for (const auto& comp : clip.components()) {
        a += comp.area;
        m = m + comp.area * comp.centroid;
      }
      if (a > 0.0) {
        piece.area = a;
        piece.centroid = (1.0 / a) * m;
        ++boundary_count[row];
      }
    }
    for (int i = 0; i < nx; ++i) {
      Piece& piece = pieces[static_cast<std::size_t>(j) * nx + i];
      if (piece.area > 0.0) {
        piece.f = inverse_condition(kappa, piece.centroid);
        // A clipped piece's centroid can lie outside it: the cell's centre next.
        if (!piece.f) piece.f = inverse_condition(kappa, {origin.x + (i + 0.5) * h, 0.5 * (y0 + y1)});
      }
    }
  });
  for (int j = 0; j < ny; ++j) {
    out.cells_inside += inside_count[j];
    out.cells_boundary += boundary_count[j];
  }

  // Fine and coarse sums, in a fixed order. Unevaluated weight counts 1/2
  // (1/κ ∈ [0, 1]) and half of it goes to the error.
  double area = 0.0, fine = 0.0, unevaluated = 0.0, coarse = 0.0, coarse_unevaluated = 0.0;
  for (const Piece& p : pieces) {
    area += p.area;
    if (p.area == 0.0) continue;
    if (p.f) fine += p.area * *p.f;
    else unevaluated += p.area;
  }
  if (!(area > 0.0)) {
    out.reason = "the workspace has no area";
    return out;
  }
  if (unevaluated >= area) {
    out.reason = std::string(mechanism.kind()) +
                 " reports no condition number in its workspace (Mechanism::evaluate leaves it undefined)";
    return out;
  }
  for (int J = 0; J < ny / 2; ++J) {
    for (int I = 0; I < nx / 2; ++I) {
      double w = 0.0;
      Point m{0.0, 0.0};
      const Piece* heaviest = nullptr;
      for (int dj = 0; dj < 2; ++dj) {
        for (int di = 0; di < 2; ++di) {
          const Piece& p = pieces[static_cast<std::size_t>(2 * J + dj) * nx + (2 * I + di)];
          if (p.area == 0.0) continue;
          w += p.area;
          m = m + p.area * p.centroid;
          if (p.f && (!heaviest || p.area > heaviest->area)) heaviest = &p;
        }
      }
      if (w == 0.0) continue;
      std::optional<double> f = inverse_condition(kappa, (1.0 / w) * m);
      if (!f && heaviest) f = heaviest->f;
      if (f) coarse += w * *f;
      else coarse_unevaluated += w;
    }
  }
  out.fine = (fine + 0.5 * unevaluated) / area;
  out.coarse = (coarse + 0.5 * coarse_unevaluated) / area;
  out.unevaluated_fraction = unevaluated / area;
  out.value = out.fine;
  out.error = std::abs(out.fine - out.coarse) + 0.5 * out.unevaluated_fraction;
  if (!workspace.exact) {
    // Mean over W with W ⊇ inner and |W − inner| ≤ band, 1/κ ∈ [0, 1] on it.
    const double band = std::max(0.0, workspace.area_upper - workspace.area_lower);
    out.error += band / (area + band) * std::max(out.fine, 1.0 - out.fine);
  }
  return out;
}

}  // namespace pkmws::design
