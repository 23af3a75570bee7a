#pragma once
/// @file held_actuation.hpp
/// The actuation of the `pet_erg` flight loop (docs/pet-erg.md, sections 10-12): at control
/// instant t_k the sensors' view of the true state (section 11) goes to AttitudeGovernor::step;
/// its torque is quantised, applied one period late with `delay_periods = 1` (section 11) and,
/// with reaction wheels, allocated to them (section 12). The result is held on [t_k, t_{k+1})
/// (zero-order hold, section 10), and the wheels' momenta are h(t) = h_k − u_k (t − t_k) between
/// the instants. The constructor may throw; every other member is noexcept and allocation-free.

#include <cstdint>
#include <span>

#include "attiguard/dynamics/attitude_sensor.hpp"
#include "attiguard/dynamics/reaction_wheel_array.hpp"
#include "attiguard/governor/attitude_governor.hpp"
#include "attiguard/lie/so3.hpp"
#include "attiguard/sim/pet_erg_scenario.hpp"

namespace attiguard::sim {

/// The held body torque (and wheel torques) of the flight loop and what the flight software does
/// at each control instant to set it (docs/pet-erg.md, sections 10-12).
class HeldActuation {
 public:
  /// The sensors, delay and torque quantum of `imperfections` (docs/pet-erg.md, section 11) and
  /// the reaction wheels (section 12; empty: the body torque is applied directly). Nothing is
  /// applied before the first control instant. Throws SetupError for a wheel set that
  /// dynamics::ReactionWheelArray refuses (set-up code only).
  HeldActuation(const PetErgImperfections& imperfections,
                std::span<const dynamics::ReactionWheel> wheels);

  /// Control instant t = t_k (non-decreasing across calls) with the true R_ib, ω_b and R_d(t):
  /// sample k of the sensors (docs/pet-erg.md, section 11), `gov.step` with that measurement
  /// ([PET-ERG eq. (6)], docs/pet-erg.md "Flight loop"), then command(t, τ). Returns the
  /// governor's output (its torque before quantisation).
  const governor::GovernorOutput& control(governor::AttitudeGovernor& gov, double t,
                                          const lie::Mat3& R_ib, const lie::Vec3& omega_b,
                                          const lie::Mat3& R_d) noexcept;

  /// Sample k of the sensors (docs/pet-erg.md, section 11): what the flight software sees of the
  /// true R_ib, ω_b at a control instant (for a governor other than AttitudeGovernor, which
  /// then computes its torque and calls command()).
  [[nodiscard]] dynamics::Measurement measure(const lie::Mat3& R_ib, const lie::Vec3& omega_b) noexcept {
    return sensor_.measure(R_ib, omega_b, sample_++);
  }

  /// The torque τ_b the flight software commands at t = t_k: quantised (docs/pet-erg.md,
  /// section 11), delayed, with wheels allocated u = A⁺τ clipped (section 12, the demand ratio
  /// recorded) and the momenta restarted from h(t_k); then held until the next command.
  void command(double t, const lie::Vec3& tau_b) noexcept;

  /// The body torque applied on [t_k, t_{k+1}): A u_k with wheels, else the (delayed) command.
  [[nodiscard]] const lie::Vec3& torque_b() const noexcept { return tau_held_b_; }
  /// Whether the torque acts through reaction wheels (docs/pet-erg.md, section 12).
  [[nodiscard]] bool has_wheels() const noexcept { return wheels_.count() > 0; }
  /// The wheel array (count() = 0 without wheels).
  [[nodiscard]] const dynamics::ReactionWheelArray& wheels() const noexcept { return wheels_; }
  /// The wheel torques u_k held on [t_k, t_{k+1}) (first wheels().count() entries).
  [[nodiscard]] const dynamics::WheelVector& wheel_torques() const noexcept { return u_held_; }
  /// The wheels' momenta h(t) = h_k − u_k (t − t_k) for t ≥ t_k (docs/pet-erg.md, section 12).
  [[nodiscard]] dynamics::WheelVector momenta(double t) const noexcept;
  /// The wheels' momentum in the body frame, A h(t) (docs/pet-erg.md, section 12).
  [[nodiscard]] lie::Vec3 momentum_b(double t) const noexcept;
  /// Folds |h_i(t)| / h_max,i into max_wheel_momentum_ratio (docs/pet-erg.md, section 12).
  void observe_momenta(double t) noexcept;
  /// Max over the commands of |(A⁺τ_cmd)_i| / u_max,i (> 1: a wheel's clip acted; 0 without
  /// wheels; docs/pet-erg.md, section 12).
  [[nodiscard]] double max_wheel_torque_ratio() const noexcept { return max_torque_ratio_; }
  /// Max over the observed instants of |h_i| / h_max,i (0 without wheels).
  [[nodiscard]] double max_wheel_momentum_ratio() const noexcept { return max_momentum_ratio_; }

 private:
  void command_wheels(double t, const lie::Vec3& command_b) noexcept;
  void command_body(const lie::Vec3& command_b) noexcept;

  dynamics::AttitudeSensor sensor_;
  int delay_periods_{0};
  double torque_quantum_{0.0};
  dynamics::ReactionWheelArray wheels_;
  std::uint64_t sample_{0};                           ///< the sensors' sample index k
  lie::Vec3 tau_held_b_{lie::Vec3::Zero()};           ///< applied on [t_k, t_{k+1})
  lie::Vec3 tau_pending_b_{lie::Vec3::Zero()};        ///< computed at t_k, applied from t_{k+1}
  dynamics::WheelVector u_held_{};
  dynamics::WheelVector u_pending_{};
  dynamics::WheelVector h_k_{};                       ///< momenta at the last command
  double t_k_{0.0};                                   ///< time of the last command
  double max_torque_ratio_{0.0};
  double max_momentum_ratio_{0.0};
};

}  // namespace attiguard::sim
