// Distributing a sweep over MPI ranks (built with -DPKMWS_MPI=ON). Dynamic
// scheduling without a coordinator: the positions in the list of designs to
// evaluate are taken from one counter in an MPI window on rank 0 (an atomic
// fetch-and-add, MPI_Fetch_and_op), so a rank takes its next design the
// moment it is free, whatever the designs cost. Every rank evaluates; the
// workers send each row to rank 0 as it is finished, and rank 0 collects them
// between its own designs (no second thread, no polling while it evaluates)
// and writes every output. When the ranks span several machines, rank 0 only
// collects rows (and so serves the counter at once on networks without
// remote atomics), unless told otherwise. Without MPI, or when not started
// by mpirun, a single rank.
//
// Each rank evaluates its designs in a child process forked before MPI_Init,
// which stays single-threaded: Open MPI starts threads of its own in every
// rank, and in a process that has ever had a second thread CGAL's handles
// count references with atomic instructions and its lazy kernel keeps the
// expression DAGs (CGAL::is_currently_single_threaded), and glibc's malloc
// locks: a design cost 15-40 % more there (docs/design_space.md, "MPI"). The
// rank sends the child a design index through a pipe and reads the row back.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "pkmws/design/sweep.hpp"

namespace pkmws::cli {

/// Whether rank 0 evaluates designs besides collecting the rows.
enum class RankZero { automatic, evaluates, collects };

class MpiSweep {
 public:
  /// Starts MPI when this process was launched by mpirun (and finalises it in
  /// the destructor, after the workers have stopped if rank 0 failed).
  /// `spec_path`: the sweep file, which the evaluating child process loads.
  explicit MpiSweep(std::string spec_path);
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
  /// finished design (in the order rank 0 learns of them); returns the rows.
  std::vector<design::DesignRow> run(const design::SweepSpec& spec, const std::vector<std::size_t>& todo,
                                     RankZero role, const std::function<void(const design::DesignRow&)>& done);
  /// Other ranks: evaluate designs from the shared counter until none is left.
  void serve();

 private:
  void open_counter();
  std::pair<std::size_t, std::size_t> take(std::size_t count);
  void ask_child(std::size_t index);  // the child evaluates this design next
  std::string child_row();            // the next row the child finished (a CSV line)
  void evaluate_all(const std::function<void()>& between, const std::function<void(std::string)>& row);
  void stop_workers();
  int rank_ = 0;
  int size_ = 1;
  bool started_ = false;
  bool released_ = false;
  bool workers_stopped_ = false;
  bool one_machine_ = true;  // all ranks in one shared-memory domain
  std::vector<unsigned long long> todo_;  // the design indices, on every rank
  std::string spec_path_;
  int child_ = -1, to_child_ = -1, from_child_ = -1;  // the evaluating process (pid) and its pipes
  int workers_left_ = 0;  // rank 0: the workers that have said they are done
  struct Window;  // the counter's MPI window (mpi.h stays out of this header)
  std::unique_ptr<Window> window_;
};

}  // namespace pkmws::cli
