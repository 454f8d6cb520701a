// Bodies and link interference (docs/format.md (bodies); [Vasilic] §4 end): distances against
// closed forms, the exact platform-vs-rectangle Minkowski sum against
// ab + 2r(a + b) + πr², every interference region against the brute-force
// pose-by-pose collision test, real ⊆ reachable, zero-size bodies, bound width
// against quadtree depth, and loader errors with field paths.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <random>
#include <string>

#include <nlohmann/json.hpp>

#include "io/document.hpp"
#include "pkmws/bodies/bodies.hpp"
#include "pkmws/geometry/primitives.hpp"
#include "pkmws/io/mechanism_file.hpp"
#include "support/classify.hpp"

using namespace pkmws;
using bodies::Shape;
using geometry::Point;
using nlohmann::json;

using testing_bodies::Classifier;
using testing_bodies::Side;

namespace {

constexpr double pi = std::numbers::pi;

// MOMA M1 ([Vasilic] §4.1: R = (∓100, 0), alpha = 270°, l = 250, h_max = 200) with parts.
json moma_m1(json bodies_field) {
  json leg1 = {{"reference", {-100, 0}}, {"guide_angle_deg", 270}, {"stroke", {0, 200}}, {"rod_length", 250}, {"branch", -1}};
  json leg2 = leg1;
  leg2["reference"] = {100, 0};
  json doc = {{"name", "m1"}, {"mechanism", "moma"}, {"units", "mm"}, {"legs", {leg1, leg2}}};
  if (!bodies_field.is_null()) doc["bodies"] = bodies_field;
  return doc;
}

json m1_parts() {
  return json::parse(R"({
    "platform_joint": {"radius": 20, "min_link_angle_deg": 15},
    "rods": [{"radius": 9}, {"radius": 9}],
    "slider_blocks": [{"length": 60, "width": 70}, {"length": 60, "width": 70}],
    "housings": [{"extent": [-60, 260], "width": 60}, {"extent": [-60, 260], "width": 60}],
    "obstacles": [{"name": "post", "polygon": [[-20, -330], [20, -330], [20, -300], [-20, -300]]}],
    "allowed_contacts": [["rod1", "housing1"], ["rod2", "housing2"]]
  })");
}

// DexTAR ([Briot]: l = 0.23 m, a = 0.1375 m) with link thickness.
json dextar(json bodies_field) {
  json doc = {{"name", "dextar"}, {"mechanism", "five_bar"}, {"units", "m"},
              {"base", {{-0.1375, 0.0}, {0.1375, 0.0}}}, {"proximal", {0.23, 0.23}},
              {"distal", {0.23, 0.23}}, {"working_mode", {1, -1}}};
  doc["bodies"] = bodies_field;
  return doc;
}

json dextar_parts() {
  return json::parse(R"({
    "platform_joint": {"radius": 0.015, "min_link_angle_deg": 20},
    "proximal": [{"radius": 0.012}, {"radius": 0.012}],
    "distal": [{"radius": 0.008}, {"radius": 0.008}],
    "obstacles": [{"name": "frame", "polygon": [[-0.05, -0.05], [0.05, -0.05], [0.05, 0.03], [-0.05, 0.03]]}],
    "allowed_contacts": [["proximal1", "proximal2"]]
  })");
}


io::MechanismFile parse(const json& doc) { return io::parse_mechanism(doc, "test"); }

