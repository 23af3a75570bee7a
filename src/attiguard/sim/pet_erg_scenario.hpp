#pragma once
/// @file pet_erg_scenario.hpp
/// The validated configuration of a `pet_erg` run: constrained attitude control with the PD law
/// (3) and the periodic event-triggered (5)-(6), continuous (4), or no reference governor of the
/// PET-ERG paper. Read from a scenario file by scenario::parse_pet_erg (keys:
/// docs/scenario-format.md, section "pet_erg"); consumed by sim/pet_erg_run.

#include <string>
#include <vector>

#include "attiguard/dynamics/attitude_sensor.hpp"
#include "attiguard/dynamics/disturbance_torque.hpp"
#include "attiguard/dynamics/reaction_wheel_array.hpp"
#include "attiguard/governor/attitude_governor.hpp"
#include "attiguard/governor/reference_schedule.hpp"
#include "attiguard/integrate/integrator_settings.hpp"
#include "attiguard/lie/so3.hpp"
#include "attiguard/sim/adversarial_disturbance.hpp"

namespace attiguard::sim {

/// The imperfections of the flight loop, `[imperfections]` (docs/pet-erg.md, section 11).
struct PetErgImperfections {
  dynamics::DisturbanceTorque disturbance;  ///< d(t) on the plant, ‖d‖ ≤ d̄
  AdversarySettings adversary;              ///< update and weight of `adversarial`
  dynamics::AttitudeSensor sensor;          ///< biases and bounded noises of R and ω
  int delay_periods{0};                     ///< 0 or 1: τ_k applied from t_{k+1} on
  double torque_quantum{0.0};               ///< q [N·m] of control::quantize_torque (0: none)
};

/// Everything a `pet_erg` run needs, validated (scenario::parse_pet_erg also checks the
/// admissibility of the initial state, PET-ERG paper Theorem 1).
struct PetErgScenario {
  std::string name;
  governor::GovernorParams params;            ///< governor, [body], [control], [erg]
  std::vector<governor::ConeConstraint> cones;  ///< [[cones]] (at most governor::kMaxCones)
  lie::Mat3 R0_ib{lie::Mat3::Identity()};     ///< [initial] attitude
  lie::Vec3 omega0_b{lie::Vec3::Zero()};      ///< [initial] omega_b [rad/s]
  lie::Mat3 R_g0{lie::Mat3::Identity()};      ///< [initial] reference (default: attitude)
  governor::ReferenceSchedule desired;        ///< [desired] attitude or schedule
  /// [control] control_period [s]: 0 integrates the continuous-time loop of the paper; > 0 runs
  /// AttitudeGovernor::step every control_period with the torque held (docs/pet-erg.md, "Flight
  /// loop").
  double control_period{0.0};
  PetErgImperfections imperfections;          ///< [imperfections] (flight loop only)
  /// [[wheels]] (flight loop only; docs/pet-erg.md, section 12): empty = the body torque is
  /// applied directly. With wheels, params.polytope_gamma_d is their polytope's Γ_d.
  std::vector<dynamics::ReactionWheel> wheels;
  double wheel_gamma_d_upper{0.0};  ///< attained value above the polytope's exact Γ_d
  int wheel_binding{-1};            ///< the wheel whose limit binds the polytope's Γ_d
  double duration{0.0};                       ///< [simulation] duration [s]
  double output_interval{0.0};                ///< [simulation] output_interval [s]
  double convergence_tolerance{1e-4};         ///< [simulation] convergence_tolerance: on φ(R_dᵀR)
  integrate::IntegratorSettings integrator;   ///< [simulation] integrator keys
};

}  // namespace attiguard::sim
