// Walks the registry of mechanism modules: every registered kind (the bundled
// modules and the tests' toy) loads from a file and answers every generic
// question of the Mechanism interface consistently; every capability is an
// object or a stated reason.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "io/document.hpp"
#include "io/registry.hpp"
#include "pkmws/bodies/bodies.hpp"
#include "pkmws/criteria/fields.hpp"
#include "pkmws/geometry/inscribed.hpp"
#include "pkmws/io/mechanism_file.hpp"
#include "pkmws/io/plot.hpp"
#include "io/load_bodies.hpp"
#include "support/fixtures.hpp"

namespace {

using namespace pkmws;
namespace fs = std::filesystem;

// One bundled dataset per keyword (the first in name order), and the toy's file.
std::map<std::string, io::MechanismFile> one_file_per_kind() {
  std::map<std::string, io::MechanismFile> out;
  for (const auto& p : pkmws::test::dataset_files()) {
    std::ifstream in(p);
    const auto doc = nlohmann::json::parse(in);
    const std::string kind = doc.at("mechanism").get<std::string>();
    if (!out.count(kind) && !doc.contains("criteria") && !doc.contains("bodies")) out.emplace(kind, io::load_mechanism(p));
  }
  const nlohmann::json toy = {{"name", "toy"}, {"mechanism", "toy_rp"}, {"units", "mm"},
                              {"base", {1.0, 2.0}}, {"stroke", {3.0, 7.0}}};
  if (io::detail::find_kind("toy_rp")) out.emplace("toy_rp", io::parse_mechanism(toy, "toy.json"));
  return out;
}

template <class C>
void expect_answer(const mechanisms::Mechanism& m) {
  const auto c = m.capability<C>();
  if (!c) {
    EXPECT_FALSE(c.reason().empty()) << m.kind();
    EXPECT_NE(c.reason().find(std::string(m.kind())), std::string::npos) << c.reason();
    EXPECT_THROW(c.get(), std::invalid_argument);
  }
}

TEST(Registry, EveryKindHasADatasetAndKeywordsAreSortedAndUnique) {
  const auto files = one_file_per_kind();
  std::string previous;
  for (const auto& kind : io::detail::kinds()) {
    EXPECT_LT(previous, kind.keyword);
    previous = kind.keyword;
    EXPECT_TRUE(files.count(kind.keyword)) << "no bundled dataset for " << kind.keyword;
    EXPECT_FALSE(kind.fields.empty()) << kind.keyword;
  }
  EXPECT_TRUE(io::detail::find_kind("toy_rp")) << "the toy module registers itself";
  EXPECT_THROW(io::detail::register_kinds({{"moma", nullptr, {}}}), std::invalid_argument);
}

TEST(Registry, EveryMechanismAnswersEveryGenericQuestion) {
  for (const auto& [kind, file] : one_file_per_kind()) {
    SCOPED_TRACE(kind);
    const mechanisms::Mechanism& m = *file.model;
    EXPECT_EQ(m.kind(), kind);
    ASSERT_GE(m.dof(), 1);
    ASSERT_LE(m.dof(), 3);
    const auto joints = m.joints();
    ASSERT_EQ(joints.size(), static_cast<std::size_t>(m.dof()));
    for (const auto& j : joints) {
      EXPECT_FALSE(j.name.empty());
      if (j.range) {
        EXPECT_LE((*j.range)[0], (*j.range)[1]) << j.name;
      }
    }
    expect_answer<mechanisms::PoseSlice>(m);
    expect_answer<mechanisms::Elimination>(m);
    expect_answer<mechanisms::GuidedRodLegs>(m);
    expect_answer<criteria::CriterionFields>(m);
    expect_answer<bodies::RigFactory>(m);
    expect_answer<io::Charts>(m);
    if (m.dof() == 1) continue;  // the Π-joint: a drive, no planar workspace (its charts instead)

    // A pose well inside the workspace (its inner enclosure where it is
    // certified): the centre of its largest inscribed circle.
    const auto enclosure = m.workspace_enclosure(6);
    const geometry::Region& w = enclosure.inner;
    if (enclosure.exact) {
      EXPECT_NEAR(m.workspace().area(), w.area(), 1e-9 * w.area());
    }
    ASSERT_GT(w.area(), 0.0);
    const auto comps = w.components();
    ASSERT_FALSE(comps.empty());
    const auto circle = geometry::largest_inscribed_circle(comps.front(), 1e-3 * std::sqrt(w.area()));
    const mechanisms::Pose pose{circle.center.x, circle.center.y, m.orientation()};
    EXPECT_TRUE(m.reachable(pose));
    EXPECT_TRUE(w.contains(circle.center));
    const geometry::Box b = m.bounds(), wb = w.bbox();
    EXPECT_LE(b.min.x, wb.min.x + 1e-9);
    EXPECT_GE(b.max.x, wb.max.x - 1e-9);

    // Inverse then direct gives the pose back in some assembly mode.
    const auto ik = m.inverse(pose);
    ASSERT_FALSE(ik.empty());
    const auto valid = std::find_if(ik.begin(), ik.end(), [](const auto& s) { return s.valid; });
    ASSERT_NE(valid, ik.end());
    EXPECT_EQ(valid->joints.size(), joints.size());
    const auto dk = m.direct(valid->joints);
    const double scale = std::sqrt(w.area());
    bool back = false;
    for (const auto& s : dk) {
      back = back || (std::hypot(s.pose.x - pose.x, s.pose.y - pose.y) < 1e-7 * scale &&
                      (m.dof() < 3 || std::abs(std::remainder(s.pose.phi - pose.phi, 2 * M_PI)) < 1e-7));
    }
    EXPECT_TRUE(back);
    const auto ev = m.evaluate(pose, file.criteria);
    ASSERT_FALSE(ev.empty());
    EXPECT_TRUE(std::any_of(ev.begin(), ev.end(), [](const auto& e) { return e.reachable; }));
    const auto d = m.draw(pose);
    EXPECT_NEAR(d.tool.x, pose.x, 1e-9 * scale);
    EXPECT_FALSE(m.workspace_label().empty());
  }
}

}  // namespace
