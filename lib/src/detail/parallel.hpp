// The one module that calls oneTBB: an execution policy (serial, or
// parallel on K threads in a tbb::task_arena) and a size threshold below which
// work runs serially. Work is cut into blocks whose boundaries depend only on
// the problem size, never on the thread count; callers write one result per
// block and combine them in block order, so output is identical with 1 and N
// threads (integer counts, or doubles summed serially in block order).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace pkmws::detail {

struct ParallelPolicy {
  /// 0: every hardware thread; 1: serial (no TBB call at all); K: K threads.
  int threads = 0;
  /// Work items (e.g. point tests) below which a call runs serially: starting
  /// threads costs ~10 us, a few 1e5 point tests.
  std::size_t serial_threshold = std::size_t{1} << 16;
};

/// Threads the policy would use (>= 1).
int effective_threads(const ParallelPolicy& policy);

/// Threads a for_each_block call with these arguments uses (>= 1).
int threads_for(const ParallelPolicy& policy, std::size_t n_blocks, std::size_t work);

/// Calls body(block) once for every block in [0, n_blocks), concurrently when
/// the policy allows it and `work` (an estimate of the total work items) is at
/// least the threshold. Exceptions from `body` propagate to the caller.
void for_each_block(const ParallelPolicy& policy, std::size_t n_blocks, std::size_t work,
                    const std::function<void(std::size_t block)>& body);

/// Blocks of `block_size` items covering [0, n): block b is
/// [b * block_size, min(n, (b + 1) * block_size)).
inline std::size_t block_count(std::size_t n, std::size_t block_size) {
  return block_size == 0 ? 0 : (n + block_size - 1) / block_size;
}

/// Deterministic sum of integer counts: count(begin, end) over fixed-size
/// blocks of [0, n), summed in block order.
std::uint64_t sum_counts(const ParallelPolicy& policy, std::size_t n, std::size_t block_size,
                         std::size_t work_per_item,
                         const std::function<std::uint64_t(std::size_t begin, std::size_t end)>& count);

}  // namespace pkmws::detail
