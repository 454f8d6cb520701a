// Biglide files: errors name the field.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "io/document.hpp"
#include "pkmws/io/mechanism_file.hpp"
#include "mechanisms/biglide/biglide.hpp"
#include "support/fixtures.hpp"
#include "support/load_error.hpp"

using namespace pkmws;
using mechanisms::Biglide;

namespace {

io::MechanismFile parse(const nlohmann::json& doc) { return io::parse_mechanism(doc, "test"); }

using pkmws::test::load_error;

}  // namespace

TEST(BiglideFile, ErrorsNameTheField) {
  const nlohmann::json doc = {{"name", "t"},        {"mechanism", "biglide"}, {"units", "mm"},
                              {"half_width", 500},  {"rods", {940, 940}},     {"stroke", {{0, 1600}, {0, 1600}}}};
  EXPECT_NO_THROW(parse(doc));
  auto with = [&](const std::string& key, const nlohmann::json& value) {
    auto d = doc;
    d[key] = value;
    return load_error(d);
  };
  EXPECT_EQ(with("half_width", -1), "half_width: must be positive (got -1.0)");
  EXPECT_EQ(with("rods", {940, 0}), "rods[1]: must be positive");
  EXPECT_EQ(with("stroke", {{0, 1600}, {1600, 0}}), "stroke[1]: expected [min, max] with min < max");
  EXPECT_EQ(with("stroke", {0, 1600}), "stroke[0]: expected [min, max]");
  EXPECT_EQ(with("tool", {{"l3", 900}, {"l4", 10}}), "tool.l4: the triangle S1 J T needs |l1 - l3| <= l4 <= l1 + l3 (l1 = rods[0])");
  EXPECT_EQ(with("tool", {{"l3", 900}, {"l4", 150}, {"l5", 1}}), "tool.l5: unknown field (expected one of: l3, l4)");
  EXPECT_EQ(with("tool", {{"l3", 900}}), "tool.l4: missing required field");
  EXPECT_EQ(with("table", 1), "table: unknown field (expected one of: name, mechanism, units, description, source, criteria, "
                                "half_width, rods, stroke, tool, bodies)");
}
