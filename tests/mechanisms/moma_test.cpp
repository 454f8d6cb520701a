// MOMA ([Vasilic], docs/theory/moma.md): the 33 bundled configurations, IK/DK round
// trips, the paper's closed form (eq. 9-12) against the robust DK, Jacobians
// against finite differences, singularities at constructed poses, pressure
// angle and reactions against their definitions, the exact workspace against an
// independent numerical integration, membership, and loader errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <Eigen/LU>
#include <Eigen/QR>

#include "pkmws/geometry/primitives.hpp"
#include "pkmws/io/mechanism_file.hpp"
#include "mechanisms/moma/moma.hpp"

using namespace pkmws;
using geometry::Point;
using mechanisms::Moma;
using mechanisms::MomaLeg;
using mechanisms::Pose;

namespace {

constexpr double pi = std::numbers::pi;
constexpr double deg = pi / 180.0;

std::string dataset(const std::string& stem) {
  return std::string(PKMWS_SOURCE_DIR) + "/datasets/" + stem + ".json";
}

std::vector<std::filesystem::path> moma_datasets() {
  std::vector<std::filesystem::path> out;
  for (const auto& e : std::filesystem::directory_iterator(std::string(PKMWS_SOURCE_DIR) + "/datasets")) {
    const std::string name = e.path().filename().string();
    if (e.path().extension() == ".json" && name.rfind("moma_", 0) == 0) out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

const Moma& as_moma(const io::MechanismFile& f) { return dynamic_cast<const Moma&>(*f.model); }

// M1 of [Vasilic] §4.1 built in code: guides at x = -+100 pointing down
// (alpha = 3pi/2 + gamma), stroke [0, 200], rods l.
Moma m1(double l = 250.0, double gamma_deg = 0.0, double stroke_max = 200.0) {
  const double a = 1.5 * pi + gamma_deg * deg;
  return Moma({MomaLeg{{-100, 0}, a, 0, stroke_max, l, -1}, MomaLeg{{100, 0}, a, 0, stroke_max, l, -1}});
}

double distance(Point a, Point b) { return std::hypot(a.x - b.x, a.y - b.y); }

// Points in the workspace's bounding box that the file's branches reach.
std::vector<Point> reachable_samples(const Moma& m, std::mt19937& rng, int count) {
  const auto box = m.workspace().bbox();
  std::uniform_real_distribution<double> x(box.min.x, box.max.x), y(box.min.y, box.max.y);
  std::vector<Point> out;
  for (int k = 0; k < 200 * count && static_cast<int>(out.size()) < count; ++k) {
    const Point p{x(rng), y(rng)};
    if (m.reachable({p.x, p.y, 0})) out.push_back(p);
  }
  return out;
}

}  // namespace

// ---------------------------------------------------------------------------
// Datasets

TEST(MomaDatasets, ThirtyThreeConfigurationsOfTheProgramOfBuilding) {
  const auto files = moma_datasets();
  ASSERT_EQ(files.size(), 33u);
  int m1_count = 0, m2_count = 0, m3_count = 0, m4_count = 0, m5_count = 0;
  for (const auto& f : files) {
    const std::string stem = f.stem().string();
    const auto mech = io::load_mechanism(f);
    const Moma& m = as_moma(mech);
    EXPECT_EQ(mech.mechanism, "moma");
    EXPECT_EQ(mech.units, "mm");
    EXPECT_FALSE(mech.description.empty()) << stem;
    ASSERT_TRUE(mech.source.is_object()) << stem;
    for (const char* key : {"paper", "figure", "note"}) EXPECT_TRUE(mech.source.contains(key)) << stem << " " << key;
    // Rod length from the name, stroke [0, 200] ([Vasilic] §4.1: h_max = 200).
    const double l = std::stod(stem.substr(stem.rfind("_l") + 2));
    EXPECT_TRUE(l == 180 || l == 195 || l == 250) << stem;
    for (const MomaLeg& leg : m.legs()) {
      EXPECT_EQ(leg.rod_length, l) << stem;
      EXPECT_EQ(leg.stroke_min, 0.0) << stem;
      EXPECT_EQ(leg.stroke_max, 200.0) << stem;
    }
    const auto& L = m.legs();
    auto gamma = [&](int i) { return L[i].guide_angle / deg - 270.0; };
    if (stem.rfind("moma_m1_", 0) == 0) {
      ++m1_count;
      const double g = stem.find("_gm5_") != std::string::npos ? -5 : stem.find("_gp5_") != std::string::npos ? 5 : 0;
      EXPECT_NEAR(gamma(0), g, 1e-12) << stem;
      EXPECT_NEAR(gamma(1), g, 1e-12) << stem;
    } else if (stem.rfind("moma_m4_", 0) == 0 || stem.rfind("moma_m5_", 0) == 0) {
      (stem[6] == '4' ? m4_count : m5_count)++;
      auto tag = [](const std::string& t) { return t == "0" ? 0.0 : (t[0] == 'p' ? 1.0 : -1.0) * std::stod(t.substr(1)); };
      // moma_m4_g<t1>_g<t2>_l<l>
      const auto first = stem.find("_g") + 2, second = stem.find("_g", first) + 2;
      const double g1 = tag(stem.substr(first, stem.find('_', first) - first));
      const double g2 = tag(stem.substr(second, stem.find('_', second) - second));
      EXPECT_NEAR(gamma(0), g1, 1e-12) << stem;
      EXPECT_NEAR(gamma(1), g2, 1e-12) << stem;
      // M4 diverging: gamma1 <= gamma2; M5 converging: gamma1 >= gamma2 ([Vasilic] §2).
      if (stem[6] == '4') {
        EXPECT_LT(g1, g2) << stem;
      } else {
        EXPECT_GT(g1, g2) << stem;
      }
    } else if (stem.rfind("moma_m2_", 0) == 0) {
      ++m2_count;
      EXPECT_EQ(L[0].reference, (Point{50, 0}));
      EXPECT_EQ(L[1].reference, (Point{0, 50}));
      EXPECT_DOUBLE_EQ(L[0].guide_angle, pi / 2);
      EXPECT_EQ(L[1].guide_angle, 0.0);
      EXPECT_EQ(L[0].branch, -1);
      EXPECT_EQ(L[1].branch, -1);
    } else if (stem.rfind("moma_m3_", 0) == 0) {
      ++m3_count;
      EXPECT_EQ(L[0].guide_angle, 0.0);
      EXPECT_DOUBLE_EQ(L[1].guide_angle, pi / 2);
      EXPECT_EQ(L[0].branch, 1);
      EXPECT_EQ(L[1].branch, 1);
      EXPECT_NE(mech.source["note"].get<std::string>().find("quadrant III"), std::string::npos);
    }
    if (stem.rfind("moma_m2_", 0) != 0 && stem.rfind("moma_m3_", 0) != 0) {
      EXPECT_EQ(L[0].reference, (Point{-100, 0})) << stem;
      EXPECT_EQ(L[1].reference, (Point{100, 0})) << stem;
    }
    EXPECT_GT(m.workspace().area(), 0.0) << stem;
  }
  EXPECT_EQ(m1_count, 9);
  EXPECT_EQ(m2_count, 3);
  EXPECT_EQ(m3_count, 3);
  EXPECT_EQ(m4_count, 9);
  EXPECT_EQ(m5_count, 9);
}

TEST(MomaDatasets, ThePapersReferenceConfigurationsNameTheirFigure) {
  // [Vasilic] §4.1: Fig. 5-7 (l = 250); §4.2: Fig. 9-11 (l = 195).
  const std::pair<const char*, const char*> cases[] = {
      {"moma_m1_g0_l250", "Fig. 5 "},      {"moma_m2_l250", "Fig. 6 "},
      {"moma_m3_l250", "Fig. 7 "},         {"moma_m1_gm5_l195", "Fig. 9 "},
      {"moma_m4_gm5_gp5_l195", "Fig. 10 "}, {"moma_m5_gp5_gm5_l195", "Fig. 11 "}};
  for (const auto& [stem, figure] : cases) {
    const auto mech = io::load_mechanism(dataset(stem));
    EXPECT_EQ(mech.source["figure"].get<std::string>().rfind(figure, 0), 0u) << stem;
  }
  // No other file claims one of those figures.
  for (const auto& f : moma_datasets()) {
    const auto mech = io::load_mechanism(f);
    const std::string fig = mech.source["figure"].get<std::string>();
    const bool reference = std::any_of(std::begin(cases), std::end(cases),
                                       [&](const auto& c) { return f.stem().string() == c.first; });
    if (!reference) {
      EXPECT_TRUE(fig.rfind("Fig. 2", 0) == 0 || fig.rfind("§2", 0) == 0) << f << ": " << fig;
    }
  }
}

TEST(MomaDatasets, M3LiesMostlyInQuadrantThreeAndM2InQuadrantOne) {
  // M3 keeps the printed guides with branch +1 (see its source.note); check the
  // described geometry. The paper's M3 (Fig. 7, l = 250): most of the workspace
  // in quadrant III. Shorter rods (program of building only) reach less far
  // back: quadrant III is still the largest share and holds the centroid.
  const geometry::Region quadrant[4] = {
      geometry::rectangle({{0, 0}, {1000, 1000}}), geometry::rectangle({{-1000, 0}, {0, 1000}}),
      geometry::rectangle({{-1000, -1000}, {0, 0}}), geometry::rectangle({{0, -1000}, {1000, 0}})};
  for (const char* l : {"180", "195", "250"}) {
    const auto ws3 = io::load_mechanism(dataset(std::string("moma_m3_l") + l)).model->workspace();
    double share[4];
    for (int k = 0; k < 4; ++k) share[k] = ws3.intersect(quadrant[k]).area() / ws3.area();
    EXPECT_NEAR(share[0] + share[1] + share[2] + share[3], 1.0, 1e-12);
    EXPECT_GT(share[2], std::max({share[0], share[1], share[3]})) << "M3 l = " << l;
    const auto parts = ws3.components(1.0);
    const auto largest = std::max_element(parts.begin(), parts.end(),
                                          [](const auto& a, const auto& b) { return a.area < b.area; });
    ASSERT_NE(largest, parts.end());
    EXPECT_LT(largest->centroid.x, 0.0);
    EXPECT_LT(largest->centroid.y, 0.0);
    if (std::string(l) == "250") {
      EXPECT_GT(share[2], 0.7);
    }
    const auto ws2 = io::load_mechanism(dataset(std::string("moma_m2_l") + l)).model->workspace();
    const double share2 = ws2.intersect(quadrant[0]).area() / ws2.area();
    EXPECT_NEAR(share2, 1.0, 1e-12) << "M2 l = " << l;
    std::printf("  l = %s: M3 shares in quadrants I-IV %.4f %.4f %.4f %.4f (%zu parts); M2 in quadrant I %.4f\n", l,
                share[0], share[1], share[2], share[3], parts.size(), share2);
  }
}

TEST(MomaDatasets, MirrorImageConfigurationsHaveEqualAreas) {
  // x -> -x swaps the legs and gamma -> -gamma: M1 +5/-5, M4 (0, +5)/(-5, 0),
  // M5 (0, -5)/(+5, 0). tan is odd, so the rational directions mirror exactly.
  const std::pair<const char*, const char*> pairs[] = {
      {"moma_m1_gm5", "moma_m1_gp5"}, {"moma_m4_g0_gp5", "moma_m4_gm5_g0"}, {"moma_m5_g0_gm5", "moma_m5_gp5_g0"}};
  for (const char* l : {"_l180", "_l195", "_l250"}) {
    for (const auto& [a, b] : pairs) {
      const double area_a = io::load_mechanism(dataset(std::string(a) + l)).model->workspace().area();
      const double area_b = io::load_mechanism(dataset(std::string(b) + l)).model->workspace().area();
      EXPECT_NEAR(area_a, area_b, 1e-12 * area_a) << a << l;
    }
  }
}

// ---------------------------------------------------------------------------
// Kinematics

TEST(MomaKinematics, InverseLegSolvesEq3OnTheBranchSide) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-400, 400);
  for (const auto& f : moma_datasets()) {
    const auto mech = io::load_mechanism(f);
    const Moma& m = as_moma(mech);
    for (int k = 0; k < 50; ++k) {
      const Point p{u(rng), u(rng)};
      for (int i = 0; i < 2; ++i) {
        for (int branch : {-1, 1}) {
          const auto q = m.inverse_leg(i, p, branch);
          const double l = m.legs()[i].rod_length;
          const Point a = m.guide_direction(i), w = p - m.legs()[i].reference;
          if (!q) {
            EXPECT_GT(std::abs(cross(a, w)), l * (1 - 1e-12));  // out of the rod's reach
            continue;
          }
          // [Vasilic] eq. 3: p^2 - 2 p a.w + |w|^2 - l^2 = 0, i.e. |P - S| = l.
          const Point s = m.slider(i, *q);
          EXPECT_NEAR(distance(p, s), l, 1e-12 * (l + norm(w)));
          // Branch -1 (eq. 5): P ahead of the slider, a.(P - S) >= 0; +1 behind.
          EXPECT_GE(-branch * dot(a, p - s), -1e-12 * (l + norm(w)));
        }
      }
    }
  }
}

