// The global conditioning index of a workspace: GCI = (1/|W|) ∫_W 1/κ dA, κ
// the 2-norm condition number of the mechanism's inverse-kinematic Jacobian as
// Mechanism::evaluate reports it for the file's working mode (the first
// evaluation), taken from the mechanism's condition-number criterion field
// (capability CriterionFields, the same κ in closed form) when it has one. A deterministic quadrature over the exact region with an error
// estimate (docs/design_space.md, "The global conditioning index").
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "pkmws/certified/cell_region.hpp"
#include "pkmws/mechanisms/mechanism.hpp"

namespace pkmws::design {

struct GciOptions {
  /// Cells of the fine grid across the longer side of the workspace's
  /// bounding box (rounded up to even); the coarse grid has half as many.
  int cells = 128;
  /// Rows of cells in parallel: 0 all cores, 1 serial; the result does not depend on it.
  int threads = 1;
};

struct GciResult {
  /// Mean of 1/κ over the workspace (fine grid); absent with `reason`.
  std::optional<double> value;
  /// Estimated error of `value` (not a certified bound): |fine − coarse| plus
  /// half the weight of pieces where κ could not be evaluated, plus, for a
  /// certified workspace, what the undecided band between the enclosures
  /// can change (1/κ ∈ [0, 1] there).
  double error = 0.0;
  std::string reason;
  double fine = 0.0;                 // the fine-grid quadrature
  double coarse = 0.0;               // the same weights summed over 2x2 blocks
  double unevaluated_fraction = 0.0; // area share where no κ was found
  std::size_t cells_inside = 0;      // fine cells wholly inside (no Boolean needed)
  std::size_t cells_boundary = 0;    // fine cells cut by the boundary (exact clip)
  double cell_size = 0.0;            // fine cell side, length unit
};

/// The GCI of `mechanism` over `workspace` (its inner region when certified).
/// Never throws for a mechanism without condition numbers or an empty
/// workspace: the result then has no value and says why.
GciResult global_conditioning_index(const mechanisms::Mechanism& mechanism,
                                    const certified::CertifiedRegion& workspace, const GciOptions& options = {});

}  // namespace pkmws::design
