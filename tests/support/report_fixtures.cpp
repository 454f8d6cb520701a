#include "report_fixtures.hpp"

#include <gtest/gtest.h>

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

}  // namespace pkmws::test
