#pragma once
/// @file rct_position_law.hpp
/// Fine position law of the reaction-control thrusters, [Waypoint eq. (28)].

#include "attiguard/lie/so3.hpp"

namespace attiguard::control {

/// Gains of [Waypoint eq. (28)].
struct RctPositionGains {
  double kappa_p{0.0};  ///< κ_p [1/s²] (the paper's simulation uses 0)
  double kappa_d{5.0};  ///< κ_d [1/s]
};

/// f^b_RCT = m R_i^b (κ_p e^i − κ_d v^i) with e^i = p_wp − p ([Waypoint eq. (28)], sign of
/// the κ_p term corrected: the printed −κ_p e^i pushes *away* from the waypoint because
/// ė^i = −v^i: docs/errata.md, Waypoint 7; the RctPositionLaw test of
/// tests/control/test_waypoint_controllers.cpp shows that the printed sign diverges).
/// Allocation-free.
[[nodiscard]] inline lie::Vec3 rct_position_force(double mass, const lie::Mat3& R_ib,
                                                  const lie::Vec3& e_i, const lie::Vec3& v_i,
                                                  const RctPositionGains& g) noexcept {
  return mass * (R_ib.transpose() * (g.kappa_p * e_i - g.kappa_d * v_i));
}

}  // namespace attiguard::control
