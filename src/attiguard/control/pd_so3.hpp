#pragma once
/// @file pd_so3.hpp
/// The PD attitude law on SO(3) and its Lyapunov function ([PET-ERG eq. (3)] and Sec. III-A).

#include "attiguard/lie/so3.hpp"

namespace attiguard::control {

using lie::Mat3;
using lie::Vec3;

/// PD gains of [PET-ERG eq. (3)].
struct PdGains {
  double kp{1.0};  ///< proportional gain [N·m]
  double kd{1.0};  ///< derivative gain [N·m·s]
};

/// τ = k_p sk(R_e)^∨ − k_d ω with R_e = Rᵀ R_g [PET-ERG eq. (3)]. Allocation-free.
[[nodiscard]] inline Vec3 pd_torque(const Mat3& R_ib, const Vec3& omega_b, const Mat3& R_g,
                                    const PdGains& gains) noexcept {
  const Mat3 R_e = R_ib.transpose() * R_g;
  return gains.kp * lie::vee(lie::sk(R_e)) - gains.kd * omega_b;
}

/// V(R, ω, R_g) = ½ ωᵀ J ω + k_p φ(Rᵀ R_g) [PET-ERG Sec. III-A]; V̇ = −k_d ‖ω‖² for a
/// constant R_g.
[[nodiscard]] inline double pd_lyapunov(const Mat3& J, const Mat3& R_ib, const Vec3& omega_b,
                                        const Mat3& R_g, const PdGains& gains) noexcept {
  return 0.5 * omega_b.dot(J * omega_b) + gains.kp * lie::phi(R_ib.transpose() * R_g);
}

}  // namespace attiguard::control
