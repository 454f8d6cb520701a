// pthread_once for pkmws's own code, without a system call when no thread
// waits.
//
// CGAL's thread-safe lazy kernel (Epeck, CGAL >= 5.3) guards the exact value
// of every node of its expression DAGs with a std::once_flag, and libstdc++'s
// std::call_once is glibc's pthread_once, whose slow path (the first call on
// each flag) ends with an unconditional FUTEX_WAKE system call. An exact
// workspace evaluates thousands of such nodes (the exact Booleans' degenerate
// comparisons, the area's exact coordinates), so a MOMA design paid thousands
// of system calls: on the paravirtualised benchmark machine they were half of
// a sweep's time (docs/benchmarks.md, "Design-space sweeps").
//
// This definition is hidden: the linker binds the library's own calls (the
// CGAL code inlined into it, region.cpp's cached components) to it, while
// shared libraries (oneTBB, Open MPI, libstdc++ itself) keep glibc's. Same
// contract as glibc's: `init` runs exactly once; concurrent callers block
// until it has returned; if it throws, the flag is reset and the exception
// propagates (another caller may run it again). States: 0 (PTHREAD_ONCE_INIT)
// not run, 1 running, 2 running with waiters, 3 done; only state 2 costs a
// wake-up. Not built under ThreadSanitizer, which must see glibc's.
#include <climits>  // glibc's <features.h>: __GLIBC__

#if defined(__linux__) && defined(__GLIBC__) && !defined(__SANITIZE_THREAD__)

#include <linux/futex.h>
#include <pthread.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <atomic>

namespace {

enum : int { kIdle = 0, kRunning = 1, kWaiters = 2, kDone = 3 };

static_assert(sizeof(pthread_once_t) == sizeof(int) && alignof(pthread_once_t) >= alignof(int));
static_assert(sizeof(std::atomic<int>) == sizeof(int) && std::atomic<int>::is_always_lock_free);

void wake_all(std::atomic<int>* s) {
  syscall(SYS_futex, reinterpret_cast<int*>(s), FUTEX_WAKE_PRIVATE, INT_MAX, nullptr, nullptr, 0);
}

void wait_while_waiters(std::atomic<int>* s) {
  syscall(SYS_futex, reinterpret_cast<int*>(s), FUTEX_WAIT_PRIVATE, int{kWaiters}, nullptr, nullptr, 0);
}

// Puts the flag back to "not run" when init throws, waking the waiters so
// that one of them can run it.
struct ResetOnThrow {
  std::atomic<int>* state;
  bool armed = true;
  ~ResetOnThrow() {
    if (armed && state->exchange(kIdle, std::memory_order_acq_rel) == kWaiters) wake_all(state);
  }
};

}  // namespace

extern "C" __attribute__((visibility("hidden"))) int pthread_once(pthread_once_t* once, void (*init)(void)) {
  static_assert(PTHREAD_ONCE_INIT == kIdle);
  auto* state = reinterpret_cast<std::atomic<int>*>(once);
  int s = state->load(std::memory_order_acquire);
  while (s != kDone) {
    if (s == kIdle) {
      if (!state->compare_exchange_weak(s, kRunning, std::memory_order_acquire)) continue;
      ResetOnThrow reset{state};
      init();
      reset.armed = false;
      if (state->exchange(kDone, std::memory_order_acq_rel) == kWaiters) wake_all(state);
      return 0;
    }
    // Running in another thread: say that someone waits, then sleep until
    // the state changes (a futex wait returns at once if it already has).
    if (s == kRunning && !state->compare_exchange_weak(s, kWaiters, std::memory_order_acquire)) continue;
    wait_while_waiters(state);
    s = state->load(std::memory_order_acquire);
  }
  return 0;
}

#endif
