// Error messages of the mechanism loaders name the offending field: an unknown
// (e.g. misspelt) key is reported first, with its path and the valid fields,
// before the "missing required field" its misspelling causes (docs/format.md).
#include <gtest/gtest.h>

#include <string>

#include <nlohmann/json.hpp>

#include "support/load_error.hpp"

namespace pkmws::test {
namespace {

nlohmann::json moma() {
  const nlohmann::json leg = {{"reference", {-100, 0}}, {"guide_angle_deg", 270}, {"stroke", {0, 200}},
                              {"rod_length", 250}, {"branch", -1}};
  nlohmann::json leg2 = leg;
  leg2["reference"] = {100, 0};
  return {{"name", "m"}, {"mechanism", "moma"}, {"units", "mm"}, {"legs", {leg, leg2}}};
}

// Renames `from` to `to` in the object at `pointer`.
nlohmann::json renamed(nlohmann::json doc, const std::string& pointer, const std::string& from, const std::string& to) {
  auto& object = doc.at(nlohmann::json::json_pointer(pointer));
  object[to] = object.at(from);
  object.erase(from);
  return doc;
}

TEST(LoaderMessages, MisspeltFieldIsNamedWithTheValidOnes) {
  EXPECT_EQ(load_error(moma()), "");
  EXPECT_EQ(load_error(renamed(moma(), "/legs/1", "rod_length", "rod_lenght")),
            "legs[1].rod_lenght: unknown field (expected one of: reference, guide_angle_deg, stroke, rod_length, "
            "branch)");
  EXPECT_EQ(load_error(renamed(moma(), "/legs/0", "branch", "brnach")),
            "legs[0].brnach: unknown field (expected one of: reference, guide_angle_deg, stroke, rod_length, branch)");
}

TEST(LoaderMessages, TopLevelUnknownFieldListsTheKindsFields) {
  EXPECT_EQ(load_error(renamed(moma(), "", "legs", "legz")),
            "legz: unknown field (expected one of: name, mechanism, units, description, source, criteria, legs, "
            "bodies)");
  // Reported before the missing `name`, whatever the order of the keys.
  auto doc = renamed(moma(), "", "legs", "legz");
  doc.erase("name");
  EXPECT_EQ(load_error(doc).rfind("legz: unknown field (expected one of: name, ", 0), 0u) << load_error(doc);
  // Without a known kind the list holds every kind's fields.
  doc = moma();
  doc["mechanism"] = "hexapod";
  doc["legz"] = 1;
  const std::string m = load_error(doc);
  EXPECT_EQ(m.rfind("legz: unknown field (expected one of: name, mechanism, ", 0), 0u) << m;
  for (const char* f : {"legs", "half_width", "crank_length", "pi_joints", "actuation", "directions_deg", "bodies"}) {
    EXPECT_NE(m.find(f), std::string::npos) << f << " in " << m;
  }
  doc.erase("legz");
  EXPECT_EQ(load_error(doc).rfind("mechanism: unknown value \"hexapod\"", 0), 0u) << load_error(doc);
}

TEST(LoaderMessages, NestedObjectsOfEveryKindNameTheirUnknownField) {
  auto criteria = moma();
  criteria["criteria"] = {{"max_pressure_angle_deg", 40}, {"max_reaction", 3}};
  EXPECT_EQ(load_error(criteria),
            "criteria.max_reaction: unknown field (expected one of: max_pressure_angle_deg, max_reaction_N, load, "
            "max_velocity_ratio, max_condition_number, characteristic_length, reaction_legs, "
            "min_singularity_distance)");
  criteria["criteria"] = {{"max_reaction_N", 300}, {"load", {{"force", 100}}}};
  EXPECT_EQ(load_error(criteria), "criteria.load.force: unknown field (expected one of: force_N, moment_Nm)");

  const nlohmann::json biglide = {{"name", "b"},           {"mechanism", "biglide"}, {"units", "mm"},
                                  {"half_width", 500},     {"rods", {940, 940}},     {"stroke", {{0, 1600}, {0, 1600}}},
                                  {"tool", {{"l3", 900}, {"l_4", 150}}}};
  EXPECT_EQ(load_error(biglide), "tool.l_4: unknown field (expected one of: l3, l4)");

  const nlohmann::json pi = {{"name", "p"},
                             {"mechanism", "pi_joint"},
                             {"units", "mm"},
                             {"crank_length", 170},
                             {"k", 0.4},
                             {"theta_limits_deg", {-60, 60}},
                             {"actuator", {{"lead", 2.54}, {"resolution", 0.0127}}}};
  EXPECT_EQ(load_error(pi),
            "actuator.resolution: unknown field (expected one of: lead, resolution_per_step, max_speed, max_force_N, "
            "efficiency)");

  nlohmann::json bodies = moma();
  bodies["bodies"] = {{"rods", {{{"radius", 9}}, {{"radius", 9}, {"width", 1}}}}};
  EXPECT_EQ(load_error(bodies), "bodies.rods[1].width: unknown field (expected one of: radius)");
  bodies["bodies"] = {{"proximal", {{{"radius", 9}}, {{"radius", 9}}}}};
  EXPECT_EQ(load_error(bodies),
            "bodies.proximal: unknown field (expected one of: platform_joint, rods, slider_blocks, housings, "
            "obstacles, allowed_contacts)");
  bodies["bodies"] = {{"housings", {{{"extent", {0, 200}}, {"width", 50}}, {{"extnt", {0, 200}}, {"width", 50}}}}};
  EXPECT_EQ(load_error(bodies), "bodies.housings[1].extnt: unknown field (expected one of: extent, width)");
}

}  // namespace
}  // namespace pkmws::test
