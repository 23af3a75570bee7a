#pragma once
/// @file metrics.hpp
/// The metrics of ConReach (contraction-reachability paper, Sec. 3.1): the P-metric on R³, the
/// left-invariant metric G_Q on SO(3) (Def. 1), the product metric G_Q × G_P (Def. 2), and
/// computable bounds on the left-invariant distance d_Q, which has no closed form:
///
///   upper (inclusion fact 1): the curve R1 exp(s ŵ), w = log(R1ᵀR2)^∨, s ∈ [0,1], joins R1 to R2
///         with constant body velocity w, so its G_Q-length is √(wᵀQw) ≥ d_Q(R1, R2);
///   lower (inclusion fact 2): every curve has G_Q-speed ≥ √λ_min(Q)·(bi-invariant speed), so
///         d_Q(R1, R2) ≥ √λ_min(Q)·d(R1, R2); hence B_Q(R0, r) ⊆ bi-invariant ball r/√λ_min(Q).
/// Proofs: docs/reach.md, "Inclusion facts".

#include <string>

#include "attiguard/reach/interval.hpp"

namespace attiguard::reach {

/// Q (on SO(3)) and P (on R³) of the product metric G_Q × G_P (Def. 2).
struct ProductMetric {
  Mat3 Q{Mat3::Identity()};
  Mat3 P{Mat3::Identity()};
};

/// Smallest / largest eigenvalue of the symmetric part of M.
[[nodiscard]] double lambda_min(const Mat3& M);
[[nodiscard]] double lambda_max(const Mat3& M);
/// True when M is finite, symmetric (to 1e-12 relative) and λ_min > 0.
[[nodiscard]] bool is_spd(const Mat3& M);
/// Throws InputError "`what`: … (must be symmetric positive definite)" unless is_spd(M).
void require_spd(const Mat3& M, const std::string& what);

/// ⟨u, v⟩ of G_Q at any R for body vectors u = (RᵀK1)^∨, v = (RᵀK2)^∨ (eq. (8)).
[[nodiscard]] inline double q_inner(const Mat3& Q, const Vec3& u, const Vec3& v) { return u.dot(Q * v); }
/// d_P(x1, x2) = ‖x1 − x2‖_P (Sec. 3.1.1).
[[nodiscard]] double p_distance(const Mat3& P, const Vec3& x1, const Vec3& x2);
/// Upper bound √(wᵀQw), w = log(R1ᵀR2)^∨, on d_Q(R1, R2).
[[nodiscard]] double dq_upper(const Mat3& Q, const Mat3& R1, const Mat3& R2);
/// Lower bound √λ_min(Q)·‖log(R1ᵀR2)‖ on d_Q(R1, R2).
[[nodiscard]] double dq_lower(const Mat3& Q, const Mat3& R1, const Mat3& R2);
/// Bounds on the product distance √(d_Q² + d_P²) (Sec. 3.1.3).
[[nodiscard]] double product_distance_upper(const ProductMetric& m, const Mat3& R1, const Vec3& w1,
                                            const Mat3& R2, const Vec3& w2);
[[nodiscard]] double product_distance_lower(const ProductMetric& m, const Mat3& R1, const Vec3& w1,
                                            const Mat3& R2, const Vec3& w2);

/// Radius of the bi-invariant ball containing B_Q(R0, r): r/√λ_min(Q) (inclusion fact 2).
[[nodiscard]] double attitude_enclosure_radius(const Mat3& Q, double r);
/// Half-widths of the box containing the P-ball {x : ‖x − x0‖_P ≤ r}: r √((P⁻¹)_kk).
[[nodiscard]] Vec3 p_ball_half_widths(const Mat3& P, double r);

}  // namespace attiguard::reach
