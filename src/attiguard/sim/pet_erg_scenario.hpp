#pragma once
/// @file pet_erg_scenario.hpp
/// The validated configuration of a `pet_erg` run: constrained attitude control with the PD law
/// (3) and the periodic event-triggered [PET-ERG eqs. (5)-(6)], continuous (4), or no reference governor of the
/// PET-ERG paper. Read from a scenario file by scenario::parse_pet_erg (keys:
/// docs/scenario-format.md, section "pet_erg"); consumed by sim/pet_erg_run.

#include <algorithm>
#include <string>
#include <vector>

#include "attiguard/dynamics/attitude_sensor.hpp"
#include "attiguard/dynamics/disturbance_torque.hpp"
#include "attiguard/dynamics/reaction_wheel_array.hpp"
#include "attiguard/governor/attitude_governor.hpp"
#include "attiguard/governor/default_gains.hpp"
#include "attiguard/governor/governor_design.hpp"
#include "attiguard/governor/reference_schedule.hpp"
#include "attiguard/governor/torque_slabs.hpp"
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

  /// β: the attitude bias's declared bound, or the bias itself when larger [rad]
  /// (docs/pet-erg.md, sections 13 and 16.3).
  [[nodiscard]] double attitude_bias_max() const noexcept {
    return std::max(sensor.attitude_bias_b.norm(), attitude_bias_bound);
  }
  /// σ_ω: the rate bias's declared bound (or the bias when larger) plus the rate noise [rad/s]
  /// (docs/pet-erg.md, sections 13 and 16.2).
  [[nodiscard]] double rate_error_max() const noexcept {
    return std::max(sensor.rate_bias_b.norm(), rate_bias_bound) + sensor.rate_noise;
  }
};

/// `[plan]` of a pet_erg scenario: the slew planner's settings (docs/slew-planner.md, "Options").
struct SlewPlanSettings {
  double torque_headroom{0.05};  ///< the plan keeps ‖τ‖ ≤ (1 − headroom) × the torque limit
  /// Whether the file gives torque_headroom: the planned mode derives it from the sensors'
  /// errors when not (docs/pet-erg.md, section 16.2); `attiguard plan` takes 0.05.
  bool torque_headroom_given{false};
  double cone_margin{0.0};       ///< [rad] every cone kept with this angle to spare
  /// Whether the file gives cone_margin_deg: the planned mode derives it when not
  /// (docs/pet-erg.md, section 16.2); `attiguard plan` takes 0.
  bool cone_margin_given{false};
  int intervals{0};              ///< N (0: derived)
};

/// Everything a `pet_erg` run needs, validated (scenario::parse_pet_erg also checks the
/// admissibility of the initial state, PET-ERG paper Theorem 1): the user's quantities only.
/// What the governor runs with (reduced limits, wheel polytope, robust margin, tightened cones)
/// is derived from them by design_governor(sc), which the simulator calls at the start of a run.
struct PetErgScenario {
  std::string name;
  /// governor, [body], [control], [erg]: the user's parameters, the inputs of the governor's
  /// design (design_governor below; the simulator builds its governor from that design). Its
  /// robust and polytope_gamma_d are no inputs: scenario::parse_pet_erg copies the design's into
  /// them for the readers that predate governor::design (docs/architecture.md, "Where the
  /// configuration structs live"); nothing in sim/ reads them.
  governor::GovernorParams params;
  /// Which values of params the reader derived from the craft because the file leaves them out,
  /// with the scales they come from (docs/pet-erg.md, section 8); default-constructed (nothing
  /// derived) for a scenario built in code. governor_values(sc) is what `check` prints and
  /// summary.json records as `derived_defaults`.
  governor::DerivedGovernorValues derived;
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
  /// applied directly.
  std::vector<dynamics::ReactionWheel> wheels;
  /// [control] margins (docs/pet-erg.md, section 13): with "robust" the governor runs with the
  /// robust margin computed from `imperfections`' bounds, reduced torque limits and tightened
  /// cones (governor::design); `cones` stay the true constraints, on which margins are reported.
  governor::Margins margins{governor::Margins::nominal};
  double robust_reference_step{0.0};  ///< [control] robust_reference_step [rad] (0: derived)
  double duration{0.0};                       ///< [simulation] duration [s]
  double output_interval{0.0};                ///< [simulation] output_interval [s]
  double convergence_tolerance{1e-4};         ///< [simulation] convergence_tolerance: on φ(R_dᵀR)
  integrate::IntegratorSettings integrator;   ///< [simulation] integrator keys
  SlewPlanSettings plan;                      ///< [plan] (docs/slew-planner.md, "Options")
};

/// The craft's scales of `sc` the defaults derive from (docs/pet-erg.md, section 8): J, τ_max,
/// the wheel polytope's inscribed torque radius, the disturbance bound, the largest slew (R_0
/// through the schedule), the initial kinetic energy and the control period.
[[nodiscard]] governor::CraftScales craft_scales(const PetErgScenario& sc);

/// The torques the scenario's wheels apply unclipped within its τ_max (docs/pet-erg.md, section
/// 16.3, "Wheels"); count 0 without wheels. Set-up code (throws SetupError for an array the
/// reader would refuse).
[[nodiscard]] governor::TorqueSlabs wheel_slabs(const PetErgScenario& sc);

/// The values `sc` runs with and the craft's scales they relate to (docs/pet-erg.md, section 8):
/// governor::derive_governor_values with every value of sc.params given; which of them the reader
/// derived is taken from sc.derived. Throws SetupError as derive_governor_values.
[[nodiscard]] governor::DerivedGovernorValues governor_values(const PetErgScenario& sc);

/// The user's quantities of `sc` as the inputs of the governor's design (docs/pet-erg.md,
/// sections 12-13): sc.params, cones, wheels, control_period, margins, robust_reference_step and
/// the bounds of `imperfections` (disturbance bound, bias bounds, noises, delay, quantum).
[[nodiscard]] governor::GovernorDesignInputs design_inputs(const PetErgScenario& sc);

/// What the governor of a run is built with and reports: governor::design(design_inputs(sc))
/// [docs/pet-erg.md, sections 12-13]. Computed from the inputs on every call (set-up code: it
/// allocates; with robust margins it takes milliseconds). Throws SetupError as governor::design.
[[nodiscard]] governor::GovernorDesign design_governor(const PetErgScenario& sc);

}  // namespace attiguard::sim
