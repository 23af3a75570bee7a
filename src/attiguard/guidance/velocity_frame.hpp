#pragma once
/// @file velocity_frame.hpp
/// The misalignment (velocity-projection) frame d of [Waypoint eqs. (17)-(22)].
///
/// Frame d is defined relative to the error frame e so that v^d = R_i^d v^i = [±‖v^i‖, 0, 0]
/// (17): its x axis lies along ±v^i. Pointing the thruster along −v^i while decelerating removes
/// every velocity component, including those left by misaligned firings (Sec. IV-C).
///
/// As printed, (18) swaps sine and cosine like [Waypoint eq. (8)], and [Waypoint eqs. (20)-(21)] are undefined at v = 0 and
/// when ±v^e is antiparallel to x_e. We implement, with w = s·v^e (s = ±1 the sign of [Waypoint eq. (17)]),
/// û = w/‖w‖, c = x·û, the blended shortest arc n = [1 + λc, λ (x × û)] with weight
/// λ = S(‖w‖/v_blend) · S(c/c_full) ∈ [0, 1] (S the C¹ smoothstep). For λ = 1 this is exactly
/// [cos(ϑ/2), k sin(ϑ/2)] of [Waypoint eq. (18)] with ϑ, k of [Waypoint eqs. (20)-(21)] (up to normalisation); λ fades the
/// projection out as ‖v‖ → 0 and as the angle between x_e and w grows from acos(c_full) to 90°,
/// so n₀ ≥ 1 and the frame and its rate stay finite and C¹ everywhere. The rate replaces [Waypoint eq. (19)]:
/// it is the exact derivative, using ẇ = s (R_i^e v̇^i − ω^e_{i,e} × v^e).

#include "attiguard/guidance/frame_rate.hpp"

namespace attiguard::guidance {

/// Parameters of the velocity projection.
struct VelocityProjectionParams {
  double blend_speed{0.05};  ///< v_blend: full projection above this speed [m/s]
  double cos_full{0.0174524064372836};  ///< c_full = cos 89°: full projection while angle(x_e, ±v^e) ≤ acos(c_full)
};

/// The velocity-projection frame at one instant.
struct VelocityFrame {
  Quat q_ed{Quat(1.0, 0.0, 0.0, 0.0)};  ///< q_{e,d}: R(q_ed) = R_d^e, [Waypoint eq. (22)]
  Vec3 omega_d{Vec3::Zero()};           ///< ω^d_{e,d} [rad/s], replaces [Waypoint eq. (19)]
  double weight{0.0};                   ///< λ ∈ [0, 1]; 0 = suppressed (q_ed = [1, 0, 0, 0])
};

/// Velocity-projection frame [Waypoint eqs. (17)-(22)]: q_ie and omega_e the error frame
/// (error_frame()), v_i and a_i = v̇^i the inertial velocity and acceleration, sign = ±1 the sign
/// of v^d in [Waypoint eq. (17)] (−1 while decelerating: thrust against the velocity). Allocation-free.
[[nodiscard]] VelocityFrame velocity_frame(const Quat& q_ie, const Vec3& omega_e, const Vec3& v_i,
                                           const Vec3& a_i, double sign,
                                           const VelocityProjectionParams& params) noexcept;

}  // namespace attiguard::guidance