TEST(MomaKinematics, InverseThenDirectRoundTripInEveryConfiguration) {
  std::mt19937 rng(2024);
  for (const auto& f : moma_datasets()) {
    const auto mech = io::load_mechanism(f);
    const Moma& m = as_moma(mech);
    const auto poses = reachable_samples(m, rng, 40);
    ASSERT_GE(poses.size(), 20u) << f;
    for (const Point p : poses) {
      const auto ik = m.inverse({p.x, p.y, 0});
      ASSERT_EQ(ik.size(), 4u);
      ASSERT_TRUE(ik[0].valid) << f << ": " << ik[0].reason;  // the file's working mode
      int found = 0;
      for (const auto& s : m.direct(ik[0].joints)) {
        if (distance({s.pose.x, s.pose.y}, p) < 1e-9 * 250) {
          ++found;
          EXPECT_TRUE(s.valid) << f << ": " << s.reason;
        }
      }
      EXPECT_EQ(found, 1) << f << " at " << p.x << ", " << p.y;
    }
  }
}

TEST(MomaKinematics, DirectThenInverseRoundTripInEveryConfiguration) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 200.0);
  for (const auto& f : moma_datasets()) {
    const auto mech = io::load_mechanism(f);
    const Moma& m = as_moma(mech);
    int checked = 0;
    for (int k = 0; k < 300 && checked < 40; ++k) {
      const std::vector<double> q{u(rng), u(rng)};
      for (const auto& s : m.direct(q)) {
        // Every assembly mode lies on both rod circles ...
        for (int i = 0; i < 2; ++i) {
          EXPECT_NEAR(distance({s.pose.x, s.pose.y}, m.slider(i, q[i])), m.legs()[i].rod_length, 1e-9 * 250);
        }
        if (!s.valid) continue;
        // ... and the valid ones give back the joints through the file's branches.
        const auto ik = m.inverse(s.pose);
        ASSERT_TRUE(ik[0].valid) << f << ": " << ik[0].reason;
        EXPECT_NEAR(ik[0].joints[0], q[0], 1e-9 * 250) << f;
        EXPECT_NEAR(ik[0].joints[1], q[1], 1e-9 * 250) << f;
        EXPECT_TRUE(m.reachable(s.pose) || std::min({q[0], q[1], 200 - q[0], 200 - q[1]}) < 1e-9) << f;
        ++checked;
      }
    }
    EXPECT_GE(checked, 10) << f;
  }
}

