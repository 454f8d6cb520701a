// The global conditioning index against closed forms: mechanisms whose
// condition number is a known field over a known region, and mechanisms that
// report none (docs/design_space.md, "The global conditioning index").
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <numbers>

#include "pkmws/design/gci.hpp"
#include "pkmws/geometry/primitives.hpp"

namespace {

using namespace pkmws;
using mechanisms::Pose;

// A mechanism that is only a condition-number field κ(x, y) over a region.
class Field final : public mechanisms::Mechanism {
 public:
  Field(geometry::Region region, std::function<double(double, double)> kappa, bool evaluations = true)
      : region_(std::move(region)), kappa_(std::move(kappa)), evaluations_(evaluations) {}
  std::string_view kind() const override { return "field"; }
  int dof() const override { return 2; }
  std::vector<mechanisms::JointInfo> joints() const override { return {{"q1", false, std::nullopt}, {"q2", false, std::nullopt}}; }
  std::vector<mechanisms::JointSolution> inverse(const Pose& p) const override {
    return {{"+", {p.x, p.y}, true, ""}};
  }
  std::vector<mechanisms::PoseSolution> direct(std::span<const double> q) const override {
    return {{"+", {q[0], q[1], 0.0}, {}, true, ""}};
  }
  std::vector<mechanisms::Evaluation> evaluate(const Pose& p, const mechanisms::Criteria&) const override {
    if (!evaluations_) return {};
    mechanisms::Evaluation e;
    e.mode = "+";
    e.reachable = true;
    e.joints = {p.x, p.y};
    e.condition_number = kappa_(p.x, p.y);
    return {e};
  }
  geometry::Region workspace() const override { return region_; }
  bool reachable(const Pose& p) const override { return region_.contains({p.x, p.y}); }
  mechanisms::Drawing draw(const Pose&) const override { return {}; }
  geometry::Box bounds() const override { return region_.bbox(); }

