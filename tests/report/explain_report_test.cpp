// The explain report (pkmws/report/explain.hpp): the pose-level collision test
// against the clearances it reports, an unreachable point, and the refusal of
// a file without bodies.
#include <gtest/gtest.h>

#include <numbers>

#include "pkmws/io/mechanism_file.hpp"
#include "pkmws/report/explain.hpp"
#include "support/fixtures.hpp"
#include "support/report_fixtures.hpp"

namespace pkmws {
namespace {

TEST(ReportExplain, ClearancesDecideTheCollisions) {
  const io::MechanismFile f = io::load_mechanism(test::dataset("machine_moma_m1"));
  const report::ExplainReport r = report::explain(f, {0.0, -300.0});
  ASSERT_TRUE(r.check.reachable);
  const auto j = test::parsed(report::to_json_text(r));
  EXPECT_EQ(j["point"], nlohmann::json::array({0.0, -300.0}));
  EXPECT_EQ(j["units"], "mm");
  ASSERT_EQ(j["pairs"].size(), r.check.contacts.size());
  std::size_t hits = 0;
  for (std::size_t k = 0; k < r.check.contacts.size(); ++k) {
    const auto& c = r.check.contacts[k];
    const auto& p = j["pairs"][k];
    EXPECT_EQ(p["collides"].get<bool>(), c.collides);
    if (c.kind == "link_angle") {
      EXPECT_DOUBLE_EQ(p["angle_margin_deg"].get<double>(), c.clearance * 180.0 / std::numbers::pi);
    } else {
      EXPECT_EQ(p["clearance"].get<double>(), c.clearance);
      EXPECT_EQ(c.collides, c.clearance < 0.0) << c.a << " / " << c.b;
    }
    hits += c.collides ? 1 : 0;
  }
  EXPECT_EQ(j["collisions"].size(), hits);
  EXPECT_EQ(j["collides"].get<bool>(), hits > 0);
  const std::string t = report::to_text(r);
  EXPECT_EQ(t.rfind(f.name + " at (0, -300) mm\n", 0), 0u) << t;
  EXPECT_NE(t.find(hits ? "COLLISION\n" : "no collision\n"), std::string::npos) << t;
  EXPECT_EQ(test::count_of(t, "  clearance ") + test::count_of(t, "  angle "), r.check.contacts.size());
}

TEST(ReportExplain, UnreachableAndNoBodies) {
  const io::MechanismFile f = io::load_mechanism(test::dataset("machine_moma_m1"));
  const report::ExplainReport far = report::explain(f, {1e5, 1e5});
  EXPECT_FALSE(far.check.reachable);
  const auto j = test::parsed(report::to_json_text(far));
  EXPECT_TRUE(j.contains("reason"));
  EXPECT_EQ(report::to_text(far).find("not reachable: "), report::to_text(far).find('\n') + 1);
  const io::MechanismFile bare = test::toy_annulus_file();
  try {
    report::explain(bare, {0.0, 0.0});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "toy_annulus.json: the file lists no `bodies` (docs/format.md (bodies)): nothing can collide");
  }
}

}  // namespace
}  // namespace pkmws
