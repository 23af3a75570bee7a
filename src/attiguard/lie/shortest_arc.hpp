#pragma once
/// @file shortest_arc.hpp
/// The smallest rotation taking one direction onto another, defined for every pair of directions.

#include "attiguard/lie/quaternion.hpp"
#include "attiguard/lie/so3.hpp"

namespace attiguard::lie {

/// Unit vector orthogonal to the non-zero vector a, chosen deterministically (a × e_j with e_j
/// the basis vector least aligned with a). Used to resolve the anti-parallel case.
[[nodiscard]] Vec3 any_orthogonal(const Vec3& a) noexcept;

/// Quaternion of the shortest-arc rotation R with R â = b̂ (â, b̂ the normalised inputs).
/// [Waypoint eqs. (8), (10), (11)] with the sine/cosine erratum fixed (docs/errata.md, Waypoint 1):
/// q = [cos(ϑ/2), k sin(ϑ/2)], k = â × b̂ / ‖â × b̂‖, computed as [η, â × b̂ / (2η)] for ϑ ≤ π/2
/// (smooth through ϑ = 0) and from atan2 beyond (accurate near π). When â = −b̂ it is by π about
/// any_orthogonal(â). Zero input vectors give the identity.
[[nodiscard]] Quat shortest_arc_quat(const Vec3& a, const Vec3& b) noexcept;

/// Rotation matrix of shortest_arc_quat(a, b): shortest_arc(a, b) · â = b̂.
[[nodiscard]] Mat3 shortest_arc(const Vec3& a, const Vec3& b) noexcept;

}  // namespace attiguard::lie
