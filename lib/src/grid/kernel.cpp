// Membership kernels (see grid/kernel.hpp). The MOMA kernel is one inline,
// branch-free loop body compiled four times: scalar (vectorisation blocked by
// an empty asm barrier on the coordinate), the compiler's baseline, AVX2 and
// AVX-512 (function target attributes, chosen at run time). ISO C++ mode
// (-std=c++20) implies -ffp-contract=off, so no variant fuses multiply-adds
// and all four give bit-identical masks (a test checks it).
#include "pkmws/grid/kernel.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>


#if (defined(__x86_64__) || defined(__i386__)) && (defined(__GNUC__) || defined(__clang__))
#define PKMWS_X86_DISPATCH 1
#define PKMWS_TARGET_AVX2 __attribute__((target("avx2")))
#define PKMWS_TARGET_AVX512 __attribute__((target("avx512f,avx512vl,avx512bw,avx512dq,avx2")))
#else
#define PKMWS_X86_DISPATCH 0
#endif

#if defined(__GNUC__) || defined(__clang__)
#define PKMWS_INLINE [[gnu::always_inline]] inline
#else
#define PKMWS_INLINE inline
#endif

namespace pkmws::grid {

using Leg = MembershipKernel::MomaLeg;

namespace {

// Blocks the vectoriser in the scalar variant without changing the arithmetic.
PKMWS_INLINE void opaque(double& v) {
#if defined(__x86_64__) || defined(__i386__)
  asm volatile("" : "+x"(v));
#elif defined(__aarch64__)
  asm volatile("" : "+w"(v));
#else
  volatile double s = v;
  v = s;
#endif
}

// Branch-free min / max in the form x86 minpd / maxpd implement (no -ffast-math needed).
PKMWS_INLINE double min2(double a, double b) { return b < a ? b : a; }
PKMWS_INLINE double max2(double a, double b) { return b > a ? b : a; }
// 1 when f >= 0, from the sign bit (f + 0.0 turns -0.0 into +0.0). Keeping
// the logic in doubles and 64-bit lanes lets SSE2 vectorise it too (a bool ->
// int conversion of a double compare has no SSE2 vector form).
PKMWS_INLINE std::uint64_t nonnegative(double f) { return (std::bit_cast<std::uint64_t>(f + 0.0) >> 63) ^ 1u; }
// 1 when f > 0 (0.0 - f is +0.0 for f = +-0.0).
PKMWS_INLINE std::uint64_t positive(double f) { return std::bit_cast<std::uint64_t>(0.0 - f) >> 63; }

// One leg of MOMA ([Vasilic] eq. 5-6). In the guide frame of leg i, with
// w = P - R_i, u = a_i . w (eq. 6's B_i) and v = a_i x w, eq. 5 reads
// p_i = u - t sqrt(l^2 - v^2) (t = -branch; t = +1 for eq. 5's minus root).
// In the t-frame (u_t = t u, stroke [lo, hi]) the condition lo <= u_t - sqrt(l^2 - v^2) <= hi
// is, without the square root:
//   v^2 <= l^2,  e1 = u_t - lo >= 0 and e1^2 + v^2 >= l^2,
//   e2 = u_t - hi <= 0 or e2^2 + v^2 <= l^2.
// Returned as one number that is >= 0 exactly when all hold (a - b >= 0 is
// a >= b in IEEE arithmetic with subnormals; the units of the terms differ,
// only the sign matters).
PKMWS_INLINE double leg_margin(const Leg& g, double x, double y) {
  const double wx = x - g.rx;
  const double wy = y - g.ry;
  const double v = g.ax * wy - g.ay * wx;
  const double u = g.t * (g.ax * wx + g.ay * wy);
  const double v2 = v * v;
  const double e1 = u - g.lo;
  const double e2 = u - g.hi;
  return min2(min2(g.l2 - v2, e1), min2(e1 * e1 + v2 - g.l2, max2(-e2, g.l2 - (e2 * e2 + v2))));
}

PKMWS_INLINE std::uint64_t inside(const Leg& g0, const Leg& g1, double x, double y) {
  return nonnegative(min2(leg_margin(g0, x, y), leg_margin(g1, x, y)));
}

// Certified state of the disk of radius r about (x, y) for one leg. The leg's
// set is {F >= 0} with the 1-Lipschitz
//   F = min(l - |v|, e1, |P - S_lo| - l, max(-e2, l - |P - S_hi|)),
// |P - S_lo|^2 = e1^2 + v^2, |P - S_hi|^2 = e2^2 + v^2. F > r: disk inside;
// F < -r: disk outside. lm2 = max(l - r, 0)^2, lp2 = (l + r)^2. `in` > 0
// means F > r, `out` > 0 means F < -r.
PKMWS_INLINE void leg_state(const Leg& g, double x, double y, double r, double lm2, double lp2, double& in,
                            double& out) {
  const double wx = x - g.rx;
  const double wy = y - g.ry;
  const double v = g.ax * wy - g.ay * wx;
  const double u = g.t * (g.ax * wx + g.ay * wy);
  const double v2 = v * v;
  const double e1 = u - g.lo;
  const double e2 = u - g.hi;
  const double d1 = e1 * e1 + v2;
  const double d2 = e2 * e2 + v2;
  in = min2(min2(lm2 - v2, e1 - r), min2(d1 - lp2, max2(-e2 - r, lm2 - d2)));
  out = max2(max2(v2 - lp2, -e1 - r), max2(lm2 - d1, min2(e2 - r, d2 - lp2)));
}

PKMWS_INLINE std::int8_t state_of(double in0, double out0, double in1, double out1) {
  const std::uint64_t in = positive(min2(in0, in1));
  const std::uint64_t out = positive(max2(out0, out1)) & (in ^ 1u);
  return std::int8_t(std::int64_t(in) - std::int64_t(out));
}

// Rows are processed in chunks with an int index so that every instruction
// set converts the index with a plain int -> double instruction.
constexpr std::size_t chunk = 1024;

template <bool Scalar>
PKMWS_INLINE void moma_row(const Leg* legs, double x0, double dx, std::size_t first, std::size_t n, double y,
                           std::uint8_t* mask) {
  const Leg g0 = legs[0], g1 = legs[1];  // locals: no aliasing with the output
  for (std::size_t c = 0; c < n; c += chunk) {
    const int m = int(std::min(chunk, n - c));
    const double base = double(first + c);
    std::uint8_t* out = mask + c;
    for (int k = 0; k < m; ++k) {
      double x = x0 + (base + double(k)) * dx;
      if constexpr (Scalar) opaque(x);
      out[k] = std::uint8_t(inside(g0, g1, x, y));
    }
  }
}

template <bool Scalar>
PKMWS_INLINE std::uint64_t moma_count_row(const Leg* legs, double x0, double dx, std::size_t first, std::size_t n,
                                          double y) {
  const Leg g0 = legs[0], g1 = legs[1];  // locals: no aliasing with the output
  std::uint64_t total = 0;
  for (std::size_t c = 0; c < n; c += chunk) {
    const int m = int(std::min(chunk, n - c));
    const double base = double(first + c);
    std::uint64_t count = 0;
    for (int k = 0; k < m; ++k) {
      double x = x0 + (base + double(k)) * dx;
      if constexpr (Scalar) opaque(x);
      count += inside(g0, g1, x, y);
    }
    total += count;
  }
  return total;
}

template <bool Scalar>
PKMWS_INLINE void moma_points(const Leg* legs, const double* xs, const double* ys, std::size_t n,
                              std::uint8_t* mask) {
  const Leg g0 = legs[0], g1 = legs[1];  // locals: no aliasing with the output
  for (std::size_t k = 0; k < n; ++k) {
    double x = xs[k];
    if constexpr (Scalar) opaque(x);
    const double y = ys[k];
    mask[k] = std::uint8_t(inside(g0, g1, x, y));
  }
}

template <bool Scalar>
PKMWS_INLINE void moma_classify(const Leg* legs, const double* xs, const double* ys, std::size_t n, double r,
                                std::int8_t* state) {
  const Leg g0 = legs[0], g1 = legs[1];  // locals: no aliasing with the output
  const double lm0 = std::max(legs[0].l - r, 0.0), lm1 = std::max(legs[1].l - r, 0.0);
  const double lm20 = lm0 * lm0, lm21 = lm1 * lm1;
  const double lp20 = (legs[0].l + r) * (legs[0].l + r), lp21 = (legs[1].l + r) * (legs[1].l + r);
  for (std::size_t k = 0; k < n; ++k) {
    double x = xs[k];
    if constexpr (Scalar) opaque(x);
    const double y = ys[k];
    double in0, out0, in1, out1;
    leg_state(g0, x, y, r, lm20, lp20, in0, out0);
    leg_state(g1, x, y, r, lm21, lp21, in1, out1);
    state[k] = state_of(in0, out0, in1, out1);
  }
}

template <bool Scalar>
PKMWS_INLINE void moma_classify_row(const Leg* legs, double x0, double dx, std::size_t first, std::size_t n,
                                    double y, double r, std::int8_t* state) {
  const Leg g0 = legs[0], g1 = legs[1];  // locals: no aliasing with the output
  const double lm0 = std::max(legs[0].l - r, 0.0), lm1 = std::max(legs[1].l - r, 0.0);
  const double lm20 = lm0 * lm0, lm21 = lm1 * lm1;
  const double lp20 = (legs[0].l + r) * (legs[0].l + r), lp21 = (legs[1].l + r) * (legs[1].l + r);
  for (std::size_t c = 0; c < n; c += chunk) {
    const int m = int(std::min(chunk, n - c));
    const double base = double(first + c);
    std::int8_t* out = state + c;
    for (int k = 0; k < m; ++k) {
      double x = x0 + (base + double(k)) * dx;
      if constexpr (Scalar) opaque(x);
      double in0, out0, in1, out1;
      leg_state(g0, x, y, r, lm20, lp20, in0, out0);
      leg_state(g1, x, y, r, lm21, lp21, in1, out1);
      out[k] = state_of(in0, out0, in1, out1);
    }
  }
}

// One set of entry points per instruction set. The bodies above are inlined
// into each, so each is compiled for its own target.
#define PKMWS_KERNEL_SET(SUFFIX, ATTR, SCALAR)                                                               \
  ATTR void row_##SUFFIX(const Leg* l, double x0, double dx, std::size_t f, std::size_t n, double y,         \
                         std::uint8_t* m) {                                                                  \
    moma_row<SCALAR>(l, x0, dx, f, n, y, m);                                                                 \
  }                                                                                                          \
  ATTR std::uint64_t count_##SUFFIX(const Leg* l, double x0, double dx, std::size_t f, std::size_t n,        \
                                    double y) {                                                              \
    return moma_count_row<SCALAR>(l, x0, dx, f, n, y);                                                       \
  }                                                                                                          \
  ATTR void points_##SUFFIX(const Leg* l, const double* x, const double* y, std::size_t n, std::uint8_t* m) { \
    moma_points<SCALAR>(l, x, y, n, m);                                                                      \
  }                                                                                                          \
  ATTR void classify_##SUFFIX(const Leg* l, const double* x, const double* y, std::size_t n, double r,       \
                              std::int8_t* s) {                                                              \
    moma_classify<SCALAR>(l, x, y, n, r, s);                                                                 \
  }                                                                                                          \
  ATTR void classify_row_##SUFFIX(const Leg* l, double x0, double dx, std::size_t f, std::size_t n, double y, \
                                  double r, std::int8_t* s) {                                                \
    moma_classify_row<SCALAR>(l, x0, dx, f, n, y, r, s);                                                     \
  }

