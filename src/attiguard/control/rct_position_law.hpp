#pragma once
/// @file rct_position_law.hpp
/// Fine position law of the reaction-control thrusters, [Waypoint eq. (28)].

#include <cmath>

#include "attiguard/lie/so3.hpp"

namespace attiguard::control {

/// Gains of [Waypoint eq. (28)].
struct RctPositionGains {
  double kappa_p{0.0};  ///< κ_p [1/s²] (the paper's simulation uses 0)
  double kappa_d{5.0};  ///< κ_d [1/s]
  /// Braking curve of the position term (not in the paper; docs/waypoint.md, "Fine control far
  /// from the waypoint"): when > 0 [m/s²], the approach speed the law asks for, (κ_p/κ_d) ‖e‖,
  /// is capped at √(2 b ‖e‖), so that an RCT leg longer than the switching line's reach is
  /// flown at a speed the thrusters can still take out. 0 = [Waypoint eq. (28)] unchanged.
  double braking_acceleration{0.0};
};

/// f^b_RCT = m R_i^b (κ_p e^i − κ_d v^i) with e^i = p_wp − p ([Waypoint eq. (28)], sign of
/// the κ_p term corrected: the printed −κ_p e^i pushes *away* from the waypoint because
/// ė^i = −v^i: docs/errata.md, Waypoint 7; the RctPositionLaw test of
/// tests/control/test_waypoint_controllers.cpp shows that the printed sign diverges).
/// With RctPositionGains::braking_acceleration b > 0 the position term is κ_d √(2b/‖e‖) e
/// wherever that is below κ_p e (docs/waypoint.md, "Fine control far from the waypoint").
/// Allocation-free.
[[nodiscard]] inline lie::Vec3 rct_position_force(double mass, const lie::Mat3& R_ib,
                                                  const lie::Vec3& e_i, const lie::Vec3& v_i,
                                                  const RctPositionGains& g) noexcept {
  double position_gain = g.kappa_p;
  if (g.braking_acceleration > 0.0 && g.kappa_p > 0.0 && g.kappa_d > 0.0) {
    // κ_p e = κ_d v_ref with v_ref = λ e; beyond 2b/λ² the curve √(2 b ‖e‖) is the lower.
    const double d = e_i.norm();
    const double lambda = g.kappa_p / g.kappa_d;
    if (lambda * lambda * d > 2.0 * g.braking_acceleration) {
      position_gain = g.kappa_d * std::sqrt(2.0 * g.braking_acceleration / d);
    }
  }
  return mass * (R_ib.transpose() * (position_gain * e_i - g.kappa_d * v_i));
}

/// A damping of the speed across the line of sight like [Waypoint eq. (28)]'s,
/// f^b = −m k R_i^b (I − êêᵀ) v^i with ê = e^i/‖e^i‖: the RCT null that speed while the main
/// engine flies the leg (beyond the paper; docs/waypoint.md, "Lateral RCT"), so that the engine's
/// line passes through the waypoint. The guidance uses the dead-beat gain k = 1/T_s: on/off
/// thrusters then fire while ‖v_⊥‖ exceeds half a pulse, a_rct T_s/2. Zero when e^i = 0.
/// Allocation-free.
[[nodiscard]] inline lie::Vec3 rct_lateral_force(double mass, const lie::Mat3& R_ib, const lie::Vec3& e_i,
                                                 const lie::Vec3& v_i, double gain) noexcept {
  const double d = e_i.norm();
  if (!(d > 0.0)) return lie::Vec3::Zero();
  const lie::Vec3 u = e_i / d;
  const lie::Vec3 v_lat = v_i - u * u.dot(v_i);
  return -mass * gain * (R_ib.transpose() * v_lat);
}

}  // namespace attiguard::control