TEST(MomaKinematics, EveryWorkingModeIsAnAssemblyModeOfItsJoints) {
  std::mt19937 rng(5);
  for (const char* stem : {"moma_m1_g0_l250", "moma_m2_l195", "moma_m3_l180", "moma_m5_gp5_gm5_l195"}) {
    const auto mech = io::load_mechanism(dataset(stem));
    const Moma& m = as_moma(mech);
    const auto box = m.bounds();
    std::uniform_real_distribution<double> x(box.min.x, box.max.x), y(box.min.y, box.max.y);
    int checked = 0;
    for (int k = 0; k < 300; ++k) {
      const Point p{x(rng), y(rng)};
      for (const auto& s : m.inverse({p.x, p.y, 0})) {
        if (s.joints.size() != 2) continue;
        double best = std::numeric_limits<double>::infinity();
        for (const auto& a : m.direct_all(s.joints[0], s.joints[1])) best = std::min(best, distance(a.platform, p));
        EXPECT_LT(best, 1e-7) << stem << " " << s.mode << " at " << p.x << ", " << p.y;
        ++checked;
      }
    }
    EXPECT_GT(checked, 200) << stem;
  }
}

TEST(MomaKinematics, InverseListsTheFilesWorkingModeFirst) {
  const Moma m = m1();
  // A pose well inside the workspace: only the file's mode (-1,-1) is valid;
  // the other roots are either outside the stroke or another working mode.
  const auto ik = m.inverse({0, -300, 0});
  ASSERT_EQ(ik.size(), 4u);
  EXPECT_EQ(ik[0].mode, "--");
  EXPECT_TRUE(ik[0].valid);
  EXPECT_TRUE(ik[0].reason.empty());
  for (std::size_t k = 1; k < 4; ++k) {
    EXPECT_FALSE(ik[k].valid) << ik[k].mode;
    EXPECT_FALSE(ik[k].reason.empty());
  }
  std::vector<std::string> modes;
  for (const auto& s : ik) modes.push_back(s.mode);
  std::sort(modes.begin(), modes.end());
  EXPECT_EQ(modes, (std::vector<std::string>{"++", "+-", "-+", "--"}));
  // With a long stroke the other roots fall inside it: flagged as another working mode.
  const Moma long_stroke = m1(250, 0, 1000);
  for (const auto& s : long_stroke.inverse({0, -300, 0})) {
    if (s.mode == "--") continue;
    EXPECT_FALSE(s.valid);
    EXPECT_NE(s.reason.find("working mode"), std::string::npos) << s.reason;
  }
  // Out of the stroke: the reason says which joint.
  const auto far = m.inverse({0, -480, 0});
  EXPECT_FALSE(far[0].valid);
  EXPECT_NE(far[0].reason.find("outside stroke"), std::string::npos) << far[0].reason;
  // Out of the rods' reach: no joints.
  const auto none = m.inverse({1000, 0, 0});
  for (const auto& s : none) {
    EXPECT_FALSE(s.valid);
    EXPECT_TRUE(s.joints.empty());
  }
}

TEST(MomaKinematics, DirectFlagsTheAssemblyModeOnTheWrongSide) {
  const Moma m = m1();
  const std::vector<double> q{50, 80};
  const auto sols = m.direct(q);
  ASSERT_EQ(sols.size(), 2u);
  for (const auto& s : sols) {
    // Branch -1 with guides pointing down: P must lie below both sliders.
    const bool below = s.pose.y < -50 && s.pose.y < -80;
    EXPECT_EQ(s.valid, below) << s.mode << " " << s.reason;
    if (!below) {
      EXPECT_NE(s.reason.find("branch"), std::string::npos);
    }
    // Assembly mode sign = sign of cross(S2 - S1, P - S1).
    const double side = cross(m.slider(1, q[1]) - m.slider(0, q[0]), Point{s.pose.x, s.pose.y} - m.slider(0, q[0]));
    EXPECT_EQ(s.mode, side > 0 ? "+" : "-");
  }
  // Joints outside the stroke: every assembly mode invalid.
  for (const auto& s : m.direct(std::vector<double>{50, 210})) {
    EXPECT_FALSE(s.valid);
    EXPECT_NE(s.reason.find("stroke"), std::string::npos);
  }
  EXPECT_THROW(m.direct(std::vector<double>{1.0}), std::invalid_argument);
}

