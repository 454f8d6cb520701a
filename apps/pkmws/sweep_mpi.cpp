#include "sweep_mpi.hpp"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <string>
#include <thread>

#include "pkmws/io/mechanism_file.hpp"

#ifdef PKMWS_WITH_MPI
#include <mpi.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <optional>
#endif

namespace pkmws::cli {

namespace {

// Started by mpirun (Open MPI, or a PMI-based launcher) with more than one rank?
int launcher_size() {
  for (const char* var : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"}) {
    if (const char* v = std::getenv(var)) return std::atoi(v);
  }
  return 1;
}

#ifdef PKMWS_WITH_MPI
constexpr int kRow = 1;   // worker -> rank 0: a finished design's row (a CSV line)
constexpr int kDone = 4;  // worker -> rank 0: the counter ran out, the worker leaves

// Waits for a message without spinning. Open MPI's blocking calls (MPI_Probe,
// MPI_Recv) busy-poll: a waiting rank 0 would take a core from the evaluating
// ranks (oversubscribed runs, or rank 0 sharing a machine with workers).
// Polls with MPI_Iprobe, sleeping 10 us after the first miss and twice as
// long after each further one, at most 1 ms; each poll also lets MPI serve the
// counter's window where the network has no remote atomics.
MPI_Status wait_message(int source, int tag) {
  MPI_Status status;
  auto pause = std::chrono::microseconds(10);
  for (;;) {
    int flag = 0;
    MPI_Iprobe(source, tag, MPI_COMM_WORLD, &flag, &status);
    if (flag) return status;
    std::this_thread::sleep_for(pause);
    pause = std::min(pause * 2, std::chrono::microseconds(1000));
  }
}

// Receives the pending row that `status` describes.
std::string receive_row(const MPI_Status& status) {
  int length = 0;
  MPI_Get_count(&status, MPI_CHAR, &length);
  std::string line(static_cast<std::size_t>(length), '\0');
  MPI_Recv(line.data(), length, MPI_CHAR, status.MPI_SOURCE, kRow, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return line;
}

// Whole reads and writes on a pipe (false: the other end is closed).
bool read_all(int fd, void* data, std::size_t n) {
  auto* p = static_cast<char*>(data);
  while (n > 0) {
    const ssize_t got = ::read(fd, p, n);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) return false;
    p += got;
    n -= static_cast<std::size_t>(got);
  }
  return true;
}

bool write_all(int fd, const void* data, std::size_t n) {
  const auto* p = static_cast<const char*>(data);
  while (n > 0) {
    const ssize_t put = ::write(fd, p, n);
    if (put < 0 && errno == EINTR) continue;
    if (put <= 0) return false;
    p += put;
    n -= static_cast<std::size_t>(put);
  }
  return true;
}

// The evaluating child: reads design indices, answers each with "r" and the
// row's CSV line (or "e" and the error), until its parent closes the pipe.
// Loads the sweep file at the first index (rank 0 has checked it by then).
[[noreturn]] void evaluator(const std::string& spec_path, pid_t parent, int in, int out) {
  prctl(PR_SET_PDEATHSIG, SIGKILL);  // ends with its rank, however the rank ends
  if (getppid() != parent) _exit(0);
  std::optional<design::SweepSpec> spec;
  for (;;) {
    std::uint64_t index = 0;
    if (!read_all(in, &index, sizeof index)) _exit(0);
    std::string reply;
    try {
      if (!spec) spec = design::load_sweep(spec_path);
      reply = "r" + design::csv_line(design::evaluate_design(*spec, static_cast<std::size_t>(index)), true);
    } catch (const std::exception& e) {
      reply = std::string("e") + e.what();
    }
    const std::uint64_t n = reply.size();
    if (!write_all(out, &n, sizeof n) || !write_all(out, reply.data(), reply.size())) _exit(0);
  }
}

// Do all ranks share one machine (one shared-memory domain)?
bool one_machine() {
  MPI_Comm node;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
  int node_size = 0, world_size = 0;
  MPI_Comm_size(node, &node_size);
  MPI_Comm_size(MPI_COMM_WORLD, &world_size);
  MPI_Comm_free(&node);
  return node_size == world_size;
}
#endif

}  // namespace

struct MpiSweep::Window {
#ifdef PKMWS_WITH_MPI
  MPI_Win win = MPI_WIN_NULL;
#endif
};

MpiSweep::MpiSweep(std::string spec_path) : spec_path_(std::move(spec_path)) {
  const int launched = launcher_size();
#ifdef PKMWS_WITH_MPI
  if (launched > 1) {
    // The evaluating child, forked while this process has one thread.
    int down[2], up[2];
    if (pipe(down) != 0 || pipe(up) != 0) throw std::runtime_error("sweep: cannot create a pipe for the evaluator");
    std::fflush(nullptr);
    const pid_t parent = getpid();
    const pid_t pid = fork();
    if (pid < 0) throw std::runtime_error("sweep: cannot start the evaluating process (fork failed)");
    if (pid == 0) {
      close(down[1]);
      close(up[0]);
      evaluator(spec_path_, parent, down[0], up[1]);
    }
    close(down[0]);
    close(up[1]);
    child_ = pid;
    to_child_ = down[1];
    from_child_ = up[0];
    signal(SIGPIPE, SIG_IGN);  // a child that died is an error from write(), not the end of this rank
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_SINGLE, &provided);
    started_ = true;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
  }
#else
  if (launched > 1) {
    throw io::InputError("sweep: started by mpirun, but this pkmws was built without MPI (configure with "
                         "-DPKMWS_MPI=ON)");
  }
#endif
}

