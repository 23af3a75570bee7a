#pragma once
/// @file so3_tracking.hpp
/// Geometric tracking of a time-varying attitude on SO(3) with feedforward of the reference's
/// angular acceleration and gyroscopic terms (docs/pet-erg.md, section 16; in the family of
/// Lee, Leok and McClamroch's tracking on SO(3)), and its Lyapunov function. With a reference
/// at rest it is the PD law [PET-ERG eq. (3)] and V its Lyapunov function [PET-ERG Sec. III-A].
/// Flight-loop code: allocation-free and noexcept.

#include "attiguard/lie/so3.hpp"

namespace attiguard::control {

using lie::Mat3;
using lie::Vec3;

/// The reference at one instant: R_d (body → inertial), its body rate ω_d and angular
/// acceleration ω̇_d, both in the reference's own body frame (docs/pet-erg.md, section 16).
struct TrackingReference {
  Mat3 R_ib{Mat3::Identity()};
  Vec3 omega_b{Vec3::Zero()};
  Vec3 omega_dot_b{Vec3::Zero()};
};

/// Gains of the tracking law: k_R [N·m] on the attitude error, k_Ω [N·m·s] on the rate error
/// (the PD law's k_p, k_d when the reference is at rest).
struct TrackingGains {
  double k_R{1.0};
  double k_Omega{1.0};
};

/// The tracking errors (docs/pet-erg.md, section 16): e_R = ½(R_dᵀR − RᵀR_d)^∨ and
/// e_Ω = ω − Rᵀ R_d ω_d, in the body frame.
struct TrackingError {
  Vec3 e_R{Vec3::Zero()};
  Vec3 e_Omega{Vec3::Zero()};
};

/// e_R and e_Ω from R_e = Rᵀ R_d (docs/pet-erg.md, section 16).
[[nodiscard]] inline TrackingError tracking_error_of(const Mat3& R_e, const Vec3& omega_b,
                                                     const TrackingReference& ref) noexcept {
  TrackingError e;
  e.e_R = -lie::vee(lie::sk(R_e));  // ½(R_dᵀR − RᵀR_d)^∨ = −sk(RᵀR_d)^∨
  e.e_Omega = omega_b - R_e * ref.omega_b;
  return e;
}

/// e_R and e_Ω of the body (R, ω) against the reference (docs/pet-erg.md, section 16).
[[nodiscard]] inline TrackingError tracking_error(const Mat3& R_ib, const Vec3& omega_b,
                                                  const TrackingReference& ref) noexcept {
  return tracking_error_of(R_ib.transpose() * ref.R_ib, omega_b, ref);
}

/// τ = −k_R e_R − k_Ω e_Ω + ω × Jω − J(ω̂ RᵀR_d ω_d − RᵀR_d ω̇_d) (docs/pet-erg.md, section
/// 16) for the rigid body J ω̇ = Jω × ω + τ [PET-ERG eq. (1)]. On the reference (R = R_d,
/// ω = ω_d) it is the inverse dynamics J ω̇_d + ω_d × Jω_d; with ω_d = ω̇_d = 0 and ω = 0 terms
/// aside it is the PD law [PET-ERG eq. (3)].
[[nodiscard]] inline Vec3 tracking_torque(const Mat3& J_b, const Mat3& R_ib, const Vec3& omega_b,
                                          const TrackingReference& ref,
                                          const TrackingGains& gains) noexcept {
  const Mat3 R_e = R_ib.transpose() * ref.R_ib;
  const TrackingError e = tracking_error_of(R_e, omega_b, ref);
  const Vec3 omega_d_in_b = R_e * ref.omega_b;
  const Vec3 feedforward =
      omega_b.cross(J_b * omega_b) - J_b * (omega_b.cross(omega_d_in_b) - R_e * ref.omega_dot_b);
  return -gains.k_R * e.e_R - gains.k_Omega * e.e_Omega + feedforward;
}

/// V = ½ e_Ωᵀ J e_Ω + k_R φ(RᵀR_d), φ(R) = ½ tr(I − R) (docs/pet-erg.md, section 16): along
/// the closed loop V̇ = −k_Ω ‖e_Ω‖². With a reference at rest it is the PD law's V
/// [PET-ERG Sec. III-A].
[[nodiscard]] inline double tracking_lyapunov(const Mat3& J_b, const Mat3& R_ib,
                                              const Vec3& omega_b, const TrackingReference& ref,
                                              const TrackingGains& gains) noexcept {
  const Mat3 R_e = R_ib.transpose() * ref.R_ib;
  const TrackingError e = tracking_error_of(R_e, omega_b, ref);
  return 0.5 * e.e_Omega.dot(J_b * e.e_Omega) + gains.k_R * lie::phi(R_e);
}

}  // namespace attiguard::control
