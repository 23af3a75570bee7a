#include "attiguard/guidance/mission_prediction.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "attiguard/guidance/rct_transfer.hpp"
#include "attiguard/lie/shortest_arc.hpp"

namespace attiguard::guidance {

namespace {


/// Samples of the reduced slew model at most (predicted_turn_time).
constexpr long kMaxTurnSamples = 1'000'000;

/// Angle between two directions [rad] (0 when either is zero).
double angle_between(const Vec3& a, const Vec3& b) noexcept {
  const double na = a.norm();
  const double nb = b.norm();
  if (!(na > 0.0) || !(nb > 0.0)) return 0.0;
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

/// The turn from R_from_ib to R_to_ib: craft.turn_time when set, else the PID's eigenaxis model
/// predicted_turn_time over the angle between the thrust axes.
double turn_time(const PredictionCraft& craft, const MissionParams& p, const lie::Mat3& R_from_ib,
                 const lie::Mat3& R_to_ib, const Vec3& x_from_i, const Vec3& x_to_i) {
  if (craft.turn_time) return craft.turn_time(R_from_ib, R_to_ib);
  return predicted_turn_time(craft, angle_between(x_from_i, x_to_i), p.pointing_tolerance);
}

/// The steady attitude that points x_b along `direction_i` from R_ib by the shortest arc
/// (guidance/leg_attitudes.hpp).
lie::Mat3 pointed_along(const lie::Mat3& R_ib, const Vec3& direction_i) noexcept {
  return lie::shortest_arc(R_ib.col(0), direction_i) * R_ib;
}

/// R_ib turned by π about its z axis: the flip of guidance/leg_attitudes.hpp.
lie::Mat3 flipped(const lie::Mat3& R_ib) noexcept {
  lie::Mat3 Rz = lie::Mat3::Identity();
  Rz(0, 0) = -1.0;
  Rz(1, 1) = -1.0;
  return R_ib * Rz;
}

/// Positive root of A x² + B x − C = 0 (A, C ≥ 0, B ≥ 0), in the form that keeps its digits.
double positive_root(double A, double B, double C) noexcept {
  if (!(C > 0.0)) return 0.0;
  return 2.0 * C / (B + std::sqrt(B * B + 4.0 * A * C));
}

/// Where and how fast decelerate hands over to fine control on the braking curve
/// v = √(2 γ a d) (docs/waypoint.md, "Prediction"): in the arrival sphere when the speed there is
/// below brake_speed, else at the main-engine cut-off speed.
struct HandOver {
  double distance;
  double speed;
};
HandOver hand_over(const MissionParams& p, double a_brake) noexcept {
  const double v_cut = p.main_cutoff_speed;
  const double d_cut = v_cut * v_cut / (2.0 * a_brake);
  const double v_sphere = std::sqrt(2.0 * a_brake * p.arrival_radius);
  const bool sphere_first = d_cut < p.arrival_radius && (p.brake_speed <= 0.0 || v_sphere <= p.brake_speed);
  return sphere_first ? HandOver{p.arrival_radius, v_sphere} : HandOver{d_cut, v_cut};
}

/// The first part of a leg that starts with more speed across the line of sight than the
/// sequencer lets through (TransitionReason::lateral_speed): turn against v, brake to rest.
struct LateralBrake {
  double time{0.0};
  double turn{0.0};
  double delta_v{0.0};
};
LateralBrake lateral_brake(const MissionParams& p, const PredictionCraft& craft, Vec3& p_i, Vec3& v_i,
                           Vec3& x_b_i, lie::Mat3& R_ib, const Vec3& wp) {
  LateralBrake b;
  const Vec3 e = wp - p_i;
  const double lateral = (v_i - e * (closing_speed(e, v_i) / std::max(e.norm(), 1e-300))).norm();
  if (!(p.brake_speed > 0.0) || !(lateral > std::max(p.brake_speed, 0.25 * p.cruise_speed))) return b;
  const double a = p.T_max / p.mass;
  const double speed = v_i.norm();
  const lie::Mat3 R_brake = pointed_along(R_ib, -v_i);
  b.turn = turn_time(craft, p, R_ib, R_brake, x_b_i, -v_i);
  b.time = b.turn + speed / a;
  b.delta_v = speed;
  p_i += v_i * (b.turn + 0.5 * speed / a);
  x_b_i = -v_i / speed;
  R_ib = R_brake;
  v_i.setZero();
  return b;
}

/// An RCT-only leg from the offset `e_i` with velocity `v_i`: the speed that does not close on
/// the waypoint (receding or across the line of sight) stopped first at a_rct, which carries the
/// craft its stopping distance farther; then predicted_fine_phase.
FinePhase rct_leg_phase(const MissionParams& p, const Vec3& e_i, const Vec3& v_i) noexcept {
  const double a = p.f_max / p.mass;
  const double d = e_i.norm();
  const double vc = std::max(closing_speed(e_i, v_i), 0.0);
  const Vec3 towards = d > 0.0 ? Vec3(e_i / d) : Vec3::Zero();
  const double other = (v_i - towards * vc).norm();
  FinePhase f = predicted_fine_phase(p, d + other * other / (2.0 * a), vc);
  f.time += other / a;
  f.delta_v += other;
  return f;
}

/// An RCT-only leg flown in Mode::rct_transfer from the offset `e_i` with velocity `v_i` and
/// the attitude R_ib held (guidance/rct_transfer.hpp): full thrust at the RCT's acceleration
/// along the line of sight in the body up to the braking curve (or V_d, then coast), the curve
/// at its braking acceleration to rest at δ_p/2, where both accuracies hold. The speed that does
/// not close on the waypoint is counted as in rct_leg_phase. A leg already within δ_p/2, or
/// whose curve is below the tracking's resolution 2θ a T_s (rct_transfer_handover_due), is
/// fine control's (rct_leg_phase).
FinePhase rct_transfer_phase(const MissionParams& p, const lie::Mat3& R_ib, const Vec3& e_i, const Vec3& v_i,
                             double control_period) noexcept {
  const double d = e_i.norm();
  if (!(d > rct_transfer_stop_distance(p)) || rct_transfer_handover_due(p, R_ib, e_i, v_i, control_period)) {
    return rct_leg_phase(p, e_i, v_i);
  }
  const Vec3 u = e_i / d;
  const double a = rct_available_acceleration(p, R_ib.transpose() * u);
  const double b = rct_transfer_braking_acceleration(a);
  const double s = std::max(closing_speed(e_i, v_i), 0.0);
  const double other = (v_i - u * s).norm();
  const double a_rct = p.f_max / p.mass;
  const double D = d - rct_transfer_stop_distance(p) + other * other / (2.0 * a_rct);
  // Acceleration from s meets the curve v² = 2 b (D − x) at x = (2bD − s²)/(2(a + b)).
  const double x = std::max(0.0, (2.0 * b * D - s * s) / (2.0 * (a + b)));
  const double v_p = std::max({std::min(p.cruise_speed, std::sqrt(s * s + 2.0 * a * x)), s, 1e-12});
  const double d_acc = std::max(v_p * v_p - s * s, 0.0) / (2.0 * a);
  const double d_brake = v_p * v_p / (2.0 * b);
  const double coast = std::max(D - d_acc - d_brake, 0.0) / v_p;
  FinePhase f;
  // The accuracies hold once the speed is below δ_v inside δ_p: on the curve, at δ_p when its
  // speed there, √(2 b (δ_p − δ_p/2)), is below δ_v, else where it falls to δ_v.
  const double v_end = std::min({p.speed_accuracy, std::sqrt(b * p.position_accuracy), v_p});
  f.time = std::max(v_p - s, 0.0) / a + coast + (v_p - v_end) / b + other / a_rct;
  f.delta_v = std::max(v_p - s, 0.0) + (v_p - v_end) + other;
  return f;
}

}  // namespace

double predicted_turn_time(const PredictionCraft& craft, double angle, double tolerance) noexcept {
  double theta = std::clamp(angle, 0.0, std::numbers::pi);
  if (!(std::sin(0.5 * theta) >= tolerance)) return 0.0;
  const double J = craft.J_max;
  const double kp = craft.gains.kp;
  const double kd = craft.gains.kd;
  if (!(J > 0.0) || !(kp > 0.0)) return HUGE_VAL;
  // Small-angle natural frequency of J θ̈ = −k_p θ/2 − k_d θ̇/2: the model needs no finer step
  // than 1 % of 1/ω_n; the sampled loop's own period when coarser.
  const double omega_n = std::sqrt(kp / (2.0 * J));
  double dt = craft.control_period;
  const double fine = 0.01 / omega_n;
  if (dt < fine) dt *= std::floor(fine / dt);
  double rate = 0.0;
  double t = 0.0;
  for (long k = 0; k < kMaxTurnSamples; ++k) {
    if (std::abs(std::sin(0.5 * theta)) < tolerance) return t;
    double torque = -kp * std::sin(0.5 * theta) - 0.5 * kd * std::cos(0.5 * theta) * rate;
    if (craft.max_wheel_torque > 0.0) torque = std::clamp(torque, -craft.max_wheel_torque, craft.max_wheel_torque);
    rate += torque / J * dt;  // semi-implicit Euler: the torque held over the sample
    theta += rate * dt;
    t += dt;
  }
  return t;
}

FinePhase predicted_fine_phase(const MissionParams& p, double distance, double speed) noexcept {
  FinePhase f;
  const double a = p.f_max / p.mass;
  const double s = std::max(speed, 0.0);
  if (s < p.speed_accuracy && (!(p.rct.kappa_p > 0.0) || distance < p.position_accuracy)) return f;  // met
  if (!(p.rct.kappa_p > 0.0)) {  // speed nulled only
    f.time = s / a;
    f.delta_v = s;
    return f;
  }
  const double lambda = p.rct.kappa_p / p.rct.kappa_d;
  // The slide ends where both accuracies hold: ‖e‖ < δ_p and λ‖e‖ < δ_v.
  const double e_end = std::min(p.position_accuracy, p.speed_accuracy / lambda);
  double e1 = distance;
  double v1 = s;
  // The braking curve v = √(2 b e) of RctPositionGains::braking_acceleration, the lower of the
  // two beyond e_x = 2b/λ²: full thrust up to it, along it at b down to e_x, then the line.
  const double b = p.rct.braking_acceleration;
  const double e_x = 2.0 * b / (lambda * lambda);
  if (b > 0.0 && distance > e_x && s * s < 2.0 * b * distance) {
    const double e_c = std::max(e_x, (s * s + 2.0 * a * distance) / (2.0 * (a + b)));
    const double v_c = std::sqrt(2.0 * b * e_c);
    const double v_x = lambda * e_x;
    f.time = (v_c - s) / a + (v_c - v_x) / b;
    f.delta_v = (v_c - s) + (v_c - v_x);
    if (e_x > e_end) f.time += std::log(e_x / e_end) / lambda;
    f.delta_v += v_x;
    return f;
  }
  if (s < lambda * distance) {
    // Full thrust towards the waypoint until v = λ e: (λ/(2a)) v² + v − λ (d + s²/(2a)) = 0.
    v1 = positive_root(lambda / (2.0 * a), 1.0, lambda * (distance + s * s / (2.0 * a)));
    f.time = (v1 - s) / a;
    f.delta_v = v1 - s;
    e1 = v1 / lambda;
  } else {
    // Faster than the line: full braking until v = λ e (λ² e² − 2 a e − (s² − 2 a d) = 0).
    const double c = s * s - 2.0 * a * distance;
    e1 = c > 0.0 ? p.position_accuracy : (a + std::sqrt(a * a - lambda * lambda * c)) / (lambda * lambda);
    e1 = std::min(e1, distance);
    v1 = lambda * e1;
    f.time = std::abs(s - v1) / a;
    f.delta_v = std::abs(s - v1);
  }
  if (e1 > e_end) f.time += std::log(e1 / e_end) / lambda;
  f.delta_v += v1;
  return f;
}

MissionPrediction predict_mission(const MissionParams& p, const PredictionCraft& craft,
                                  const PredictionStart& start, std::span<const Vec3> waypoints_i) {
  MissionPrediction out;
  const double a = p.T_max / p.mass;
  const double a_brake = p.braking_margin * a;
  Vec3 p_i = start.p_i;
  Vec3 v_i = start.v_i;
  lie::Mat3 R_ib = start.R_ib;
  Vec3 x_b_i = R_ib.col(0);
  for (const Vec3& wp : waypoints_i) {
    LegPrediction leg;
    const double L0 = (wp - p_i).norm();
    const bool slow = !(p.brake_speed > 0.0) || v_i.norm() <= p.brake_speed;
    if (L0 <= p.arrival_radius || (p.rct.kappa_p > 0.0 && L0 <= 0.5 * p.replan_distance && slow)) {
      const bool transfer = p.rct_transfer && L0 > p.arrival_radius;
      const FinePhase fp = transfer ? rct_transfer_phase(p, R_ib, wp - p_i, v_i, craft.control_period) : rct_leg_phase(p, wp - p_i, v_i);
      leg.time = leg.fine_time = fp.time;
      leg.delta_v = fp.delta_v;
      leg.rct_only = true;
    } else {
      const LateralBrake b = lateral_brake(p, craft, p_i, v_i, x_b_i, R_ib, wp);
      // Align: the turn to the line of sight, drifting meanwhile; the flip turns by π.
      const lie::Mat3 R_acc = pointed_along(R_ib, wp - p_i);
      const double t_align = turn_time(craft, p, R_ib, R_acc, x_b_i, wp - p_i);
      const double t_flip = craft.turn_time ? craft.turn_time(R_acc, flipped(R_acc))
                                            : predicted_turn_time(craft, std::numbers::pi, p.pointing_tolerance);
      R_ib = flipped(R_acc);
      p_i += v_i * t_align;
      const Vec3 e = wp - p_i;
      const double L = e.norm();
      const double vc = closing_speed(e, v_i);
      // Accelerate (13) up to V_d, the acceleration fraction, or the braking point
      // ‖e‖ − v²/(2γa) = v · flip_lead_time (measure_leg's flip_due).
      const double v_frac = std::sqrt(std::max(0.0, vc * vc + 2.0 * a * p.acceleration_fraction * L));
      const double v_flip = positive_root((1.0 + 1.0 / p.braking_margin) / (2.0 * a), p.flip_lead_time,
                                          L + vc * vc / (2.0 * a));
      const double v_peak = std::max({std::min({p.cruise_speed, v_frac, v_flip}), vc, 1e-12});
      const double t_acc = (v_peak - vc) / a;
      const double d_acc = (v_peak * v_peak - vc * vc) / (2.0 * a);
      // Coast, flip (coasting) and coast on to the braking curve.
      const double d_dec = v_peak * v_peak / (2.0 * a_brake);
      const double d_cruise = std::max(L - d_acc - d_dec, v_peak * t_flip);
      const HandOver h = hand_over(p, a_brake);
      const double v_h = std::min(h.speed, v_peak);
      // Speed across the line of sight (below the lateral-brake threshold) is not thrust out
      // before the braking, whose velocity projection turns it out over the braking: the
      // offset it leaves at the hand-over is flown by fine control.
      const double lateral = (v_i - e * (vc / L)).norm();
      const double t_dec = (v_peak - v_h) / a_brake;
      const double offset = lateral * (t_align + t_acc + d_cruise / v_peak + 0.5 * t_dec);
      const FinePhase fp = predicted_fine_phase(p, std::hypot(h.distance, offset), v_h);
      leg.peak_speed = v_peak;
      leg.turn_time = b.turn + t_align + t_flip;
      leg.fine_time = fp.time;
      leg.time = b.time + t_align + t_acc + d_cruise / v_peak + t_dec + fp.time;
      leg.delta_v = b.delta_v + (v_peak - vc) + (v_peak - v_h) + fp.delta_v;
      x_b_i = -e / L;  // braking attitude, held into the next leg's align
    }
    p_i = wp;
    v_i.setZero();
    out.time += leg.time;
    out.delta_v += leg.delta_v;
    out.legs.push_back(leg);
  }
  return out;
}

}  // namespace attiguard::guidance