TEST(BodiesShapes, DistancesMatchClosedForms) {
  // Point to segment, segment to segment (parallel, offset 3), crossing segments, containment.
  EXPECT_DOUBLE_EQ(bodies::core_distance({{0, 5}}, {{-1, 0}, {1, 0}}), 5.0);
  EXPECT_DOUBLE_EQ(bodies::core_distance({{0, 0}, {4, 0}}, {{2, 3}, {9, 3}}), 3.0);
  EXPECT_DOUBLE_EQ(bodies::core_distance({{6, 0}}, {{0, 0}, {4, 0}}), 2.0);
  EXPECT_EQ(bodies::core_distance({{-1, -1}, {1, 1}}, {{-1, 1}, {1, -1}}), 0.0);
  const std::vector<Point> square{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  EXPECT_EQ(bodies::core_distance({{5, 5}}, square), 0.0);            // inside
  EXPECT_EQ(bodies::core_distance({{2, 2}, {3, 3}}, square), 0.0);    // segment inside
  EXPECT_DOUBLE_EQ(bodies::core_distance({{13, 14}}, square), 5.0);  // corner: 3-4-5
  EXPECT_DOUBLE_EQ(bodies::core_distance(square, {{20, 0}, {20, 10}, {30, 5}}), 10.0);
  // Capsule vs capsule: clearance = distance − radii.
  EXPECT_DOUBLE_EQ(bodies::clearance({{{0, 0}, {4, 0}}, 1.0}, {{{2, 3}, {9, 3}}, 0.5}), 1.5);
  EXPECT_TRUE(bodies::overlap({{{0, 0}, {4, 0}}, 1.5}, {{{2, 3}, {9, 3}}, 1.5}));
  // Hull of a square's corners plus interior and collinear points.
  const auto h = bodies::convex_hull({{0, 0}, {1, 1}, {2, 0}, {2, 2}, {0, 2}, {1, 0}, {0, 1}});
  ASSERT_EQ(h.size(), 4u);
  double area2 = 0;
  for (std::size_t i = 0; i < h.size(); ++i) area2 += cross(h[i], h[(i + 1) % h.size()]);
  EXPECT_DOUBLE_EQ(area2, 8.0);  // counter-clockwise, area 4
  EXPECT_NEAR(bodies::unsigned_angle({1, 0}, {-1, 1e-300}), pi, 1e-15);
}

TEST(BodiesMinkowski, DiskAgainstRectangleIsTheRoundedRectangle) {
  // Platform disk of radius r against an a × b rectangle (rotated by 25° about its corner):
  // area ab + 2r(a + b) + πr² exactly, and membership agrees with the disk-vs-polygon distance.
  const double a = 70, b = 30, r = 12.5, t = 25 * pi / 180;
  const Point u{std::cos(t), std::sin(t)}, n{-u.y, u.x};
  const Point o{3, -4};
  const Shape rect{{o, o + a * u, o + a * u + b * n, o + b * n}, 0.0};
  const auto region = bodies::minkowski_with_disk(rect, r);
  EXPECT_NEAR(region.area(), a * b + 2 * r * (a + b) + pi * r * r, 1e-9 * a * b);
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> x(-60, 100), y(-30, 90);
  int agree = 0, checked = 0;
  for (int k = 0; k < 4000; ++k) {
    const Point p{x(gen), y(gen)};
    const double c = bodies::clearance({{p}, r}, rect);
    if (std::abs(c) < 1e-9) continue;
    ++checked;
    agree += (c <= 0) == region.contains(p);
  }
  EXPECT_EQ(agree, checked);
  EXPECT_GT(checked, 3900);
}

// Every interference region against the pose-level test at random reachable poses:
// certainly inside (inner) ⇒ the pair collides; outside outer ⇒ it does not.
void check_against_brute_force(const io::MechanismFile& mech, int samples, int& inside_hits, int& outside_hits) {
  const auto reachable = mech.model->workspace();
  bodies::InterferenceOptions opt;
  opt.max_depth = 5;
  const auto real = bodies::real_workspace(*mech.bodies, reachable, opt);
  const auto bb = reachable.bbox();
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> x(bb.min.x, bb.max.x), y(bb.min.y, bb.max.y);
  int tested = 0;
  const double tol = 1e-7 * std::hypot(bb.width(), bb.height());
  std::vector<std::pair<Classifier, Classifier>> cls;
  for (const auto& i : real.interference) cls.emplace_back(Classifier(i.region.inner, tol), Classifier(i.region.outer, tol));
  const Classifier real_inner(real.real.inner, tol), real_outer(real.real.outer, tol);
  for (int k = 0; k < samples; ++k) {
    const Point p{x(gen), y(gen)};
    const auto check = bodies::check_pose(*mech.bodies, p);
    if (!check.reachable) continue;
    ++tested;
    for (std::size_t j = 0; j < real.interference.size(); ++j) {
      const auto& i = real.interference[j];
      bool collides = false;
      for (const auto& c : check.contacts) {
        if (c.a == i.a && c.b == i.b && c.kind == i.kind) collides = c.collides;
      }
      if (cls[j].first(p) == Side::inside) {
        ++inside_hits;
        EXPECT_TRUE(collides) << i.a << " / " << i.b << " at (" << p.x << ", " << p.y << ")";
      }
      if (cls[j].second(p) == Side::outside) {
        ++outside_hits;
        EXPECT_FALSE(collides) << i.a << " / " << i.b << " at (" << p.x << ", " << p.y << ")";
      }
    }
    // The real workspace: inner ⇒ no collision at all; outside outer ⇒ some collision.
    if (real_inner(p) == Side::inside) {
      EXPECT_FALSE(check.collides()) << p.x << ", " << p.y;
    }
    if (real_outer(p) == Side::outside) {
      EXPECT_TRUE(check.collides()) << p.x << ", " << p.y;
    }
  }
  EXPECT_GT(tested, samples / 10);
  std::printf("[ brute force ] %s: %d reachable poses, %d certainly-inside and %d certainly-outside checks agreed\n",
              mech.name.c_str(), tested, inside_hits, outside_hits);
}

TEST(BodiesInterference, MomaRegionsAgreeWithPoseByPoseTest) {
  const auto mech = parse(moma_m1(m1_parts()));
  ASSERT_TRUE(mech.bodies);
  int in = 0, out = 0;
  check_against_brute_force(mech, 3000, in, out);
  EXPECT_GT(in, 100);   // the regions are not empty: rods over the other axis, folded rods
  EXPECT_GT(out, 1000);
}

TEST(BodiesInterference, FiveBarRegionsAgreeWithPoseByPoseTest) {
  const auto mech = parse(dextar(dextar_parts()));
  ASSERT_TRUE(mech.bodies);
  int in = 0, out = 0;
  check_against_brute_force(mech, 3000, in, out);
  EXPECT_GT(in, 50);
  EXPECT_GT(out, 1000);
}

TEST(BodiesInterference, RealInsideReachableAndPlatformPairsExact) {
  const auto mech = parse(moma_m1(m1_parts()));
  const auto reachable = mech.model->workspace();
  bodies::InterferenceOptions opt;
  opt.max_depth = 5;
  const auto real = bodies::real_workspace(*mech.bodies, reachable, opt);
  const double area = reachable.area();
  EXPECT_LE(real.real.outer.subtract(reachable).area(), 1e-9 * area);
  EXPECT_LE(real.real.inner.subtract(real.real.outer).area(), 1e-9 * area);
  EXPECT_LE(real.real.area_upper, area * (1 + 1e-12));
  EXPECT_LT(real.real.area_upper, area);  // something is lost: the paper's fig. 5 difference
  EXPECT_LE(real.real.area_lower, real.real.area_upper);
  EXPECT_FALSE(real.exact());
  int exact_pairs = 0;
  for (const auto& i : real.interference) {
    const bool platform_fixed = i.a == "platform" && (i.b.rfind("housing", 0) == 0 || i.b == "post");
    EXPECT_EQ(i.region.exact, platform_fixed || i.region.outer.empty()) << i.a << " / " << i.b;
    exact_pairs += platform_fixed;
  }
  EXPECT_EQ(exact_pairs, 3);
  // The platform against the post (a 40 × 30 rectangle wholly inside the workspace, away
  // from its boundary): exactly the rounded rectangle's area.
  for (const auto& i : real.interference) {
    if (i.a == "platform" && i.b == "post") {
      EXPECT_NEAR(i.region.area_lower, 40 * 30 + 2 * 20 * 70 + pi * 400, 1e-9 * area);
    }
  }
}

TEST(BodiesInterference, ZeroSizeBodiesGiveRealEqualReachable) {
  json parts = json::parse(R"({
    "platform_joint": {"radius": 0, "min_link_angle_deg": 0},
    "rods": [{"radius": 0}, {"radius": 0}],
    "slider_blocks": [{"length": 0, "width": 0}, {"length": 0, "width": 0}],
    "housings": [{"extent": [-60, 260], "width": 0}, {"extent": [-60, 260], "width": 0}]
  })");
  const auto mech = parse(moma_m1(parts));
  const auto reachable = mech.model->workspace();
  const auto real = bodies::real_workspace(*mech.bodies, reachable);
  EXPECT_TRUE(real.interference.empty());
  EXPECT_TRUE(real.exact());
  EXPECT_EQ(real.real.area_lower, reachable.area());
  EXPECT_EQ(real.real.area_upper, reachable.area());
  EXPECT_TRUE(real.real.inner.symmetric_difference(reachable).empty());
  // And the pose test finds nothing anywhere.
  const auto check = bodies::check_pose(*mech.bodies, {0, -300});
  EXPECT_TRUE(check.reachable);
  EXPECT_FALSE(check.collides());
}

