#pragma once
/// @file worker_pool.hpp
/// Runs a body on W worker threads and never calls std::terminate (docs/errors.md, "No
/// abort"): every thread is created before any starts working, so when the system refuses one
/// (std::system_error: a process or user thread limit, `ulimit -u`; std::bad_alloc: a memory
/// limit, `ulimit -v`) the threads already made
/// are released without work, joined, and ThreadStartError is thrown; an exception a worker
/// throws is caught in the worker and the first one is rethrown to the caller once all joined.

#include <condition_variable>
#include <exception>
#include <mutex>
#include <new>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

namespace attiguard::parallel {

/// The system refused to create worker thread `started` + 1 of `wanted` (`reason`: the
/// system's message). app/failure.cpp turns it into an exit-2 message naming --threads.
class ThreadStartError : public std::runtime_error {
 public:
  ThreadStartError(long started, long wanted, const std::string& reason)
      : std::runtime_error("cannot start worker thread " + std::to_string(started + 1) + " of " +
                           std::to_string(wanted) + " (" + reason + ")"),
        started_(started),
        wanted_(wanted) {}
  /// Threads that were created before the refusal (none of them did any work).
  [[nodiscard]] long started() const noexcept { return started_; }
  /// Threads asked for.
  [[nodiscard]] long wanted() const noexcept { return wanted_; }

 private:
  long started_;
  long wanted_;
};

/// Runs body(w) for w in [0, workers) on `workers` threads (on the caller's thread when
/// workers <= 1) and returns when all have returned. Throws ThreadStartError when a thread
/// cannot be created (then no body ran), else rethrows the first exception a body threw.
template <class Body>
void run_workers(long workers, Body&& body) {
  if (workers <= 1) {
    body(0L);
    return;
  }
  std::mutex gate_mutex;
  std::condition_variable gate;
  bool open = false;
  bool cancelled = false;
  std::exception_ptr error;
  std::mutex error_mutex;
  const auto worker = [&](long w) {
    {
      std::unique_lock<std::mutex> lock(gate_mutex);
      gate.wait(lock, [&] { return open || cancelled; });
      if (cancelled) return;
    }
    try {
      body(w);
    } catch (...) {
      std::lock_guard<std::mutex> lock(error_mutex);
      if (!error) error = std::current_exception();
    }
  };
  std::vector<std::thread> pool;
  const auto release = [&](bool go) {
    {
      std::lock_guard<std::mutex> lock(gate_mutex);
      (go ? open : cancelled) = true;
    }
    gate.notify_all();
    for (std::thread& t : pool) t.join();
  };
  try {
    pool.reserve(static_cast<std::size_t>(workers));
    for (long w = 0; w < workers; ++w) pool.emplace_back(worker, w);
  } catch (const std::system_error& e) {
    release(false);
    throw ThreadStartError(static_cast<long>(pool.size()), workers, e.what());
  } catch (const std::bad_alloc&) {
    // The pool or a thread's state could not be allocated (a memory limit, `ulimit -v`): the
    // same refusal as a thread the system refuses, located by the caller at its setting.
    release(false);
    throw ThreadStartError(static_cast<long>(pool.size()), workers, "out of memory");
  } catch (...) {
    release(false);
    throw;
  }
  release(true);
  if (error) std::rethrow_exception(error);
}

}  // namespace attiguard::parallel