MpiSweep::~MpiSweep() {
#ifdef PKMWS_WITH_MPI
  if (!started_) return;
  if (rank_ == 0) {
    if (!released_) release(false);
    else stop_workers();
  }
  MPI_Finalize();
  close(to_child_);  // the child leaves at the end of its input
  close(from_child_);
  waitpid(child_, nullptr, 0);
#endif
}

void MpiSweep::ask_child(std::size_t index) {
#ifdef PKMWS_WITH_MPI
  const std::uint64_t i = index;
  if (!write_all(to_child_, &i, sizeof i)) {
    throw std::runtime_error("sweep: rank " + std::to_string(rank_) + "'s evaluating process ended unexpectedly");
  }
#else
  (void)index;
#endif
}

std::string MpiSweep::child_row() {
#ifdef PKMWS_WITH_MPI
  std::uint64_t n = 0;
  std::string reply;
  bool ok = read_all(from_child_, &n, sizeof n);
  if (ok) {
    reply.resize(static_cast<std::size_t>(n));
    ok = read_all(from_child_, reply.data(), reply.size());
  }
  if (!ok || reply.empty()) {
    throw std::runtime_error("sweep: rank " + std::to_string(rank_) + "'s evaluating process ended unexpectedly");
  }
  if (reply[0] != 'r') throw std::runtime_error("sweep: rank " + std::to_string(rank_) + ": " + reply.substr(1));
  return reply.substr(1);
#else
  return {};
#endif
}

// Evaluates designs from the counter until none is left. Positions are taken
// in chunks: one design at first, then as many as make about 2 ms of work at
// the rate just measured (at most 64), and never more than a quarter of an
// even share of what is left, so that cheap designs do not pay a counter
// access and a pipe round trip each while costly ones are
// still taken one by one and the last ones spread over the ranks. The child
// gets a chunk's indices at once and answers them in order. `between` runs
// before each chunk; `row` gets each finished row.
void MpiSweep::evaluate_all(const std::function<void()>& between, const std::function<void(std::string)>& row) {
  std::size_t count = 1;
  for (;;) {
    between();
    const auto [first, last] = take(count);
    if (first == last) return;
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t p = first; p < last; ++p) ask_child(static_cast<std::size_t>(todo_[p]));
    for (std::size_t p = first; p < last; ++p) row(child_row());
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() /
        static_cast<double>(last - first);
    const double share = static_cast<double>(todo_.size() - last) / (4.0 * size_);
    count = static_cast<std::size_t>(std::clamp(std::min(2.0 / std::max(ms, 1e-3), share), 1.0, 64.0));
  }
}

void MpiSweep::release(bool ok) {
  released_ = true;
#ifdef PKMWS_WITH_MPI
  if (!started_) return;
  int go = ok ? 1 : 0;
  MPI_Bcast(&go, 1, MPI_INT, 0, MPI_COMM_WORLD);
  if (!ok) workers_stopped_ = true;
#else
  (void)ok;
#endif
}

bool MpiSweep::wait_release() {
#ifdef PKMWS_WITH_MPI
  int go = 0;
  MPI_Bcast(&go, 1, MPI_INT, 0, MPI_COMM_WORLD);
  return go == 1;
#else
  return false;
#endif
}

// Collective: every rank learns the list of designs and whether all ranks
// share a machine, and the counter (one integer on rank 0, starting at 0) is
// opened for passive-target access.
void MpiSweep::open_counter() {
#ifdef PKMWS_WITH_MPI
  one_machine_ = one_machine();
  unsigned long long n = todo_.size();
  MPI_Bcast(&n, 1, MPI_UNSIGNED_LONG_LONG, 0, MPI_COMM_WORLD);
  todo_.resize(static_cast<std::size_t>(n));
  MPI_Bcast(todo_.data(), static_cast<int>(n), MPI_UNSIGNED_LONG_LONG, 0, MPI_COMM_WORLD);
  window_ = std::make_unique<Window>();
  void* base = nullptr;
  const MPI_Aint bytes = rank_ == 0 ? static_cast<MPI_Aint>(sizeof(unsigned long long)) : 0;
  MPI_Win_allocate(bytes, sizeof(unsigned long long), MPI_INFO_NULL, MPI_COMM_WORLD, &base, &window_->win);
  MPI_Win_fence(0, window_->win);
  if (rank_ == 0) *static_cast<unsigned long long*>(base) = 0;
  MPI_Win_fence(0, window_->win);
  MPI_Win_lock_all(MPI_MODE_NOCHECK, window_->win);
#endif
}

