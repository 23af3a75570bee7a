#pragma once
/// @file symmetric_eigen.hpp
/// Eigenvalues of the symmetric part of a 3×3 matrix: the one definition of λ_min / λ_max of an
/// inertia matrix, a metric block or a Gram matrix (docs/architecture.md, "One definition").

#include "attiguard/lie/so3.hpp"

namespace attiguard::lie {

/// Eigenvalues of the symmetric part ½(M + Mᵀ), ascending (Eigen's self-adjoint solver,
/// eigenvalues only). For a symmetric M the symmetric part is M itself, bit for bit.
[[nodiscard]] Vec3 symmetric_eigenvalues(const Mat3& M);

/// Smallest eigenvalue of ½(M + Mᵀ), e.g. the smallest principal moment of an inertia J.
[[nodiscard]] double lambda_min(const Mat3& M);

/// Largest eigenvalue of ½(M + Mᵀ).
[[nodiscard]] double lambda_max(const Mat3& M);

}  // namespace attiguard::lie