TEST(MomaKinematics, CircleIntersectionDegenerateCases) {
  // Tangent circles (rods aligned): |S1S2| = l1 + l2 = 500 with S1 = (-100, 0),
  // S2 = (100, -p2), p2 = sqrt(500^2 - 200^2).
  const Moma m = m1(250, 0, 1000);
  const double p2 = std::sqrt(500.0 * 500.0 - 200.0 * 200.0);
  const auto tangent = m.direct_all(0, p2);
  ASSERT_EQ(tangent.size(), 1u);
  EXPECT_EQ(tangent[0].sign, 0);
  EXPECT_NEAR(distance(tangent[0].platform, {0, -p2 / 2}), 0.0, 1e-9);
  EXPECT_EQ(m.direct_all(0, p2 - 1).size(), 2u);
  EXPECT_EQ(m.direct_all(0, p2 + 1).size(), 0u);
  // Internally tangent: l1 = 300, l2 = 100, |S1S2| = 200 (p1 = p2 = 0).
  const Moma unequal({MomaLeg{{-100, 0}, 1.5 * pi, 0, 200, 300, -1}, MomaLeg{{100, 0}, 1.5 * pi, 0, 200, 100, -1}});
  const auto inner = unequal.direct_all(0, 0);
  ASSERT_EQ(inner.size(), 1u);
  EXPECT_NEAR(distance(inner[0].platform, {200, 0}), 0.0, 1e-9);
  // Coincident centres: no isolated assembly mode (no division by zero either).
  const Moma crossing({MomaLeg{{0, 0}, 0.0, 0, 200, 100, -1}, MomaLeg{{100, -100}, 0.5 * pi, 0, 200, 100, -1}});
  EXPECT_TRUE(crossing.direct_all(100, 100).empty());  // both sliders at (100, 0)
  // One circle inside the other (|S1S2| = 10 < l1 - l2 = 70), or concentric with
  // different radii: none.
  const Moma nested({MomaLeg{{0, 0}, 0.0, 0, 200, 100, -1}, MomaLeg{{100, -100}, 0.5 * pi, 0, 200, 30, -1}});
  EXPECT_TRUE(nested.direct_all(100, 90).empty());
  EXPECT_TRUE(nested.direct_all(100, 100).empty());
  EXPECT_EQ(nested.direct_all(100, 30).size(), 1u);  // internally tangent: |S1S2| = 70
}

TEST(MomaKinematics, ClosedFormAgreesWithTheRobustDkWhereDefined) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 200.0);
  int compared = 0;
  for (const auto& f : moma_datasets()) {
    const auto mech = io::load_mechanism(f);
    const Moma& m = as_moma(mech);
    for (int k = 0; k < 40; ++k) {
      const double p1 = u(rng), p2 = u(rng);
      const auto all = m.direct_all(p1, p2);
      for (int sign : {-1, 1}) {
        const auto cf = m.direct_closed_form(p1, p2, sign);
        if (!cf) continue;
        double best = std::numeric_limits<double>::infinity();
        for (const auto& a : all) best = std::min(best, distance(a.platform, *cf));
        EXPECT_LE(best, 1e-9 * (norm(*cf) + 250)) << f << " p = " << p1 << ", " << p2;
        ++compared;
      }
      // Where the DK has two assembly modes and eq. 12 is defined, eq. 10's two
      // signs give both of them.
      if (all.size() == 2 && m.direct_closed_form(p1, p2, 1) && m.direct_closed_form(p1, p2, -1)) {
        EXPECT_GT(distance(*m.direct_closed_form(p1, p2, 1), *m.direct_closed_form(p1, p2, -1)), 1e-6);
      }
    }
  }
  EXPECT_GT(compared, 2000);
}

TEST(MomaKinematics, M2AtP2Equal50DefeatsTheClosedFormButNotTheRobustDk) {
  const auto mech = io::load_mechanism(dataset("moma_m2_l250"));
  const Moma& m = as_moma(mech);
  // Slider 1 at (50, p1), slider 2 at (p2, 50): at p2 = 50 both have x = 50 and
  // v4 = v1 in [Vasilic] eq. 12. The rods' circles meet at y = (p1 + 50) / 2,
  // x = 50 +- sqrt(250^2 - ((p1 - 50) / 2)^2); branch -1 needs P above slider 1
  // (p1 <= 50) and right of slider 2 (the + root): one valid mode for p1 < 50,
  // none for p1 > 50 (coincident sliders at p1 = 50: no isolated solution).
  for (double p1 : {0.0, 10.0, 40.0, 120.0, 200.0}) {
    EXPECT_FALSE(m.direct_closed_form(p1, 50.0, 1).has_value());
    EXPECT_FALSE(m.direct_closed_form(p1, 50.0, -1).has_value());
    const auto sols = m.direct(std::vector<double>{p1, 50.0});
    int valid = 0;
    for (const auto& s : sols) {
      for (int i = 0; i < 2; ++i) {
        EXPECT_NEAR(distance({s.pose.x, s.pose.y}, m.slider(i, i == 0 ? p1 : 50.0)), 250.0, 1e-9);
      }
      if (!s.valid) continue;
      ++valid;
      EXPECT_NEAR(s.pose.x, 50 + std::sqrt(250.0 * 250.0 - (p1 - 50) * (p1 - 50) / 4), 1e-9);
      EXPECT_NEAR(s.pose.y, (p1 + 50) / 2, 1e-9);
      const auto ik = m.inverse(s.pose);
      EXPECT_NEAR(ik[0].joints[0], p1, 1e-9);
      EXPECT_NEAR(ik[0].joints[1], 50.0, 1e-9);
    }
    EXPECT_EQ(sols.size(), 2u);
    EXPECT_EQ(valid, p1 < 50 ? 1 : 0) << "p1 = " << p1;
  }
  EXPECT_TRUE(m.direct(std::vector<double>{50.0, 50.0}).empty());
  // The robust DK is continuous through p2 = 50 (the platform moves by about dp2).
  const auto at = m.direct(std::vector<double>{10.0, 50.0});
  for (double dp : {-1e-9, 1e-9}) {
    const auto moved = m.direct(std::vector<double>{10.0, 50.0 + dp});
    ASSERT_EQ(moved.size(), at.size());
    for (std::size_t k = 0; k < at.size(); ++k) {
      EXPECT_EQ(moved[k].mode, at[k].mode);
      EXPECT_LT(distance({moved[k].pose.x, moved[k].pose.y}, {at[k].pose.x, at[k].pose.y}), 1e-7);
    }
  }
}

TEST(MomaKinematics, ThePapersFixedSignOfEq10PicksTheWrongModeInM2AboveP2Equal50) {
  // [Vasilic] eq. 10 uses "+" for M2. Just above p2 = 50 the line S1S2 tilts the
  // other way and the valid platform (right of slider 2, above slider 1) is the
  // intersection with the smaller y: p1 = 10, p2 = 52 gives P ~ (299.9, 17.6).
  const auto mech = io::load_mechanism(dataset("moma_m2_l250"));
  const Moma& m = as_moma(mech);
  const std::vector<double> q{10.0, 52.0};
  const auto sols = m.direct(q);
  const auto valid = std::find_if(sols.begin(), sols.end(), [](const auto& s) { return s.valid; });
  ASSERT_NE(valid, sols.end());
  EXPECT_NEAR(valid->pose.x, 299.9, 0.1);
  EXPECT_NEAR(valid->pose.y, 17.6, 0.1);
  const auto paper = m.direct_closed_form(q[0], q[1], +1);
  const auto other = m.direct_closed_form(q[0], q[1], -1);
  ASSERT_TRUE(paper && other);
  EXPECT_GT(distance(*paper, {valid->pose.x, valid->pose.y}), 100.0);
  EXPECT_LT(distance(*other, {valid->pose.x, valid->pose.y}), 1e-9 * 300);
  // Below p2 = 50 the paper's sign is the valid mode.
  const auto below = m.direct(std::vector<double>{10.0, 48.0});
  const auto valid_below = std::find_if(below.begin(), below.end(), [](const auto& s) { return s.valid; });
  ASSERT_NE(valid_below, below.end());
  EXPECT_LT(distance(*m.direct_closed_form(10.0, 48.0, +1), {valid_below->pose.x, valid_below->pose.y}), 1e-9 * 300);
}

