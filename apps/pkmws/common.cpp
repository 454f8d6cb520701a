#include <unistd.h>

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <future>
#include <cstdlib>
#include <iostream>
#include <mutex>
#include <optional>

#include "cli.hpp"

#include "pkmws/report/common.hpp"
#include "pkmws/io/export.hpp"

namespace pkmws::cli {

double elapsed_ms(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

double parse_length(const std::string& text, const std::string& what) {
  const double v = parse_number(text, what);
  if (!(std::abs(v) <= max_argument_length)) {
    throw io::InputError(what + ": " + text + " is beyond the magnitude where positions mean something (1e15)");
  }
  return v;
}

double parse_angle(const std::string& text, const std::string& what) {
  const double v = parse_number(text, what);
  if (!(std::abs(v) <= max_argument_degrees)) {
    throw io::InputError(what + ": " + text + " degrees is beyond the magnitude where angles mean something (1e6)");
  }
  return v;
}

void strict_numeric_options(CLI::App& app) {
  const CLI::Validator decimal_number(
      [](std::string& text) {
        std::string problem;
        return report::decimal_number(text, problem) ? std::string() : problem;
      },
      "", "decimal number");
  // CLI11 reads integers with strtoll(base 0): "0x10" would be 16 and "010" 8.
  const CLI::Validator decimal_integer(
      [](std::string& text) {
        std::size_t i = (!text.empty() && (text[0] == '+' || text[0] == '-')) ? 1 : 0;
        const bool ok = i < text.size() && text.find_first_not_of("0123456789", i) == std::string::npos &&
                        (text[i] != '0' || i + 1 == text.size());
        return ok ? std::string() : "expected a decimal integer, got \"" + text + "\"";
      },
      "", "decimal integer");
  auto visit = [&](CLI::App& a, auto& self) -> void {
    for (CLI::Option* opt : a.get_options()) {
      const std::string type = opt->get_type_name();
      if (type.rfind("FLOAT", 0) == 0) {
        opt->check(decimal_number);
      } else if (type.rfind("INT", 0) == 0 || type.rfind("UINT", 0) == 0) {
        opt->check(decimal_integer);
      }
    }
    for (CLI::App* sub : a.get_subcommands([](CLI::App*) { return true; })) self(*sub, self);
  };
  visit(app, visit);
}

void check_outputs(const std::vector<std::string>& paths) {
  namespace fs = std::filesystem;
  std::vector<fs::path> seen;
  for (const std::string& text : paths) {
    if (text.empty()) continue;
    const fs::path path(text);
    auto fail = [&text](const std::string& reason) { throw io::InputError(text + ": cannot write: " + reason); };
    if (!path.has_filename()) fail("not a file name");
    const fs::path dir = path.parent_path().empty() ? fs::path(".") : path.parent_path();
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) fail("directory " + dir.string() + " does not exist");
    if (fs::is_directory(path, ec)) fail("is a directory");
    if (::access(dir.c_str(), W_OK | X_OK) != 0) fail("directory " + dir.string() + " is not writable");
    if (fs::exists(path, ec) && ::access(path.c_str(), W_OK) != 0) fail("the file is not writable");
    const fs::path key = fs::weakly_canonical(path, ec);
    for (const fs::path& s : seen) {
      if (s == key) fail("given twice as an output");
    }
    seen.push_back(key);
  }
}

void write_outputs(const std::vector<std::pair<std::string, std::string>>& files) {
  namespace fs = std::filesystem;
  std::vector<std::string> paths;
  for (const auto& f : files) paths.push_back(f.first);
  check_outputs(paths);
  std::vector<fs::path> temps;
  auto discard = [&temps] {
    std::error_code ignore;
    for (const auto& t : temps) fs::remove(t, ignore);
  };
  for (const auto& [path, content] : files) {
    const fs::path tmp = path + ".partial-" + std::to_string(::getpid());
    try {
      io::write_file_atomic(tmp, content);
    } catch (const std::exception& e) {
      discard();
      std::string reason = e.what();
      const auto pos = reason.find(": cannot write: ");
      throw io::InputError(path + ": cannot write: " +
                           (pos == std::string::npos ? reason : reason.substr(pos + 16)));
    }
    temps.push_back(tmp);
  }
  for (std::size_t k = 0; k < files.size(); ++k) {
    std::error_code ec;
    fs::rename(temps[k], files[k].first, ec);
    if (ec) {
      temps.erase(temps.begin(), temps.begin() + static_cast<std::ptrdiff_t>(k));
      discard();
      throw io::InputError(files[k].first + ": cannot write: " + ec.message());
    }
  }
}

struct CertifiedWork::Line {
  std::string command;
  std::chrono::steady_clock::time_point start;
  std::chrono::steady_clock::time_point last{};
  bool tty = false;
  bool drawn = false;
  std::mutex mutex;
};

CertifiedWork::CertifiedWork(std::string command, double max_seconds)
    : line_(std::make_shared<Line>()), max_seconds_(max_seconds), start_(std::chrono::steady_clock::now()) {
  line_->command = std::move(command);
  line_->start = start_;
  line_->tty = ::isatty(STDERR_FILENO) == 1;
}

CertifiedWork::~CertifiedWork() {
  std::lock_guard lock(line_->mutex);
  if (line_->drawn) std::fprintf(stderr, "\r\033[K");
}

certified::LevelSetOptions CertifiedWork::options(certified::LevelSetOptions o, const std::string& stage) const {
  if (max_seconds_ > 0.0) {
    o.deadline = start_ + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                              std::chrono::duration<double>(max_seconds_));
  }
  if (line_->tty) {
    o.progress = [line = line_, stage, bound = max_seconds_](double fraction) {
      const auto now = std::chrono::steady_clock::now();
      std::lock_guard lock(line->mutex);
      const double seconds = std::chrono::duration<double>(now - line->start).count();
      if (seconds < 1.0 || now - line->last < std::chrono::milliseconds(200)) return;
      line->last = now;
      line->drawn = true;
      std::fprintf(stderr, "\r\033[Kpkmws %s: %s%s%.0f %% of the cells refined, %.1f s", line->command.c_str(),
                   stage.c_str(), stage.empty() ? "" : ", ", 100.0 * fraction, seconds);
      if (bound > 0.0) std::fprintf(stderr, " (--max-time %g)", bound);
      std::fflush(stderr);
    };
  }
  return o;
}

