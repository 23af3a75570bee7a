#pragma once
/// @file error_frame.hpp
/// The position-error frame e of [Waypoint eqs. (6)-(12)], with errata fixed.
///
/// e^i = p_wp − p (or its opposite for the deceleration phase, Fig. 1(b)), e^e := [‖e^i‖, 0, 0]:
/// the frame e has its x axis along e^i. The paper builds R_e^i as the shortest-arc rotation
/// from the inertial x axis onto ê^i; we build it from the x axis of a *chart* frame r fixed per
/// phase of a leg (R_e^i = R_r^i · shortest_arc(x, R_i^r ê^i)), which is the paper's construction
/// for R_r^i = I. The chart keeps the rotation angle ϑ ≤ π/2, far from the antiparallel
/// singularity ϑ = π where k of [Waypoint eq. (11)] and the rate blow up (docs/errata.md, Waypoint 3).
///
/// Errata (docs/waypoint.md): (8) swaps sine and cosine — we use q = [cos(ϑ/2), k sin(ϑ/2)],
/// written as the unnormalised n = [1 + x·û, x × û] (smooth through ϑ = 0); (9) as printed is
/// identically zero (R_i^e e^i = e^e and S†(e^e) e^e = 0): the rate follows from ė^i = −v^i
/// (waypoint fixed), and it also contains the twist about x that the S†-formula omits when ϑ ≠ 0.

#include "attiguard/guidance/frame_rate.hpp"

namespace attiguard::guidance {

/// Result of the error-frame construction at one instant.
struct ErrorFrame {
  Quat q_ie{Quat(1.0, 0.0, 0.0, 0.0)};  ///< q_{i,e}: R(q_ie) = R_e^i (e → inertial), [Waypoint eq. (12)]
  Vec3 omega_e{Vec3::Zero()};           ///< ω^e_{i,e}, body rate of frame e [rad/s], [Waypoint eq. (9)] fixed
  double cos_chart{1.0};                ///< cos ϑ between the chart x axis and ê^i
};

/// Error frame [Waypoint eqs. (6)-(12)] for the error vector e_i and its rate e_dot_i
/// (ė^i = −v^i for a fixed waypoint; +v^i for the reversed vector of the deceleration phase),
/// relative to the chart q_ir (R(q_ir) = R_r^i). R_e^i maps body x onto ê_i. When
/// ‖e_i‖ < e_floor the rate uses e_floor in place of ‖e_i‖ (finite as ‖e‖ → 0); e_i = 0 gives the
/// chart itself. The chart must satisfy cos ϑ > −1 (the guidance keeps cos ϑ ≥ 0 by
/// re-anchoring). Allocation-free.
[[nodiscard]] ErrorFrame error_frame(const Quat& q_ir, const Vec3& e_i, const Vec3& e_dot_i,
                                     double e_floor = 1e-6) noexcept;

/// The paper's [Waypoint eq. (9)] with the missing derivative restored, ω^e_{i,e} = −S†(e^e) R_i^e ė^i =
/// (e^e × R_i^e ė^i)/‖e‖² (S† the pseudo-inverse of S): the component of the true rate
/// perpendicular to x_e only. Exact when ϑ = 0 (chart x along ê), for tests and docs.
[[nodiscard]] Vec3 eq9_corrected_rate(const Quat& q_ie, const Vec3& e_i, const Vec3& e_dot_i) noexcept;

/// The paper's [Waypoint eq. (9)] exactly as printed, −S†(e^e) R_i^e e^i, which is identically zero.
[[nodiscard]] Vec3 eq9_as_printed(const Quat& q_ie, const Vec3& e_i) noexcept;

/// The paper's [Waypoint eq. (8)] as printed, [sin(ϑ/2), k cos(ϑ/2)] with ϑ, k from [Waypoint eqs. (10)-(11)]: it rotates
/// the x axis by π − ϑ instead of ϑ (erratum; for tests and docs only). Needs 0 < ϑ < π.
[[nodiscard]] Quat eq8_as_printed(const Vec3& e_i) noexcept;

}  // namespace attiguard::guidance
