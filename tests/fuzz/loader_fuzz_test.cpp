// Bounded generative fuzzing of the mechanism-file loader (tests/fuzz/README.md):
// every bundled dataset, mutated value by value (numbers replaced by 0, -0.0,
// 1e308, -1, strings, nulls, arrays; keys deleted, renamed, duplicated; deep
// nesting; NaN literals) and written as text, must either load or fail with
// io::InputError whose message is one line naming a path. Any other exception,
// a crash or a sanitizer report is a bug. Deterministic: a fixed seed, a fixed
// number of mutations per dataset.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pkmws/io/mechanism_file.hpp"
#include "support/fixtures.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

using pkmws::test::slurp;

// Every value's JSON pointer (objects, arrays and leaves), the root excluded.
void pointers(const json& v, const json::json_pointer& at, std::vector<json::json_pointer>& out) {
  if (v.is_object()) {
    for (auto it = v.begin(); it != v.end(); ++it) {
      out.push_back(at / it.key());
      pointers(it.value(), at / it.key(), out);
    }
  } else if (v.is_array()) {
    for (std::size_t i = 0; i < v.size(); ++i) {
      out.push_back(at / i);
      pointers(v[i], at / i, out);
    }
  }
}

// What a mutated document does when loaded: "" (it loads) or the error.
struct Outcome {
  bool ok = true;       // loaded, or refused with a well-formed InputError
  bool loaded = false;
  std::string failure;  // a defect: not InputError, or a malformed message
};

Outcome load_text(const std::string& text, const fs::path& file) {
  {
    std::ofstream out(file, std::ios::trunc);
    out << text;
  }
  Outcome o;
  try {
    (void)pkmws::io::load_mechanism(file);
    o.loaded = true;
  } catch (const pkmws::io::InputError& e) {
    const std::string m = e.what();
    if (m.find('\n') != std::string::npos) o = {false, false, "a multi-line message: " + m};
    if (m.rfind(file.string() + ": ", 0) != 0) o = {false, false, "the message does not start with the file: " + m};
  } catch (const std::exception& e) {
    o = {false, false, std::string("not an InputError: ") + e.what()};
  }
  return o;
}

// A mutation of one value: the replacement document, or text for what JSON
// values cannot express (duplicate keys, NaN).
std::string mutate(const json& doc, const json::json_pointer& at, int kind, std::mt19937& rng) {
  json d = doc;
  const std::string key = at.back();
  json::json_pointer parent = at.parent_pointer();
  json& value = d[at];
  switch (kind) {
    case 0: value = 0; break;
    case 1: value = -0.0; break;
    case 2: value = 1e308; break;
    case 3: value = -1; break;
    case 4: value = "text"; break;
    case 5: value = nullptr; break;
    case 6: value = json::array(); break;
    case 7: value = json::object(); break;
    case 8: value = json::array({value, value}); break;
    case 9: value = -1e308; break;
    case 10: value = 1e-308; break;
    case 11: value = 4294967297LL; break;
    case 12: {  // delete
      json& p = d[parent];
      if (p.is_object()) p.erase(key); else p.erase(std::stoul(key));
      break;
    }
    case 13: {  // rename
      json& p = d[parent];
      if (p.is_object()) {
        json v = p[key];
        p.erase(key);
        p[key + "_x"] = v;
      }
      break;
    }
    case 14: {  // duplicate the key (text level: a JSON value cannot hold it)
      json& p = d[parent];
      if (!p.is_object()) break;
      const std::string marker = "\"__dup__\"";
      p["__dup__"] = 0;
      std::string text = d.dump();
      const auto pos = text.find(marker);
      return text.replace(pos, marker.size() + 2, json(key).dump() + ":" + p[key].dump());
    }
    case 15: {  // NaN / Infinity literals (not JSON)
      const char* lit[] = {"NaN", "Infinity", "-Infinity", "nan"};
      value = "__lit__";
      std::string text = d.dump();
      const auto pos = text.find("\"__lit__\"");
      return text.replace(pos, 9, lit[rng() % 4]);
    }
    case 16: {  // deep nesting at this value
      value = "__deep__";
      std::string text = d.dump();
      const std::size_t depth = 1000 + rng() % 100000;
      const auto pos = text.find("\"__deep__\"");
      return text.replace(pos, 10, std::string(depth, '[') + "1" + std::string(depth, ']'));
    }
    default: {  // a number perturbed in its text (sign, scale)
      if (value.is_number()) value = value.get<double>() * (rng() % 2 ? -1e6 : 1e-9);
      break;
    }
  }
  return d.dump(1);
}

TEST(LoaderFuzz, MutatedDatasetsLoadOrFailWithOneLine) {
  constexpr int kinds = 18;
  constexpr std::size_t per_dataset = 160;
  std::mt19937 rng(20261201);
  const fs::path dir = fs::temp_directory_path() / ("pkmws-loader-fuzz-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path file = dir / "mutated.json";
  std::size_t runs = 0, loaded = 0;
  std::vector<std::string> failures;
  for (const fs::path& p : pkmws::test::dataset_files()) {
    const std::string text = slurp(p);
    const json doc = json::parse(text);
    std::vector<json::json_pointer> ptrs;
    pointers(doc, json::json_pointer(), ptrs);
    ASSERT_FALSE(ptrs.empty()) << p;
    for (std::size_t n = 0; n < per_dataset; ++n) {
      const auto& at = ptrs[rng() % ptrs.size()];
      const int kind = static_cast<int>(rng() % kinds);
      const std::string mutated = mutate(doc, at, kind, rng);
      Outcome o = load_text(mutated, file);
      ++runs;
      // A duplicated key, a NaN literal and deep nesting are never valid.
      const bool must_refuse = kind == 15 || kind == 16 || (kind == 14 && mutated != doc.dump(1));
      if (o.ok && o.loaded && must_refuse) o = {false, true, "accepted silently"};
      if (o.ok) continue;
      failures.push_back(p.filename().string() + " " + at.to_string() + " kind " + std::to_string(kind) + ": " +
                         o.failure);
    }
    // Whole-document mutations: truncation, nesting around the document.
    for (std::size_t cut : {std::size_t{0}, std::size_t{1}, text.size() / 2, text.size() - 2}) {
      const Outcome o = load_text(text.substr(0, cut), file);
      ++runs;
      if (!o.ok) failures.push_back(p.filename().string() + " truncated at " + std::to_string(cut) + ": " + o.failure);
    }
    const Outcome deep = load_text(std::string(100000, '{'), file);
    ++runs;
    if (!deep.ok) failures.push_back("deep objects: " + deep.failure);
    // The unmutated file loads.
    if (load_text(text, file).loaded) ++loaded;
  }
  fs::remove_all(dir);
  EXPECT_GT(runs, 1000u);
  EXPECT_EQ(loaded, pkmws::test::dataset_files().size());
  EXPECT_TRUE(failures.empty()) << failures.size() << " defects, the first: " << failures.front();
}

}  // namespace
