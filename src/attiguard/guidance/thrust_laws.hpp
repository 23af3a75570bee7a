#pragma once
/// @file thrust_laws.hpp
/// On/off main-thruster laws of the Waypoint paper: acceleration (13), deceleration [Waypoint eqs. (15)-(16)].

namespace attiguard::guidance {

/// Acceleration phase, [Waypoint eq. (13)]: T_max while ‖v‖ ≤ V_d, else 0.
[[nodiscard]] inline double acceleration_thrust(double speed, double cruise_speed,
                                                double T_max) noexcept {
  return speed <= cruise_speed ? T_max : 0.0;
}

/// Desired deceleration magnitude |a_d| from [Waypoint eq. (14)] with final speed 0: |a_d| = ‖v‖²/(2‖e‖).
/// Erratum: (15) prints −‖v‖/(2‖e‖), which is not an acceleration (unit 1/s) and fires far too
/// late to stop (tests/guidance/test_thrust_laws.cpp). ‖e‖ = 0 gives +∞ (brake).
[[nodiscard]] inline double braking_deceleration(double speed, double distance) noexcept {
  if (!(distance > 0.0)) {
    return speed > 0.0 ? 1e300 : 0.0;
  }
  return speed * speed / (2.0 * distance);
}

/// Deceleration phase, [Waypoint eq. (16)] with (15) corrected: T_max when
/// m |a_d| ≥ γ T_max, else 0, with the braking margin γ ∈ (0, 1] (γ = 1 is (16) as printed).
/// With γ = 1 a sampled controller always starts braking up to one period late and reaches the
/// waypoint with up to √(2 (T_max/m) ‖v‖ T_s) of speed left; with γ < 1 the on/off thrust
/// chatters along the braking curve ‖v‖ = √(2 γ (T_max/m) ‖e‖) down to ‖e‖, ‖v‖ → 0.
[[nodiscard]] inline double deceleration_thrust(double mass, double speed, double distance,
                                                double T_max, double margin = 1.0) noexcept {
  return mass * braking_deceleration(speed, distance) >= margin * T_max ? T_max : 0.0;
}

/// [Waypoint eqs. (15)-(16)] exactly as printed (m ‖v‖/(2‖e‖) ≥ T_max), for tests and docs only.
[[nodiscard]] inline double deceleration_thrust_as_printed(double mass, double speed,
                                                           double distance, double T_max) noexcept {
  if (!(distance > 0.0)) {
    return T_max;
  }
  return mass * speed / (2.0 * distance) >= T_max ? T_max : 0.0;
}

}  // namespace attiguard::guidance
