#pragma once
/// @file bounded_noise.hpp
/// Counter-based bounded random vectors for the flight-loop imperfections (docs/pet-erg.md,
/// section 11): the value for (seed, stream, k) is a pure function of its arguments (SplitMix64
/// finaliser of the counter), uniform in the ball of the given radius. No state, no allocation,
/// the same value whatever the order of the calls (runs are reproducible in campaigns).

#include <numbers>
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "attiguard/lie/so3.hpp"

namespace attiguard::dynamics {

/// SplitMix64 finaliser (Steele, Lea, Flood 2014): a bijective 64-bit mix.
[[nodiscard]] constexpr std::uint64_t mix64(std::uint64_t x) noexcept {
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30U)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27U)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31U);
}

/// Uniform in [0, 1) from the 53 high bits of mix64 of the counter (seed, stream, k, draw).
[[nodiscard]] inline double uniform01(std::uint64_t seed, std::uint64_t stream, std::uint64_t k,
                                      std::uint64_t draw) noexcept {
  const std::uint64_t h = mix64(mix64(mix64(seed ^ (stream * 0xD1B54A32D192ED03ULL)) ^ k) ^ draw);
  return static_cast<double>(h >> 11U) * 0x1.0p-53;
}

/// A vector uniform in the closed ball of `radius` for (seed, stream, k) (docs/pet-erg.md,
/// section 11): direction uniform on S² (z = 1 − 2u, azimuth 2πv), length radius·w^(1/3).
[[nodiscard]] inline lie::Vec3 uniform_in_ball(std::uint64_t seed, std::uint64_t stream,
                                               std::uint64_t k, double radius) noexcept {
  if (!(radius > 0.0)) return lie::Vec3::Zero();
  const double z = 1.0 - 2.0 * uniform01(seed, stream, k, 0);
  const double azimuth = 2.0 * std::numbers::pi * uniform01(seed, stream, k, 1);
  const double rho = std::sqrt(std::max(0.0, 1.0 - z * z));
  const double length = radius * std::cbrt(uniform01(seed, stream, k, 2));
  return length * lie::Vec3(rho * std::cos(azimuth), rho * std::sin(azimuth), z);
}

}  // namespace attiguard::dynamics