TEST(BodiesInterference, BoundWidthShrinksWithDepth) {
  const auto mech = parse(moma_m1(m1_parts()));
  const auto reachable = mech.model->workspace();
  double previous = std::numeric_limits<double>::infinity();
  double first = 0;
  for (int depth : {2, 4, 6}) {
    bodies::InterferenceOptions opt;
    opt.max_depth = depth;
    const auto real = bodies::real_workspace(*mech.bodies, reachable, opt);
    EXPECT_LT(real.real.width(), previous) << depth;
    if (depth == 2) first = real.real.width();
    previous = real.real.width();
  }
  EXPECT_LT(previous, 0.4 * first);  // roughly halves per level
}

TEST(BodiesLoader, ErrorsNameTheField) {
  auto expect_error = [](const json& doc, const std::string& needle) {
    try {
      io::parse_mechanism(doc, "test");
      ADD_FAILURE() << "no error, expected " << needle;
    } catch (const io::InputError& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  };
  json p = m1_parts();
  p["rods"][1]["radius"] = -1;
  expect_error(moma_m1(p), "bodies.rods[1].radius");
  p = m1_parts();
  p["rods"][0]["colour"] = "red";
  expect_error(moma_m1(p), "bodies.rods[0].colour");
  p = m1_parts();
  p["allowed_contacts"][0][1] = "housing7";
  expect_error(moma_m1(p), "bodies.allowed_contacts[0]: no part named \"housing7\"");
  p = m1_parts();
  p["obstacles"][0]["polygon"] = json::parse("[[0,0],[10,10],[10,0],[0,5]]");
  expect_error(moma_m1(p), "bodies.obstacles[0].polygon: must be a simple polygon");
  p = m1_parts();
  p["platform_joint"]["min_link_angle_deg"] = 180;
  expect_error(moma_m1(p), "bodies.platform_joint.min_link_angle_deg");
  p = m1_parts();
  p["housings"][0]["extent"] = {10, 5};
  expect_error(moma_m1(p), "bodies.housings[0].extent");
  p = m1_parts();
  p["proximal"] = json::array();  // a five-bar field in a MOMA file
  expect_error(moma_m1(p), "bodies.proximal");
  p = m1_parts();
  p["obstacles"][0]["name"] = "rod1";
  expect_error(moma_m1(p), "bodies.obstacles[0].name");
}

}  // namespace
