// The real workspace on the command line and on the bundled machines (docs/format.md,
// bodies): pkmws explain / area / export / eval, and every bundled machine's
// interference regions against the pose-by-pose test.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "pkmws/bodies/bodies.hpp"
#include "pkmws/io/mechanism_file.hpp"
#include "support/cli_runner.hpp"
#include "support/classify.hpp"

namespace fs = std::filesystem;
using nlohmann::json;
using namespace pkmws;

namespace {

using pkmws::test::dataset;

using Result = pkmws::test::CliResult;
using pkmws::test::slurp;

Result run(const std::string& args) {
  const fs::path dir = pkmws::test::scratch_dir("bodies");
  Result r = pkmws::test::run_cli(args, dir);
  fs::remove_all(dir);
  return r;
}

TEST(BodiesCli, ExplainNamesTheCollidingParts) {
  // M1 machine, P beyond guide 2 (x = 120): rod 1 crosses the axis body of guide 2.
  auto r = run("explain " + dataset("machine_moma_m1") + " 120 -272 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  auto j = json::parse(r.out);
  EXPECT_TRUE(j["reachable"].get<bool>());
  EXPECT_TRUE(j["collides"].get<bool>());
  bool rod_housing = false;
  for (const auto& c : j["collisions"]) rod_housing = rod_housing || c == "rod1 / housing2";
  EXPECT_TRUE(rod_housing) << r.out;
  // Between the guides, low: nothing touches.
  r = run("explain " + dataset("machine_moma_m1") + " 0 -350 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  j = json::parse(r.out);
  EXPECT_FALSE(j["collides"].get<bool>());
  EXPECT_TRUE(j["collisions"].empty());
  EXPECT_EQ(j["pairs"].size(), 12u);  // 11 part pairs and the rods' angle
  // Text form, an unreachable point, and a file without bodies (one line, exit 2).
  r = run("explain " + dataset("machine_moma_m1") + " 120 -272");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("COLLISION"), std::string::npos);
  r = run("explain " + dataset("machine_moma_m1") + " 0 0 --json");
  EXPECT_EQ(r.status, 0);
  EXPECT_FALSE(json::parse(r.out)["reachable"].get<bool>());
  r = run("explain " + dataset("moma_m1_g0_l250") + " 0 -300");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("no `bodies`"), std::string::npos);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1);
  r = run("explain " + dataset("machine_moma_m1") + " 0 nan");
  EXPECT_EQ(r.status, 2);
}

