// Point-membership kernels of the grid baseline (docs/theory/grid.md; [Vasilic] §4.2,
// algorithm of fig. 8: a task-space point is in the workspace when the inverse
// kinematics has a solution within the strokes).
//
// One kernel per mechanism, behind one class. MOMA has a fast path written so
// the compiler vectorises it: a whole row of x values for one y, evaluated
// with branch-free arithmetic into a uint8 mask, compiled for several
// instruction sets and chosen at run time. Every other mechanism goes through
// Mechanism::reachable, one virtual call per point.
#pragma once

#include <optional>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

#include "pkmws/geometry/types.hpp"
#include "pkmws/mechanisms/mechanism.hpp"

namespace pkmws::grid {

using geometry::Point;

/// Instruction set of the vectorised kernels. `baseline` is what the compiler
/// targets by default (SSE2 on x86-64: two doubles per instruction); `avx2`
/// and `avx512` are the same source compiled with function target attributes
/// and selected at run time only when the CPU has them (no -march needed).
/// `scalar` is the same arithmetic with vectorisation blocked, to measure the
/// speed-up. `best` resolves to the fastest available one.
enum class Isa { scalar, baseline, avx2, avx512, best };

std::string_view to_string(Isa isa);
/// The concrete instruction sets this CPU can run, scalar first.
std::vector<Isa> available_isas();

/// Certified cell states (classify()).
inline constexpr std::int8_t cell_outside = -1;
inline constexpr std::int8_t cell_undecided = 0;
inline constexpr std::int8_t cell_inside = 1;

struct KernelOptions {
  Isa isa = Isa::best;
  /// Platform orientation (radians) given to Mechanism::reachable by the
  /// generic kernel; 2-DOF mechanisms ignore it. Unset: Mechanism::orientation().
  std::optional<double> phi;
};

/// Membership test of one mechanism's reachable workspace. Holds a pointer to
/// the mechanism: the mechanism must outlive the kernel. Thread-safe (const).
class MembershipKernel {
 public:
  explicit MembershipKernel(const mechanisms::Mechanism& mechanism, KernelOptions options = {});

  /// True on the vectorised path (a mechanism with GuidedRodLegs), false per point.
  bool vectorised() const { return moma_; }
  /// "moma" (vectorised fast path) or "generic" (Mechanism::reachable per point).
  std::string_view name() const;
  /// The instruction set in use (never `best`; `scalar` for the generic kernel).
  Isa isa() const { return isa_; }
  /// True when the kernel has a certified cell test (classify()).
  bool certified() const { return moma_; }

  /// mask[k] = 1 when the point (x0 + (first + k) dx, y) is in the workspace,
  /// else 0, for k in [0, n). The x of a point depends on first + k only, so
  /// splitting a row into pieces gives the same bits.
  void row(double x0, double dx, std::size_t first, std::size_t n, double y, std::uint8_t* mask) const;
  /// Number of points of the same row in the workspace (no mask written).
  std::uint64_t count_row(double x0, double dx, std::size_t first, std::size_t n, double y) const;
  /// mask[k] = 1 when (x[k], y[k]) is in the workspace.
  void points(const double* x, const double* y, std::size_t n, std::uint8_t* mask) const;
  bool contains(Point p) const;

  /// Certified classification of the closed disks of radius `radius` (length
  /// unit) about the points: cell_inside when the whole disk is in the
  /// workspace, cell_outside when none of it is, else cell_undecided (also
  /// when unsure within the rounding margin). Requires certified().
  /// MOMA rule: the workspace is {F >= 0} for a 1-Lipschitz F built from the
  /// distances to the legs' strips, half-planes and stroke-end circles
  /// (docs/theory/grid.md), so |F(c)| > radius decides the whole disk.
  void classify(const double* x, const double* y, std::size_t n, double radius, std::int8_t* state) const;
  /// The same for the points of a row (x0 + (first + k) dx, y).
  void classify_row(double x0, double dx, std::size_t first, std::size_t n, double y, double radius,
                    std::int8_t* state) const;

  /// Absolute length added to every certified radius for the rounding of the
  /// double evaluation (length unit).
  double rounding_margin() const;

  /// MOMA leg coefficients in the guide frame (public for the kernels only).
  struct MomaLeg {
    double rx = 0, ry = 0;  // reference point R_i
    double ax = 0, ay = 0;  // guide unit vector a_i
    double t = 1;           // -branch: P is ahead (t = +1) or behind the slider
    double lo = 0, hi = 0;  // stroke in the t-frame: t u - sqrt(l^2 - v^2) in [lo, hi]
    double l = 0, l2 = 0;   // rod length and its square
  };

 private:
  const mechanisms::Mechanism* mechanism_;
  KernelOptions options_;
  double phi_ = 0.0;  // options_.phi or the mechanism's orientation
  Isa isa_ = Isa::scalar;
  bool moma_ = false;
  MomaLeg legs_[2];
  double margin_ = 0.0;
};

}  // namespace pkmws::grid
