#pragma once
/// @file waypoint_run.hpp
/// Simulation of the `waypoint` scenario kind [Waypoint Sec. VI]: the plant [Waypoint eqs. (2)-(5)] on
/// SO(3) × R⁹ with the RKMK integrators, the mission state machine and its controllers sampled
/// every control period with zero-order hold of every command (main thruster, RCT, torque).

#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "attiguard/dynamics/spacecraft_plant.hpp"
#include "attiguard/guidance/waypoint_sequencer.hpp"
#include "attiguard/io/row_sink.hpp"
#include "attiguard/sim/waypoint_scenario.hpp"

namespace attiguard::sim {

/// Result for one waypoint (summary.json `waypoints[k]` and `legs[k]`).
struct WaypointResult {
  int index{0};
  bool reached{false};
  double arrival_time{0.0};           ///< time of the accuracy_met transition [s]
  double final_position_error{0.0};   ///< ‖e‖ then (or at the end of the run) [m]
  double final_speed{0.0};            ///< ‖v‖ then [m/s]
  double delta_v_main{0.0};           ///< ∫T/m over the leg [m/s]
  double delta_v_rct{0.0};            ///< ∫Σ f_j/m over the leg [m/s]
  double peak_speed{0.0};             ///< max ‖v‖ over the leg [m/s]
  [[nodiscard]] double delta_v() const noexcept { return delta_v_main + delta_v_rct; }
};

/// One logged mode transition.
struct TransitionRecord {
  double t{0.0};
  int waypoint{0};
  guidance::Mode from{guidance::Mode::align};
  guidance::Mode to{guidance::Mode::align};
  guidance::TransitionReason reason{guidance::TransitionReason::none};
};

/// Result of a simulation.
struct WaypointSimResult {
  std::vector<WaypointResult> waypoints;
  std::vector<TransitionRecord> transitions;
  bool completed{false};       ///< every waypoint reached within the duration
  double total_time{0.0};      ///< time at the end of the run [s]
  double max_torque_norm{0.0};  ///< max ‖τ_b‖ applied [N·m]
  long steps{0};               ///< accepted integrator steps
  long samples{0};             ///< controller samples
  bool finite{true};           ///< every state and command finite
  /// The state of the guidance at the end of the run (for the outcome, waypoint_outcome()).
  guidance::Mode final_mode{guidance::Mode::align};
  int final_waypoint{0};        ///< active waypoint at the end (= count when done)
  double final_distance{0.0};   ///< ‖e‖ to the active waypoint at the end [m]
  double final_speed{0.0};      ///< ‖v‖ at the end [m/s]
  double final_closing_speed{0.0};  ///< ê·v at the end [m/s] (< 0: moving away)
  int replans{0};               ///< re-plans and overshoots (a leg restarted or braked off)
};

/// The honest end of a flight (docs/waypoint.md, "Outcome"): `completed`, or `incomplete` with
/// one sentence naming why (time out while moving away, fine control short of its accuracy,
/// repeated re-plans, …) and the distance and speed left.
struct WaypointOutcome {
  bool completed{false};
  std::string reason;  ///< empty when completed
  [[nodiscard]] const char* value() const noexcept { return completed ? "completed" : "incomplete"; }
};

/// The outcome of a waypoint flight (Waypoint paper, Algorithm 1's termination, judged).
[[nodiscard]] WaypointOutcome waypoint_outcome(const WaypointScenario& sc, const WaypointSimResult& res);

/// Called at every control sample with the state and the command computed there.
using SampleObserver =
    std::function<void(double t, const dynamics::SpacecraftState& y, const guidance::MissionCommand& cmd)>;

/// Simulates the scenario; stops when the mission is done or at the duration. Throws
/// NumericalError on divergence of the integrator.
/// Replaces the attitude part of a sample's command before it is applied (the `mission` kind:
/// the PET-ERG turns the guidance's R_d into the torque, sim/mission_run.cpp).
using CommandFilter =
    std::function<void(double t, const dynamics::SpacecraftState& y, guidance::MissionCommand& cmd)>;

/// Simulates Algorithm 1 of the Waypoint paper on the plant [Waypoint eqs. (3)-(5)]; `filter`, when set, may
/// change each sample's command (torque, thrust) before the observer sees it and it is applied.
[[nodiscard]] WaypointSimResult simulate_waypoint(const WaypointScenario& sc,
                                                  const SampleObserver& observer = {},
                                                  const CommandFilter& filter = {});

/// simulate_waypoint with the trajectory rows emitted into `rows`: one row every
/// output_interval (rounded to control samples), at every mode transition and at the end
/// (columns t, p_x..p_z, v_x..v_z, q_w..q_z, omega_x..omega_z, tau_x..tau_z, thrust,
/// rct_1..rct_6, mode, waypoint). Throws NumericalError when a state or command is not finite
/// (after emitting the rows).
[[nodiscard]] WaypointSimResult record_waypoint(const WaypointScenario& sc, io::RowSink& rows);

/// The summary.json object of a waypoint run (Waypoint paper, Sec. VI figures; keys:
/// docs/scenario-format.md, section "waypoint"), without wall_time_s.
[[nodiscard]] nlohmann::json waypoint_summary(const WaypointScenario& sc,
                                              const WaypointSimResult& res);

}  // namespace attiguard::sim
