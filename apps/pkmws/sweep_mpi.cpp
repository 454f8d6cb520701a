#include "sweep_mpi.hpp"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <mutex>
#include <string>
#include <thread>

#include "pkmws/io/mechanism_file.hpp"

#ifdef PKMWS_WITH_MPI
#include <mpi.h>
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
constexpr int kReady = 1;  // worker -> rank 0: a request, with the previous row (CSV line) or ""
constexpr int kWork = 2;   // rank 0 -> worker: a design index
constexpr int kStop = 3;   // rank 0 -> worker: no more designs
constexpr int kDone = 4;   // worker -> rank 0: every request answered, the worker leaves
// A worker's open requests: one while it evaluates (the row it sends asks for
// the next design), so that no design waits in its hands while another rank
// is idle at the end of a sweep of costly designs. After a design that took
// less than kQuickMs it opens up to kMaxOpen, so that designs under a
// millisecond do not wait for rank 0's answer.
constexpr int kMaxOpen = 3;
constexpr double kQuickMs = 20.0;

// Waits for a message without spinning. Open MPI's blocking calls (MPI_Probe,
// MPI_Recv) busy-poll: rank 0's communication thread would take a whole core
// from the evaluation threads (three busy threads on two cores for two
// ranks). Polls with MPI_Iprobe, sleeping 10 us after the first miss and
// twice as long after each further one, at most 1 ms: an answer is late by
// less than the time already waited and at most 1 ms (open requests hide it
// for quick designs), and a waiting rank 0 wakes 1 000 times a second. (At
// 250 us it woke 4 000 times a second; each wake-up takes a core from an
// evaluating thread for a context switch, about 36 us on a paravirtualised
// machine: a tenth of a core.)
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

// Receives the pending request (a row, or "" for a first request) that
// `status` describes.
std::string receive_request(const MPI_Status& status) {
  int length = 0;
  MPI_Get_count(&status, MPI_CHAR, &length);
  std::string line(static_cast<std::size_t>(length), '\0');
  MPI_Recv(line.data(), length, MPI_CHAR, status.MPI_SOURCE, kReady, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return line;
}

std::vector<std::size_t>::size_type next_index(std::mutex& m, std::size_t& position, std::size_t end) {
  const std::lock_guard<std::mutex> lock(m);
  return position < end ? position++ : end;
}
#endif

}  // namespace

MpiSweep::MpiSweep() {
  const int launched = launcher_size();
#ifdef PKMWS_WITH_MPI
  if (launched > 1) {
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
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
#endif
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

void MpiSweep::stop_workers() {
#ifdef PKMWS_WITH_MPI
  if (workers_stopped_) return;
  workers_stopped_ = true;
  // Answer every worker's open requests with "stop" until it leaves (rank 0
  // failed early, or no designs are left); a worker busy with a design asks
  // once it is done.
  left_.resize(static_cast<std::size_t>(size_), 0);
  for (int w = 1; w < size_; ++w) {
    while (!left_[static_cast<std::size_t>(w)]) {
      const MPI_Status status = wait_message(w, MPI_ANY_TAG);
      if (status.MPI_TAG == kDone) {
        MPI_Recv(nullptr, 0, MPI_CHAR, w, kDone, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        left_[static_cast<std::size_t>(w)] = 1;
      } else {
        (void)receive_request(status);
        MPI_Send(nullptr, 0, MPI_CHAR, w, kStop, MPI_COMM_WORLD);
      }
    }
  }
#endif
}

std::vector<design::DesignRow> MpiSweep::run(const design::SweepSpec& spec, const std::vector<std::size_t>& todo,
                                             const std::function<void(const design::DesignRow&)>& done) {
  std::vector<design::DesignRow> rows;
#ifdef PKMWS_WITH_MPI
  std::mutex m;
  std::size_t position = 0;
  const auto finished = [&](design::DesignRow row) {
    const std::lock_guard<std::mutex> lock(m);
    if (done) done(row);
    rows.push_back(std::move(row));
  };
  // Rank 0 evaluates too, on a thread of its own; this thread talks to the workers.
  std::thread local([&] {
    for (;;) {
      const std::size_t k = next_index(m, position, todo.size());
      if (k == todo.size()) return;
      finished(design::evaluate_design(spec, todo[k]));
    }
  });
  const std::size_t parameters = spec.parameters.size(), metrics = design::metric_columns(spec).size();
  left_.assign(static_cast<std::size_t>(size_), 0);
  int active = size_ - 1;  // workers that have not left
  while (active > 0) {
    const MPI_Status status = wait_message(MPI_ANY_SOURCE, MPI_ANY_TAG);
    if (status.MPI_TAG == kDone) {
      MPI_Recv(nullptr, 0, MPI_CHAR, status.MPI_SOURCE, kDone, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      left_[static_cast<std::size_t>(status.MPI_SOURCE)] = 1;
      --active;
      continue;
    }
    const std::string line = receive_request(status);
    if (!line.empty()) {
      auto row = design::parse_csv_line(line, parameters, metrics, true);
      if (!row) {
        MPI_Send(nullptr, 0, MPI_CHAR, status.MPI_SOURCE, kStop, MPI_COMM_WORLD);  // answered: no deadlock
        {
          const std::lock_guard<std::mutex> lock(m);
          position = todo.size();  // the local thread stops after its design
        }
        local.join();
        throw std::runtime_error("sweep: rank " + std::to_string(status.MPI_SOURCE) + " sent a malformed row");
      }
      finished(std::move(*row));
    }
    const std::size_t k = next_index(m, position, todo.size());
    if (k == todo.size()) {
      MPI_Send(nullptr, 0, MPI_CHAR, status.MPI_SOURCE, kStop, MPI_COMM_WORLD);
    } else {
      const unsigned long long index = todo[k];
      MPI_Send(&index, 1, MPI_UNSIGNED_LONG_LONG, status.MPI_SOURCE, kWork, MPI_COMM_WORLD);
    }
  }
  workers_stopped_ = true;
  local.join();
#else
  (void)spec;
  (void)todo;
  (void)done;
#endif
  return rows;
}

void MpiSweep::serve(const design::SweepSpec& spec) {
#ifdef PKMWS_WITH_MPI
  // Every request is answered by a design index or "stop" (only stops once
  // the designs run out); the worker leaves when all its requests are.
  MPI_Send(nullptr, 0, MPI_CHAR, 0, kReady, MPI_COMM_WORLD);
  bool stopped = false;
  for (int open = 1; open > 0;) {
    MPI_Status status;
    unsigned long long index = 0;
    MPI_Recv(&index, 1, MPI_UNSIGNED_LONG_LONG, 0, MPI_ANY_TAG, MPI_COMM_WORLD, &status);
    --open;
    if (status.MPI_TAG == kStop) {
      stopped = true;
      continue;
    }
    const design::DesignRow row = design::evaluate_design(spec, static_cast<std::size_t>(index));
    const std::string line = design::csv_line(row, true);
    MPI_Send(line.data(), static_cast<int>(line.size()), MPI_CHAR, 0, kReady, MPI_COMM_WORLD);
    ++open;
    for (; !stopped && row.time_ms < kQuickMs && open < kMaxOpen; ++open) {
      MPI_Send(nullptr, 0, MPI_CHAR, 0, kReady, MPI_COMM_WORLD);
    }
  }
  MPI_Send(nullptr, 0, MPI_CHAR, 0, kDone, MPI_COMM_WORLD);
#else
  (void)spec;
#endif
}

}  // namespace pkmws::cli
