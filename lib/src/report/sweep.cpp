// `pkmws sweep` (pkmws/report/sweep.hpp): moved from the command line's
// sweep.cpp, CSV, JSON and text unchanged.
#include "pkmws/report/sweep.hpp"

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>

#include "pkmws/core/error.hpp"
#include "report/json.hpp"
#include "report/text.hpp"

namespace pkmws::report {

using detail::Json;

namespace {

// Where a CSV's columns fall: parameters between `index` and `status`,
// metrics after it, then optionally `time_ms`, then `reason`.
struct Layout {
  std::size_t parameters = 0, metrics = 0;
  bool timing = false;
};

Layout layout_of(const std::string& header, const std::string& where) {
  std::vector<std::string> cols;
  std::stringstream ss(header);
  for (std::string c; std::getline(ss, c, ',');) cols.push_back(c);
  const auto status = std::find(cols.begin(), cols.end(), "status");
  if (cols.size() < 3 || cols.front() != "index" || cols.back() != "reason" || status == cols.end()) {
    throw InputError(where + ": not a pkmws sweep CSV (header " + header + ")");
  }
  Layout l;
  l.parameters = static_cast<std::size_t>(status - cols.begin()) - 1;
  l.timing = cols[cols.size() - 2] == "time_ms";
  l.metrics = cols.size() - l.parameters - 3 - (l.timing ? 1 : 0);
  return l;
}

}  // namespace

SweepCsv read_sweep_csv(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string() + ": cannot open");
  std::stringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  if (!text.empty() && text.back() != '\n') text.erase(text.rfind('\n') == std::string::npos ? 0 : text.rfind('\n') + 1);
  std::stringstream lines(text);
  SweepCsv csv;
  if (!std::getline(lines, csv.header)) throw InputError(path.string() + ": empty file");
  const Layout l = layout_of(csv.header, path.string());
  csv.timing = l.timing;
  std::size_t number = 1;
  for (std::string line; std::getline(lines, line);) {
    ++number;
    if (line.empty()) continue;
    auto row = design::parse_csv_line(line, l.parameters, l.metrics, l.timing);
    if (!row) throw InputError(path.string() + ":" + std::to_string(number) + ": malformed row");
    csv.rows.push_back(std::move(*row));
  }
  return csv;
}

SweepCsv merge_sweep_csvs(const std::vector<std::string>& parts) {
  SweepCsv merged;
  std::map<std::size_t, design::DesignRow> rows;
  for (const std::string& part : parts) {
    SweepCsv csv = read_sweep_csv(part);
    for (auto& r : csv.rows) {
      if (!rows.emplace(r.index, r).second) {
        throw InputError(part + ": design " + std::to_string(r.index) + " is in two shards");
      }
    }
    if (merged.header.empty()) merged.header = csv.header;
    if (csv.header != merged.header) throw InputError(part + ": its columns differ from " + parts.front() + "'s");
  }
  for (auto& [i, r] : rows) merged.rows.push_back(std::move(r));
  merged.timing = layout_of(merged.header, parts.front()).timing;
  return merged;
}

std::string csv_text(const SweepCsv& csv) {
  std::string out = csv.header + "\n";
  for (const auto& r : csv.rows) out += design::csv_line(r, csv.timing) + "\n";
  return out;
}

std::string rows_json_text(const SweepReport& report) {
  const design::SweepSpec& spec = report.spec;
  const std::vector<std::string> cols = design::metric_columns(spec);
  Json arr = Json::array();
  for (const auto& r : report.rows) {
    Json j;
    j["index"] = r.index;
    for (std::size_t k = 0; k < spec.parameters.size(); ++k) j[spec.parameters[k].name] = r.values[k];
    j["status"] = r.status;
    for (std::size_t k = 0; k < cols.size(); ++k) j[cols[k]] = r.metrics[k] ? Json(*r.metrics[k]) : Json(nullptr);
    j["time_ms"] = r.time_ms;
    j["reason"] = r.reason;
    arr.push_back(j);
  }
  Json params = Json::array();
  for (const auto& p : spec.parameters) params.push_back({{"name", p.name}, {"paths", p.paths}});
  const Json out{{"base", spec.base_file.string()}, {"parameters", params}, {"metrics", spec.metrics},
                 {"columns", cols}, {"rows", arr}};
  return out.dump(1) + "\n";
}

std::string to_text(const SweepReport& r) {
  std::map<std::string, std::size_t> by_status;
  for (const auto& row : r.rows) ++by_status[row.status];
  std::string counts;
  for (const auto& [s, n] : by_status) counts += (counts.empty() ? "" : ", ") + std::to_string(n) + " " + s;
  return detail::format("%zu designs (%s) -> %s; %zu evaluated in %.3f s (%.1f designs/s)\n", r.rows.size(),
                        counts.c_str(), r.output.c_str(), r.evaluated, r.seconds,
                        r.seconds > 0 ? static_cast<double>(r.evaluated) / r.seconds : 0.0);
}

std::string merge_text(const SweepCsv& merged, std::size_t files, const std::string& output) {
  return detail::format("merged %zu designs from %zu files into %s\n", merged.rows.size(), files, output.c_str());
}

}  // namespace pkmws::report
