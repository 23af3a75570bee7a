#pragma once
/// @file desired_attitude.hpp
/// The composite desired attitude of [Waypoint eqs. (23)-(24)].

#include "attiguard/guidance/error_frame.hpp"
#include "attiguard/guidance/velocity_frame.hpp"

namespace attiguard::guidance {

/// How the desired attitude is built in the current phase of a leg.
struct GuidanceFrameSpec {
  Quat q_ir{Quat(1.0, 0.0, 0.0, 0.0)};  ///< chart of the error frame (error_frame())
  double error_sign{1.0};  ///< +1: e^i = p_wp − p (Fig. 1(a)); −1: reversed vector (Fig. 1(b))
  bool projection{false};  ///< velocity projection [Waypoint eqs. (17)-(22)] on; off = q_ed = [1, 0, 0, 0]
  double projection_sign{-1.0};  ///< sign of v^d in [Waypoint eq. (17)]
  VelocityProjectionParams projection_params{};
  double e_floor{1e-6};  ///< see error_frame() [m]
};

/// Every frame of the guidance at one instant.
struct DesiredAttitude {
  ErrorFrame error;        ///< q_{i,e}, ω^e_{i,e}: [Waypoint eqs. (6)-(12)]
  VelocityFrame velocity;  ///< q_{e,d}, ω^d_{e,d}: [Waypoint eqs. (17)-(22)]
  Quat q_id{Quat(1.0, 0.0, 0.0, 0.0)};  ///< q_{i,d} = q_{i,e} ⊗ q_{e,d}, [Waypoint eq. (23)]
  Vec3 omega_d{Vec3::Zero()};           ///< ω^d_{i,d} = R_e^d ω^e_{i,e} + ω^d_{e,d}, [Waypoint eq. (24)]
};

/// Desired attitude and feed-forward angular velocity of [Waypoint eqs. (23)-(24)], for the
/// waypoint p_wp_i, position p_i, velocity v_i and acceleration a_i = v̇^i (all inertial). The
/// body x axis of q_id points along ê^i (or ±v̂^i where the projection is active).
/// Allocation-free.
[[nodiscard]] DesiredAttitude desired_attitude(const GuidanceFrameSpec& spec, const Vec3& p_wp_i,
                                               const Vec3& p_i, const Vec3& v_i,
                                               const Vec3& a_i) noexcept;

}  // namespace attiguard::guidance
