#pragma once
/// @file rct_transfer.hpp
/// The RCT transfer law of the legs the RCT fly alone (beyond the Waypoint paper;
/// docs/waypoint.md, "The RCT-only legs"): instead of fine control's switching line and braking
/// curve at half the RCT's acceleration ([Waypoint eq. (28)] with
/// RctPositionGains::braking_acceleration), the thrusters track the near time-optimal speed
/// profile along the line of sight — full RCT thrust up to the speed cap, coast, brake on a
/// curve at (1 − margin) a_rct shifted by one control period of flight, to rest inside the
/// position accuracy — with the speed across the line of sight nulled; fine control takes over
/// only if the accuracies are not met there. Allocation-free and noexcept (flight loop).

#include <algorithm>
#include <cmath>

#include "attiguard/guidance/waypoint_sequencer.hpp"

namespace attiguard::guidance {

/// Share of the RCT's acceleration kept in reserve on the transfer's braking curve for mass
/// and thrust uncertainty (docs/waypoint.md, "The RCT-only legs"): the craft brakes at
/// (1 − this) a_rct and so stops in time with up to this much less thrust-to-mass than nominal.
inline constexpr double kRctTransferThrustReserve = 0.1;

/// The RCT's acceleration along the direction `u_b` (unit, body frame) [m/s²]: with one thruster
/// pair per body axis, f_max/m / max_k |u_k| — f_max/m along a body axis, up to √3 f_max/m along
/// a body diagonal ([Waypoint eqs. (29)-(30)]; docs/waypoint.md, "The RCT-only legs").
[[nodiscard]] inline double rct_available_acceleration(const MissionParams& p, const Vec3& u_b) noexcept {
  const double largest = u_b.cwiseAbs().maxCoeff();
  return largest > 0.0 ? p.f_max / p.mass / largest : p.f_max / p.mass;
}

/// Braking acceleration of the transfer along a line of sight on which the RCT give
/// `available` [m/s²]: (1 − kRctTransferThrustReserve) × available. Each body axis then needs at
/// most that share of its own f_max/m to follow the curve (docs/waypoint.md, "The RCT-only legs").
[[nodiscard]] inline double rct_transfer_braking_acceleration(double available) noexcept {
  return (1.0 - kRctTransferThrustReserve) * available;
}

/// Distance to the waypoint at which the transfer's braking curve ends at rest [m]: half the
/// position accuracy, δ_p/2 (docs/waypoint.md, "The RCT-only legs"). The craft crosses δ_p
/// still braking and meets both accuracies (‖e‖ < δ_p, ‖v‖ < δ_v) on the way in, without fine
/// control's slide along its switching line [Waypoint eq. (28)], which would have to go on to
/// ‖e‖ < δ_v/λ.
[[nodiscard]] inline double rct_transfer_stop_distance(const MissionParams& p) noexcept {
  return 0.5 * p.position_accuracy;
}

/// The transfer's reference approach speed at distance `d` with closing speed `closing`
/// (docs/waypoint.md, "The RCT-only legs") [m/s]: min(V_d, √(2 b (d − d_s − v_c T_s))) (0
/// inside) with b the braking acceleration on `available` (rct_transfer_braking_acceleration),
/// d_s = rct_transfer_stop_distance and T_s = `dt` (the curve moved one control period of flight
/// closer: the command is held for a period).
[[nodiscard]] inline double rct_transfer_speed(const MissionParams& p, double d, double closing, double dt,
                                               double available) noexcept {
  const double room = std::max(d - rct_transfer_stop_distance(p) - std::max(closing, 0.0) * dt, 0.0);
  return std::min(p.cruise_speed, std::sqrt(2.0 * rct_transfer_braking_acceleration(available) * room));
}

/// The transfer's RCT force in the body frame [N]: f^b = m R_i^b (v_ref ê − v^i)/T_s with
/// v_ref = rct_transfer_speed on the RCT's acceleration along ê in the body — the dead-beat
/// tracking of a reference velocity like control::rct_lateral_force, so that the on/off
/// thrusters of each body axis fire while that axis' speed error exceeds half a pulse and the
/// speed across the line of sight is nulled (docs/waypoint.md, "The RCT-only legs"; allocated and
/// fired as [Waypoint eqs. (29)-(30)]). Zero when e^i = 0.
[[nodiscard]] inline Vec3 rct_transfer_force(const MissionParams& p, const lie::Mat3& R_ib, const Vec3& e_i,
                                             const Vec3& v_i, double dt) noexcept {
  const double d = e_i.norm();
  if (!(d > 0.0) || !(dt > 0.0)) return Vec3::Zero();
  const Vec3 u = e_i / d;
  const double available = rct_available_acceleration(p, R_ib.transpose() * u);
  const Vec3 v_ref = u * rct_transfer_speed(p, d, u.dot(v_i), dt, available);
  return p.mass / dt * (R_ib.transpose() * (v_ref - v_i));
}

/// Whether the transfer hands over to fine control now (docs/waypoint.md, "The RCT-only legs"):
/// when both its reference speed and the craft's speed are below two on-threshold pulses of the
/// RCT along ê, 2 θ a T_s (θ the on threshold of [Waypoint eq. (30)]'s bang-bang,
/// a = rct_available_acceleration) — at rest at the end of its curve with the accuracies not
/// met (a speed accuracy finer than its dead-beat tracking resolves): fine control's law
/// [Waypoint eq. (28)] takes the rest.
[[nodiscard]] inline bool rct_transfer_handover_due(const MissionParams& p, const lie::Mat3& R_ib, const Vec3& e_i,
                                                    const Vec3& v_i, double dt) noexcept {
  const double d = e_i.norm();
  if (!(d > 0.0)) return true;
  const Vec3 u = e_i / d;
  const double available = rct_available_acceleration(p, R_ib.transpose() * u);
  const double resolution = 2.0 * p.rct_threshold * available * dt;
  return v_i.norm() <= resolution && rct_transfer_speed(p, d, u.dot(v_i), dt, available) <= resolution;
}

}  // namespace attiguard::guidance