 private:
  geometry::Region region_;
  std::function<double(double, double)> kappa_;
  bool evaluations_;
};

certified::CertifiedRegion exact(const geometry::Region& r) { return certified::from_exact(r); }

TEST(Gci, UnitDiskAgainstTheClosedForm) {
  // κ = 1 + x² on the unit disk: (1/π) ∫∫ dA / (1 + x²) = (2/π) ∫ √(1 − x²)/(1 + x²) dx = 2 (√2 − 1).
  const Field m(geometry::disk({0.3, -0.2}, 1.0), [](double x, double) { return 1.0 + (x - 0.3) * (x - 0.3); });
  const auto g = design::global_conditioning_index(m, exact(m.workspace()));
  ASSERT_TRUE(g.value) << g.reason;
  const double truth = 2.0 * (std::sqrt(2.0) - 1.0);
  EXPECT_LE(std::abs(*g.value - truth), g.error) << *g.value << " vs " << truth;
  EXPECT_LT(g.error, 2e-4);
  EXPECT_GT(g.cells_boundary, 0u);
  EXPECT_GT(g.cells_inside, g.cells_boundary);
}

TEST(Gci, AnnulusWithSingularCircle) {
  // κ = ∞ on the circle r = 1.5 (1/κ = |r − 1.5|) inside the annulus 1 ≤ r ≤ 2:
  // mean = ∫ |r − 1.5| r dr / ∫ r dr over [1, 2] = (1/2 (1/12 + 1/24) ... ) computed below.
  const Field m(geometry::annulus({0, 0}, 1.0, 2.0), [](double x, double y) {
    const double d = std::abs(std::hypot(x, y) - 1.5);
    return d == 0.0 ? std::numeric_limits<double>::infinity() : 1.0 / d;
  });
  const auto g = design::global_conditioning_index(m, exact(m.workspace()));
  ASSERT_TRUE(g.value) << g.reason;
  // ∫_1^1.5 (1.5 − r) r dr = 1.5·(1.125 − 0.5) − (3.375 − 1)/3 = 0.9375 − 0.791667 = 0.145833...
  // ∫_1.5^2 (r − 1.5) r dr = (8 − 3.375)/3 − 1.5·(2 − 1.125) = 1.541667 − 1.3125 = 0.229167...
  const double num = (1.5 * (1.125 - 0.5) - (3.375 - 1.0) / 3.0) + ((8.0 - 3.375) / 3.0 - 1.5 * (2.0 - 1.125));
  const double truth = num / 1.5;  // ∫_1^2 r dr = 1.5
  EXPECT_LE(std::abs(*g.value - truth), g.error) << *g.value << " vs " << truth;
  EXPECT_LT(g.error, 1e-3);
}

TEST(Gci, ThreadsDoNotChangeTheResult) {
  const Field m(geometry::disk({0, 0}, 2.0), [](double x, double y) { return 1.0 + x * x + 0.5 * y; });
  design::GciOptions one, two;
  one.threads = 1;
  two.threads = 2;
  const auto a = design::global_conditioning_index(m, exact(m.workspace()), one);
  const auto b = design::global_conditioning_index(m, exact(m.workspace()), two);
  ASSERT_TRUE(a.value && b.value);
  EXPECT_EQ(*a.value, *b.value);
  EXPECT_EQ(a.error, b.error);
}

TEST(Gci, ErrorShrinksWithTheGrid) {
  const Field m(geometry::disk({0, 0}, 1.0), [](double x, double y) { return 1.0 + 3.0 * x * x + y * y; });
  design::GciOptions coarse, fine;
  coarse.cells = 16;
  fine.cells = 64;
  const auto a = design::global_conditioning_index(m, exact(m.workspace()), coarse);
  const auto b = design::global_conditioning_index(m, exact(m.workspace()), fine);
  ASSERT_TRUE(a.value && b.value);
  EXPECT_LT(b.error, a.error / 4.0);
  EXPECT_LE(std::abs(*a.value - *b.value), a.error + b.error);
}

TEST(Gci, NoConditionNumberIsAReasonNotACrash) {
  const Field nan(geometry::disk({0, 0}, 1.0), [](double, double) { return std::numeric_limits<double>::quiet_NaN(); });
  const auto a = design::global_conditioning_index(nan, exact(nan.workspace()));
  EXPECT_FALSE(a.value);
  EXPECT_NE(a.reason.find("field reports no condition number"), std::string::npos) << a.reason;
  const Field unset(geometry::disk({0, 0}, 1.0), [](double, double) { return 0.0; });  // the default: never set
  EXPECT_FALSE(design::global_conditioning_index(unset, exact(unset.workspace())).value);
  const Field none(geometry::disk({0, 0}, 1.0), [](double, double) { return 2.0; }, false);
  EXPECT_FALSE(design::global_conditioning_index(none, exact(none.workspace())).value);
  const auto empty = design::global_conditioning_index(nan, exact(geometry::Region()));
  EXPECT_FALSE(empty.value);
  EXPECT_EQ(empty.reason, "the workspace is empty");
}

TEST(Gci, CertifiedBandWidensTheError) {
  const Field m(geometry::disk({0, 0}, 1.0), [](double, double) { return 2.0; });
  certified::CertifiedRegion r;
  r.inner = geometry::disk({0, 0}, 1.0);
  r.outer = geometry::disk({0, 0}, 1.1);
  r.area_lower = r.inner.area();
  r.area_upper = r.outer.area();
  const auto g = design::global_conditioning_index(m, r);
  ASSERT_TRUE(g.value);
  EXPECT_NEAR(*g.value, 0.5, 1e-12);
  // The band may hold 1/κ anywhere in [0, 1]: the true mean lies within the error.
  const double band = r.area_upper - r.area_lower;
  for (double f : {0.0, 1.0}) {
    const double mean = (0.5 * r.area_lower + f * band) / r.area_upper;
    EXPECT_LE(std::abs(mean - *g.value), g.error + 1e-12);
  }
}

}  // namespace
