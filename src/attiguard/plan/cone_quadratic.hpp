#pragma once
/// @file cone_quadratic.hpp
/// A pointing cone [PET-ERG eq. (2b)] as a quadratic form in the attitude quaternion
/// (docs/slew-planner.md, "Cones in quaternions"): for R = R(q) of a unit q,
/// a_cᵀ R a_b = qᵀ M q with M = [[a_cᵀa_b, (a_b × a_c)ᵀ], [a_b × a_c, a_b a_cᵀ + a_c a_bᵀ −
/// (a_cᵀa_b) I]] (Davenport's form). For any q ≠ 0, qᵀ(M − cos θ I)q ≥ 0 ⇔ the cone holds at the
/// attitude q/‖q‖: the constraint is homogeneous, so the quaternion's norm never matters.

#include <Eigen/Core>

#include "attiguard/lie/so3.hpp"

namespace attiguard::plan {

/// M of a_cᵀ R(q) a_b = qᵀ M q (docs/slew-planner.md, "Cones in quaternions").
[[nodiscard]] Eigen::Matrix4d cone_quadratic(const lie::Vec3& axis_b,
                                             const lie::Vec3& direction_i) noexcept;

}  // namespace attiguard::plan
