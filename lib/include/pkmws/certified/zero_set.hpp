// The zero set Z = closure{ p ∈ W : g(p) = 0 } of a smooth field g inside a
// workspace W, traced as chord polylines with a certified distance bound
// (docs/theory/level_sets.md, "Distance to the type-2 singularity"):
//
//  * every point of Z lies within `error` of a segment of `pieces`, or in one
//    of the `undecided` boxes;
//  * every point of a segment of `pieces` lies within `error` of a point of Z.
//
// A quadtree over the window drops boxes where the interval enclosure of g
// excludes 0 or the box is outside W; in a box B where the interval gradient
// proves that Z is a graph v = φ(u) over the extended box B' ⊆ W ∩ domain,
// φ is sampled by certified root brackets and the chord error is bounded by
// the interval enclosure of φ'' over the tent of each chord
// (|φ − chord| <= max|φ''| Δ²/8 + half the brackets' width); chords are
// halved until that is <= `max_error`. Boxes where this fails are split; at
// the depth limit they are `undecided`.
//
// Lengths in the field's unit.
#pragma once

#include <chrono>
#include <cstdint>
#include <vector>

#include "pkmws/certified/level_set.hpp"
#include "pkmws/geometry/types.hpp"

namespace pkmws::certified {

struct ZeroSetOptions {
  /// The largest accepted distance bound between a chord and the curve (> 0).
  double max_error = 1e-6;
  /// Base cells per side of the window, and splits below them.
  int base = 16;
  int max_depth = 16;
  /// Cells first tried for tracing no larger than this many levels below base.
  int min_trace_depth = 1;
  /// 0: every hardware thread, 1: serial. Results do not depend on it.
  int threads = 0;
  /// A bound on the number of undecided boxes (past it the rest of a base
  /// cell stays undecided as one box: still sound, only wider).
  std::size_t max_undecided = 200000;
  std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
};

struct ZeroSetResult {
  std::vector<std::vector<geometry::Point>> pieces;
  /// The certified bound actually reached (<= max_error; 0 with no pieces).
  double error = 0.0;
  std::vector<geometry::Box> undecided;
  std::uint64_t cell_tests = 0;
  std::uint64_t traced_cells = 0;
  std::uint64_t samples = 0;
  /// The deadline or the undecided-box bound cut the work (bounds stay valid).
  bool stopped = false;
  /// Total length of the pieces.
  double length() const;
  /// Adds another trace's pieces, boxes and counts (its pieces are moved).
  void append(ZeroSetResult&& other);
};

/// Traces the zero set of `g` inside the set classified by `within` (boxes it
/// calls inside are in W), over `window`.
ZeroSetResult trace_zero_set(const ScalarField& g, const geometry::Box& window, const WithinTest& within,
                             const ZeroSetOptions& options);

}  // namespace pkmws::certified
