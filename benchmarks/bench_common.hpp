// Shared by the Google Benchmark cases and the report generator.
#pragma once

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace pkmws::bench {

inline std::string datasets_dir() { return std::string(PKMWS_SOURCE_DIR) + "/datasets"; }

inline std::string dataset(const std::string& stem) { return datasets_dir() + "/" + stem + ".json"; }

/// Every bundled dataset's stem, sorted.
inline std::vector<std::string> dataset_stems() {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(datasets_dir())) {
    if (e.path().extension() == ".json") out.push_back(e.path().stem().string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

/// The three MOMA configurations of the report ([Vasilic] figs. 5, 10, 11).
struct Case {
  const char* stem;
  const char* label;
};
inline const std::vector<Case>& report_cases() {
  static const std::vector<Case> cases{{"moma_m1_g0_l250", "MOMA M1 (γ = 0°, l = 250 mm)"},
                                       {"moma_m4_gm5_gp5_l195", "MOMA M4 (γ = −5°/+5°, l = 195 mm)"},
                                       {"moma_m5_gp5_gm5_l195", "MOMA M5 (γ = +5°/−5°, l = 195 mm)"}};
  return cases;
}

/// The certified level-set cases (bench_levels.cpp), registered from main.
void register_level_set_benchmarks();

}  // namespace pkmws::bench