TEST(MomaKinematics, JacobiansMatchFiniteDifferences) {
  std::mt19937 rng(3);
  for (const char* stem : {"moma_m1_gm5_l195", "moma_m2_l250", "moma_m3_l195", "moma_m4_gm5_gp5_l180"}) {
    const auto mech = io::load_mechanism(dataset(stem));
    const Moma& m = as_moma(mech);
    const auto box = m.bounds();
    std::uniform_real_distribution<double> x(box.min.x, box.max.x), y(box.min.y, box.max.y);
    int checked = 0;
    for (int k = 0; k < 400 && checked < 60; ++k) {
      const Point p{x(rng), y(rng)};
      for (const auto& s : m.inverse({p.x, p.y, 0})) {
        if (s.joints.size() != 2) continue;
        const auto j = m.jacobians(p, s.joints[0], s.joints[1]);
        // Keep away from singular poses, where finite differences break down.
        if (std::abs(j.B(0, 0)) < 20 || std::abs(j.B(1, 1)) < 20 || std::abs(j.A.determinant()) < 2000) continue;
        const int b1 = s.mode[0] == '-' ? -1 : 1;  // one sign per leg
        const int b2 = s.mode[1] == '-' ? -1 : 1;
        const double h = 1e-4;
        auto q = [&](Point at, int i) { return *m.inverse_leg(i, at, i == 0 ? b1 : b2); };
        Eigen::Matrix2d fd;
        for (int i = 0; i < 2; ++i) {
          fd(i, 0) = (q({p.x + h, p.y}, i) - q({p.x - h, p.y}, i)) / (2 * h);
          fd(i, 1) = (q({p.x, p.y + h}, i) - q({p.x, p.y - h}, i)) / (2 * h);
        }
        // IK Jacobian dq/dx = B^-1 A.
        const Eigen::Matrix2d jq = j.B.inverse() * j.A;
        EXPECT_LT((jq - fd).norm(), 1e-6 * (1 + jq.norm())) << stem << " " << s.mode;
        // DK Jacobian dx/dq = A^-1 B against the circle intersection, same assembly mode.
        const double side = cross(m.slider(1, s.joints[1]) - m.slider(0, s.joints[0]), p - m.slider(0, s.joints[0]));
        auto x_of = [&](double q1, double q2) {
          for (const auto& a : m.direct_all(q1, q2)) {
            if (a.sign == (side > 0 ? 1 : -1)) return a.platform;
          }
          ADD_FAILURE() << "assembly mode lost";
          return Point{};
        };
        Eigen::Matrix2d fdx;
        for (int i = 0; i < 2; ++i) {
          const double d1 = i == 0 ? h : 0, d2 = i == 1 ? h : 0;
          const Point plus = x_of(s.joints[0] + d1, s.joints[1] + d2);
          const Point minus = x_of(s.joints[0] - d1, s.joints[1] - d2);
          fdx(0, i) = (plus.x - minus.x) / (2 * h);
          fdx(1, i) = (plus.y - minus.y) / (2 * h);
        }
        const Eigen::Matrix2d jx = j.A.inverse() * j.B;
        EXPECT_LT((jx - fdx).norm(), 1e-6 * (1 + jx.norm())) << stem << " " << s.mode;
        // evaluate() reports det(dq/dx) and its conditioning for this mode.
        for (const auto& e : m.evaluate({p.x, p.y, 0}, {})) {
          if (e.mode != s.mode) continue;
          EXPECT_NEAR(e.jacobian_det, jq.determinant(), 1e-12 * (1 + std::abs(jq.determinant())));
          // 2x2 singular values in closed form: s1 s2 = |det|, s1^2 + s2^2 = |J|_F^2.
          const double fro2 = jq.squaredNorm(), det = std::abs(jq.determinant());
          const double s_max = std::sqrt((fro2 + std::sqrt(fro2 * fro2 - 4 * det * det)) / 2);
          const double s_min = det / s_max;
          EXPECT_NEAR(e.condition_number, s_max / s_min, 1e-9 * (s_max / s_min));
          ASSERT_TRUE(e.velocity_ratio.has_value());
          EXPECT_NEAR(*e.velocity_ratio, s_max, 1e-9 * s_max);
        }
        ++checked;
      }
    }
    EXPECT_GE(checked, 30) << stem;
  }
}

TEST(MomaKinematics, SingularitiesAtConstructedPoses) {
  // Type 1 (serial): rod 1 perpendicular to its guide. M1 l = 250, P = (150, 0):
  // |P - R1| = 250 along x, so p1 = 0 on both roots and (P - S1) . a1 = 0.
  const Moma m = m1(250, 0, 1000);
  for (const auto& e : m.evaluate({150, 0, 0}, {})) {
    EXPECT_TRUE(e.singular) << e.mode;
    EXPECT_EQ(e.singularity, "type1") << e.mode;
    EXPECT_TRUE(std::isinf(e.jacobian_det));
    EXPECT_TRUE(std::isinf(e.condition_number));
  }
  // Type 2 (parallel): rods aligned. P = (0, -y0), y0 = sqrt(250^2 - 100^2):
  // mode "-+" (branches -1, 1) puts S1 = (-100, 0) and S2 = (100, -2 y0), P their midpoint.
  const double y0 = std::sqrt(250.0 * 250.0 - 100.0 * 100.0);
  for (const auto& e : m.evaluate({0, -y0, 0}, {})) {
    if (e.mode == "-+" || e.mode == "+-") {
      EXPECT_EQ(e.singularity, "type2") << e.mode;
      EXPECT_TRUE(e.singular);
      EXPECT_NEAR(e.jacobian_det, 0.0, 1e-9);
      EXPECT_TRUE(std::isinf(e.condition_number));
      // Aligned rods cannot resist a load across them: pressure angle 90 degrees.
      EXPECT_NEAR(e.pressure_angle_deg[0], 90.0, 1e-6);
    } else {
      EXPECT_EQ(e.singularity, "") << e.mode;
      EXPECT_FALSE(e.singular);
      EXPECT_TRUE(std::isfinite(e.condition_number));
    }
  }
  // Both: rods of 100 from (-100, 0) and (100, 0) meeting at the origin are
  // aligned and perpendicular to the guides.
  const Moma touching({MomaLeg{{-100, 0}, 1.5 * pi, 0, 200, 100, -1}, MomaLeg{{100, 0}, 1.5 * pi, 0, 200, 100, -1}});
  const auto both = touching.evaluate({0, 0, 0}, {});
  EXPECT_EQ(both[0].singularity, "both");
  EXPECT_TRUE(both[0].singular);
  // 1 mm beside the aligned pose every mode is regular.
  const auto near = m.evaluate({1, -y0, 0}, {});
  for (const auto& e : near) EXPECT_EQ(e.singularity, "") << e.mode;
  // A regular pose of the file's mode.
  const auto regular = m1().evaluate({0, -300, 0}, {});
  EXPECT_FALSE(regular[0].singular);
  EXPECT_TRUE(std::isfinite(regular[0].jacobian_det));
}

