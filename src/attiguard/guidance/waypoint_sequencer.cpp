#include "attiguard/guidance/waypoint_sequencer.hpp"

#include <algorithm>
#include <cmath>

#include "attiguard/guidance/rct_transfer.hpp"
#include "attiguard/guidance/thrust_laws.hpp"
#include "attiguard/lie/shortest_arc.hpp"

namespace attiguard::guidance {

const char* mode_name(Mode mode) noexcept {
  switch (mode) {
    case Mode::align: return "align";
    case Mode::accelerate: return "accelerate";
    case Mode::coast: return "coast";
    case Mode::flip: return "flip";
    case Mode::decelerate: return "decelerate";
    case Mode::fine: return "fine";
    case Mode::done: return "done";
    case Mode::brake: return "brake";
    case Mode::rct_transfer: return "rct_transfer";
  }
  return "?";
}

const char* reason_name(TransitionReason reason) noexcept {
  switch (reason) {
    case TransitionReason::none: return "none";
    case TransitionReason::pointing_reached: return "pointing_reached";
    case TransitionReason::acceleration_done: return "acceleration_done";
    case TransitionReason::cruise_speed_reached: return "cruise_speed_reached";
    case TransitionReason::flip_point: return "flip_point";
    case TransitionReason::arrival_sphere: return "arrival_sphere";
    case TransitionReason::main_cutoff_speed: return "main_cutoff_speed";
    case TransitionReason::closest_approach: return "closest_approach";
    case TransitionReason::accuracy_met: return "accuracy_met";
    case TransitionReason::speed_left: return "speed_left";
    case TransitionReason::braked: return "braked";
    case TransitionReason::replan: return "replan";
    case TransitionReason::overshoot: return "overshoot";
    case TransitionReason::lateral_speed: return "lateral_speed";
    case TransitionReason::handover: return "handover";
  }
  return "?";
}

WaypointSequencer::WaypointSequencer(const MissionParams& params,
                                     const control::QuaternionPidGains& gains,
                                     std::span<const Vec3> waypoints_i) noexcept
    : params_(params), pid_(gains), waypoints_(waypoints_i) {
  if (waypoints_.empty()) {
    mode_ = Mode::done;
  }
}

GuidanceFrameSpec WaypointSequencer::frame_spec() const noexcept {
  GuidanceFrameSpec spec;
  spec.e_floor = params_.e_floor;
  spec.projection_params = params_.projection;
  const bool reversed = mode_ == Mode::flip || mode_ == Mode::decelerate;
  spec.q_ir = reversed ? chart_decel_ : chart_accel_;
  spec.error_sign = reversed ? -1.0 : 1.0;
  spec.projection = reversed && params_.velocity_projection;
  spec.projection_sign = -1.0;
  return spec;
}

Quat WaypointSequencer::continuous_q_ib(const lie::Mat3& R_ib) const noexcept {
  // The quaternion of [Waypoint eq. (4)] evolves continuously; rotation_to_quat picks η ≥ 0, so restore the
  // sign nearest the previous sample. (27) is not invariant under q → −q: a sign jump would
  // reverse the proportional term.
  const Quat q = lie::rotation_to_quat(R_ib);
  return q.dot(q_ib_) < 0.0 ? Quat(-q) : q;
}

void WaypointSequencer::start_leg(const MissionInputs& in) noexcept {
  const Vec3 e_i = waypoints_[static_cast<std::size_t>(index_)] - in.p_i;
  leg_distance_ = e_i.norm();
  // Chart: the current attitude turned by the shortest arc from x_b to ê, so that aligning
  // needs no roll and ϑ starts at 0 (the parallel case of [Waypoint eq. (11)], handled smoothly).
  const Vec3 x_i = in.R_ib.col(0);
  chart_accel_ = lie::quat_multiply(lie::shortest_arc_quat(x_i, e_i), q_ib_);
  // Sign of the chart such that η_{d,b} ≥ 0: the PID [Waypoint eq. (27)] then takes the short way round.
  if (control::attitude_error(chart_accel_, q_ib_)(0) < 0.0) {
    chart_accel_ = -chart_accel_;
  }
  chart_decel_ = chart_accel_;
  // A leg inside half the re-plan distance, started slowly enough for the RCT, is flown by fine
  // control (28) alone: the main engine's speed quantum is too coarse for it.
  const bool rct_leg = params_.rct.kappa_p > 0.0 && leg_distance_ <= 0.5 * params_.replan_distance &&
                       !brake_needed(in.v_i.norm());
  mode_ = leg_distance_ <= params_.arrival_radius || rct_leg ? Mode::fine : Mode::align;
  // Beyond the paper: the RCT fly such a leg near time-optimally (fine control only what the
  // transfer cannot resolve), unless the accuracies already hold (a zero-length leg): fine
  // control then ends the leg at the next sample without a pulse.
  const bool met = leg_distance_ < params_.position_accuracy && in.v_i.norm() < params_.speed_accuracy;
  if (mode_ == Mode::fine && rct_leg && params_.rct_transfer && leg_distance_ > params_.arrival_radius && !met) {
    mode_ = Mode::rct_transfer;
    q_hold_ = q_ib_;  // attitude held as it is: the line of sight keeps its RCT acceleration
    return;
  }
  q_hold_ = chart_accel_;
}

void WaypointSequencer::enter(Mode next, const MissionInputs& in) noexcept {
  if (next == Mode::flip) {
    // Reversed error frame (Fig. 1(b)): the current error frame turned by π about its z axis,
    // so the reversed vector starts on the chart's x axis (ϑ = 0) and not at ϑ = π.
    GuidanceFrameSpec spec = frame_spec();
    const Vec3 e_i = waypoints_[static_cast<std::size_t>(index_)] - in.p_i;
    const ErrorFrame ef = error_frame(spec.q_ir, e_i, -in.v_i, params_.e_floor);
    chart_decel_ = lie::quat_multiply(ef.q_ie, Quat(0.0, 0.0, 0.0, 1.0));
  }
  if (next == Mode::fine) {
    q_hold_ = q_last_;
  }
  mode_ = next;
  if (next == Mode::align) {
    start_leg(in);
  }
}

namespace {

/// What the transitions of one sample are decided on (docs/waypoint.md, "State machine").
struct LegMeasures {
  Vec3 e_i;                  ///< p_wp − p_i [m]
  double dist;               ///< ‖e_i‖ [m]
  double speed;              ///< ‖v_i‖ [m/s]
  double closing;            ///< closing speed ê·v_i [m/s]
  double lateral;            ///< speed across the line of sight [m/s]
  bool accel_distance_done;  ///< the acceleration fraction of the leg flown
  bool flip_due;             ///< braking, flip included, must begin now
  bool brake_needed;         ///< more speed than the RCT can take back
};

/// The measures of a sample towards waypoint `p_wp` on a leg of length `leg_distance`; the
/// caller sets brake_needed.
LegMeasures measure_leg(const MissionParams& p, const Vec3& p_wp, const MissionInputs& in,
                        double leg_distance) noexcept {
  LegMeasures m{};
  m.e_i = p_wp - in.p_i;
  m.dist = m.e_i.norm();
  m.speed = in.v_i.norm();
  m.closing = closing_speed(m.e_i, in.v_i);
  m.accel_distance_done = m.dist < (1.0 - p.acceleration_fraction) * leg_distance;
  // The flip must start flip_lead_time before braking must begin: the predicted stopping
  // distance at the closing speed (not ‖v‖: lateral or receding motion does not bring the
  // craft closer) plus the distance flown during the flip.
  m.flip_due = m.closing > 0.0 && m.dist - stopping_distance(m.closing, p) <= m.closing * p.flip_lead_time;
  m.lateral = m.dist > 0.0 ? (in.v_i - m.e_i * (m.e_i.dot(in.v_i) / (m.dist * m.dist))).norm() : 0.0;
  return m;
}

/// The transition to `mode` for `reason`.
TransitionReason go_to(Mode mode, TransitionReason reason, Mode& next) noexcept {
  next = mode;
  return reason;
}

/// The transition to `after` for `reason`, or to brake first when the speed is too high for
/// the RCT (reason speed_left).
TransitionReason brake_first_or(const LegMeasures& m, Mode after, TransitionReason reason,
                                Mode& next) noexcept {
  if (m.brake_needed) return go_to(Mode::brake, TransitionReason::speed_left, next);
  return go_to(after, reason, next);
}

/// Moving away from the waypoint (or past it) while not braking: re-plan, never coast away;
/// brake first when the speed is too high for the RCT.
TransitionReason overshoot_to(const LegMeasures& m, Mode after_slow, Mode& next) noexcept {
  next = m.brake_needed ? Mode::brake : after_slow;
  return TransitionReason::overshoot;
}

/// Speed across the line of sight that thrust along ê cannot take out: brake to rest first.
bool lateral_too_fast(const MissionParams& p, const LegMeasures& m) noexcept {
  return p.brake_speed > 0.0 && m.lateral > std::max(p.brake_speed, 0.25 * p.cruise_speed);
}

/// Mode accelerate: to coast at the end of the acceleration distance or at the cruise speed.
TransitionReason accelerate_transition(const MissionParams& p, const LegMeasures& m,
                                       Mode& next) noexcept {
  // Acceleration also ends when the flip is already due: on a short leg (a re-plan, or a
  // fast start) the fraction rule alone would leave no room to flip and brake.
  if ((m.accel_distance_done && m.closing > 0.0) || m.flip_due) {
    return go_to(Mode::coast, TransitionReason::acceleration_done, next);
  }
  if (m.closing > p.cruise_speed) return go_to(Mode::coast, TransitionReason::cruise_speed_reached, next);
  return TransitionReason::none;
}

/// Mode coast: to flip at the flip point (FlipTiming), or re-plan when not closing.
TransitionReason coast_transition(const MissionParams& p, const LegMeasures& m, Mode& next) noexcept {
  if (!(m.closing > 0.0)) return overshoot_to(m, Mode::align, next);
  const bool flip = m.flip_due || (p.flip_timing == FlipTiming::immediate && m.accel_distance_done);
  if (flip) return go_to(Mode::flip, TransitionReason::flip_point, next);
  return TransitionReason::none;
}

/// Mode flip: passed the waypoint (or drifting away) before the flip is over: the reversed
/// error direction would swing through π; brake against v or hand over to fine control.
TransitionReason flip_transition(const MissionParams& p, const LegMeasures& m, Mode& next) noexcept {
  if (!(m.closing > 0.0) && m.dist > p.arrival_radius) return overshoot_to(m, Mode::fine, next);
  if (m.dist <= p.arrival_radius) return brake_first_or(m, Mode::fine, TransitionReason::arrival_sphere, next);
  return TransitionReason::none;
}

/// Mode decelerate: to fine control in the arrival sphere, at the main cut-off speed or at the
/// closest approach.
TransitionReason decelerate_transition(const MissionParams& p, const LegMeasures& m,
                                       const Vec3& v_i, Mode& next) noexcept {
  // Hand over to the RCT only at a speed they can remove (brake_speed); faster, keep braking
  // with (16), which fires harder the closer the waypoint.
  if (m.dist <= p.arrival_radius && !m.brake_needed) {
    return go_to(Mode::fine, TransitionReason::arrival_sphere, next);
  }
  if (m.speed <= p.main_cutoff_speed) return go_to(Mode::fine, TransitionReason::main_cutoff_speed, next);
  // Closest approach: the angle between e and v reaches acos(c_full), where the velocity
  // projection starts to fade out (e·v = 0 exactly at the closest approach).
  if (m.e_i.dot(v_i) <= p.projection.cos_full * m.dist * m.speed) {
    return brake_first_or(m, Mode::fine, TransitionReason::closest_approach, next);
  }
  return TransitionReason::none;
}

/// Mode fine: the waypoint reached at its accuracies, or re-plan beyond the re-plan distance.
TransitionReason fine_transition(const MissionParams& p, const LegMeasures& m, Mode& next) noexcept {
  const bool speed_ok = m.speed < p.speed_accuracy;
  const bool position_ok = p.rct.kappa_p <= 0.0 || m.dist < p.position_accuracy;
  if (speed_ok && position_ok) {
    return go_to(Mode::done, TransitionReason::accuracy_met, next);  // resolved to align/done by step()
  }
  if (m.dist > p.replan_distance) return brake_first_or(m, Mode::align, TransitionReason::replan, next);
  return TransitionReason::none;
}

/// Mode rct_transfer: as fine (accuracy met, re-plan), else to fine when the hand-over is due
/// (rct_transfer_handover_due) (docs/waypoint.md, "The RCT-only legs").
TransitionReason rct_transfer_transition(const MissionParams& p, const LegMeasures& m, const MissionInputs& in,
                                         Mode& next) noexcept {
  const TransitionReason fine_reason = fine_transition(p, m, next);
  if (fine_reason != TransitionReason::none) return fine_reason;
  if (rct_transfer_handover_due(p, in.R_ib, m.e_i, in.v_i, in.dt)) {
    return go_to(Mode::fine, TransitionReason::handover, next);
  }
  return TransitionReason::none;
}

}  // namespace

TransitionReason WaypointSequencer::state_transition(const MissionInputs& in, Mode& next) const noexcept {
  LegMeasures m = measure_leg(params_, waypoints_[static_cast<std::size_t>(index_)], in, leg_distance_);
  m.brake_needed = brake_needed(m.speed);
  if (lateral_too_fast(params_, m) && (mode_ == Mode::align || mode_ == Mode::accelerate || mode_ == Mode::coast)) {
    return go_to(Mode::brake, TransitionReason::lateral_speed, next);
  }
  switch (mode_) {
    case Mode::accelerate: return accelerate_transition(params_, m, next);
    case Mode::coast: return coast_transition(params_, m, next);
    case Mode::flip: return flip_transition(params_, m, next);
    case Mode::decelerate: return decelerate_transition(params_, m, in.v_i, next);
    case Mode::brake:
      if (m.speed <= params_.main_cutoff_speed) return go_to(Mode::fine, TransitionReason::braked, next);
      break;
    case Mode::fine: return fine_transition(params_, m, next);
    case Mode::rct_transfer: return rct_transfer_transition(params_, m, in, next);
    case Mode::align:
    case Mode::done:
      break;
  }
  return TransitionReason::none;
}


DesiredAttitude WaypointSequencer::evaluate(const MissionInputs& in, const Vec3& a_i) noexcept {
  if (mode_ == Mode::brake) {
    // x_b against the velocity, reached from the current attitude by the shortest arc (no
    // roll), re-aimed every sample: a misaligned engine turns the velocity while braking.
    q_hold_ = lie::quat_multiply(lie::shortest_arc_quat(in.R_ib.col(0), Vec3(-in.v_i)), q_ib_);
  }
  if (mode_ == Mode::fine || mode_ == Mode::done || mode_ == Mode::brake || mode_ == Mode::rct_transfer) {
    DesiredAttitude hold;
    hold.q_id = q_hold_;
    hold.error.q_ie = q_hold_;
    return hold;
  }
  const Vec3& p_wp = waypoints_[static_cast<std::size_t>(index_)];
  GuidanceFrameSpec spec = frame_spec();
  DesiredAttitude d = desired_attitude(spec, p_wp, in.p_i, in.v_i, a_i);
  if (d.error.cos_chart < params_.reanchor_cos) {
    // Re-anchor the chart on the current error frame: q_ie is continuous, ϑ returns to 0.
    const bool reversed = mode_ == Mode::flip || mode_ == Mode::decelerate;
    (reversed ? chart_decel_ : chart_accel_) = d.error.q_ie;
    spec = frame_spec();
    d = desired_attitude(spec, p_wp, in.p_i, in.v_i, a_i);
  }
  return d;
}


namespace {

/// The pointing error the thrust waits for: ‖ε_{d,b}‖ of the attitude error [Waypoint eq. (27)], or, with
/// pointing_thrust_axis, sin(α/2) of the angle α between x_b and x_d, which equals ‖ε_{d,b}‖
/// when the error has no roll about x (only the thrust axis matters for firing).
double pointing_error_of(const MissionParams& p, const lie::Mat3& R_ib, const Quat& q_ib,
                         const Quat& q_id) noexcept {
  double pointing = control::attitude_error(q_id, q_ib).tail<3>().norm();
  if (p.pointing_thrust_axis) {
    const Vec3 x_b = R_ib.col(0);
    const Vec3 x_d = lie::quat_to_rotation(q_id).col(0);
    pointing = std::sqrt(std::max(0.0, 0.5 * (1.0 - x_b.dot(x_d))));
  }
  return pointing;
}

/// The main engine's thrust in `mode` once pointed [Waypoint eq. (13)] [Waypoint eq. (16)]:
/// (13) when accelerating, [Waypoint eqs. (15)-(16)] when decelerating, full thrust when braking, else 0 [N].
double main_engine_thrust(const MissionParams& p, Mode mode, const Vec3& e_i, const Vec3& v_i) noexcept {
  if (mode == Mode::accelerate) {
    // (13) on the closing speed: a craft receding (or drifting sideways) faster than V_d still
    // has to be brought towards the waypoint.
    return acceleration_thrust(closing_speed(e_i, v_i), p.cruise_speed, p.T_max);
  }
  if (mode == Mode::decelerate) {
    // (14) holds along a line: the distance that the braking must cover is the distance to the
    // point of closest approach, e·v̂ (= ‖e‖ when v points at the waypoint).
    const double speed = v_i.norm();
    const double d_brake = p.brake_along_velocity && speed > 0.0 ? std::max(e_i.dot(v_i) / speed, 0.0)
                                                                 : e_i.norm();
    return deceleration_thrust(p.mass, speed, d_brake, p.T_max, p.braking_margin);  // [Waypoint eqs. (15)-(16)]
  }
  if (mode == Mode::brake) return p.T_max;
  return 0.0;
}

/// The body force f_b allocated to the six thrusters, bang-bang, and their resulting body force
/// [Waypoint eqs. (29)-(30)].
void fire_rct(const MissionParams& p, const Vec3& f_b, MissionCommand& cmd) noexcept {
  cmd.rct = control::rct_bang_bang(control::rct_allocate(f_b), p.f_max, p.rct_threshold);
  cmd.inputs.f_rct_b = control::rct_body_force(cmd.rct);
}

/// Fine control's RCT command [Waypoint eq. (28)]-(30): the position force, fired.
void set_fine_rct(const MissionParams& p, const MissionInputs& in, const Vec3& e_i,
                  MissionCommand& cmd) noexcept {
  fire_rct(p, control::rct_position_force(p.mass, in.R_ib, e_i, in.v_i, p.rct), cmd);  // [Waypoint eq. (28)]
}

/// The RCT's lateral nulling while the main engine flies the leg (control::rct_lateral_force with
/// the dead-beat gain 1/T_s), fired as fine control's force, while the line the craft flies
/// misses the waypoint by more than the arrival radius (docs/waypoint.md, "Lateral RCT"): within it the
/// thrusters stay off, so that they do not turn v̂ under the braking engine.
void set_lateral_rct(const MissionParams& p, const MissionInputs& in, const Vec3& e_i,
                     MissionCommand& cmd) noexcept {
  if (miss_distance(e_i, in.v_i) <= p.arrival_radius) return;
  fire_rct(p, control::rct_lateral_force(p.mass, in.R_ib, e_i, in.v_i, 1.0 / in.dt), cmd);
}

/// A sampled loop cannot follow a frame turning by more than half a radian per period (the
/// velocity direction of a craft whose thrust quantum a T_s is comparable to its speed, ê next
/// to the waypoint): the PID gets the feed-forward ω_d capped at 0.5/T_s.
Vec3 capped_feed_forward(const Vec3& omega_d, double dt) noexcept {
  const double ff_max = 0.5 / dt;
  const double ff = omega_d.norm();
  return ff > ff_max ? Vec3(omega_d * (ff_max / ff)) : omega_d;
}

}  // namespace

void WaypointSequencer::begin_sample(const MissionInputs& in) noexcept {
  q_ib_ = started_ ? continuous_q_ib(in.R_ib) : lie::rotation_to_quat(in.R_ib);
  if (!started_) {
    started_ = true;
    if (mode_ != Mode::done) {
      start_leg(in);
    }
  }
}

void WaypointSequencer::take_position_transition(const MissionInputs& in, MissionCommand& cmd) noexcept {
  Mode next = mode_;
  const TransitionReason reason = state_transition(in, next);
  if (reason == TransitionReason::none) return;
  cmd.transition = true;
  cmd.from = mode_;
  cmd.reason = reason;
  if (reason != TransitionReason::accuracy_met) {
    enter(next, in);
    return;
  }
  ++index_;
  if (index_ >= static_cast<int>(waypoints_.size())) {
    q_hold_ = q_last_;
    mode_ = Mode::done;
  } else {
    enter(Mode::align, in);
  }
}

void WaypointSequencer::take_pointing_transition(double pointing, MissionCommand& cmd) noexcept {
  if (!cmd.transition && pointing < params_.pointing_tolerance &&
      (mode_ == Mode::align || mode_ == Mode::flip)) {
    cmd.transition = true;
    cmd.from = mode_;
    cmd.reason = TransitionReason::pointing_reached;
    mode_ = mode_ == Mode::align ? Mode::accelerate : Mode::decelerate;
  }
}

MissionCommand WaypointSequencer::step(const MissionInputs& in) noexcept {
  MissionCommand cmd;
  begin_sample(in);
  // (a) transitions decided by position and velocity.
  if (mode_ != Mode::done) {
    take_position_transition(in, cmd);
  }
  // (b) desired attitude and pointing error.
  const lie::Quat& q_ib = q_ib_;
  DesiredAttitude d = evaluate(in, Vec3::Zero());
  const double pointing = pointing_error_of(params_, in.R_ib, q_ib, d.q_id);
  // (c) transitions decided by the pointing error (one transition per sample).
  take_pointing_transition(pointing, cmd);
  // (d) thrust (Algorithm 1) and RCT.
  const Vec3 e_i = mode_ == Mode::done ? Vec3::Zero()
                                       : Vec3(waypoints_[static_cast<std::size_t>(index_)] - in.p_i);
  const bool pointed = pointing < params_.pointing_tolerance;
  const double thrust = pointed ? main_engine_thrust(params_, mode_, e_i, in.v_i) : 0.0;
  cmd.inputs.thrust = thrust;
  if (mode_ == Mode::fine) {
    set_fine_rct(params_, in, e_i, cmd);
  } else if (mode_ == Mode::rct_transfer) {
    fire_rct(params_, rct_transfer_force(params_, in.R_ib, e_i, in.v_i, in.dt), cmd);
  } else if (params_.lateral_rct && (mode_ == Mode::align || mode_ == Mode::accelerate ||
                                     mode_ == Mode::coast || mode_ == Mode::flip)) {
    // Not while decelerating or braking: each RCT pulse turns v̂, which the engine's pointing
    // (x_d = −v̂, within the pointing tolerance) would have to chase.
    set_lateral_rct(params_, in, e_i, cmd);
  }
  // (e) feed-forward with the acceleration the commands will produce, then the PID [Waypoint eq. (27)] with
  // the feed-forward capped (cmd.omega_d_d stays exact).
  const Vec3 a_i = in.R_ib * (Vec3(thrust, 0.0, 0.0) + cmd.inputs.f_rct_b) / params_.mass;
  d = evaluate(in, a_i);
  q_last_ = d.q_id;
  const control::QuaternionPidOutput pid =
      pid_.step(q_ib, in.omega_b, d.q_id, capped_feed_forward(d.omega_d, in.dt), in.dt);
  cmd.inputs.tau_b = pid.tau_b;
  cmd.mode = mode_;
  cmd.waypoint = index_;
  cmd.q_id = d.q_id;
  cmd.q_ib = q_ib_;
  cmd.spec = frame_spec();
  cmd.omega_d_d = d.omega_d;
  cmd.pointing_error = pointing;
  cmd.projection_weight = d.velocity.weight;
  return cmd;
}

}  // namespace attiguard::guidance
