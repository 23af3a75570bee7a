#pragma once
/// @file so3.hpp
/// The rotation group SO(3): hat/vee, exponential and logarithm, distances, projection.
///
/// Conventions (docs/conventions.md): R maps body to inertial coordinates, the kinematics are
/// Ṙ = R ω̂ [PET-ERG eq. (1)]. All functions are allocation-free and noexcept, so they may be
/// called from flight-loop code.

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products
#include <cmath>

namespace attiguard::lie {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

/// Hat map R³ → so(3) with hat(x) y = x × y (PET-ERG paper, Notation; Waypoint paper S(·)).
[[nodiscard]] inline Mat3 hat(const Vec3& x) noexcept {
  Mat3 X;
  X << 0.0, -x.z(), x.y(),  //
      x.z(), 0.0, -x.x(),   //
      -x.y(), x.x(), 0.0;
  return X;
}

/// Vee map so(3) → R³, inverse of hat. Reads the three independent entries of a skew matrix
/// (the input is not checked to be skew; use vee(sk(A)) for a general matrix).
[[nodiscard]] inline Vec3 vee(const Mat3& X) noexcept { return Vec3(X(2, 1), X(0, 2), X(1, 0)); }

/// Skew-symmetric part sk(A) = (A − Aᵀ)/2 (PET-ERG paper, Notation).
[[nodiscard]] inline Mat3 sk(const Mat3& A) noexcept { return 0.5 * (A - A.transpose()); }

/// The coefficients of Rodrigues' formula [ConReach Sec. 2] at θ = ‖w‖, a = sin θ/θ and
/// b = (1 − cos θ)/θ², and of the inverse right Jacobian c = 1/θ² − (1 + cos θ)/(2θ sin θ)
/// (lie/jacobians.hpp), from one sin θ and one cos θ; Taylor series of all three for θ < 1e-4.
struct ExpCoefficients {
  double a;  ///< sin θ/θ
  double b;  ///< (1 − cos θ)/θ²
  double c;  ///< 1/θ² − (1 + cos θ)/(2θ sin θ) (valid for θ < 2π, θ ≠ π)
};

/// exp's and J_r⁻¹'s coefficients at w [ConReach Sec. 2] (docs/performance.md, "Lean core").
/// The same operations as exp and right_jacobian_inverse apply separately, so the results are
/// bit-for-bit theirs (the RKMK stages use chart_coefficients instead).
[[nodiscard]] inline ExpCoefficients exp_coefficients(const Vec3& w) noexcept {
  const double theta2 = w.squaredNorm();
  const double theta = std::sqrt(theta2);
  if (theta < 1e-4) {
    return {1.0 - theta2 / 6.0 + theta2 * theta2 / 120.0,  //
            0.5 - theta2 / 24.0 + theta2 * theta2 / 720.0,
            1.0 / 12.0 + theta2 / 720.0 + theta2 * theta2 / 30240.0};
  }
  const double s = std::sin(theta);
  const double co = std::cos(theta);
  return {s / theta, (1.0 - co) / theta2, 1.0 / theta2 - (1.0 + co) / (2.0 * theta * s)};
}

/// The coefficients a, b, c of ExpCoefficients for the charts of the RKMK stages
/// (integrate/product_state.hpp; docs/performance.md, "Lean core (issue 48, item 2)") [ConReach
/// Sec. 2]: for θ² < 10⁻² their Taylor series in θ² to degree 4, with no square root, sine,
/// cosine or division; the first term left out is below 3·10⁻¹⁸ of each coefficient at θ = 0.1,
/// so the series is exact to double precision there (and has none of the cancellation of
/// 1 − cos θ and 1/θ² − …). For θ² ≥ 10⁻² the closed forms of exp_coefficients.
[[nodiscard]] inline ExpCoefficients chart_coefficients(const Vec3& w) noexcept {
  const double t2 = w.squaredNorm();
  if (t2 < 1e-2) {
    const double t4 = t2 * t2;
    const double t6 = t4 * t2;
    const double t8 = t4 * t4;
    // Estrin's scheme: (p0 + p1 θ²) + θ⁴ (p2 + p3 θ²) + p4 θ⁸, three products deep.
    const double a = (1.0 - (1.0 / 6.0) * t2) + ((1.0 / 120.0) * t4 - (1.0 / 5040.0) * t6) +
                     (1.0 / 362880.0) * t8;
    const double b = (0.5 - (1.0 / 24.0) * t2) + ((1.0 / 720.0) * t4 - (1.0 / 40320.0) * t6) +
                     (1.0 / 3628800.0) * t8;
    const double c = (1.0 / 12.0 + (1.0 / 720.0) * t2) + ((1.0 / 30240.0) * t4 + (1.0 / 1209600.0) * t6) +
                     (1.0 / 47900160.0) * t8;
    return {a, b, c};
  }
  const double theta = std::sqrt(t2);
  const double s = std::sin(theta);
  const double co = std::cos(theta);
  return {s / theta, (1.0 - co) / t2, 1.0 / t2 - (1.0 + co) / (2.0 * theta * s)};
}

/// R exp(ŵ) = R + a R ŵ + b (R ŵ) ŵ, Rodrigues' formula [ConReach Sec. 2] multiplied out with R
/// (coefficients of chart_coefficients or exp_coefficients): row r of R ŵ is R_r × w, so R ŵ
/// and (R ŵ) ŵ need no coefficient and are formed while a and b are computed; the rotation is
/// not re-projected (docs/performance.md, "Lean core (issue 48, item 2)").
[[nodiscard]] inline Mat3 times_exp(const Mat3& R, const Vec3& w, double a, double b) noexcept {
  Mat3 out;
  for (int r = 0; r < 3; ++r) {
    const double u0 = R(r, 0);
    const double u1 = R(r, 1);
    const double u2 = R(r, 2);
    // m = R_r × w, n = m × w.
    const double m0 = u1 * w.z() - u2 * w.y();
    const double m1 = u2 * w.x() - u0 * w.z();
    const double m2 = u0 * w.y() - u1 * w.x();
    const double n0 = m1 * w.z() - m2 * w.y();
    const double n1 = m2 * w.x() - m0 * w.z();
    const double n2 = m0 * w.y() - m1 * w.x();
    out(r, 0) = u0 + (a * m0 + b * n0);
    out(r, 1) = u1 + (a * m1 + b * n1);
    out(r, 2) = u2 + (a * m2 + b * n2);
  }
  return out;
}

/// Rodrigues' formula exp(ŵ) = I + a ŵ + b ŵ² [ConReach Sec. 2] with the coefficients of
/// exp_coefficients, written out entry by entry: the operations Eigen performs for
/// I + a·hat(w) + b·(hat(w)·hat(w)) (which it evaluates as (b·hat(w))·hat(w)) without the
/// products by hat(w)'s zeros, so the result is bit-for-bit that expression's
/// (docs/performance.md, "Lean core").
[[nodiscard]] inline Mat3 rodrigues(const Vec3& w, double a, double b) noexcept {
  const double x = w.x();
  const double y = w.y();
  const double z = w.z();
  const double bx = b * x;
  const double by = b * y;
  const double bz = b * z;
  Mat3 E;
  E(0, 0) = 1.0 + (-(bz * z) - by * y);
  E(1, 1) = 1.0 + (-(bz * z) - bx * x);
  E(2, 2) = 1.0 + (-(by * y) - bx * x);
  E(0, 1) = -(a * z) + by * x;
  E(1, 0) = a * z + bx * y;
  E(0, 2) = a * y + bz * x;
  E(2, 0) = -(a * y) + bx * z;
  E(1, 2) = -(a * x) + bz * y;
  E(2, 1) = a * x + by * z;
  return E;
}

/// Exponential map so(3) → SO(3), Rodrigues' formula exp(ŵ) = I + (sin θ/θ) ŵ + ((1−cos θ)/θ²) ŵ²
/// with θ = ‖w‖, and Taylor series of both coefficients for θ < 1e-4 [ConReach Sec. 2].
[[nodiscard]] inline Mat3 exp(const Vec3& w) noexcept {
  const ExpCoefficients k = exp_coefficients(w);
  return rodrigues(w, k.a, k.b);
}

/// Principal logarithm SO(3) → R³ (rotation vector, ‖w‖ ∈ [0, π]): exp(log(R)) = R.
/// θ = atan2(‖vee(R − Rᵀ)‖/2, (tr R − 1)/2); for small θ the series of θ/sin θ, for θ > π/2 the
/// axis is read from the symmetric part (R + Rᵀ)/2 − cos θ I = (1 − cos θ) k kᵀ, which is exact
/// at θ = π, and its sign from the skew part. At exactly θ = π either of ±πk is returned.
[[nodiscard]] Vec3 log(const Mat3& R) noexcept;

/// Bi-invariant (geodesic) distance d(R1, R2) = ‖log(R1ᵀ R2)‖ ∈ [0, π] (docs/conventions.md).
[[nodiscard]] double distance(const Mat3& R1, const Mat3& R2) noexcept;

/// Attitude error function φ(R) = ½ tr(I − R) = 1 − cos θ ∈ [0, 2] [PET-ERG Sec. III-A].
[[nodiscard]] inline double phi(const Mat3& R) noexcept { return 0.5 * (3.0 - R.trace()); }

/// Closest rotation to a near-rotation M in the Frobenius norm (polar factor via SVD, with the
/// determinant sign fixed). For input cleaning only: integrators never call this.
[[nodiscard]] Mat3 project_to_so3(const Mat3& M) noexcept;

/// ‖MᵀM − I‖_F: how far M is from orthonormal (0 for an exact rotation).
[[nodiscard]] double orthonormality_error(const Mat3& M) noexcept;

/// True when ‖MᵀM − I‖_F ≤ tol, det M > 0 and every entry is finite.
[[nodiscard]] bool is_rotation(const Mat3& M, double tol = 1e-9) noexcept;

}  // namespace attiguard::lie
