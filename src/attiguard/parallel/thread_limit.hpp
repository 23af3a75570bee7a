#pragma once
/// @file thread_limit.hpp
/// The most worker threads per process the `--threads` flags of `campaign` and `tune` accept
/// (docs/errors.md, "No abort"): 4 per hardware thread of this machine (more only wait for a
/// core, and each holds a run's memory), at least kMinThreadLimit, at most kThreadCap.

#include <algorithm>
#include <string>
#include <thread>

#include "attiguard/core/errors.hpp"

namespace attiguard::parallel {

/// Threads accepted on any machine, however few cores it reports.
inline constexpr int kMinThreadLimit = 8;
/// Threads accepted on no machine, however many cores it reports.
inline constexpr int kThreadCap = 256;
/// Threads accepted per hardware thread.
inline constexpr int kThreadsPerCore = 4;

/// The hardware threads of this machine (std::thread::hardware_concurrency; 1 when unknown).
[[nodiscard]] inline int hardware_threads() noexcept {
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

/// The `--threads` limit: clamp(kThreadsPerCore · hardware_threads(), kMinThreadLimit, kThreadCap).
[[nodiscard]] inline int thread_limit() noexcept {
  return std::clamp(kThreadsPerCore * std::min(hardware_threads(), kThreadCap), kMinThreadLimit,
                    kThreadCap);
}

/// Throws InputError "--threads: …" unless 1 <= threads <= thread_limit(): "--threads: 200 is
/// more than the limit 8 of this machine (4 per hardware thread, 2 hardware threads; never more
/// than 256): use --threads 8 or fewer".
inline void check_thread_count(long threads) {
  if (threads < 1) throw InputError("--threads: must be at least 1, got " + std::to_string(threads));
  if (threads > thread_limit()) {
    throw InputError("--threads: " + std::to_string(threads) + " is more than the limit " +
                     std::to_string(thread_limit()) + " of this machine (" +
                     std::to_string(kThreadsPerCore) + " per hardware thread, " +
                     std::to_string(hardware_threads()) + " hardware threads; at least " +
                     std::to_string(kMinThreadLimit) + ", never more than " +
                     std::to_string(kThreadCap) + "): use --threads " +
                     std::to_string(thread_limit()) + " or fewer");
  }
}

}  // namespace attiguard::parallel