TEST(BodiesCli, InfoListsTheCheckedPairs) {
  // MOMA machine: 7 parts; joined pairs (platform-rods, rods, rod-own slider, slider-own housing),
  // allowed rod-own housing and the fixed pair housing1-housing2 are not checked: 11 remain.
  const auto r = run("info " + dataset("machine_moma_m1") + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto pairs = json::parse(r.out)["derived"]["collision_pairs"];
  ASSERT_EQ(pairs.size(), 11u);
  for (const auto& p : pairs) {
    EXPECT_FALSE(p[0] == "rod1" && p[1] == "housing1");
    EXPECT_FALSE(p[0] == "housing1" && p[1] == "housing2");
  }
}

TEST(BodiesCli, AreaReportsReachableAndRealWithBounds) {
  const auto r = run("area " + dataset("machine_moma_m1") + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = json::parse(r.out);
  const double reach = j["reachable_area"], lo = j["real_area_lower"], hi = j["real_area_upper"];
  EXPECT_NEAR(reach, j["area"].get<double>(), 1e-9 * reach);
  EXPECT_LT(lo, hi);
  EXPECT_LT(hi, reach);
  EXPECT_EQ(j["real_method"], "certified");
  double exact_sum = 0;
  for (const auto& i : j["interference"]) {
    EXPECT_LE(i["area_lower"].get<double>(), i["area_upper"].get<double>());
    if (i["method"] == "exact") exact_sum += i["area_lower"].get<double>();
  }
  // Lost area: at least the largest single interference, at most their sum.
  EXPECT_GT(exact_sum, 0.0);
  const auto text = run("area " + dataset("machine_moma_m1"));
  EXPECT_NE(text.out.find("real       "), std::string::npos);
  EXPECT_NE(text.out.find("rod1 / housing2"), std::string::npos);
}

TEST(BodiesCli, ExportDrawsInterferenceAndRealOutline) {
  const fs::path out = fs::temp_directory_path() / ("pkmws-bodies-fig-" + std::to_string(::getpid()) + ".svg");
  const auto r = run("export " + dataset("machine_moma_m5") + " -f svg -o " + out.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string svg = slurp(out);
  fs::remove(out);
  EXPECT_NE(svg.find("rod1 / housing2"), std::string::npos);
  EXPECT_NE(svg.find("real workspace"), std::string::npos);
  EXPECT_NE(svg.find("stroke=\"black\""), std::string::npos);
  // Interference hatched (overlaps stay readable), not translucent fills.
  EXPECT_NE(svg.find("fill=\"url(#hatch"), std::string::npos);
  EXPECT_EQ(svg.find("fill-opacity=\"0.4"), std::string::npos);
  // --real: the real workspace's inner enclosure, e.g. as WKT; needs bodies.
  const fs::path wkt = fs::temp_directory_path() / ("pkmws-bodies-real-" + std::to_string(::getpid()) + ".wkt");
  // WKT has no metadata: the enclosure is named on the command line.
  auto w = run("export " + dataset("machine_moma_m5") + " -f wkt --real -o " + wkt.string());
  EXPECT_EQ(w.status, 2);
  EXPECT_NE(w.err.find("--bound"), std::string::npos);
  EXPECT_FALSE(fs::exists(wkt));
  w = run("export " + dataset("machine_moma_m5") + " -f wkt --real --bound inner -o " + wkt.string());
  ASSERT_EQ(w.status, 0) << w.err;
  EXPECT_EQ(slurp(wkt).rfind("MULTIPOLYGON", 0), 0u);
  fs::remove(wkt);
  w = run("export " + dataset("moma_m5_gp5_gm5_l195") + " -f wkt --real -o " + wkt.string());
  EXPECT_EQ(w.status, 2);
  EXPECT_NE(w.err.find("--real needs `bodies`"), std::string::npos);
  EXPECT_FALSE(fs::exists(wkt));
}

// Every certified pair of the M3 machine (rods, slider blocks and axis bodies
// against each other) converges: its bound width shrinks with the quadtree depth.
TEST(BodiesMachines, EveryPairsBoundWidthShrinksWithDepth) {
  const auto mech = io::load_mechanism(dataset("machine_moma_m3"));
  const auto reachable = mech.model->workspace();
  bodies::InterferenceOptions coarse, fine;
  coarse.max_depth = 4;
  fine.max_depth = 6;
  const auto a = bodies::real_workspace(*mech.bodies, reachable, coarse);
  const auto b = bodies::real_workspace(*mech.bodies, reachable, fine);
  ASSERT_EQ(a.interference.size(), b.interference.size());
  int certified_pairs = 0;
  for (std::size_t k = 0; k < a.interference.size(); ++k) {
    const double wa = a.interference[k].region.width(), wb = b.interference[k].region.width();
    if (wa == 0.0) continue;
    ++certified_pairs;
    // Two levels: about a quarter; at most 0.6 allowed.
    EXPECT_LT(wb, 0.6 * wa) << a.interference[k].a << " / " << a.interference[k].b;
  }
  EXPECT_GE(certified_pairs, 5);
}

// The DexTAR machine: where the distal links fold onto each other (near the
// type-2 singularity ε = 0, docs/theory/five_bar.md) the link-angle pair collides, and such
// poses lie in that pair's certified region.
TEST(BodiesMachines, DistalLinksCannotFoldOntoEachOther) {
  const auto mech = io::load_mechanism(dataset("machine_five_bar_dextar"));
  const auto reachable = mech.model->workspace();
  ASSERT_GT(mech.bodies->model().min_link_angle, 0.0);
  certified::CellOptions cells;
  cells.max_depth = 5;
  const auto fold = certified::certify(bodies::link_angle_test(*mech.bodies, 1e-9), reachable, cells);
  EXPECT_GT(fold.area_lower, 0.0);
  const auto bb = reachable.bbox();
  const testing_bodies::Classifier outer(fold.outer, 1e-9);
  std::mt19937 gen(3);
  std::uniform_real_distribution<double> x(bb.min.x, bb.max.x), y(bb.min.y, bb.max.y);
  int folded = 0;
  for (int k = 0; k < 20000 && folded < 20; ++k) {
    const geometry::Point p{x(gen), y(gen)};
    const auto v = mech.bodies->link_vectors_at(p);
    if (!v) continue;
    const double angle = bodies::unsigned_angle((*v)[0], (*v)[1]);
    if (angle > 10.0 * std::numbers::pi / 180.0) continue;  // well below the 20° minimum
    ++folded;
    const auto check = bodies::check_pose(*mech.bodies, p);
    EXPECT_TRUE(check.collides());
    EXPECT_EQ(check.contacts.back().kind, "link_angle");
    EXPECT_TRUE(check.contacts.back().collides);
    EXPECT_NE(outer(p), testing_bodies::Side::outside) << p.x << ", " << p.y;
  }
  EXPECT_GE(folded, 5);
}

// Every bundled machine: the certified regions against the pose-by-pose test.
TEST(BodiesMachines, EveryRegionAgreesWithThePoseTest) {
  for (const char* stem : {"machine_moma_m1", "machine_moma_m3", "machine_moma_m5", "machine_five_bar_dextar"}) {
    const auto mech = io::load_mechanism(dataset(stem));
    ASSERT_TRUE(mech.bodies) << stem;
    const auto reachable = mech.model->workspace();
    bodies::InterferenceOptions opt;
    opt.max_depth = 5;
    const auto real = bodies::real_workspace(*mech.bodies, reachable, opt);
    EXPECT_LT(real.real.area_upper, reachable.area()) << stem;  // the real workspace is smaller
    EXPECT_GT(real.real.area_lower, 0.3 * reachable.area()) << stem;
    // Pose test at random reachable poses vs the real workspace's enclosure.
    const auto bb = reachable.bbox();
    const double tol = 1e-7 * std::hypot(bb.width(), bb.height());
    const testing_bodies::Classifier inner(real.real.inner, tol), outer(real.real.outer, tol);
    std::vector<std::pair<testing_bodies::Classifier, testing_bodies::Classifier>> pairs;
    for (const auto& i : real.interference) pairs.emplace_back(testing_bodies::Classifier(i.region.inner, tol),
                                                               testing_bodies::Classifier(i.region.outer, tol));
    int pair_in = 0, pair_out = 0;
    std::mt19937 gen(5);
    std::uniform_real_distribution<double> x(bb.min.x, bb.max.x), y(bb.min.y, bb.max.y);
    int tested = 0, in = 0, out = 0;
    while (tested < 4000) {
      const geometry::Point p{x(gen), y(gen)};
      const auto check = bodies::check_pose(*mech.bodies, p);
      if (!check.reachable) continue;
      ++tested;
      // Each pair's region: inner ⇒ that pair collides; outside outer ⇒ it does not.
      for (std::size_t k = 0; k < real.interference.size(); ++k) {
        const auto& i = real.interference[k];
        bool collides = false;
        for (const auto& c : check.contacts) {
          if (c.a == i.a && c.b == i.b && c.kind == i.kind) collides = c.collides;
        }
        if (pairs[k].first(p) == testing_bodies::Side::inside) {
          ++pair_in;
          EXPECT_TRUE(collides) << stem << " " << i.a << " / " << i.b << " (" << p.x << ", " << p.y << ")";
        } else if (pairs[k].second(p) == testing_bodies::Side::outside) {
          ++pair_out;
          EXPECT_FALSE(collides) << stem << " " << i.a << " / " << i.b << " (" << p.x << ", " << p.y << ")";
        }
      }
      if (inner(p) == testing_bodies::Side::inside) {
        ++in;
        EXPECT_FALSE(check.collides()) << stem << " (" << p.x << ", " << p.y << ")";
      } else if (outer(p) == testing_bodies::Side::outside) {
        ++out;
        EXPECT_TRUE(check.collides()) << stem << " (" << p.x << ", " << p.y << ")";
      }
    }
    std::printf("[ brute force ] %s: %d poses: %d certainly real and collision-free, %d certainly colliding, %d undecided;"
                " per pair: %d certainly-colliding and %d certainly-clear checks agreed\n",
                stem, tested, in, out, tested - in - out, pair_in, pair_out);
    EXPECT_GT(in, 1000) << stem;
    EXPECT_GT(out, 500) << stem;
  }
}

}  // namespace
