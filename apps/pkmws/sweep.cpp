// pkmws sweep SPEC.json -o OUT.csv: metrics over a design space
// (docs/design_space.md). Rows are appended to OUT.csv.partial as designs
// finish, so an interrupted sweep resumes (--resume) without repeating or
// losing a design; OUT.csv is written at the end, ordered by design index.
// The CSV read back, its JSON and the summary are the library's
// (pkmws/report/sweep.hpp); the partial file, the shards, MPI and the progress
// line are this command's.
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>

#include "cli.hpp"
#include "sweep_mpi.hpp"
#include "pkmws/design/sweep.hpp"
#include "pkmws/io/export.hpp"
#include "pkmws/report/sweep.hpp"

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
    RankZero rank0 = RankZero::automatic;
    bool resume = false, no_timing = false;
  };
  auto a = std::make_shared<Args>();
  sub->add_option("SPEC", a->spec, "Sweep file (JSON; docs/design_space.md)");
  sub->add_option("-o,--out", a->out, "Output CSV (one row per design, ordered by index)")->required();
  sub->add_option("--json", a->json, "Also write the rows as JSON");
  sub->add_option("--threads", a->threads, "Threads (0: all cores, 1: serial)")->check(CLI::Range(0, 1024));
  sub->add_option("--mpi-rank0", a->rank0,
                  "Under mpirun: whether rank 0 evaluates designs besides collecting rows (auto: when all "
                  "ranks share one machine)")
      ->transform(CLI::CheckedTransformer(
          std::map<std::string, RankZero>{
              {"auto", RankZero::automatic}, {"evaluate", RankZero::evaluates}, {"collect", RankZero::collects}},
          CLI::ignore_case));
  sub->add_option("--shard", a->shard, "Evaluate only designs with index % N == i (i/N), for job arrays");
  sub->add_flag("--resume", a->resume, "Continue an interrupted sweep from OUT.partial");
  sub->add_flag("--no-timing", a->no_timing, "Leave out the time_ms column (outputs compare byte for byte)");
  sub->add_option("--merge", a->merge, "Join shard CSVs into OUT (instead of SPEC)")->expected(1, -1);
  commands.push_back({sub, [a] {
    const fs::path out = a->out;
    if (!a->merge.empty()) {
      check_writable_dir(out);
      if (!a->spec.empty()) throw io::InputError("sweep: give SPEC or --merge, not both");
      const report::SweepCsv merged = report::merge_sweep_csvs(a->merge);
      io::write_file_atomic(out, report::csv_text(merged));
      std::cout << report::merge_text(merged, a->merge.size(), out.string());
      return 0;
    }
    if (a->spec.empty()) throw io::InputError("sweep: SPEC (a sweep file) or --merge is required");
    MpiSweep mpi(a->spec);
    if (mpi.rank() != 0) {  // an MPI worker: rank 0 checks everything and writes everything
      if (!mpi.wait_release()) return 0;
      mpi.serve();
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
      report::SweepCsv done = report::read_sweep_csv(partial);
      for (auto& r : done.rows) finished.emplace(r.index, std::move(r));
      if (done.header != header) throw io::InputError(partial.string() + ": written by a different sweep file");
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
      rows = mpi.size() > 1 ? mpi.run(spec, todo, a->rank0, done) : design::run_sweep(spec, todo, a->threads, done);
    }
    report::SweepReport result;
    result.spec = spec;
    result.seconds = elapsed_ms(start) / 1000.0;
    result.evaluated = todo.size();
    result.output = out.string();
    for (auto& r : rows) finished.emplace(r.index, std::move(r));
    for (auto& [i, r] : finished) result.rows.push_back(std::move(r));
    io::write_file_atomic(out, report::csv_text({design::csv_header(spec, !a->no_timing), result.rows, !a->no_timing}));
    if (!a->json.empty()) io::write_file_atomic(a->json, report::rows_json_text(result));
    log.close();
    fs::remove(partial);
    std::cout << report::to_text(result);
    return 0;
  }});
}

}  // namespace pkmws::cli
