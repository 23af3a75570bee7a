#include "attiguard/sim/held_actuation.hpp"

#include <algorithm>
#include <cmath>

#include "attiguard/control/torque_quantizer.hpp"

namespace attiguard::sim {

HeldActuation::HeldActuation(const PetErgImperfections& imperfections,
                             std::span<const dynamics::ReactionWheel> wheels)
    : sensor_(imperfections.sensor),
      delay_periods_(imperfections.delay_periods),
      torque_quantum_(imperfections.torque_quantum),
      wheels_(wheels.empty() ? dynamics::ReactionWheelArray() : dynamics::ReactionWheelArray(wheels)) {
  for (int i = 0; i < wheels_.count(); ++i) h_k_[static_cast<std::size_t>(i)] = wheels_.wheel(i).momentum0;
}

const governor::GovernorOutput& HeldActuation::control(governor::AttitudeGovernor& gov, double t,
                                                       const lie::Mat3& R_ib, const lie::Vec3& omega_b,
                                                       const lie::Mat3& R_d) noexcept {
  // What the flight software sees (sensor errors) and computes: docs/pet-erg.md, section 11.
  const dynamics::Measurement m = sensor_.measure(R_ib, omega_b, sample_++);
  const governor::GovernorOutput& out = gov.step(t, m.R_ib, m.omega_b, R_d);
  command(t, out.tau_b);
  return out;
}

void HeldActuation::command(double t, const lie::Vec3& tau_b) noexcept {
  // Commanded quantised, possibly one period late (docs/pet-erg.md, section 11).
  const lie::Vec3 command_b = control::quantize_torque(tau_b, torque_quantum_);
  if (has_wheels()) {
    command_wheels(t, command_b);
  } else {
    command_body(command_b);
  }
}

void HeldActuation::command_wheels(double t, const lie::Vec3& command_b) noexcept {
  h_k_ = momenta(t);
  t_k_ = t;
  // u = A⁺τ (minimum norm), clipped to the wheels' limits; the demand ratio is reported.
  for (int i = 0; i < wheels_.count(); ++i) {
    max_torque_ratio_ = std::max(max_torque_ratio_, std::abs(wheels_.allocation_row(i).dot(command_b)) /
                                                        wheels_.wheel(i).torque_max);
  }
  const dynamics::WheelVector u = wheels_.allocate(command_b);
  u_held_ = delay_periods_ == 1 ? u_pending_ : u;
  u_pending_ = u;
  tau_held_b_ = wheels_.body_torque(u_held_);
}

void HeldActuation::command_body(const lie::Vec3& command_b) noexcept {
  if (delay_periods_ == 1) {
    tau_held_b_ = tau_pending_b_;
    tau_pending_b_ = command_b;
  } else {
    tau_held_b_ = command_b;
  }
}

dynamics::WheelVector HeldActuation::momenta(double t) const noexcept {
  dynamics::WheelVector h = h_k_;
  for (int i = 0; i < wheels_.count(); ++i) {
    h[static_cast<std::size_t>(i)] -= u_held_[static_cast<std::size_t>(i)] * (t - t_k_);
  }
  return h;
}

lie::Vec3 HeldActuation::momentum_b(double t) const noexcept { return wheels_.body_momentum(momenta(t)); }

void HeldActuation::observe_momenta(double t) noexcept {
  const dynamics::WheelVector h = momenta(t);
  for (int i = 0; i < wheels_.count(); ++i) {
    max_momentum_ratio_ = std::max(max_momentum_ratio_,
                                   std::abs(h[static_cast<std::size_t>(i)]) / wheels_.wheel(i).momentum_max);
  }
}

}  // namespace attiguard::sim