#define PKMWS_NO_ATTR
PKMWS_KERNEL_SET(scalar, PKMWS_NO_ATTR, true)
PKMWS_KERNEL_SET(baseline, PKMWS_NO_ATTR, false)
#if PKMWS_X86_DISPATCH
PKMWS_KERNEL_SET(avx2, PKMWS_TARGET_AVX2, false)
PKMWS_KERNEL_SET(avx512, PKMWS_TARGET_AVX512, false)
#endif

bool cpu_has(Isa isa) {
  switch (isa) {
    case Isa::scalar:
    case Isa::baseline:
      return true;
#if PKMWS_X86_DISPATCH
    case Isa::avx2:
      return __builtin_cpu_supports("avx2");
    case Isa::avx512:
      return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
             __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512dq");
#endif
    default:
      return false;
  }
}

Isa resolve(Isa requested) {
  if (requested == Isa::best) {
    for (Isa isa : {Isa::avx512, Isa::avx2}) {
      if (cpu_has(isa)) return isa;
    }
    return Isa::baseline;
  }
  if (!cpu_has(requested)) {
    throw std::invalid_argument(std::string("grid kernel: this CPU does not support ") +
                                std::string(to_string(requested)));
  }
  return requested;
}

}  // namespace

std::string_view to_string(Isa isa) {
  switch (isa) {
    case Isa::scalar: return "scalar";
    case Isa::baseline: return "baseline";
    case Isa::avx2: return "avx2";
    case Isa::avx512: return "avx512";
    case Isa::best: return "best";
  }
  return "?";
}

