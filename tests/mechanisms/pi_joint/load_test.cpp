// Active Π-joint files: errors name the field.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "io/document.hpp"
#include "pkmws/io/mechanism_file.hpp"
#include "pkmws/io/plot.hpp"
#include "mechanisms/pi_joint/charts.hpp"
#include "support/fixtures.hpp"
#include "support/mechanisms/pi_joint.hpp"
#include "support/load_error.hpp"

using namespace pkmws;
using namespace pkmws::test::pi_joint;

namespace {

using pkmws::test::load_error;

}  // namespace

TEST(PiJointFile, ErrorsNameTheField) {
  const nlohmann::json doc = {{"name", "t"},       {"mechanism", "pi_joint"}, {"units", "mm"},
                              {"crank_length", 170}, {"k", 0.4},            {"theta_limits_deg", {-60, 60}}};
  EXPECT_NO_THROW(io::parse_mechanism(doc, "test"));
  auto with = [&](const std::string& key, const nlohmann::json& value) {
    auto d = doc;
    d[key] = value;
    return load_error(d);
  };
  EXPECT_EQ(with("theta_limits_deg", {-60, 95}).rfind("theta_limits_deg: must lie inside (-90, 90) degrees", 0), 0u);
  EXPECT_EQ(with("k", 0), "k: must be positive (got 0.0)");
  EXPECT_EQ(with("stroke", {300, 400}).rfind("stroke: does not meet the d range", 0), 0u) << with("stroke", {300, 400});
  EXPECT_EQ(with("actuator", {{"lead", 2.54}, {"resolution_per_step", 0.0127}, {"max_speed", 50},
                              {"max_force_N", 130}, {"efficiency", 1.5}}),
            "actuator.efficiency: must lie in (0, 1]");
  EXPECT_EQ(with("actuator", {{"lead", 2.54}, {"resolution_per_step", 0.0127}, {"max_speed", 50},
                              {"max_force_N", 130}, {"pitch", 1}}),
            "actuator.pitch: unknown field (expected one of: lead, resolution_per_step, max_speed, max_force_N, efficiency)");
  EXPECT_EQ(with("actuator", {{"lead", 2.54}}), "actuator.resolution_per_step: missing required field");
  EXPECT_EQ(with("b", 68).rfind("b: unknown field (expected one of: name, mechanism, units, description, source, criteria, crank_length, k, ", 0), 0u) << with("b", 68);
}
