#pragma once
/// @file governor_design.hpp
/// The governor's design (docs/pet-erg.md, sections 12-13): the offline step that turns the
/// user's quantities — inertia, gains, κ and the other GovernorParams, the torque limit, the
/// reaction wheels, the cones, the bounds on the flight loop's imperfections, the choice of
/// nominal or robust margins and the flight-loop period — into what AttitudeGovernor runs with:
/// its GovernorParams (the reduced torque limits, the wheel polytope's Γ_d, the robust margin, the
/// bounded step), the cones it enforces (tightened with robust margins) and the derived figures a
/// run reports. Set-up code: it allocates and throws SetupError (core/errors.hpp) with a one-line
/// reason; nothing here runs per step.
///
///   const GovernorDesign d = design(inputs);      // once, offline
///   AttitudeGovernor gov(d.params, d.cones);      // then the flight loop as usual

#include <vector>

#include "attiguard/core/name_table.hpp"
#include "attiguard/dynamics/reaction_wheel_array.hpp"
#include "attiguard/governor/attitude_governor.hpp"
#include "attiguard/governor/cone_constraint.hpp"
#include "attiguard/governor/robust_margin.hpp"

namespace attiguard::governor {

/// Which safety margins the governor keeps (docs/pet-erg.md, section 13).
enum class Margins {
  nominal,  ///< the PET-ERG paper's thresholds, which ignore the flight loop's imperfections
  robust,   ///< robust margins: every sublevel set in use is invariant under the bounded errors
};

/// Names of Margins in scenario files (`[control] margins = "robust"`), summaries and the Python
/// bindings (docs/scenario-format.md, "pet_erg").
inline constexpr NameTable<Margins, 2> kMarginsNames{
    {{{Margins::nominal, "nominal"}, {Margins::robust, "robust"}}}};

/// The bounds on the flight loop's imperfections the robust margins assume (docs/pet-erg.md,
/// section 13, "Assumptions"); unused with the nominal margins.
struct ImperfectionBounds {
  double disturbance{0.0};     ///< d̄ ≥ ‖d(t)‖, the disturbance torque [N·m]
  double attitude_bias{0.0};   ///< β ≥ ‖attitude bias‖ [rad] (tightens the cones)
  double attitude_noise{0.0};  ///< σ_n ≥ the attitude noise angle [rad]
  double rate_bias{0.0};       ///< ≥ ‖rate bias‖ [rad/s]
  double rate_noise{0.0};      ///< ≥ ‖rate noise‖ [rad/s]
  int delay_periods{0};        ///< 0 or 1: the torque computed at t_k is applied from t_{k+d}
  double torque_quantum{0.0};  ///< q [N·m] of the command quantiser (0: none)
};

/// The user's quantities the governor is designed from (docs/pet-erg.md, sections 10-13).
struct GovernorDesignInputs {
  /// mode, gains k_p/k_d, J, τ_max, κ, c_Γ, T_s, ε, ε_Γ of the PET-ERG paper. Its robust,
  /// polytope_gamma_d and bounded_step are outputs of the design: their values here are ignored.
  GovernorParams params;
  std::vector<ConeConstraint> cones;           ///< the true pointing constraints [PET-ERG eq. (2b)]
  std::vector<dynamics::ReactionWheel> wheels;  ///< empty: the body torque is applied directly
  double control_period{0.0};  ///< flight-loop period h [s]; 0: the continuous-time loop
  Margins margins{Margins::nominal};
  ImperfectionBounds bounds;   ///< with margins = robust
  /// Cap Δ_max on one move of R_g with robust margins and one period of delay [rad]; 0: derived
  /// (RobustMarginInputs::max_reference_step).
  double max_reference_step{0.0};
};

/// The wheel polytope {|r_iᵀτ| ≤ u_max,i} of the pseudo-inverse allocation at the wheels' own
/// limits (docs/pet-erg.md, section 12).
struct WheelPolytope {
  double gamma_d{0.0};        ///< its Γ_d (certified lower bound); 0 without wheels
  double gamma_d_upper{0.0};  ///< attained value above the exact Γ_d
  int binding{-1};            ///< the wheel whose limit binds Γ_d (-1 without wheels)
};

/// What the governor runs with, and the derived figures a run reports (docs/pet-erg.md,
/// sections 12-13).
struct GovernorDesign {
  /// The parameters to construct AttitudeGovernor with: bounded_step in the flight loop, the
  /// wheel polytope's Γ_d, and with robust margins the robust margin and the torque limits
  /// reduced by its command error.
  GovernorParams params;
  /// The cones the governor enforces: the inputs' cones, or with robust margins each tightened
  /// by the attitude bias bound with its repulsive band moved inwards as Γ_min needs.
  std::vector<ConeConstraint> cones;
  WheelPolytope wheels;             ///< at the wheels' own limits (the nominal polytope)
  double tau_max_reduced{0.0};      ///< robust: τ_max − e_cmd (0 with the nominal margins)
  /// robust with wheels: Γ_d of the polytope with each u_max,i − ‖r_i‖ e_cmd (else 0)
  double wheel_gamma_d_reduced{0.0};
};

/// The wheel polytope's Γ_d at the wheels' own limits [docs/pet-erg.md, section 12]: the minimum
/// over the slabs of compute_polytope_torque_threshold. All zero without wheels. Throws
/// SetupError when wheels are given without the flight loop (control_period ≤ 0), for an array
/// ReactionWheelArray refuses, or when the polytope's Γ_d cannot be computed.
[[nodiscard]] WheelPolytope wheel_polytope(const GovernorDesignInputs& in);

/// The bounds of the flight loop, the imperfections and the wheels that the robust margins take
/// (docs/pet-erg.md, section 13, "Assumptions"): sensors, quantum, disturbance, delay, the
/// applied torque's bound and ‖A h‖ ≤ σ_max(A)‖h_max‖ of the wheels. The gains k_p, k_d and
/// Γ_top are left for the caller.
[[nodiscard]] RobustMarginInputs margin_inputs(const GovernorDesignInputs& in);

/// The governor's design [docs/pet-erg.md, sections 12-13]: wheel_polytope, then with robust
/// margins the command error e_cmd, the reduced torque limits, the robust margin of
/// compute_robust_margin and the tightened cones. Throws SetupError with the reason (the messages
/// of docs/errors.md) when an input is refused or the bounds leave no admissible set: robust
/// margins without the flight loop or without a governor, a command error reaching a torque limit,
/// Γ_min ≥ (1 − δ) Γ_d', or a cone that leaves no attitude Γ_min deep inside it.
[[nodiscard]] GovernorDesign design(const GovernorDesignInputs& in);

}  // namespace attiguard::governor
