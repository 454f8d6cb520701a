// What only some mechanisms can do, asked through the Mechanism interface:
// `mechanism.capability<C>()` gives the capability C or the reason it is not
// available ("not available: ..."), never a cast to a concrete mechanism type.
//
// A capability type C is a struct with
//   static constexpr std::string_view capability_name = "...";
// (used in the default reason). The capability types of this layer are below;
// analyses define theirs beside them (criteria fields, body rigs, charts).
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <typeindex>
#include <utility>
#include <vector>

#include "pkmws/geometry/region.hpp"
#include "pkmws/geometry/types.hpp"

namespace pkmws::mechanisms {

/// A capability, or why the mechanism does not have it. The object stays
/// valid while the mechanism that gave it lives.
template <class C>
class Capability {
 public:
  explicit Capability(std::shared_ptr<const C> value) : value_(std::move(value)) {}
  explicit Capability(std::string reason) : reason_(std::move(reason)) {}

  explicit operator bool() const { return value_ != nullptr; }
  const C* operator->() const { return &get(); }
  const C& operator*() const { return get(); }
  /// The capability; throws std::invalid_argument("not available: reason") when absent.
  const C& get() const {
    if (!value_) throw std::invalid_argument("not available: " + reason_);
    return *value_;
  }
  /// Why it is not available ("" when it is).
  const std::string& reason() const { return reason_; }

 private:
  std::shared_ptr<const C> value_;
  std::string reason_;
};

/// A type-erased answer to "do you have capability T?" (Mechanism::provide).
struct Offer {
  std::shared_ptr<const void> value;  // a `const C*` for the asked C, or null
  std::string reason;                 // why not (optional: a default names the capability)

  /// Offer `c` (not owned: it lives as long as the mechanism) as capability C.
  template <class C>
  static Offer of(const C* c) {
    return {std::shared_ptr<const void>(std::shared_ptr<const void>{}, static_cast<const void*>(c)), {}};
  }
  /// Offer an owned capability object.
  template <class C>
  static Offer owned(std::shared_ptr<const C> c) {
    return {std::static_pointer_cast<const void>(std::move(c)), {}};
  }
  static Offer refuse(std::string why) { return {nullptr, std::move(why)}; }
  template <class C>
  static bool asks(std::type_index t) {
    return t == std::type_index(typeid(C));
  }
};

// ------------------------------------------------------------------ capabilities

/// 3-DOF mechanisms: the constant-orientation workspace at any orientation phi
/// (radians), not only the file's.
struct PoseSlice {
  static constexpr std::string_view capability_name = "constant-orientation slices (3-DOF only)";
  virtual ~PoseSlice() = default;
  virtual geometry::Region workspace_at(double phi) const = 0;
};

/// Direct kinematics by elimination to one polynomial in t = tan(angle / 2)
/// (3-RRP/3-PRP: the Assur group's eliminant; 3-RPR: the sextic).
struct Elimination {
  static constexpr std::string_view capability_name = "a direct-kinematics eliminant";
  struct Root {
    double re = 0.0, im = 0.0;
  };
  /// One real solution of the eliminant with what it gives.
  struct Solution {
    std::vector<double> values;  // the unknowns it determines (named by `solution_values`)
    std::string label;           // e.g. "platform" / "mirror image"
    double residual = 0.0;
  };
  struct Report {
    std::string method;                     // what was eliminated, in words (with the source)
    std::string variable;                   // the polynomial's variable; "" without a polynomial
    int nominal_degree = -1;                // the method's degree (-1: no polynomial)
    int degree = -1;                        // the true degree after cancellation
    std::vector<double> coefficients_ascending;
    std::vector<double> real_roots;
    std::vector<Root> complex_roots;
    std::string solution_values;            // what Solution::values are, e.g. "s" (slider positions)
    std::vector<Solution> solutions;
    std::size_t poses = 0;                  // assembly modes found
    bool continuum = false;                 // a continuum of poses (none listed)
    /// Method-specific numbers (scales, offsets, a check against a second
    /// method); NaN where undefined, with `note` saying why.
    std::vector<std::pair<std::string, double>> figures;
    std::string note;
  };
  virtual ~Elimination() = default;
  /// The elimination for joint values q (size dof()).
  virtual Report elimination(std::span<const double> q) const = 0;
};

/// Legs that are rods of fixed length on straight guides (MOMA): the numbers a
/// vectorised membership kernel needs ([Vasilic] eq. 5).
struct GuidedRodLegs {
  static constexpr std::string_view capability_name = "rod-on-guide legs (the vectorised membership kernel)";
  struct Leg {
    geometry::Point reference;  // guide reference point R_i
    geometry::Point direction;  // unit guide direction a_i (the rational one the exact workspace uses)
    double rod_length = 0.0;
    int branch = 1;             // working mode: +1 or -1
    double stroke_min = 0.0, stroke_max = 0.0;
  };
  virtual ~GuidedRodLegs() = default;
  virtual std::vector<Leg> guided_rod_legs() const = 0;
};

}  // namespace pkmws::mechanisms
