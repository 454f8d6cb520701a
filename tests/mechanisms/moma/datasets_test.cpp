// MOMA ([Vasilic], docs/theory/moma.md): the 33 bundled configurations of the
// program of building, the paper's reference configurations, quadrants and
// mirror images.
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

#include "io/document.hpp"
#include "pkmws/geometry/primitives.hpp"
#include "pkmws/io/mechanism_file.hpp"
#include "mechanisms/moma/moma.hpp"
#include "support/fixtures.hpp"
#include "support/mechanisms/moma.hpp"

using namespace pkmws;
using namespace pkmws::test::moma;
using geometry::Point;
using mechanisms::Moma;
using mechanisms::MomaLeg;
using pkmws::test::dataset;

namespace {

constexpr double pi = std::numbers::pi;
constexpr double deg = pi / 180.0;

}  // namespace

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
    ASSERT_TRUE(io::source_json(mech).is_object()) << stem;
    for (const char* key : {"paper", "figure", "note"}) EXPECT_TRUE(io::source_json(mech).contains(key)) << stem << " " << key;
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
      EXPECT_NE(io::source_json(mech)["note"].get<std::string>().find("quadrant III"), std::string::npos);
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
    EXPECT_EQ(io::source_json(mech)["figure"].get<std::string>().rfind(figure, 0), 0u) << stem;
  }
  // No other file claims one of those figures.
  for (const auto& f : moma_datasets()) {
    const auto mech = io::load_mechanism(f);
    const std::string fig = io::source_json(mech)["figure"].get<std::string>();
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
