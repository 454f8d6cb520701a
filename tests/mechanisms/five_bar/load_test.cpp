// Five-bar files: errors name the field.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include <nlohmann/json.hpp>

#include "io/document.hpp"
#include "support/load_error.hpp"

#include "pkmws/geometry/primitives.hpp"
#include "pkmws/io/mechanism_file.hpp"
#include "mechanisms/five_bar/five_bar.hpp"
#include "support/fixtures.hpp"
#include "support/mechanisms/five_bar.hpp"

using namespace pkmws;
using namespace pkmws::test::five_bar;
using mechanisms::FiveBar;

namespace {

io::MechanismFile parse(const nlohmann::json& doc) { return io::parse_mechanism(doc, "test"); }

nlohmann::json dextar_doc() {
  return {{"name", "t"},
          {"mechanism", "five_bar"},
          {"units", "m"},
          {"base", {{-A, 0.0}, {A, 0.0}}},
          {"proximal", {L, L}},
          {"distal", {L, L}},
          {"working_mode", {1, -1}}};
}

using pkmws::test::load_error;

}  // namespace

TEST(FiveBarFile, ErrorsNameTheField) {
  auto doc = dextar_doc();
  EXPECT_NO_THROW(parse(doc));
  {
    auto d = doc;
    d["working_mode"] = {1, 0};
    EXPECT_EQ(load_error(d), "working_mode[1]: expected -1 or 1");
  }
  {
    auto d = doc;
    d["proximal"] = {-0.23, 0.23};
    EXPECT_EQ(load_error(d), "proximal[0]: must be positive");
  }
  {
    auto d = doc;
    d["distal"] = {0.23};
    EXPECT_NE(load_error(d).find("distal: expected an array of 2 numbers"), std::string::npos);
  }
  {
    auto d = doc;
    d["actuator_limits_deg"] = {{30, 150}, {150, 30}};
    EXPECT_EQ(load_error(d), "actuator_limits_deg[1]: expected [min, max] with min < max");
  }
  {
    auto d = doc;
    d["actuator_limits_deg"] = {nullptr, {0, 400}};
    EXPECT_EQ(load_error(d), "actuator_limits_deg[1]: the range must not exceed 360 degrees");
  }
  {
    auto d = doc;
    d["actuator_limits_deg"] = {{30, 150}, nullptr};
    const auto f = parse(d);
    const auto& m = dynamic_cast<const FiveBar&>(*f.model);
    EXPECT_TRUE(m.crank_limits(0).has_value());
    EXPECT_FALSE(m.crank_limits(1).has_value());
  }
  {
    auto d = doc;
    d["pi_joints"] = {{{"k", 0.4}, {"stroke", {0.1, 0.3}}, {"base_angle_deg", 90}},
                      {{"k", 0.4}, {"stroke", {0.15, 0.3}}, {"base_angle_deg", 90}, {"sense", -1}}};
    EXPECT_EQ(load_error(d).rfind("pi_joints[0].stroke: must lie strictly inside", 0), 0u) << load_error(d);
  }
  {
    auto d = doc;
    d["pi_joints"] = {{{"k", 0.4}, {"stroke", {0.15, 0.3}}, {"base_angle_deg", 90}},
                      {{"k", 0.4}, {"stroke", {0.15, 0.3}}, {"base_angle_deg", 90}, {"sense", 2}}};
    EXPECT_EQ(load_error(d), "pi_joints[1].sense: expected -1 or 1");
  }
  {
    auto d = doc;
    d["pi_joints"] = {{{"k", 0.4}, {"stroke", {0.15, 0.3}}, {"base_angle_deg", 90}, {"lead", 2}},
                      {{"k", 0.4}, {"stroke", {0.15, 0.3}}, {"base_angle_deg", 90}}};
    EXPECT_EQ(load_error(d), "pi_joints[0].lead: unknown field (expected one of: k, stroke, base_angle_deg, sense)");
  }
  {
    auto d = doc;
    d["actuator_limits_deg"] = {{30, 150}, {30, 150}};
    d["pi_joints"] = {{{"k", 0.4}, {"stroke", {0.15, 0.3}}, {"base_angle_deg", 90}},
                      {{"k", 0.4}, {"stroke", {0.15, 0.3}}, {"base_angle_deg", 90}}};
    EXPECT_EQ(load_error(d).rfind("pi_joints: give either", 0), 0u) << load_error(d);
  }
  {
    auto d = doc;
    d["elbows"] = 2;
    EXPECT_EQ(load_error(d).rfind("elbows: unknown field (expected one of: name, ", 0), 0u) << load_error(d);
  }
}
