#pragma once
/// @file attitude_sensor.hpp
/// Measurement errors of the attitude and rate sensors of the flight loop (docs/pet-erg.md,
/// section 11): R̃ = R exp(b̂_R) exp(n̂_R,k), ω̃ = ω + b_ω + n_ω,k, with constant biases b and
/// noises uniform in the balls ‖n_R‖ ≤ σ_R [rad], ‖n_ω‖ ≤ σ_ω [rad/s], a new draw per sample k.
/// The attitude error angle is at most ‖b_R‖ + σ_R. Allocation-free and noexcept.

#include <cstdint>

#include "attiguard/dynamics/bounded_noise.hpp"
#include "attiguard/lie/so3.hpp"

namespace attiguard::dynamics {

/// What the flight loop measures (docs/pet-erg.md, section 11).
struct Measurement {
  lie::Mat3 R_ib{lie::Mat3::Identity()};
  lie::Vec3 omega_b{lie::Vec3::Zero()};
};

/// Biased, bounded-noise attitude and rate sensors (docs/pet-erg.md, section 11).
struct AttitudeSensor {
  lie::Vec3 attitude_bias_b{lie::Vec3::Zero()};  ///< b_R, a body rotation vector [rad]
  double attitude_noise{0.0};                    ///< σ_R [rad]
  lie::Vec3 rate_bias_b{lie::Vec3::Zero()};      ///< b_ω [rad/s]
  double rate_noise{0.0};                        ///< σ_ω [rad/s]
  std::uint64_t seed{0};

  /// The measurement of sample k of the true (R, ω) (docs/pet-erg.md, section 11).
  [[nodiscard]] Measurement measure(const lie::Mat3& R_ib, const lie::Vec3& omega_b,
                                    std::uint64_t k) const noexcept {
    Measurement m;
    m.R_ib = R_ib * lie::exp(attitude_bias_b) *
             lie::exp(uniform_in_ball(seed, 2, k, attitude_noise));
    m.omega_b = omega_b + rate_bias_b + uniform_in_ball(seed, 3, k, rate_noise);
    return m;
  }
  /// Bound on the attitude error angle d(R̃, R) ≤ ‖b_R‖ + σ_R [rad].
  [[nodiscard]] double attitude_error_bound() const noexcept {
    return attitude_bias_b.norm() + attitude_noise;
  }
  /// Bound on the rate error ‖ω̃ − ω‖ ≤ ‖b_ω‖ + σ_ω [rad/s].
  [[nodiscard]] double rate_error_bound() const noexcept { return rate_bias_b.norm() + rate_noise; }
};

}  // namespace attiguard::dynamics