// The next `count` positions in the list to evaluate, [first, last), fewer
// at its end; empty when none is left.
std::pair<std::size_t, std::size_t> MpiSweep::take(std::size_t count) {
#ifdef PKMWS_WITH_MPI
  const unsigned long long add = count;
  unsigned long long position = 0;
  MPI_Fetch_and_op(&add, &position, MPI_UNSIGNED_LONG_LONG, 0, 0, MPI_SUM, window_->win);
  MPI_Win_flush(0, window_->win);
  const unsigned long long n = todo_.size();
  return {static_cast<std::size_t>(std::min(position, n)), static_cast<std::size_t>(std::min(position + add, n))};
#else
  (void)count;
  return {todo_.size(), todo_.size()};
#endif
}

// Rank 0 failed after the release: the counter is moved past the end, so
// every worker stops after the design in its hands; waits until all have.
void MpiSweep::stop_workers() {
#ifdef PKMWS_WITH_MPI
  if (workers_stopped_) return;
  workers_stopped_ = true;
  if (!window_) {
    todo_.clear();  // the workers wait for the list: an empty one
    open_counter();
  } else {
    const unsigned long long end = todo_.size();
    unsigned long long old = 0;
    MPI_Fetch_and_op(&end, &old, MPI_UNSIGNED_LONG_LONG, 0, 0, MPI_REPLACE, window_->win);
    MPI_Win_flush(0, window_->win);
  }
  while (workers_left_ < size_ - 1) {
    const MPI_Status status = wait_message(MPI_ANY_SOURCE, MPI_ANY_TAG);
    if (status.MPI_TAG == kDone) {
      MPI_Recv(nullptr, 0, MPI_CHAR, status.MPI_SOURCE, kDone, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      ++workers_left_;
    } else {
      (void)receive_row(status);
    }
  }
  MPI_Win_unlock_all(window_->win);
  MPI_Win_free(&window_->win);
#endif
}

std::vector<design::DesignRow> MpiSweep::run(const design::SweepSpec& spec, const std::vector<std::size_t>& todo,
                                             RankZero role, const std::function<void(const design::DesignRow&)>& done) {
  std::vector<design::DesignRow> rows;
#ifdef PKMWS_WITH_MPI
  todo_.assign(todo.begin(), todo.end());
  open_counter();
  const bool evaluates = role == RankZero::evaluates || (role == RankZero::automatic && one_machine_);
  const auto finished = [&](design::DesignRow row) {
    if (done) done(row);
    rows.push_back(std::move(row));
  };
  const std::size_t parameters = spec.parameters.size(), metrics = design::metric_columns(spec).size();
  const auto handle = [&](const MPI_Status& status) {
    if (status.MPI_TAG == kDone) {
      MPI_Recv(nullptr, 0, MPI_CHAR, status.MPI_SOURCE, kDone, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      ++workers_left_;
      return;
    }
    auto row = design::parse_csv_line(receive_row(status), parameters, metrics, true);
    if (!row) throw std::runtime_error("sweep: rank " + std::to_string(status.MPI_SOURCE) + " sent a malformed row");
    finished(std::move(*row));
  };
  if (evaluates) {
    evaluate_all(
        [&] {  // the rows that arrived while this rank evaluated
          for (;;) {
            int flag = 0;
            MPI_Status status;
            MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status);
            if (!flag) break;
            handle(status);
          }
        },
        [&](const std::string& line) {
          auto row = design::parse_csv_line(line, parameters, metrics, true);
          if (!row) throw std::runtime_error("sweep: rank 0's evaluating process sent a malformed row");
          finished(std::move(*row));
        });
  }
  while (workers_left_ < size_ - 1) handle(wait_message(MPI_ANY_SOURCE, MPI_ANY_TAG));
  workers_stopped_ = true;
  MPI_Win_unlock_all(window_->win);
  MPI_Win_free(&window_->win);
#else
  (void)spec;
  (void)todo;
  (void)role;
  (void)done;
#endif
  return rows;
}

void MpiSweep::serve() {
#ifdef PKMWS_WITH_MPI
  open_counter();
  // Rows are small (eager: MPI_Send returns at once); rank 0 collects them between its designs.
  evaluate_all([] {}, [](const std::string& line) {
    MPI_Send(line.data(), static_cast<int>(line.size()), MPI_CHAR, 0, kRow, MPI_COMM_WORLD);
  });
  MPI_Send(nullptr, 0, MPI_CHAR, 0, kDone, MPI_COMM_WORLD);
  MPI_Win_unlock_all(window_->win);
  MPI_Win_free(&window_->win);
#endif
}

}  // namespace pkmws::cli