std::vector<Isa> available_isas() {
  std::vector<Isa> out;
  for (Isa isa : {Isa::scalar, Isa::baseline, Isa::avx2, Isa::avx512}) {
    if (cpu_has(isa)) out.push_back(isa);
  }
  return out;
}

MembershipKernel::MembershipKernel(const mechanisms::Mechanism& mechanism, KernelOptions options)
    : mechanism_(&mechanism), options_(options), phi_(options.phi.value_or(mechanism.orientation())) {
  // The vectorised path: two rods on straight guides (MOMA), asked as a capability.
  const auto guided = mechanism.capability<mechanisms::GuidedRodLegs>();
  const auto legs = guided ? guided->guided_rod_legs() : std::vector<mechanisms::GuidedRodLegs::Leg>{};
  if (legs.size() == 2) {
    moma_ = true;
    isa_ = resolve(options.isa);
    double scale = 0.0;
    for (std::size_t i = 0; i < 2; ++i) {
      const auto& src = legs[i];
      Leg& g = legs_[i];
      g.rx = src.reference.x;
      g.ry = src.reference.y;
      g.ax = src.direction.x;
      g.ay = src.direction.y;
      g.t = -double(src.branch);
      g.lo = g.t > 0 ? src.stroke_min : -src.stroke_max;
      g.hi = g.t > 0 ? src.stroke_max : -src.stroke_min;
      g.l = src.rod_length;
      g.l2 = src.rod_length * src.rod_length;
      scale = std::max({scale, std::abs(g.rx) + std::abs(g.ry) + std::max(std::abs(g.lo), std::abs(g.hi)) + g.l});
    }
    // u, v carry a few ulp of the coordinates' magnitude (~scale); squared
    // comparisons a few ulp of l^2. 1e-11 scale is ~1e4 ulp: generous.
    margin_ = 1e-11 * scale;
  } else {
    isa_ = Isa::scalar;
  }
}