std::string CertifiedWork::stopped_note() const {
  char buf[200];
  std::snprintf(buf, sizeof buf,
                "stopped at --max-time %g s: the bounds are valid but wider than the tolerance asked for", max_seconds_);
  return buf;
}

report::Budget CertifiedWork::budget() const {
  return {[this](certified::LevelSetOptions o, const std::string& stage) { return options(std::move(o), stage); },
          stopped_note()};
}

std::string CertifiedWork::finish_by_deadline(const std::function<std::string()>& job,
                                             const std::string& refusal) const {
  if (!(max_seconds_ > 0.0)) return job();
  const auto deadline =
      start_ + std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(max_seconds_));
  std::future<std::string> result = std::async(std::launch::async, job);
  if (result.wait_until(deadline) == std::future_status::ready) return result.get();
  // The job cannot be interrupted (one CGAL operation may run for minutes):
  // the process ends here, before anything is written; the thread ends with it.
  {
    std::lock_guard lock(line_->mutex);
    if (line_->drawn) std::fprintf(stderr, "\r\033[K");
  }
  std::fflush(stdout);
  std::fprintf(stderr, "pkmws: error: %s\n", refusal.c_str());
  std::fflush(stderr);
  std::_Exit(2);
}

std::string format_g(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

void check_tolerance(double tolerance) {
  if (!(tolerance > 0.0 && tolerance < 1.0)) throw io::InputError("--tolerance: must be in (0, 1)");
}

void add_max_time_option(CLI::App* sub, double& seconds) {
  sub->add_option("--max-time", seconds,
                  "Stop refining after SECONDS: the certified bounds reached so far, labelled `stopped` "
                  "(default: no bound; a progress line on a terminal)")
      ->check(CLI::PositiveNumber);
}

}  // namespace pkmws::cli
