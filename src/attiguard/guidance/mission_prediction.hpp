#pragma once
/// @file mission_prediction.hpp
/// The mission-time and Δv prediction of the waypoint guidance (docs/waypoint.md, "Prediction";
/// issue 25): every leg of the state machine of waypoint_sequencer.hpp flown by its own rules on
/// a reduced model — the turns (align, flip) as the eigenaxis slew of the attitude PID
/// [Waypoint eq. (27)] about the heaviest axis at the wheel limit, the acceleration (13), coast,
/// flip and braking curve [Waypoint eqs. (14)-(16)] along the line of the leg, and the RCT phase
/// [Waypoint eqs. (28)-(30)] along its switching line. Set-up code (check, summary.json): it
/// allocates; it is not in the flight loop.

#include <functional>
#include <span>
#include <vector>

#include "attiguard/control/quaternion_pid.hpp"
#include "attiguard/guidance/waypoint_sequencer.hpp"

namespace attiguard::guidance {

/// The time of one attitude turn of the mission, from the steady attitude R_from_ib to R_to_ib
/// (both at rest), until the pointing error is within the guidance's pointing tolerance [s]
/// (docs/mission.md, "Prediction"). Set-up code: may allocate and simulate.
using TurnTimeModel = std::function<double(const lie::Mat3& R_from_ib, const lie::Mat3& R_to_ib)>;

/// What the prediction needs besides the mission parameters.
struct PredictionCraft {
  double J_max{20.0};             ///< largest principal inertia [kg·m²]
  double max_wheel_torque{0.0};   ///< per-axis wheel limit, 0 = none [N·m]
  double control_period{0.1};     ///< T_s [s]
  control::QuaternionPidGains gains{};  ///< the attitude PID flown [Waypoint eq. (27)]
  /// The turns' model: empty = predicted_turn_time with `gains` (kind waypoint); kind mission
  /// sets the governed slew of its attitude loop (sim/mission_prediction.hpp).
  TurnTimeModel turn_time{};
};

/// The start of the mission.
struct PredictionStart {
  Vec3 p_i{Vec3::Zero()};    ///< position [m]
  Vec3 v_i{Vec3::Zero()};    ///< velocity [m/s]
  lie::Mat3 R_ib{lie::Mat3::Identity()};  ///< attitude; its first column is the thrust axis x_b
};

/// The predicted leg (docs/waypoint.md, "Prediction").
struct LegPrediction {
  double time{0.0};          ///< from the previous waypoint's arrival (or t = 0) to this one [s]
  double delta_v{0.0};       ///< main engine + RCT [m/s]
  double turn_time{0.0};     ///< align and flip (and the pre-brake turn of a lateral start) [s]
  double fine_time{0.0};     ///< the RCT-only phase [s]
  double peak_speed{0.0};    ///< closing speed at the end of the acceleration [m/s]
  bool rct_only{false};      ///< flown by fine control alone (a leg inside half the re-plan distance)
};

/// The predicted mission: its legs and totals.
struct MissionPrediction {
  std::vector<LegPrediction> legs;
  double time{0.0};       ///< Σ legs [s]
  double delta_v{0.0};    ///< Σ legs [m/s]
};

/// Time of an eigenaxis slew of `angle` rad from rest with the PID of `craft` until the pointing
/// error sin(θ/2) is below `tolerance` (docs/waypoint.md, "Prediction"): J_max θ̈ =
/// sat_τw(−k_p sin(θ/2) − ½ k_d cos(θ/2) θ̇) sampled at the control period (shaped or scalar gains:
/// the heaviest axis is the slowest). Capped at 10⁶ samples of the reduced model [s].
[[nodiscard]] double predicted_turn_time(const PredictionCraft& craft, double angle, double tolerance) noexcept;

/// Predicted RCT-only phase [Waypoint eqs. (28)-(30)] from distance `distance` and speed `speed`
/// (towards the waypoint) with the thrusters at a_rct = f_max/m: full thrust until the switching
/// line v = λe (λ = κ_p/κ_d), then the slide e(t) = e₁ exp(−λt) down to the position accuracy;
/// with κ_p = 0, the speed alone is nulled. Returns {time [s], Δv [m/s]}.
struct FinePhase {
  double time{0.0};
  double delta_v{0.0};
};
[[nodiscard]] FinePhase predicted_fine_phase(const MissionParams& p, double distance, double speed) noexcept;

/// The prediction of a whole mission (docs/waypoint.md, "Prediction"): each leg's turn to the
/// line of sight, acceleration by (13) to min(V_d, the acceleration fraction, the braking point),
/// coast, half-turn flip, braking along the curve of (16) at γ T_max/m down to the hand-over,
/// and the fine phase; legs the sequencer gives to the RCT alone are predicted as such. The
/// turns are between the steady attitudes of guidance/leg_attitudes.hpp (the shortest arc that
/// points x_b along the leg, then π about z_b for the flip), timed by craft.turn_time when set.
[[nodiscard]] MissionPrediction predict_mission(const MissionParams& p, const PredictionCraft& craft,
                                                const PredictionStart& start,
                                                std::span<const Vec3> waypoints_i);

}  // namespace attiguard::guidance
