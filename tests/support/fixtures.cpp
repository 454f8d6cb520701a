#include "fixtures.hpp"

#include <algorithm>
#include <fstream>
#include <iterator>

namespace pkmws::test {

std::filesystem::path datasets_dir() { return std::filesystem::path(PKMWS_SOURCE_DIR) / "datasets"; }

std::string dataset(const std::string& stem) { return std::string(PKMWS_SOURCE_DIR) + "/datasets/" + stem + ".json"; }

std::vector<std::filesystem::path> dataset_files(const std::string& prefix) {
  std::vector<std::filesystem::path> out;
  for (const auto& e : std::filesystem::directory_iterator(datasets_dir())) {
    const std::string name = e.path().filename().string();
    if (e.path().extension() == ".json" && name.rfind(prefix, 0) == 0) out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::size_t count_of(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
}

}  // namespace pkmws::test