std::string_view MembershipKernel::name() const { return moma_ ? "moma" : "generic"; }

double MembershipKernel::rounding_margin() const { return margin_; }

bool MembershipKernel::contains(Point p) const {
  std::uint8_t m = 0;
  points(&p.x, &p.y, 1, &m);
  return m != 0;
}

#if PKMWS_X86_DISPATCH
#define PKMWS_DISPATCH(NAME, ...)                            \
  switch (isa_) {                                            \
    case Isa::scalar: return NAME##_scalar(__VA_ARGS__);     \
    case Isa::avx2: return NAME##_avx2(__VA_ARGS__);         \
    case Isa::avx512: return NAME##_avx512(__VA_ARGS__);     \
    default: return NAME##_baseline(__VA_ARGS__);            \
  }
#else
#define PKMWS_DISPATCH(NAME, ...)                            \
  if (isa_ == Isa::scalar) return NAME##_scalar(__VA_ARGS__); \
  return NAME##_baseline(__VA_ARGS__);
#endif

void MembershipKernel::row(double x0, double dx, std::size_t first, std::size_t n, double y,
                           std::uint8_t* mask) const {
  if (moma_) {
    PKMWS_DISPATCH(row, legs_, x0, dx, first, n, y, mask)
  }
  for (std::size_t k = 0; k < n; ++k) {
    const double x = x0 + double(first + k) * dx;
    mask[k] = std::uint8_t(mechanism_->reachable({x, y, phi_}));
  }
}

std::uint64_t MembershipKernel::count_row(double x0, double dx, std::size_t first, std::size_t n,
                                          double y) const {
  if (moma_) {
    PKMWS_DISPATCH(count, legs_, x0, dx, first, n, y)
  }
  std::uint64_t count = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double x = x0 + double(first + k) * dx;
    count += mechanism_->reachable({x, y, phi_}) ? 1 : 0;
  }
  return count;
}

void MembershipKernel::points(const double* x, const double* y, std::size_t n, std::uint8_t* mask) const {
  if (moma_) {
    PKMWS_DISPATCH(points, legs_, x, y, n, mask)
  }
  for (std::size_t k = 0; k < n; ++k) {
    mask[k] = std::uint8_t(mechanism_->reachable({x[k], y[k], phi_}));
  }
}

void MembershipKernel::classify(const double* x, const double* y, std::size_t n, double radius,
                                std::int8_t* state) const {
  if (!moma_) throw std::logic_error("grid kernel: no certified cell test for " + std::string(mechanism_->kind()));
  const double r = radius + margin_;
  PKMWS_DISPATCH(classify, legs_, x, y, n, r, state)
}

void MembershipKernel::classify_row(double x0, double dx, std::size_t first, std::size_t n, double y,
                                    double radius, std::int8_t* state) const {
  if (!moma_) throw std::logic_error("grid kernel: no certified cell test for " + std::string(mechanism_->kind()));
  const double r = radius + margin_;
  PKMWS_DISPATCH(classify_row, legs_, x0, dx, first, n, y, r, state)
}

}  // namespace pkmws::grid
