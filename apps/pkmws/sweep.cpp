// pkmws sweep SPEC.json -o OUT.csv: metrics over a design space
// (docs/design_space.md). Rows are appended to OUT.csv.partial as designs
// finish, so an interrupted sweep resumes (--resume) without repeating or
// losing a design; OUT.csv is written at the end, ordered by design index.
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "cli.hpp"
#include "sweep_mpi.hpp"
#include "pkmws/design/sweep.hpp"
#include "pkmws/io/export.hpp"

namespace pkmws::cli {

namespace {

namespace fs = std::filesystem;

struct Shard {
  std::size_t index = 0, count = 1;
};

Shard parse_shard(const std::string& text) {
  const auto slash = text.find('/');
  const auto whole = [](const std::string& s) {
    return !s.empty() && s.size() < 10 && s.find_first_not_of("0123456789") == std::string::npos;
  };
  if (slash == std::string::npos || !whole(text.substr(0, slash)) || !whole(text.substr(slash + 1))) {
    throw io::InputError("--shard: expected i/N with 0 <= i < N, got '" + text + "'");
  }
  Shard s{std::stoul(text.substr(0, slash)), std::stoul(text.substr(slash + 1))};
  if (s.count == 0 || s.index >= s.count) throw io::InputError("--shard: expected i/N with 0 <= i < N, got '" + text + "'");
  return s;
}

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
    throw io::InputError(where + ": not a pkmws sweep CSV (header " + header + ")");
  }
  Layout l;
  l.parameters = static_cast<std::size_t>(status - cols.begin()) - 1;
  l.timing = cols[cols.size() - 2] == "time_ms";
  l.metrics = cols.size() - l.parameters - 3 - (l.timing ? 1 : 0);
  return l;
}

// Reads the rows of a sweep CSV. A last line without its line break was cut
// short by a kill: it is left out (and so evaluated again on --resume).
std::vector<design::DesignRow> read_rows(const fs::path& path, std::string& header) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw io::InputError(path.string() + ": cannot open");
  std::stringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  if (!text.empty() && text.back() != '\n') text.erase(text.rfind('\n') == std::string::npos ? 0 : text.rfind('\n') + 1);
  std::stringstream lines(text);
  if (!std::getline(lines, header)) throw io::InputError(path.string() + ": empty file");
  const Layout l = layout_of(header, path.string());
  std::vector<design::DesignRow> rows;
  std::size_t number = 1;
  for (std::string line; std::getline(lines, line);) {
    ++number;
    if (line.empty()) continue;
    auto row = design::parse_csv_line(line, l.parameters, l.metrics, l.timing);
    if (!row) throw io::InputError(path.string() + ":" + std::to_string(number) + ": malformed row");
    rows.push_back(std::move(*row));
  }
  return rows;
}

std::string format_rows(const std::string& header, const std::vector<design::DesignRow>& rows, bool timing) {
  std::string out = header + "\n";
  for (const auto& r : rows) out += design::csv_line(r, timing) + "\n";
  return out;
}

Json rows_json(const design::SweepSpec& spec, const std::vector<design::DesignRow>& rows) {
  const std::vector<std::string> cols = design::metric_columns(spec);
  Json arr = Json::array();
  for (const auto& r : rows) {
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
  return Json{{"base", spec.base_file.string()}, {"parameters", params}, {"metrics", spec.metrics},
              {"columns", cols}, {"rows", arr}};
}

// "\r120/1000 designs  35.2/s  ETA 25 s" on a terminal, at most 5 times a second.
class Progress {
 public:
  Progress(std::size_t total, std::size_t done) : total_(total), done_(done), start_(std::chrono::steady_clock::now()) {}
  void step() {
    ++done_;
    ++new_;
    if (!tty_) return;
    const auto now = std::chrono::steady_clock::now();
    if (now - last_ < std::chrono::milliseconds(200) && done_ < total_) return;
    last_ = now;
    const double s = std::chrono::duration<double>(now - start_).count();
    const double rate = s > 0 ? static_cast<double>(new_) / s : 0.0;
    const double eta = rate > 0 ? static_cast<double>(total_ - done_) / rate : 0.0;
    std::fprintf(stderr, "\rsweep: %zu/%zu designs  %.1f/s  ETA %.0f s   ", done_, total_, rate, eta);
    shown_ = true;
  }
  ~Progress() {
    if (shown_) std::fprintf(stderr, "\n");
  }

 private:
  std::size_t total_, done_, new_ = 0;
  std::chrono::steady_clock::time_point start_, last_{};
  bool tty_ = isatty(fileno(stderr)) != 0;
  bool shown_ = false;
};

void check_writable_dir(const fs::path& out) {
  const fs::path dir = out.parent_path().empty() ? fs::path(".") : out.parent_path();
  if (!fs::is_directory(dir)) throw io::InputError("-o: directory " + dir.string() + " does not exist");
}

}  // namespace

