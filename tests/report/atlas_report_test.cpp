// The atlas report (pkmws/report/atlas.hpp) over a sweep CSV written here: the
// grid of values read (z = x·y where the design is ok), the missing cells, the
// JSON text parsed back, the text line and the errors naming the option or line.
#include <gtest/gtest.h>

#include "pkmws/core/error.hpp"
#include "pkmws/report/atlas.hpp"
#include "support/report_fixtures.hpp"

namespace pkmws {
namespace {

// A 3 x 3 grid sweep over a and b with metric m = a·b; the design (2, 3) failed.
std::string grid_csv(const std::string& extra = "") {
  std::string csv = "index,a,b,status,m,reason\n";
  int i = 0;
  for (int b = 1; b <= 3; ++b) {
    for (int a = 1; a <= 3; ++a) {
      const bool ok = !(a == 2 && b == 3);
      csv += std::to_string(i++) + "," + std::to_string(a) + "," + std::to_string(b) + "," +
             (ok ? "ok," + std::to_string(a * b) + "," : "invalid,,bad") + "\n";
    }
  }
  return csv + extra;
}

report::AtlasOptions options(const std::string& csv) {
  report::AtlasOptions o;
  o.csv = csv;
  o.x = "a";
  o.y = "b";
  o.metric = "m";
  o.output = "atlas.svg";
  return o;
}

TEST(ReportAtlas, ReadsTheGridOfValues) {
  const auto dir = test::fresh_dir();
  const report::AtlasReport r = report::atlas(options(test::write_text(dir / "s.csv", grid_csv()).string()));
  EXPECT_EQ(r.data.xs, (std::vector<double>{1, 2, 3}));
  EXPECT_EQ(r.data.ys, (std::vector<double>{1, 2, 3}));
  ASSERT_EQ(r.data.z.size(), 9u);
  for (std::size_t j = 0; j < 3; ++j) {
    for (std::size_t i = 0; i < 3; ++i) {
      const auto& z = r.data.z[j * 3 + i];
      if (i == 1 && j == 2) {
        EXPECT_FALSE(z);
      } else {
        ASSERT_TRUE(z);
        EXPECT_EQ(*z, r.data.xs[i] * r.data.ys[j]);
      }
    }
  }
  EXPECT_EQ(r.missing, 1u);
  EXPECT_EQ(r.data.title, "m over a \u00d7 b");
  EXPECT_TRUE(r.data.maximize);
  EXPECT_NE(r.svg.find("<svg"), std::string::npos);
  const auto j = test::parsed(report::to_json_text(r));
  EXPECT_EQ(j["columns"], 3);
  EXPECT_EQ(j["rows"], 3);
  EXPECT_EQ(j["cells_without_value"], 1);
  EXPECT_EQ(j["marked"], "largest");
  EXPECT_EQ(j["output"], "atlas.svg");
  EXPECT_EQ(report::to_text(r), "atlas of m over 3 x 3 designs -> atlas.svg\n");
}

TEST(ReportAtlas, ErrorsNameTheOptionOrTheLine) {
  const auto dir = test::fresh_dir();
  const auto message = [&](const report::AtlasOptions& o) {
    try {
      report::atlas(o);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string good = test::write_text(dir / "s.csv", grid_csv()).string();
  report::AtlasOptions o = options(good);
  o.x = "nope";
  EXPECT_EQ(message(o), "--x: no column 'nope' in " + good + " (columns: index, a, b, status, m, reason)");
  const std::string twice = test::write_text(dir / "t.csv", grid_csv("9,1,1,ok,5,\n")).string();
  EXPECT_EQ(message(options(twice)).rfind(twice + ":11: a second design at (1, 1)", 0), 0u) << message(options(twice));
  const std::string bad = test::write_text(dir / "u.csv", grid_csv("9,4,1\n")).string();
  EXPECT_EQ(message(options(bad)), bad + ":11: malformed row");
  const std::string hex = test::write_text(dir / "v.csv", grid_csv("9,0x4,1,ok,1,\n")).string();
  EXPECT_EQ(message(options(hex)), "a: expected a decimal number, got \"0x4\"");
}

}  // namespace
}  // namespace pkmws
