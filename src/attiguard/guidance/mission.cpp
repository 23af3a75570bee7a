#include "attiguard/guidance/mission.hpp"

#include <algorithm>
#include <cmath>

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
  }
  return "?";
}

Mission::Mission(const MissionParams& params, const control::QuaternionPidGains& gains,
                 std::span<const Vec3> waypoints_i) noexcept
    : params_(params), pid_(gains), waypoints_(waypoints_i) {
  if (waypoints_.empty()) {
    mode_ = Mode::done;
  }
}

GuidanceFrameSpec Mission::frame_spec() const noexcept {
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

Quat Mission::continuous_q_ib(const lie::Mat3& R_ib) const noexcept {
  // The quaternion of (4) evolves continuously; rotation_to_quat picks η ≥ 0, so restore the
  // sign nearest the previous sample. (27) is not invariant under q → −q: a sign jump would
  // reverse the proportional term.
  const Quat q = lie::rotation_to_quat(R_ib);
  return q.dot(q_ib_) < 0.0 ? Quat(-q) : q;
}

void Mission::start_leg(const MissionInputs& in) noexcept {
  const Vec3 e_i = waypoints_[static_cast<std::size_t>(index_)] - in.p_i;
  leg_distance_ = e_i.norm();
  // Chart: the current attitude turned by the shortest arc from x_b to ê, so that aligning
  // needs no roll and ϑ starts at 0 (the parallel case of (11), handled smoothly).
  const Vec3 x_i = in.R_ib.col(0);
  chart_accel_ = lie::quat_multiply(lie::shortest_arc_quat(x_i, e_i), q_ib_);
  // Sign of the chart such that η_{d,b} ≥ 0: the PID (27) then takes the short way round.
  if (control::attitude_error(chart_accel_, q_ib_)(0) < 0.0) {
    chart_accel_ = -chart_accel_;
  }
  chart_decel_ = chart_accel_;
  // A leg inside half the re-plan distance, started slowly enough for the RCT, is flown by fine
  // control (28) alone: the main engine's speed quantum is too coarse for it.
  const bool rct_leg = params_.rct.kappa_p > 0.0 && leg_distance_ <= 0.5 * params_.replan_distance &&
                       !brake_needed(in.v_i.norm());
  mode_ = leg_distance_ <= params_.arrival_radius || rct_leg ? Mode::fine : Mode::align;
  q_hold_ = chart_accel_;
}

void Mission::enter(Mode next, const MissionInputs& in) noexcept {
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

TransitionReason Mission::state_transition(const MissionInputs& in, Mode& next) const noexcept {
  const Vec3 e_i = waypoints_[static_cast<std::size_t>(index_)] - in.p_i;
  const double dist = e_i.norm();
  const double speed = in.v_i.norm();
  const double closing = closing_speed(e_i, in.v_i);
  const bool accel_distance_done =
      dist < (1.0 - params_.acceleration_fraction) * leg_distance_;
  // The flip must start flip_lead_time before braking must begin: the predicted stopping
  // distance at the closing speed (not ‖v‖: lateral or receding motion does not bring the
  // craft closer) plus the distance flown during the flip.
  const bool flip_due =
      closing > 0.0 && dist - stopping_distance(closing, params_) <= closing * params_.flip_lead_time;
  // Moving away from the waypoint (or past it) while not braking: re-plan, never coast away.
  auto overshoot = [&](Mode after_slow) {
    next = brake_needed(speed) ? Mode::brake : after_slow;
    return TransitionReason::overshoot;
  };
  // Speed across the line of sight that thrust along ê cannot take out: brake to rest first.
  const double lateral = dist > 0.0 ? (in.v_i - e_i * (e_i.dot(in.v_i) / (dist * dist))).norm() : 0.0;
  const bool lateral_too_fast = params_.brake_speed > 0.0 &&
                                lateral > std::max(params_.brake_speed, 0.25 * params_.cruise_speed);
  if (lateral_too_fast && (mode_ == Mode::align || mode_ == Mode::accelerate || mode_ == Mode::coast)) {
    next = Mode::brake;
    return TransitionReason::lateral_speed;
  }
  switch (mode_) {
    case Mode::accelerate:
      // Acceleration also ends when the flip is already due: on a short leg (a re-plan, or a
      // fast start) the fraction rule alone would leave no room to flip and brake.
      if ((accel_distance_done && closing > 0.0) || flip_due) {
        next = Mode::coast;
        return TransitionReason::acceleration_done;
      }
      if (closing > params_.cruise_speed) {
        next = Mode::coast;
        return TransitionReason::cruise_speed_reached;
      }
      break;
    case Mode::coast: {
      if (!(closing > 0.0)) {
        return overshoot(Mode::align);
      }
      const bool flip = flip_due || (params_.flip_timing == FlipTiming::immediate && accel_distance_done);
      if (flip) {
        next = Mode::flip;
        return TransitionReason::flip_point;
      }
      break;
    }
    case Mode::flip:
      // Passed the waypoint (or drifting away) before the flip is over: the reversed error
      // direction would swing through π; brake against v or hand over to fine control.
      if (!(closing > 0.0) && dist > params_.arrival_radius) {
        return overshoot(Mode::fine);
      }
      if (dist <= params_.arrival_radius) {
        if (brake_needed(speed)) {
          next = Mode::brake;
          return TransitionReason::speed_left;
        }
        next = Mode::fine;
        return TransitionReason::arrival_sphere;
      }
      break;
    case Mode::decelerate:
      // Hand over to the RCT only at a speed they can remove (brake_speed); faster, keep braking
      // with (16), which fires harder the closer the waypoint.
      if (dist <= params_.arrival_radius && !brake_needed(speed)) {
        next = Mode::fine;
        return TransitionReason::arrival_sphere;
      }
      if (speed <= params_.main_cutoff_speed) {
        next = Mode::fine;
        return TransitionReason::main_cutoff_speed;
      }
      // Closest approach: the angle between e and v reaches acos(c_full), where the velocity
      // projection starts to fade out (e·v = 0 exactly at the closest approach).
      if (e_i.dot(in.v_i) <= params_.projection.cos_full * dist * speed) {
        if (brake_needed(speed)) {
          next = Mode::brake;
          return TransitionReason::speed_left;
        }
        next = Mode::fine;
        return TransitionReason::closest_approach;
      }
      break;
    case Mode::brake:
      if (speed <= params_.main_cutoff_speed) {
        next = Mode::fine;
        return TransitionReason::braked;
      }
      break;
    case Mode::fine: {
      const bool speed_ok = speed < params_.speed_accuracy;
      const bool position_ok =
          params_.rct.kappa_p <= 0.0 || dist < params_.position_accuracy;
      if (speed_ok && position_ok) {
        next = Mode::done;  // resolved to align/done by step()
        return TransitionReason::accuracy_met;
      }
      if (dist > params_.replan_distance) {
        if (brake_needed(speed)) {
          next = Mode::brake;
          return TransitionReason::speed_left;
        }
        next = Mode::align;
        return TransitionReason::replan;
      }
      break;
    }
    case Mode::align:
    case Mode::done:
      break;
  }
  return TransitionReason::none;
}

DesiredAttitude Mission::evaluate(const MissionInputs& in, const Vec3& a_i) noexcept {
  if (mode_ == Mode::brake) {
    // x_b against the velocity, reached from the current attitude by the shortest arc (no
    // roll), re-aimed every sample: a misaligned engine turns the velocity while braking.
    q_hold_ = lie::quat_multiply(lie::shortest_arc_quat(in.R_ib.col(0), Vec3(-in.v_i)), q_ib_);
  }
  if (mode_ == Mode::fine || mode_ == Mode::done || mode_ == Mode::brake) {
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

MissionCommand Mission::step(const MissionInputs& in) noexcept {
  MissionCommand cmd;
  q_ib_ = started_ ? continuous_q_ib(in.R_ib) : lie::rotation_to_quat(in.R_ib);
  if (!started_) {
    started_ = true;
    if (mode_ != Mode::done) {
      start_leg(in);
    }
  }
  // (a) transitions decided by position and velocity.
  if (mode_ != Mode::done) {
    Mode next = mode_;
    const TransitionReason reason = state_transition(in, next);
    if (reason != TransitionReason::none) {
      cmd.transition = true;
      cmd.from = mode_;
      cmd.reason = reason;
      if (reason == TransitionReason::accuracy_met) {
        ++index_;
        if (index_ >= static_cast<int>(waypoints_.size())) {
          q_hold_ = q_last_;
          mode_ = Mode::done;
        } else {
          enter(Mode::align, in);
        }
      } else {
        enter(next, in);
      }
    }
  }
  // (b) desired attitude and pointing error.
  const lie::Quat& q_ib = q_ib_;
  DesiredAttitude d = evaluate(in, Vec3::Zero());
  double pointing = control::attitude_error(d.q_id, q_ib).tail<3>().norm();
  if (params_.pointing_thrust_axis) {
    // Only the thrust axis matters for firing: sin(α/2) of the angle α between x_b and x_d,
    // which equals ‖ε_{d,b}‖ when the error has no roll about x.
    const Vec3 x_b = in.R_ib.col(0);
    const Vec3 x_d = lie::quat_to_rotation(d.q_id).col(0);
    pointing = std::sqrt(std::max(0.0, 0.5 * (1.0 - x_b.dot(x_d))));
  }
  // (c) transitions decided by the pointing error (one transition per sample).
  if (!cmd.transition && pointing < params_.pointing_tolerance &&
      (mode_ == Mode::align || mode_ == Mode::flip)) {
    cmd.transition = true;
    cmd.from = mode_;
    cmd.reason = TransitionReason::pointing_reached;
    mode_ = mode_ == Mode::align ? Mode::accelerate : Mode::decelerate;
  }
  // (d) thrust (Algorithm 1) and RCT.
  const double speed = in.v_i.norm();
  const Vec3 e_i = mode_ == Mode::done ? Vec3::Zero()
                                       : Vec3(waypoints_[static_cast<std::size_t>(index_)] - in.p_i);
  const bool pointed = pointing < params_.pointing_tolerance;
  double thrust = 0.0;
  if (pointed && mode_ == Mode::accelerate) {
    // (13) on the closing speed: a craft receding (or drifting sideways) faster than V_d still
    // has to be brought towards the waypoint.
    thrust = acceleration_thrust(closing_speed(e_i, in.v_i), params_.cruise_speed, params_.T_max);
  } else if (pointed && mode_ == Mode::decelerate) {
    // (14) holds along a line: the distance that the braking must cover is the distance to the
    // point of closest approach, e·v̂ (= ‖e‖ when v points at the waypoint).
    const double d_brake = params_.brake_along_velocity && speed > 0.0
                               ? std::max(e_i.dot(in.v_i) / speed, 0.0)
                               : e_i.norm();
    thrust = deceleration_thrust(params_.mass, speed, d_brake, params_.T_max,
                                 params_.braking_margin);  // (15)-(16)
  } else if (pointed && mode_ == Mode::brake) {
    thrust = params_.T_max;
  }
  cmd.inputs.thrust = thrust;
  if (mode_ == Mode::fine) {
    const Vec3 f_b = control::rct_position_force(params_.mass, in.R_ib, e_i, in.v_i, params_.rct);
    cmd.rct = control::rct_bang_bang(control::rct_allocate(f_b), params_.f_max,
                                     params_.rct_threshold);  // (28)-(30)
    cmd.inputs.f_rct_b = control::rct_body_force(cmd.rct);
  }
  // (e) feed-forward with the acceleration the commands will produce, then the PID (27).
  const Vec3 a_i = in.R_ib * (Vec3(thrust, 0.0, 0.0) + cmd.inputs.f_rct_b) / params_.mass;
  d = evaluate(in, a_i);
  q_last_ = d.q_id;
  // A sampled loop cannot follow a frame turning by more than half a radian per period (the
  // velocity direction of a craft whose thrust quantum a T_s is comparable to its speed, ê next
  // to the waypoint): the PID gets the feed-forward capped at 0.5/T_s (cmd.omega_d_d stays exact).
  const double ff_max = 0.5 / in.dt;
  const double ff = d.omega_d.norm();
  const Vec3 omega_ff = ff > ff_max ? Vec3(d.omega_d * (ff_max / ff)) : d.omega_d;
  const control::QuaternionPidOutput pid = pid_.step(q_ib, in.omega_b, d.q_id, omega_ff, in.dt);
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
