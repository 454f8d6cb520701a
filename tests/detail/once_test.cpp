// The library's pthread_once (lib/src/detail/once.cpp), through what calls it:
// std::call_once. It is the one linked here (not glibc's), runs every
// initialiser exactly once under contention, makes waiters wait for it, and
// resets a flag whose initialiser throws.
#include <gtest/gtest.h>

#include <dlfcn.h>
#include <pthread.h>

#include <atomic>
#include <chrono>
#include <climits>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

#if defined(__linux__) && defined(__GLIBC__) && !defined(__SANITIZE_THREAD__)
TEST(Once, TheLibrarysPthreadOnceIsTheOneLinked) {
  // Hidden in this executable: not what the dynamic linker exports (glibc's).
  EXPECT_NE(reinterpret_cast<void*>(&pthread_once), dlsym(RTLD_DEFAULT, "pthread_once"));
}
#endif

TEST(Once, EveryInitialiserRunsOnceUnderContention) {
  constexpr int kFlags = 2000, kThreads = 4;
  std::vector<std::once_flag> flags(kFlags);
  std::vector<std::atomic<int>> runs(kFlags);
  std::vector<int> values(kFlags, 0);
  std::atomic<int> wrong{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([&, t] {
      for (int k = 0; k < kFlags; ++k) {
        const int i = (k + t * 7) % kFlags;  // threads meet on every flag
        std::call_once(flags[i], [&] {
          runs[i].fetch_add(1);
          values[i] = i + 1;  // published by call_once
        });
        if (values[i] != i + 1) wrong.fetch_add(1);
      }
    });
  }
  for (auto& th : threads) th.join();
  for (int i = 0; i < kFlags; ++i) ASSERT_EQ(runs[i].load(), 1) << i;
  EXPECT_EQ(wrong.load(), 0);
}

TEST(Once, WaitersReturnAfterTheInitialiser) {
  std::once_flag flag;
  std::atomic<bool> started{false};
  int value = 0;
  std::thread first([&] {
    std::call_once(flag, [&] {
      started = true;
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      value = 42;
    });
  });
  while (!started) std::this_thread::yield();
  std::vector<std::thread> waiters;
  std::atomic<int> seen{0};
  for (int t = 0; t < 3; ++t) {
    waiters.emplace_back([&] {
      std::call_once(flag, [] { ADD_FAILURE() << "ran twice"; });
      if (value == 42) seen.fetch_add(1);
    });
  }
  first.join();
  for (auto& th : waiters) th.join();
  EXPECT_EQ(seen.load(), 3);
}

TEST(Once, AThrowingInitialiserLeavesTheFlagToRunAgain) {
  std::once_flag flag;
  int runs = 0;
  EXPECT_THROW(std::call_once(flag, [&] {
                 ++runs;
                 throw std::runtime_error("first");
               }),
               std::runtime_error);
  std::call_once(flag, [&] { ++runs; });
  std::call_once(flag, [&] { ++runs; });
  EXPECT_EQ(runs, 2);
}
