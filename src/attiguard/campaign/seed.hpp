#pragma once
/// @file seed.hpp
/// Per-run seeds and the random number generator of campaigns. Everything here is defined
/// bit for bit (no std:: distributions, whose output is implementation-defined), so a run
/// replays identically on any machine, thread or MPI rank.

#include <cstdint>

namespace attiguard::campaign {

/// SplitMix64 finaliser (a bijective 64-bit mix).
[[nodiscard]] std::uint64_t splitmix64(std::uint64_t x) noexcept;

/// The seed of run k of a campaign with seed S: splitmix64(splitmix64(S) ^ (k + 1) · φ64).
[[nodiscard]] std::uint64_t run_seed(std::uint64_t campaign_seed, std::uint64_t run_index) noexcept;

/// Deterministic generator (SplitMix64 stream) with uniform and normal variates.
class Rng {
 public:
  explicit Rng(std::uint64_t seed) noexcept : state_(seed) {}
  /// Next 64 random bits.
  [[nodiscard]] std::uint64_t next() noexcept;
  /// Uniform in [0, 1) with 53 random bits.
  [[nodiscard]] double uniform01() noexcept;
  /// Uniform in [lo, hi).
  [[nodiscard]] double uniform(double lo, double hi) noexcept;
  /// Standard normal (Box–Muller, one variate per call; no cached second value).
  [[nodiscard]] double normal() noexcept;

 private:
  std::uint64_t state_;
};

}  // namespace attiguard::campaign
