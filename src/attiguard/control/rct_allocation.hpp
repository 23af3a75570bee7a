#pragma once
/// @file rct_allocation.hpp
/// Allocation of a body force to six on/off reaction-control thrusters, Waypoint paper
/// [Waypoint eqs. (29)-(30)], and their bang-bang modulation.

#include <Eigen/Core>

#include "attiguard/lie/so3.hpp"

namespace attiguard::control {

/// Six thruster forces [f_1 … f_6] (thruster j pushes along column j of B) [N].
using RctVector = Eigen::Matrix<double, 6, 1>;
/// The 3×6 allocation matrix.
using AllocationMatrix = Eigen::Matrix<double, 3, 6>;

/// B of [Waypoint eq. (30)]: thrusters 1/2 push ±x_b, 3/4 ±y_b, 5/6 ±z_b.
[[nodiscard]] AllocationMatrix rct_allocation_matrix() noexcept;

/// T = B† f of [Waypoint eq. (29)] (B† = Bᵀ(BBᵀ)⁻¹ = ½ Bᵀ): the minimum-norm solution, which has a negative
/// entry for every non-zero force component — not realisable by thrusters that only push.
[[nodiscard]] RctVector rct_pseudo_inverse(const lie::Vec3& f_b) noexcept;

/// The realisable allocation: B† f plus the null-space component of B that makes every entry
/// non-negative with least norm, i.e. T_{2k−1} = max(f_k, 0), T_{2k} = max(−f_k, 0). B T = f
/// exactly; each T_j ≤ f_max when |f_k| ≤ f_max. Allocation-free.
[[nodiscard]] RctVector rct_allocate(const lie::Vec3& f_b) noexcept;

/// Bang-bang modulation after [Waypoint eq. (29)] [Waypoint Sec. V-B]: thruster j is on (f_max) when T_j ≥ threshold·f_max, else off (0).
[[nodiscard]] RctVector rct_bang_bang(const RctVector& T, double f_max, double threshold) noexcept;

/// Body force f^b_RCT = B T of thruster forces T [Waypoint eq. (30)].
[[nodiscard]] lie::Vec3 rct_body_force(const RctVector& T) noexcept;

}  // namespace attiguard::control
