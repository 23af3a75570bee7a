#pragma once
/// @file parallel_for.hpp
/// parallel_for over [0, n) with std::thread workers (worker_pool.hpp); the first exception
/// is rethrown, a thread the system refuses is a ThreadStartError, never std::terminate.

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>

#include "attiguard/parallel/worker_pool.hpp"

namespace attiguard::parallel {

/// Runs fn(i) for i in [0, n) on `threads` workers (0: hardware concurrency, at most n).
/// Throws ThreadStartError (worker_pool.hpp) when a worker thread cannot be created.
template <class Fn>
void parallel_for(long n, int threads, Fn&& fn) {
  if (n <= 0) return;
  long workers = threads > 0 ? threads : static_cast<long>(std::max(1u, std::thread::hardware_concurrency()));
  workers = std::min(workers, n);
  std::atomic<long> next{0};
  std::exception_ptr error;
  std::mutex error_mutex;
  auto work = [&](long) {
    for (long i = next++; i < n; i = next++) {
      try {
        fn(i);
      } catch (...) {
        std::lock_guard<std::mutex> lock(error_mutex);
        if (!error) error = std::current_exception();
        next = n;
      }
    }
  };
  run_workers(workers, work);
  if (error) std::rethrow_exception(error);
}

}  // namespace attiguard::parallel