void add_sweep(CLI::App& app, std::vector<Command>& commands) {
  auto* sub = app.add_subcommand("sweep", "Metrics over a design space (grid or Sobol), in parallel");
  struct Args {
    std::string spec, out, json, shard;
    std::vector<std::string> merge;
    int threads = 0;
    bool resume = false, no_timing = false;
  };
  auto a = std::make_shared<Args>();
  sub->add_option("SPEC", a->spec, "Sweep file (JSON; docs/design_space.md)");
  sub->add_option("-o,--out", a->out, "Output CSV (one row per design, ordered by index)")->required();
  sub->add_option("--json", a->json, "Also write the rows as JSON");
  sub->add_option("--threads", a->threads, "Threads (0: all cores, 1: serial)")->check(CLI::Range(0, 1024));
  sub->add_option("--shard", a->shard, "Evaluate only designs with index % N == i (i/N), for job arrays");
  sub->add_flag("--resume", a->resume, "Continue an interrupted sweep from OUT.partial");
  sub->add_flag("--no-timing", a->no_timing, "Leave out the time_ms column (outputs compare byte for byte)");
  sub->add_option("--merge", a->merge, "Join shard CSVs into OUT (instead of SPEC)")->expected(1, -1);
  commands.push_back({sub, [a] {
    const fs::path out = a->out;
    if (!a->merge.empty()) {
      check_writable_dir(out);
      if (!a->spec.empty()) throw io::InputError("sweep: give SPEC or --merge, not both");
      std::string header;
      std::map<std::size_t, design::DesignRow> rows;
      for (const std::string& part : a->merge) {
        std::string h;
        for (auto& r : read_rows(part, h)) {
          if (!rows.emplace(r.index, r).second) {
            throw io::InputError(part + ": design " + std::to_string(r.index) + " is in two shards");
          }
        }
        if (header.empty()) header = h;
        if (h != header) throw io::InputError(part + ": its columns differ from " + a->merge.front() + "'s");
      }
      std::vector<design::DesignRow> sorted;
      for (auto& [i, r] : rows) sorted.push_back(std::move(r));
      const Layout l = layout_of(header, a->merge.front());
      io::write_file_atomic(out, format_rows(header, sorted, l.timing));
      std::printf("merged %zu designs from %zu files into %s\n", sorted.size(), a->merge.size(), out.c_str());
      return 0;
    }
    if (a->spec.empty()) throw io::InputError("sweep: SPEC (a sweep file) or --merge is required");
    MpiSweep mpi;
    if (mpi.rank() != 0) {  // an MPI worker: rank 0 checks everything and writes everything
      if (!mpi.wait_release()) return 0;
      mpi.serve(design::load_sweep(a->spec));
      return 0;
    }
    check_writable_dir(out);
    if (!a->json.empty()) check_writable_dir(a->json);
    const design::SweepSpec spec = design::load_sweep(a->spec);
    const Shard shard = a->shard.empty() ? Shard{} : parse_shard(a->shard);
    const std::size_t count = design::design_count(spec);
    const fs::path partial = out.string() + ".partial";
    const std::string header = design::csv_header(spec, true);
    std::map<std::size_t, design::DesignRow> finished;
    if (fs::exists(partial)) {
      if (!a->resume) {
        throw io::InputError(partial.string() + " exists (an interrupted sweep): add --resume to continue it, "
                             "or delete it");
      }
      std::string h;
      for (auto& r : read_rows(partial, h)) finished.emplace(r.index, std::move(r));
      if (h != header) throw io::InputError(partial.string() + ": written by a different sweep file");
    }
    std::vector<std::size_t> todo;
    std::size_t in_shard = 0;
    for (std::size_t i = shard.index; i < count; i += shard.count) {
      ++in_shard;
      if (!finished.count(i)) todo.push_back(i);
    }
    // Rewrite the partial file with the complete rows only, then append.
    {
      std::string text = header + "\n";
      for (const auto& [i, r] : finished) text += design::csv_line(r, true) + "\n";
      io::write_file_atomic(partial, text);
    }
    std::ofstream log(partial, std::ios::app);
    const auto start = std::chrono::steady_clock::now();
    std::vector<design::DesignRow> rows;
    {
      Progress progress(in_shard, finished.size());
      const auto done = [&](const design::DesignRow& r) {
        log << design::csv_line(r, true) << '\n';
        log.flush();
        progress.step();
      };
      mpi.release(true);
      rows = mpi.size() > 1 ? mpi.run(spec, todo, done) : design::run_sweep(spec, todo, a->threads, done);
    }
    const double seconds = elapsed_ms(start) / 1000.0;
    for (auto& r : rows) finished.emplace(r.index, std::move(r));
    std::vector<design::DesignRow> all;
    for (auto& [i, r] : finished) all.push_back(std::move(r));
    io::write_file_atomic(out, format_rows(design::csv_header(spec, !a->no_timing), all, !a->no_timing));
    if (!a->json.empty()) io::write_file_atomic(a->json, rows_json(spec, all).dump(1) + "\n");
    log.close();
    fs::remove(partial);
    std::map<std::string, std::size_t> by_status;
    for (const auto& r : all) ++by_status[r.status];
    std::string counts;
    for (const auto& [s, n] : by_status) counts += (counts.empty() ? "" : ", ") + std::to_string(n) + " " + s;
    std::printf("%zu designs (%s) -> %s; %zu evaluated in %.3f s (%.1f designs/s)\n", all.size(), counts.c_str(),
                out.c_str(), todo.size(), seconds, seconds > 0 ? static_cast<double>(todo.size()) / seconds : 0.0);
    return 0;
  }});
}

}  // namespace pkmws::cli
