// MOMA files: every field read, each bad field named by its path, file errors
// carry the path.
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

#include <nlohmann/json.hpp>

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

namespace {

constexpr double pi = std::numbers::pi;
constexpr double deg = pi / 180.0;

}  // namespace

namespace {

const std::string good_moma = R"({"name": "t", "mechanism": "moma", "units": "mm", "legs": [
    {"reference": [-100, 0], "guide_angle_deg": 270, "stroke": [0, 200], "rod_length": 250, "branch": -1},
    {"reference": [100, 0], "guide_angle_deg": 270, "stroke": [0, 200], "rod_length": 250, "branch": -1}]})";

// good_moma with the first `from` (in the second leg if `second_leg`) replaced by `to`.
std::string edit(const std::string& from, const std::string& to, bool second_leg = false) {
  std::string s = good_moma;
  const auto start = second_leg ? s.find("\"reference\": [100") : 0;
  const auto pos = s.find(from, start);
  if (pos == std::string::npos) throw std::logic_error("test edit not found: " + from);
  return s.replace(pos, from.size(), to);
}

std::string load_error(const std::string& text) {
  try {
    io::parse_mechanism(nlohmann::json::parse(text), "test");
  } catch (const io::InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(MomaLoader, ReadsEveryField) {
  const auto f = io::parse_mechanism(nlohmann::json::parse(edit("\"guide_angle_deg\": 270", "\"guide_angle_deg\": 265")), "t");
  const Moma& m = as_moma(f);
  EXPECT_EQ(m.legs()[0].reference, (Point{-100, 0}));
  EXPECT_NEAR(m.legs()[0].guide_angle, 265 * deg, 1e-15);
  EXPECT_DOUBLE_EQ(m.legs()[1].guide_angle, 270 * deg);
  EXPECT_EQ(m.legs()[1].stroke_max, 200.0);
  EXPECT_EQ(m.legs()[1].rod_length, 250.0);
  EXPECT_EQ(m.legs()[1].branch, -1);
  // 270 degrees is exactly the axis direction (0, -1).
  EXPECT_EQ(m.guide_direction(1), (Point{0, -1}));
  // Angles beyond a turn are the same guide.
  const auto g = io::parse_mechanism(nlohmann::json::parse(edit("\"guide_angle_deg\": 270", "\"guide_angle_deg\": 990")), "t");
  EXPECT_EQ(as_moma(g).guide_direction(0), (Point{0, -1}));
  // A negative start of the stroke is allowed.
  EXPECT_NO_THROW(io::parse_mechanism(nlohmann::json::parse(edit("\"stroke\": [0, 200]", "\"stroke\": [-50, 200]")), "t"));
}

TEST(MomaLoader, EachBadFieldNamesItsPath) {
  const std::pair<std::string, std::string> cases[] = {
      {edit("\"legs\": [", "\"legz\": ["), "legz: unknown field (expected one of: name, mechanism, units, description, source, criteria, legs, bodies)"},
      {edit("\"rod_length\": 250", "\"rod_length\": -250", true), "legs[1].rod_length: must be positive"},
      {edit("\"rod_length\": 250", "\"rod_length\": 0"), "legs[0].rod_length: must be positive"},
      {edit("\"rod_length\": 250", "\"rod_length\": 1e300"), "legs[0].rod_length"},
      {edit(", \"rod_length\": 250", "", true), "legs[1].rod_length: missing"},
      {edit("\"branch\": -1", "\"branch\": 2", true), "legs[1].branch"},
      {edit("\"branch\": -1", "\"branch\": 0"), "legs[0].branch"},
      {edit("\"branch\": -1", "\"branch\": -1.0"), "legs[0].branch"},
      {edit("\"guide_angle_deg\": 270", "\"guide_angle_deg\": 270, \"foo\": 1"), "legs[0].foo: unknown field (expected one of: reference, guide_angle_deg, stroke, rod_length, branch)"},
      {edit("\"guide_angle_deg\": 270", "\"guide_angle_deg\": \"down\""), "legs[0].guide_angle_deg"},
      {edit("\"stroke\": [0, 200]", "\"stroke\": [200, 0]"), "legs[0].stroke"},
      {edit("\"stroke\": [0, 200]", "\"stroke\": [100, 100]", true), "legs[1].stroke"},
      {edit("\"stroke\": [0, 200]", "\"stroke\": [0]"), "legs[0].stroke"},
      {edit("\"reference\": [-100, 0]", "\"reference\": [-100]"), "legs[0].reference"},
      {edit("\"reference\": [-100, 0]", "\"reference\": [-100, null]"), "legs[0].reference[1]"},
      {edit("\"units\": \"mm\"", "\"units\": \"ft\""), "units"},
      {edit("\"mechanism\": \"moma\"", "\"mechanism\": \"hexapod\""), "mechanism"},
      {edit(",\n    {\"reference\": [100, 0], \"guide_angle_deg\": 270, \"stroke\": [0, 200], \"rod_length\": 250, "
            "\"branch\": -1}",
            ""),
       "legs: expected an array of 2 objects"},
      {edit("{\"reference\": [100, 0], \"guide_angle_deg\": 270, \"stroke\": [0, 200], \"rod_length\": 250, "
            "\"branch\": -1}",
            "42"),
       "legs[1]: expected a JSON object"},
  };
  for (const auto& [text, needle] : cases) {
    const std::string message = load_error(text);
    EXPECT_NE(message.find(needle), std::string::npos) << "expected \"" << needle << "\", got \"" << message << "\"";
  }
  EXPECT_EQ(load_error(good_moma), "");
}

TEST(MomaLoader, FileErrorsCarryThePath) {
  const auto dir = std::filesystem::temp_directory_path() / "pkmws_moma_loader_test";
  std::filesystem::create_directories(dir);
  const auto path = dir / "bad.json";
  {
    std::ofstream out(path);
    out << edit("\"branch\": -1", "\"branch\": 3", true);
  }
  try {
    io::load_mechanism(path);
    ADD_FAILURE() << "no error";
  } catch (const io::InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(path.string()), std::string::npos) << what;
    EXPECT_NE(what.find("legs[1].branch"), std::string::npos) << what;
  }
  std::filesystem::remove_all(dir);
}
