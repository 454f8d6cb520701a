// Distributing a sweep over MPI ranks (built with -DPKMWS_MPI=ON): rank 0
// hands out design indices one at a time to whichever rank asks (dynamic
// scheduling: designs differ a lot in cost; a worker asks ahead only for
// designs under 20 ms, holding at most two in reserve), evaluates designs itself
// on a second thread, collects the rows and writes every output; its
// communication thread sleeps between polls instead of spinning. The other
// ranks only evaluate. Without MPI, or when not started by mpirun, a single rank.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "pkmws/design/sweep.hpp"

namespace pkmws::cli {

class MpiSweep {
 public:
  /// Starts MPI when this process was launched by mpirun (and finalises it in
  /// the destructor, after telling the workers to stop if rank 0 failed).
  MpiSweep();
  ~MpiSweep();
  MpiSweep(const MpiSweep&) = delete;
  MpiSweep& operator=(const MpiSweep&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }

  /// Rank 0, once the sweep is known to be valid (or on failure, by the
  /// destructor): lets the other ranks start (or end quietly).
  void release(bool ok);
  /// Other ranks: waits for rank 0's word; true when there is work to do.
  bool wait_release();

  /// Rank 0: evaluates `todo` over every rank, calling done(row) for each
  /// finished design (serialised); returns the rows in completion order.
  std::vector<design::DesignRow> run(const design::SweepSpec& spec, const std::vector<std::size_t>& todo,
                                     const std::function<void(const design::DesignRow&)>& done);
  /// Other ranks: evaluate what rank 0 sends until it says stop.
  void serve(const design::SweepSpec& spec);

 private:
  void stop_workers();
  int rank_ = 0;
  int size_ = 1;
  bool started_ = false;
  bool released_ = false;
  bool workers_stopped_ = false;
  std::vector<char> left_;  // rank 0: the workers that have left (every request answered)
};

}  // namespace pkmws::cli
