#pragma once
/// @file disturbance_torque.hpp
/// A bounded external disturbance torque d(t) on the rigid body, J ω̇ = Jω × ω + τ + d
/// (docs/pet-erg.md, section 11): none, constant d̄ a, sinusoidal d̄ sin(2π t / P) a, or random
/// (uniform in the ball ‖d‖ ≤ d̄, a new value every `hold` seconds). ‖d(t)‖ ≤ d̄ always.
/// A pure function of t: allocation-free, noexcept, usable inside the integrator's vector field.
/// The kind `adversarial` depends on the state and the cones: it is computed by
/// sim/adversarial_disturbance.hpp, and `at` returns zero for it.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "attiguard/core/name_table.hpp"
#include "attiguard/dynamics/bounded_noise.hpp"
#include "attiguard/lie/so3.hpp"

namespace attiguard::dynamics {

/// Shape of the disturbance torque (docs/pet-erg.md, section 11).
enum class DisturbanceKind { none, constant, sinusoidal, random, adversarial };

/// Names of DisturbanceKind in scenario files (`[imperfections] disturbance`).
inline constexpr NameTable<DisturbanceKind, 5> kDisturbanceKindNames{
    {{{DisturbanceKind::none, "none"},
      {DisturbanceKind::constant, "constant"},
      {DisturbanceKind::sinusoidal, "sinusoidal"},
      {DisturbanceKind::random, "random"},
      {DisturbanceKind::adversarial, "adversarial"}}}};

/// d(t) of docs/pet-erg.md, section 11 (body frame, N·m).
struct DisturbanceTorque {
  DisturbanceKind kind{DisturbanceKind::none};
  double bound{0.0};                       ///< d̄ [N·m]
  lie::Vec3 axis_b{lie::Vec3::UnitX()};    ///< unit axis a of constant / sinusoidal
  double period{100.0};                    ///< P of sinusoidal [s]
  double hold{0.1};                        ///< random: a new value every `hold` seconds
  std::uint64_t seed{0};                   ///< random: counter-based seed

  /// d(t), ‖d(t)‖ ≤ bound (docs/pet-erg.md, section 11); zero for `adversarial` (state-dependent,
  /// sim/adversarial_disturbance.hpp).
  [[nodiscard]] lie::Vec3 at(double t) const noexcept {
    switch (kind) {
      case DisturbanceKind::none:
        return lie::Vec3::Zero();
      case DisturbanceKind::constant:
        return bound * axis_b;
      case DisturbanceKind::sinusoidal:
        return bound * std::sin(2.0 * std::numbers::pi * t / period) * axis_b;
      case DisturbanceKind::random: {
        const double k = std::floor(std::max(0.0, t) / hold);
        return uniform_in_ball(seed, 1, static_cast<std::uint64_t>(k), bound);
      }
      case DisturbanceKind::adversarial:
        return lie::Vec3::Zero();
    }
    return lie::Vec3::Zero();
  }
};

}  // namespace attiguard::dynamics