TEST(MomaKinematics, PressureAngleMatchesItsDefinition) {
  // alpha_i = angle between rod i (the force line) and the velocity of P when
  // only actuator i moves (dP = A^-1 B e_i), as an unoriented line angle.
  std::mt19937 rng(23);
  for (const char* stem : {"moma_m1_g0_l250", "moma_m4_g0_gp5_l195", "moma_m3_l250"}) {
    const auto mech = io::load_mechanism(dataset(stem));
    const Moma& m = as_moma(mech);
    for (const Point p : reachable_samples(m, rng, 30)) {
      const auto e = m.evaluate({p.x, p.y, 0}, {})[0];
      if (e.singular) continue;
      const auto j = m.jacobians(p, e.joints[0], e.joints[1]);
      const Eigen::Matrix2d dx = j.A.inverse() * j.B;
      ASSERT_EQ(e.pressure_angle_deg.size(), 2u);
      for (int i = 0; i < 2; ++i) {
        const Eigen::Vector2d v = dx.col(i).normalized();
        const Eigen::Vector2d z = j.A.row(i).transpose().normalized();
        const double alpha = std::acos(std::min(1.0, std::abs(v.dot(z)))) / deg;
        EXPECT_NEAR(e.pressure_angle_deg[i], alpha, 1e-7) << stem;
      }
    }
  }
}

TEST(MomaKinematics, ReactionsMatchTheStatics) {
  const Moma m = m1();
  mechanisms::Criteria c;
  c.load = mechanisms::Load{100.0, 5.0};  // the moment is not transmitted by a point platform
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> ang(0, 2 * pi);
  for (const Point p : {Point{0, -300}, Point{-40, -350}, Point{60, -260}}) {
    const auto e = m.evaluate({p.x, p.y, 0}, c)[0];
    ASSERT_EQ(e.reactions_N.size(), 2u);
    // Rod forces F_i along z_i balance the load w: F1 z1 + F2 z2 = -w.
    const Eigen::Vector2d z1 = Eigen::Vector2d(p.x - m.slider(0, e.joints[0]).x, p.y - m.slider(0, e.joints[0]).y).normalized();
    const Eigen::Vector2d z2 = Eigen::Vector2d(p.x - m.slider(1, e.joints[1]).x, p.y - m.slider(1, e.joints[1]).y).normalized();
    Eigen::Matrix2d Z;
    Z << z1, z2;
    double worst[2] = {0, 0};
    for (int k = 0; k < 4000; ++k) {
      const double t = ang(rng);
      const Eigen::Vector2d f = Z.colPivHouseholderQr().solve(-Eigen::Vector2d(100 * std::cos(t), 100 * std::sin(t)));
      for (int i = 0; i < 2; ++i) worst[i] = std::max(worst[i], std::abs(f(i)));
    }
    for (int i = 0; i < 2; ++i) {
      EXPECT_LE(worst[i], e.reactions_N[i] * (1 + 1e-12));
      EXPECT_GE(worst[i], e.reactions_N[i] * (1 - 1e-5));
      // R_i,max = f / cos(alpha_i).
      EXPECT_NEAR(e.reactions_N[i], 100.0 / std::cos(e.pressure_angle_deg[i] * deg), 1e-9 * e.reactions_N[i]);
    }
  }
  // Without a load: no reactions.
  EXPECT_TRUE(m.evaluate({0, -300, 0}, {})[0].reactions_N.empty());
}

TEST(MomaKinematics, ConstructorRejectsImpossibleLegs) {
  const MomaLeg good{{0, 0}, 0.0, 0, 100, 50, -1};
  auto with = [&](auto change) {
    MomaLeg bad = good;
    change(bad);
    return std::array<MomaLeg, 2>{good, bad};
  };
  EXPECT_NO_THROW(Moma({good, good}));
  EXPECT_THROW(Moma(with([](MomaLeg& l) { l.rod_length = 0; })), std::invalid_argument);
  EXPECT_THROW(Moma(with([](MomaLeg& l) { l.rod_length = std::nan(""); })), std::invalid_argument);
  EXPECT_THROW(Moma(with([](MomaLeg& l) { l.stroke_min = 100; })), std::invalid_argument);
  EXPECT_THROW(Moma(with([](MomaLeg& l) { l.branch = 0; })), std::invalid_argument);
  EXPECT_THROW(Moma(with([](MomaLeg& l) { l.reference.x = std::numeric_limits<double>::infinity(); })),
               std::invalid_argument);
}

// ---------------------------------------------------------------------------
// Workspace

namespace {

using LD = long double;

// Adaptive Gauss-Kronrod (7/15) in long double: an interval is accepted when
// |K15 - G7| <= tol (a pessimistic bound on the K15 error), else bisected.
LD gauss_kronrod(const std::function<LD(LD)>& f, LD a, LD b, LD tol, int depth = 0) {
  static const LD xk[8] = {0.991455371120812639206854697526329L, 0.949107912342758524526189684047851L,
                           0.864864423359769072789712788640926L, 0.741531185599394439863864773280788L,
                           0.586087235467691130294144845693013L, 0.405845151377397166906606412076961L,
                           0.207784955007898467600689403773245L, 0.0L};
  static const LD wk[8] = {0.022935322010529224963732008058970L, 0.063092092629978553290700663189204L,
                           0.104790010322250183839876322541518L, 0.140653259715525918745189590510238L,
                           0.169004726639267902826583426598550L, 0.190350578064785409913256402421014L,
                           0.204432940075298892414161999234649L, 0.209482141084727828012999174891714L};
  static const LD wg[4] = {0.129484966168869693270611432679082L, 0.279705391489276667901467771423780L,
                           0.381830050505118944950369775488975L, 0.417959183673469387755102040816327L};
  const LD c = (a + b) / 2, h = (b - a) / 2;
  LD kronrod = wk[7] * f(c), gauss = wg[3] * f(c);
  for (int i = 0; i < 7; ++i) {
    const LD s = f(c - h * xk[i]) + f(c + h * xk[i]);
    kronrod += wk[i] * s;
    if (i % 2 == 1) gauss += wg[i / 2] * s;
  }
  kronrod *= h;
  gauss *= h;
  if (std::abs(kronrod - gauss) <= tol || depth >= 60) return kronrod;
  return gauss_kronrod(f, a, c, tol, depth + 1) + gauss_kronrod(f, c, b, tol, depth + 1);
}

struct Interval {
  LD lo, hi;
};

// The x-slice at height y of one M1 leg band (gamma = 0, guide pointing down
// from (c, 0), stroke [0, h], rod l, branch -1: P below its slider). With
// s = a . (P - S) = -(y + p) in [0, l] and p in [0, h]:
// s in [max(0, -y - h), min(l, -y)] and |x - c| = sqrt(l^2 - s^2).
std::vector<Interval> m1_slice(LD c, LD y, LD l, LD h) {
  const LD s_lo = std::max<LD>(0, -y - h), s_hi = std::min<LD>(l, -y);
  if (s_lo > s_hi) return {};
  const LD inner = std::sqrt(std::max<LD>(0, (l - s_hi) * (l + s_hi)));
  const LD outer = std::sqrt(std::max<LD>(0, (l - s_lo) * (l + s_lo)));
  return {{c - outer, c - inner}, {c + inner, c + outer}};
}

}  // namespace

