#pragma once
/// @file pet_erg_run.hpp
/// Simulation of the `pet_erg` scenario kind: the rigid body (1) under the PD law [PET-ERG eq. (3)] with the
/// [PET-ERG eqs. (5)-(6)], the continuous ERG [PET-ERG eq. (4)], or no governor (PET-ERG paper). The state
/// (R, R_g, ω) ∈ SO(3)² × R³ is integrated with the RKMK integrators, which stop exactly at every
/// sampling instant t_k = k·T_s where the trigger [PET-ERG eq. (5)] is evaluated and then held.

#include <functional>
#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "attiguard/governor/attitude_governor.hpp"
#include "attiguard/integrate/product_state.hpp"
#include "attiguard/io/row_sink.hpp"
#include "attiguard/sim/pet_erg_outcome.hpp"
#include "attiguard/sim/pet_erg_scenario.hpp"
#include "attiguard/sim/planned_figures.hpp"

namespace attiguard::sim {

/// (R_ib, R_g, ω_b): R[0] the attitude, R[1] the auxiliary reference, x the body rate.
using PetErgState = integrate::ProductState<2, 3>;

/// Called at t = 0 and at every output instant with the state, R_d(t) and the governor's view.
using PetErgRowObserver = std::function<void(double t, const PetErgState& y, const lie::Mat3& R_d,
                                             const governor::GovernorOutput& out)>;

/// Figures of one simulation (every "max"/"min" is over t = 0, every accepted integrator step
/// and every stop instant).
struct PetErgResult {
  /// What the governor flew with: governor::design of the scenario's inputs (sim::design_governor;
  /// docs/pet-erg.md, sections 12-13), whose figures summary.json reports.
  governor::GovernorDesign design;
  double gamma_d{0.0};           ///< Γ_d (certified lower bound)
  double gamma_d_upper{0.0};     ///< attained value bracketing the exact Γ_d from above
  double gamma_d_loose{0.0};     ///< closed-form bound on Γ_d
  double gamma_cap{0.0};         ///< the cap k_p(2 − ε_Γ) of Γ
  double gamma_g_initial{0.0};   ///< Γ_g(R_g(0)) (+∞ without cones)
  double gamma_initial{0.0};     ///< Γ(R_g(0))
  double V_initial{0.0};         ///< V(R_0, ω_0, R_g(0))
  double max_torque_norm{0.0};
  double min_pointing_margin{0.0};  ///< min over time and cones of a_cᵀ R a_b − cos θ_c (+∞: none)
  std::vector<double> min_margin_per_cone;
  double first_pointing_violation_time{-1.0};  ///< first step with a margin < 0, −1 if none
  double max_V_minus_Gamma{0.0};  ///< max of V − Γ(R_g) (R_g = R_d in mode none)
  double final_attitude_error{0.0};   ///< φ(R_dᵀR) at the end
  double final_reference_error{0.0};  ///< φ(R_dᵀR_g) at the end
  double final_omega_norm{0.0};
  /// Earliest time from which φ(R_d(t)ᵀR(t)) ≤ the scenario's convergence_tolerance at every
  /// later step up to the end; −1 when the end is not within the tolerance.
  double convergence_time{-1.0};
  PetErgOutcome outcome{PetErgOutcome::not_converged_by_end};  ///< docs/pet-erg.md, "Outcomes"
  double reference_distance_left{0.0};  ///< d(R_g, R_d) at the end [rad] (0 in mode none)
  ReferenceMotion reference_motion;     ///< R_g over the last half of the run
  std::vector<int> active_cones;        ///< cones with c(R_g) < ζ at the end (repulsive band)
  double slew_angle{0.0};               ///< d(R_0, final R_d) [rad]
  double eigenaxis_bang_bang_time{0.0};  ///< of that slew at τ_max (dynamics/eigenaxis_slew.hpp)
  /// With wheels: the same at the torque they apply unclipped along J k within τ_max (the
  /// craft's own bang-bang time; governor/torque_slabs.hpp); 0 without wheels
  double wheel_bang_bang_time{0.0};
  /// Wheels (docs/pet-erg.md, section 12): max over the control instants of |(A⁺τ_cmd)_i| /
  /// u_max,i (> 1: the allocation demanded more than a wheel gives, the command was clipped) …
  double max_wheel_torque_ratio{0.0};
  /// … and max over the steps of |h_i| / h_max,i; the momenta at the end [N·m·s].
  double max_wheel_momentum_ratio{0.0};
  std::vector<double> final_wheel_momentum;
  /// Saddle tie-breaks started (docs/pet-erg.md, section 4, "Saddles: the tie-break"), the time
  /// of the first (−1 if none) and the cones they went around (distinct, in the order met).
  long saddle_tie_breaks{0};
  double first_tie_break_time{-1.0};
  std::vector<int> tie_break_cones;
  long samples{0};           ///< sampling instants at which (5) was evaluated (mode pet)
  long samples_updating{0};  ///< of which the condition held
  long steps{0};
  long rejected_steps{0};
  long evaluations{0};
  long output_rows{0};  ///< rows emitted into a sink (record_pet_erg)
  /// governor = "planned" only: the plan, gains, margins and the progress (docs/pet-erg.md,
  /// section 16.2).
  std::optional<PlannedFigures> planned;
};

/// Simulates (1) under [PET-ERG eq. (3)] with the update [PET-ERG eq. (4)], [PET-ERG eqs. (5)-(6)] or none (PET-ERG paper) without any
/// file output; `on_output` (optional) receives t = 0 and every
/// output instant. Throws NumericalError on divergence.
[[nodiscard]] PetErgResult simulate_pet_erg(const PetErgScenario& sc,
                                            const PetErgRowObserver& on_output = {});

/// simulate_pet_erg with one row per output instant emitted into `rows` (columns t, q_w..q_z,
/// omega_x..z, tau_x..z, tau_norm, qg_w..qg_z, qd_w..qd_z, V, gamma_d, gamma_g, gamma, trigger,
/// attitude_error, reference_error, margin_0..: docs/scenario-format.md, "pet_erg", "Outputs").
[[nodiscard]] PetErgResult record_pet_erg(const PetErgScenario& sc, io::RowSink& rows);

/// summary.json's `planned` object of the planned mode (docs/pet-erg.md, section 16.2,
/// "Outputs"): the plan, the tracking gains, headroom and cone margin, the clock's figures and
/// `convergence_time_over_plan` (null when `convergence_time` < 0). Also each slew of a planned
/// mission (docs/mission.md, "Planned slews").
[[nodiscard]] nlohmann::json planned_figures_json(const PlannedFigures& f, double convergence_time);

/// The summary.json object of a PET-ERG run (PET-ERG paper, Sec. V figures; keys:
/// docs/scenario-format.md, section "pet_erg"), without wall_time_s.
[[nodiscard]] nlohmann::json pet_erg_summary(const PetErgScenario& sc, const PetErgResult& result);

}  // namespace attiguard::sim
