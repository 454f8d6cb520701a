#include "io/registry.hpp"

#include <algorithm>
#include <stdexcept>

namespace pkmws::io::detail {

namespace {

std::vector<Kind>& registry() {
  static std::vector<Kind> all = [] {
    std::vector<Kind> v;
    auto add = [&v](std::vector<Kind> more) {
      for (auto& k : more) v.push_back(std::move(k));
    };
#define PKMWS_MODULE(name) add(name##_kinds());
#include "mechanisms/modules.def"
#undef PKMWS_MODULE
    std::sort(v.begin(), v.end(), [](const Kind& a, const Kind& b) { return a.keyword < b.keyword; });
    return v;
  }();
  return all;
}

}  // namespace

const std::vector<Kind>& kinds() { return registry(); }

const Kind* find_kind(const std::string& keyword) {
  for (const Kind& k : kinds()) {
    if (k.keyword == keyword) return &k;
  }
  return nullptr;
}

bool register_kinds(std::vector<Kind> more) {
  auto& all = registry();
  for (auto& k : more) {
    if (find_kind(k.keyword)) throw std::invalid_argument("mechanism kind \"" + k.keyword + "\" is already registered");
    all.push_back(std::move(k));
  }
  std::sort(all.begin(), all.end(), [](const Kind& a, const Kind& b) { return a.keyword < b.keyword; });
  return true;
}

}  // namespace pkmws::io::detail
