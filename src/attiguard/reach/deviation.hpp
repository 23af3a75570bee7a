#pragma once
/// @file deviation.hpp
/// The state of the tube's comparison system (docs/reach.md, "Enclosure U_i", step 2; tube.hpp):
/// bounds on how far a state (R, ω) lies from a nominal point (R_n, ω_n),
///   |ω_k − ω_n,k| ≤ d_k (k = 1, 2, 3),   ‖ω − ω_n‖ ≤ e_ω,   d(R, R_n) ≤ e_R,
/// and, laid out the same way, the nominal's integration error ε of nominal_error.hpp.
/// The linear comparison system ż ≤ M z acts on the vector z = (d_1, d_2, d_3, e_ω, e_R).

#include <Eigen/Core>

#include "attiguard/lie/so3.hpp"

namespace attiguard::reach {

/// z of the comparison system with its components named (docs/reach.md, "Enclosure U_i").
struct Deviation {
  /// z = (d_1, d_2, d_3, e_ω, e_R): the comparison system's vector (docs/reach.md, "Enclosure
  /// U_i", step 2).
  using Vector = Eigen::Matrix<double, 5, 1>;

  lie::Vec3 d_omega_b{lie::Vec3::Zero()};  ///< d_k: per body axis, |ω_k − ω_n,k| ≤ d_k [rad/s]
  double e_omega_b{0.0};                   ///< e_ω: ‖ω − ω_n‖ ≤ e_ω [rad/s]
  double e_R{0.0};                         ///< e_R: bi-invariant d(R, R_n) ≤ e_R [rad]

  /// The bounds of every state of B_I(R_n, attitude_radius) × B_I(ω_n, omega_radius): d_k = e_ω =
  /// omega_radius, e_R = attitude_radius (the initial set, conreach.hpp).
  [[nodiscard]] static Deviation of_balls(double attitude_radius, double omega_radius);
  /// z of the comparison system (docs/reach.md, "Enclosure U_i", step 2).
  [[nodiscard]] Vector vector() const;
  /// The deviation whose z is `z`.
  [[nodiscard]] static Deviation from_vector(const Vector& z);
  /// Half-widths of the ω box around ω_n: min(d_k, e_ω) per axis.
  [[nodiscard]] lie::Vec3 omega_half_widths() const;
  /// Componentwise minimum: the bounds that hold when both hold.
  [[nodiscard]] Deviation min(const Deviation& other) const;
  /// Every component finite.
  [[nodiscard]] bool all_finite() const;
  /// Every component equal (the tube is propagated again only for a different start).
  [[nodiscard]] bool operator==(const Deviation& other) const;
};

}  // namespace attiguard::reach
