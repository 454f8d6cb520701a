#include "report_fixtures.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "io/document.hpp"

namespace pkmws::test {

io::MechanismFile toy_annulus_file() {
  const nlohmann::json toy = {{"name", "toy annulus"}, {"mechanism", "toy_rp"}, {"units", "mm"},
                              {"base", {1.0, 2.0}}, {"stroke", {3.0, 7.0}}};
  return io::parse_mechanism(toy, "toy_annulus.json");
}

nlohmann::json parsed(const std::string& json_text) {
  nlohmann::json j;
  EXPECT_NO_THROW(j = nlohmann::json::parse(json_text)) << json_text;
  return j;
}

std::filesystem::path fresh_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("pkmws-report-" + std::string(info->test_suite_name()) + "-" + info->name());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

std::filesystem::path write_toy(const std::filesystem::path& dir, const std::string& stem, double base_x,
                                double base_y, double rho_min, double rho_max, const std::string& units) {
  const nlohmann::json toy = {{"name", stem}, {"mechanism", "toy_rp"}, {"units", units},
                              {"base", {base_x, base_y}}, {"stroke", {rho_min, rho_max}}};
  return write_text(dir / (stem + ".json"), toy.dump(2));
}

std::filesystem::path write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream ss(text);
  for (std::string line; std::getline(ss, line);) out.push_back(line);
  return out;
}

}  // namespace pkmws::test
