#pragma once
/// @file mission_run.hpp
/// Runs a `mission` scenario: the waypoint guidance [Waypoint Alg. 1] with its desired
/// attitude R_d(t) passed through the PET-ERG (PD law [PET-ERG eq. (3)] and [PET-ERG eqs. (5)-(6)]); thrust only
/// when the governed reference R_g is aligned with R_d. The same mission is also flown with the
/// other setting of the governor (the unconstrained twin, `governor = "none"`, or the PET-ERG when
/// the scenario itself is unconstrained) so the summary gives the cost of the constraints.


#include <atomic>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "attiguard/io/row_sink.hpp"
#include "attiguard/sim/mission_scenario.hpp"
#include "attiguard/sim/mission_slews.hpp"
#include "attiguard/sim/waypoint_run.hpp"

namespace attiguard::sim {

/// One flight of the mission and its constraint figures.
struct MissionResult {
  WaypointSimResult flight;          ///< waypoints, transitions, completion, steps
  double min_pointing_margin{0.0};   ///< min over samples and cones of a_cᵀ R a_b − cos θ_c, (2b)
  double first_pointing_violation_time{-1.0};  ///< first sample with a margin < 0, −1 if none
  double max_torque_norm{0.0};       ///< max over samples of ‖τ‖ applied [N·m], cf. (2a)
  long torque_violations{0};         ///< samples with ‖τ‖ > τ_max (1e-9 relative tolerance)
  long thrust_gated{0};              ///< samples whose thrust was withheld: R_g not aligned with R_d
  /// The numerical failure that ended this flight (NumericalError's message), empty if none:
  /// the other flight's results are still reported (docs/mission.md, "Outcome").
  std::string failure;
  /// governor = "planned": the attitude slews, each planned at its start (docs/mission.md,
  /// "Planned slews"); empty in the other modes.
  std::vector<MissionSlew> slews;
  /// Δv of the flight: Σ over waypoints of ∫T/m + ∫Σf_j/m [Waypoint eq. (5)] [m/s].
  [[nodiscard]] double delta_v() const noexcept;
};

/// Sees each control sample with the guidance command and the governor's output.
using MissionObserver = std::function<void(double t, const dynamics::SpacecraftState& y,
                                           const guidance::MissionCommand& cmd,
                                           const governor::GovernorOutput& gov)>;

/// The planned mission's view of a control sample: the observer's, with the slew being flown.
using PlannedMissionObserver =
    std::function<void(double t, const dynamics::SpacecraftState& y, const guidance::MissionCommand& cmd,
                       const governor::GovernorOutput& gov, const MissionSlewState& slew)>;

/// Flies the mission with the governor in `mode` ([PET-ERG eqs. (3)-(6)] on the Waypoint paper's
/// Algorithm 1; `planned`: each slew planned at its start and flown by the planned mode,
/// docs/mission.md, "Planned slews"); `observer` sees each sample with the governor's output. Once `stop` is set and
/// true (the interruption flag of a run that writes files), the flight ends at its next control
/// step with io::Interrupted, which is never recorded as the flight's failure (docs/mission.md,
/// "Outcome").
[[nodiscard]] MissionResult simulate_mission(const MissionScenario& sc,
                                             governor::GovernorMode mode,
                                             const MissionObserver& observer = {},
                                             const std::atomic<bool>* stop = nullptr);

/// simulate_mission in mode `planned` with the slew being flown at each sample
/// (docs/mission.md, "Planned slews").
[[nodiscard]] MissionResult simulate_planned_mission(const MissionScenario& sc,
                                                     const PlannedMissionObserver& observer = {},
                                                     const std::atomic<bool>* stop = nullptr);

/// The scenario's own flight and its twin (the other setting of the governor).
struct MissionFlights {
  governor::GovernorMode mode{governor::GovernorMode::pet};       ///< the scenario's governor
  governor::GovernorMode twin_mode{governor::GovernorMode::none};  ///< none, or pet when mode is none
  MissionResult own;
  MissionResult twin;
};

/// Flies the scenario (its trajectory rows emitted into `rows`: t, p_x..p_z, v_x..v_z,
/// q_w..q_z, omega_x..omega_z, tau_x..tau_z, tau_norm, thrust, mode, waypoint, qg_w..qg_z,
/// qd_w..qd_z, trigger, min_margin; with governor = "planned" also slew, s, s_dot,
/// docs/mission.md, "Planned slews") and its twin ([PET-ERG eqs. (3)-(6)] on the Waypoint paper's
/// Algorithm 1). Throws NumericalError when a state or command is not finite, io::Interrupted
/// at the next control step of either flight once `stop` is set and true.
[[nodiscard]] MissionFlights record_mission(const MissionScenario& sc, io::RowSink& rows,
                                            const std::atomic<bool>* stop = nullptr);

/// The outcome of one flight of a mission: that of its waypoint flight (waypoint_outcome()), or
/// the numerical failure that ended it, or, when the governor withheld the thrust, "stalled by
/// the constraints" with the count of gated samples.
[[nodiscard]] WaypointOutcome mission_outcome(const MissionScenario& sc, const MissionResult& r);

/// The summary.json object of a mission (docs/mission.md, "Outputs"), without wall_time_s.
/// `time_cost` / `delta_v_cost` are null unless both flights completed.
[[nodiscard]] nlohmann::json mission_summary(const MissionScenario& sc, const MissionFlights& f);

}  // namespace attiguard::sim
