// A pool of threads over independent tasks: the one home of the threading used by `prove
// --jobs`, `sweep run --threads` and `report --jobs`. Results must not depend on the number of
// threads or on the order tasks finish in: every task writes only its own slot and draws only
// from its own seeded stream.
#pragma once
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace splinex {

/// Every core this process may use (at least 1).
inline std::size_t hardware_threads() {
  const unsigned n = std::thread::hardware_concurrency();
  return n == 0 ? 1 : n;
}

/// Functions every worker thread parallel_for starts runs before it ends: the place where a
/// library frees what it keeps per thread (float/ registers MPFR's constant caches, which
/// LeakSanitizer reports once a thread is gone). Registered at start-up, before any pool runs.
inline std::vector<void (*)()>& thread_exit_hooks() {
  static std::vector<void (*)()> hooks;
  return hooks;
}

/// task(k) for k = 0, ..., n - 1, each once, on min(threads, n) threads (the caller's among
/// them); tasks are handed out in increasing k. The first exception a task throws stops the
/// handing out of further tasks and is rethrown once every thread has finished its current task.
template <class Task>
void parallel_for(std::size_t n, std::size_t threads, Task&& task) {
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::mutex lock;
  std::exception_ptr error;
  auto worker = [&] {
    while (!failed.load()) {
      const std::size_t k = next++;
      if (k >= n) return;
      try {
        task(k);
      } catch (...) {
        std::lock_guard<std::mutex> g(lock);
        if (!error) error = std::current_exception();
        failed = true;
      }
    }
  };
  std::vector<std::thread> pool;
  for (std::size_t t = 1; t < threads && t < n; ++t)
    pool.emplace_back([&] {
      worker();
      for (auto hook : thread_exit_hooks()) hook();
    });
  worker();
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace splinex
