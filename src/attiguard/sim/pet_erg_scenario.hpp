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
  /// Declared bounds on the biases the robust margins assume (docs/pet-erg.md, section 13):
  /// ≥ ‖attitude_bias‖ [rad] and ≥ ‖rate_bias‖ [rad/s]; default the biases' own norms.
  double attitude_bias_bound{0.0};
  double rate_bias_bound{0.0};
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
  /// [control] margins = "robust" (docs/pet-erg.md, section 13): params.robust is set and the
  /// governor runs with the torque limits reduced by its command error: τ_max − e_cmd and the
  /// wheel polytope with each u_max,i − ‖r_i‖ e_cmd (whose Γ_d is robust_polytope_gamma_d).
  double robust_tau_max{0.0};
  double robust_polytope_gamma_d{0.0};
  /// With robust margins, the cones the governor enforces: each θ_c tightened by the attitude
  /// bias bound and its repulsive band moved inwards as Γ_min needs (section 13). `cones` stay
  /// the true constraints, on which the margins are reported.
  std::vector<governor::ConeConstraint> robust_cones;
  double duration{0.0};                       ///< [simulation] duration [s]
  double output_interval{0.0};                ///< [simulation] output_interval [s]
  double convergence_tolerance{1e-4};         ///< [simulation] convergence_tolerance: on φ(R_dᵀR)
  integrate::IntegratorSettings integrator;   ///< [simulation] integrator keys
};

/// The cones the governor of a run enforces: `cones`, or with robust margins `robust_cones`
/// (docs/pet-erg.md, section 13).
[[nodiscard]] inline const std::vector<governor::ConeConstraint>& governor_cones(const PetErgScenario& sc) {
  return sc.params.robust ? sc.robust_cones : sc.cones;
}

/// The parameters the governor of a run is built with (docs/pet-erg.md, sections 10 and 13): in
/// the flight loop the bounded reference step; with robust margins the reduced torque limits.
[[nodiscard]] inline governor::GovernorParams governor_params(const PetErgScenario& sc) {
  governor::GovernorParams p = sc.params;
  p.bounded_step = sc.control_period > 0.0;
  if (p.robust) {
    p.tau_max = sc.robust_tau_max;
    if (!sc.wheels.empty()) p.polytope_gamma_d = sc.robust_polytope_gamma_d;
  }
  return p;
}

}  // namespace attiguard::sim