TEST(MomaWorkspace, TheIntegratorIsAccurate) {
  // Half disk with its sqrt end singularities: pi l^2 / 2.
  const LD l = 250;
  const LD half_disk = gauss_kronrod([&](LD x) { return std::sqrt(std::max<LD>(0, l * l - x * x)); }, -l, l, 1e-13L);
  EXPECT_NEAR(static_cast<double>(half_disk / (std::numbers::pi_v<long double> * l * l / 2) - 1), 0.0, 1e-14);
}

TEST(MomaWorkspace, SingleBandAreaIsTwiceRodTimesStroke) {
  // Cavalieri: each line parallel to the guide cuts the band in a chord of length h.
  for (const auto& f : moma_datasets()) {
    const auto mech = io::load_mechanism(f);
    const Moma& m = as_moma(mech);
    for (int i = 0; i < 2; ++i) {
      const MomaLeg& leg = m.legs()[i];
      for (int side : {-1, 1}) {
        const auto band = geometry::band(m.slider(i, leg.stroke_min), leg.guide_angle,
                                         leg.stroke_max - leg.stroke_min, leg.rod_length, side);
        const double expected = 2 * leg.rod_length * (leg.stroke_max - leg.stroke_min);
        EXPECT_NEAR(band.area(), expected, 1e-12 * expected) << f;
      }
    }
  }
}

TEST(MomaWorkspace, M1AreaAgainstIndependentIntegrationAndClosedForm) {
  const double exact = io::load_mechanism(dataset("moma_m1_g0_l250")).model->workspace().area();
  const LD l = 250, h = 200;
  // (1) Numerical integration in y of the length of the x-slice of band 1 and band 2.
  auto overlap = [&](LD y) {
    LD total = 0;
    for (const Interval& u : m1_slice(-100, y, l, h)) {
      for (const Interval& v : m1_slice(100, y, l, h)) {
        total += std::max<LD>(0, std::min(u.hi, v.hi) - std::max(u.lo, v.lo));
      }
    }
    return total;
  };
  const LD by_y = gauss_kronrod(overlap, -(h + l), 0, 1e-13L);
  // (2) Closed form in x: for |x| < x* the vertical slices [-h - s_i, -s_i],
  // s_i = sqrt(l^2 - (x -+ 100)^2), overlap in 200 - |s1 - s2|; x* solves
  // s2 - s1 = h; F is an antiderivative of sqrt(l^2 - u^2) (docs/theory/moma.md).
  auto F = [&](LD u) { return (u * std::sqrt(l * l - u * u) + l * l * std::asin(u / l)) / 2; };
  auto gap = [&](LD x) { return std::sqrt(l * l - (x - 100) * (x - 100)) - std::sqrt(l * l - (x + 100) * (x + 100)) - h; };
  LD lo = 0, hi = 150;
  for (int k = 0; k < 200; ++k) {
    const LD mid = (lo + hi) / 2;
    (gap(mid) < 0 ? lo : hi) = mid;
  }
  const LD xs = (lo + hi) / 2;
  const LD closed = 2 * (h * xs + (F(xs + 100) - F(100)) - (F(xs - 100) - F(-100)));
  std::printf("  M1 (gamma = 0, l = 250): exact %.17g, integral in y %.17Lg (rel. diff %.2Le),\n"
              "  closed form in x %.17Lg (rel. diff %.2Le)\n",
              exact, by_y, (by_y - exact) / exact, closed, (closed - exact) / exact);
  EXPECT_NEAR(exact, static_cast<double>(by_y), 1e-10 * exact);
  EXPECT_NEAR(exact, static_cast<double>(closed), 1e-12 * exact);
}

TEST(MomaWorkspace, MembershipAgreesWithTheExactRegionAwayFromTheBoundary) {
  std::mt19937 rng(9);
  for (const auto& f : moma_datasets()) {
    const auto mech = io::load_mechanism(f);
    const Moma& m = as_moma(mech);
    const auto ws = m.workspace();
    const auto b = m.bounds();
    std::uniform_real_distribution<double> x(b.min.x, b.max.x), y(b.min.y, b.max.y);
    int inside = 0, compared = 0;
    for (int k = 0; k < 400; ++k) {
      const Point p{x(rng), y(rng)};
      // Distance (in joint or rod terms) from each leg's limits: skip near-boundary points.
      bool near = false;
      for (int i = 0; i < 2; ++i) {
        const MomaLeg& leg = m.legs()[i];
        const double across = std::abs(cross(m.guide_direction(i), p - leg.reference));
        const auto q = m.inverse_leg(i, p, leg.branch);
        near = near || std::abs(leg.rod_length - across) < 1e-6 * leg.rod_length;
        if (q) near = near || std::min(std::abs(*q - leg.stroke_min), std::abs(*q - leg.stroke_max)) < 1e-6 * leg.stroke_max;
      }
      if (near) continue;
      const bool exact = ws.contains(p);
      inside += exact;
      ++compared;
      EXPECT_EQ(m.reachable({p.x, p.y, 0}), exact) << f << " at " << p.x << ", " << p.y;
    }
    EXPECT_GT(compared, 390) << f;
    EXPECT_GT(inside, 20) << f;
  }
}

TEST(MomaWorkspace, BoundsContainTheWorkspaceAndEmptyIntersectionsAreEmpty) {
  for (const auto& f : moma_datasets()) {
    const auto mech = io::load_mechanism(f);
    const auto box = mech.model->bounds();
    const auto ws_box = mech.model->workspace().bbox();
    EXPECT_TRUE(box.contains(ws_box.min) && box.contains(ws_box.max)) << f;
  }
  // Guides 1000 apart, rods 100: the two bands never meet. Not an error: area 0.
  const Moma apart({MomaLeg{{-500, 0}, 1.5 * pi, 0, 200, 100, -1}, MomaLeg{{500, 0}, 1.5 * pi, 0, 200, 100, -1}});
  EXPECT_TRUE(apart.workspace().empty());
  EXPECT_EQ(apart.workspace().area(), 0.0);
  EXPECT_FALSE(apart.reachable({0, -100, 0}));
  EXPECT_FALSE(apart.bounds().empty());
}

