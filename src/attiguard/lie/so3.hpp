#pragma once
/// @file so3.hpp
/// The rotation group SO(3): hat/vee, exponential and logarithm, distances, projection.
///
/// Conventions (docs/conventions.md): R maps body to inertial coordinates, the kinematics are
/// Ṙ = R ω̂ [PET-ERG eq. (1)]. All functions are allocation-free and noexcept, so they may be
/// called from flight-loop code.

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products

namespace attiguard::lie {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

/// Hat map R³ → so(3) with hat(x) y = x × y (PET-ERG paper, Notation; Waypoint paper S(·)).
[[nodiscard]] Mat3 hat(const Vec3& x) noexcept;

/// Vee map so(3) → R³, inverse of hat. Reads the three independent entries of a skew matrix
/// (the input is not checked to be skew; use vee(sk(A)) for a general matrix).
[[nodiscard]] Vec3 vee(const Mat3& X) noexcept;

/// Skew-symmetric part sk(A) = (A − Aᵀ)/2 (PET-ERG paper, Notation).
[[nodiscard]] Mat3 sk(const Mat3& A) noexcept;

/// Exponential map so(3) → SO(3), Rodrigues' formula exp(ŵ) = I + (sin θ/θ) ŵ + ((1−cos θ)/θ²) ŵ²
/// with θ = ‖w‖, and Taylor series of both coefficients for θ < 1e-4 [ConReach Sec. 2].
[[nodiscard]] Mat3 exp(const Vec3& w) noexcept;

/// Principal logarithm SO(3) → R³ (rotation vector, ‖w‖ ∈ [0, π]): exp(log(R)) = R.
/// θ = atan2(‖vee(R − Rᵀ)‖/2, (tr R − 1)/2); for small θ the series of θ/sin θ, for θ > π/2 the
/// axis is read from the symmetric part (R + Rᵀ)/2 − cos θ I = (1 − cos θ) k kᵀ, which is exact
/// at θ = π, and its sign from the skew part. At exactly θ = π either of ±πk is returned.
[[nodiscard]] Vec3 log(const Mat3& R) noexcept;

/// Bi-invariant (geodesic) distance d(R1, R2) = ‖log(R1ᵀ R2)‖ ∈ [0, π] (docs/conventions.md).
[[nodiscard]] double distance(const Mat3& R1, const Mat3& R2) noexcept;

/// Attitude error function φ(R) = ½ tr(I − R) = 1 − cos θ ∈ [0, 2] [PET-ERG Sec. III-A].
[[nodiscard]] double phi(const Mat3& R) noexcept;

/// Closest rotation to a near-rotation M in the Frobenius norm (polar factor via SVD, with the
/// determinant sign fixed). For input cleaning only: integrators never call this.
[[nodiscard]] Mat3 project_to_so3(const Mat3& M) noexcept;

/// ‖MᵀM − I‖_F: how far M is from orthonormal (0 for an exact rotation).
[[nodiscard]] double orthonormality_error(const Mat3& M) noexcept;

/// True when ‖MᵀM − I‖_F ≤ tol, det M > 0 and every entry is finite.
[[nodiscard]] bool is_rotation(const Mat3& M, double tol = 1e-9) noexcept;

}  // namespace attiguard::lie