TEST(MomaWorkspace, DrawingShowsGuidesSlidersAndRods) {
  const Moma m = m1(195, -5);
  const Point p{10, -280};
  ASSERT_TRUE(m.reachable({p.x, p.y, 0}));
  const auto d = m.draw({p.x, p.y, 0});
  ASSERT_EQ(d.guides.size(), 2u);
  ASSERT_EQ(d.sliders.size(), 2u);
  ASSERT_EQ(d.links.size(), 2u);
  EXPECT_EQ(d.tool, p);
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(distance(d.guides[i].a, m.slider(i, 0)), 0.0, 1e-12);
    EXPECT_NEAR(distance(d.guides[i].b, m.slider(i, 200)), 0.0, 1e-12);
    // The slider lies on its guide and the rod has its length.
    EXPECT_NEAR(cross(d.guides[i].b - d.guides[i].a, d.sliders[i] - d.guides[i].a), 0.0, 1e-9);
    EXPECT_NEAR(distance(d.links[i].a, d.links[i].b), 195.0, 1e-9);
  }
}

// ---------------------------------------------------------------------------
// Loader

namespace {

const std::string good_moma = R"({"name": "t", "mechanism": "moma", "units": "mm", "legs": [
    {"reference": [-100, 0], "guide_angle_deg": 270, "stroke": [0, 200], "rod_length": 250, "branch": -1},
    {"reference": [100, 0], "guide_angle_deg": 270, "stroke": [0, 200], "rod_length": 250, "branch": -1}]})";

// good_moma with the first `from` (in the second leg if `second_leg`) replaced by `to`.
std::string edit(const std::string& from, const std::string& to, bool second_leg = false) {
  std::string s = good_moma;
  const auto start = second_leg ? s.find("\"reference\": [100") : 0;
  const auto pos = s.find(from, start);
  if (pos == std::string::npos) throw std::logic_error("test edit not found: " + from);
  return s.replace(pos, from.size(), to);
}

std::string load_error(const std::string& text) {
  try {
    io::parse_mechanism(nlohmann::json::parse(text), "test");
  } catch (const io::InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(MomaLoader, ReadsEveryField) {
  const auto f = io::parse_mechanism(nlohmann::json::parse(edit("\"guide_angle_deg\": 270", "\"guide_angle_deg\": 265")), "t");
  const Moma& m = as_moma(f);
  EXPECT_EQ(m.legs()[0].reference, (Point{-100, 0}));
  EXPECT_NEAR(m.legs()[0].guide_angle, 265 * deg, 1e-15);
  EXPECT_DOUBLE_EQ(m.legs()[1].guide_angle, 270 * deg);
  EXPECT_EQ(m.legs()[1].stroke_max, 200.0);
  EXPECT_EQ(m.legs()[1].rod_length, 250.0);
  EXPECT_EQ(m.legs()[1].branch, -1);
  // 270 degrees is exactly the axis direction (0, -1).
  EXPECT_EQ(m.guide_direction(1), (Point{0, -1}));
  // Angles beyond a turn are the same guide.
  const auto g = io::parse_mechanism(nlohmann::json::parse(edit("\"guide_angle_deg\": 270", "\"guide_angle_deg\": 990")), "t");
  EXPECT_EQ(as_moma(g).guide_direction(0), (Point{0, -1}));
  // A negative start of the stroke is allowed.
  EXPECT_NO_THROW(io::parse_mechanism(nlohmann::json::parse(edit("\"stroke\": [0, 200]", "\"stroke\": [-50, 200]")), "t"));
}

TEST(MomaLoader, EachBadFieldNamesItsPath) {
  const std::pair<std::string, std::string> cases[] = {
      {edit("\"legs\": [", "\"legz\": ["), "legz: unknown field (expected one of: name, mechanism, units, description, source, criteria, legs, bodies)"},
      {edit("\"rod_length\": 250", "\"rod_length\": -250", true), "legs[1].rod_length: must be positive"},
      {edit("\"rod_length\": 250", "\"rod_length\": 0"), "legs[0].rod_length: must be positive"},
      {edit("\"rod_length\": 250", "\"rod_length\": 1e300"), "legs[0].rod_length"},
      {edit(", \"rod_length\": 250", "", true), "legs[1].rod_length: missing"},
      {edit("\"branch\": -1", "\"branch\": 2", true), "legs[1].branch"},
      {edit("\"branch\": -1", "\"branch\": 0"), "legs[0].branch"},
      {edit("\"branch\": -1", "\"branch\": -1.0"), "legs[0].branch"},
      {edit("\"guide_angle_deg\": 270", "\"guide_angle_deg\": 270, \"foo\": 1"), "legs[0].foo: unknown field (expected one of: reference, guide_angle_deg, stroke, rod_length, branch)"},
      {edit("\"guide_angle_deg\": 270", "\"guide_angle_deg\": \"down\""), "legs[0].guide_angle_deg"},
      {edit("\"stroke\": [0, 200]", "\"stroke\": [200, 0]"), "legs[0].stroke"},
      {edit("\"stroke\": [0, 200]", "\"stroke\": [100, 100]", true), "legs[1].stroke"},
      {edit("\"stroke\": [0, 200]", "\"stroke\": [0]"), "legs[0].stroke"},
      {edit("\"reference\": [-100, 0]", "\"reference\": [-100]"), "legs[0].reference"},
      {edit("\"reference\": [-100, 0]", "\"reference\": [-100, null]"), "legs[0].reference[1]"},
      {edit("\"units\": \"mm\"", "\"units\": \"ft\""), "units"},
      {edit("\"mechanism\": \"moma\"", "\"mechanism\": \"hexapod\""), "mechanism"},
      {edit(",\n    {\"reference\": [100, 0], \"guide_angle_deg\": 270, \"stroke\": [0, 200], \"rod_length\": 250, "
            "\"branch\": -1}",
            ""),
       "legs: expected an array of 2 objects"},
      {edit("{\"reference\": [100, 0], \"guide_angle_deg\": 270, \"stroke\": [0, 200], \"rod_length\": 250, "
            "\"branch\": -1}",
            "42"),
       "legs[1]: expected a JSON object"},
  };
  for (const auto& [text, needle] : cases) {
    const std::string message = load_error(text);
    EXPECT_NE(message.find(needle), std::string::npos) << "expected \"" << needle << "\", got \"" << message << "\"";
  }
  EXPECT_EQ(load_error(good_moma), "");
}

TEST(MomaLoader, FileErrorsCarryThePath) {
  const auto dir = std::filesystem::temp_directory_path() / "pkmws_moma_loader_test";
  std::filesystem::create_directories(dir);
  const auto path = dir / "bad.json";
  {
    std::ofstream out(path);
    out << edit("\"branch\": -1", "\"branch\": 3", true);
  }
  try {
    io::load_mechanism(path);
    ADD_FAILURE() << "no error";
  } catch (const io::InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(path.string()), std::string::npos) << what;
    EXPECT_NE(what.find("legs[1].branch"), std::string::npos) << what;
  }
  std::filesystem::remove_all(dir);
}
