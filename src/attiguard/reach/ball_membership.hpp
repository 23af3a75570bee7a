#pragma once
/// @file ball_membership.hpp
/// A cheap sufficient test that the sampled soundness check's attitude distance lies within a
/// bi-invariant ball (docs/reach.md, "Inclusion facts" 4; docs/performance.md, "ConReach",
/// "Soundness check without atan2"): it proves lie::distance(C, R) ≤ L for the value that
/// lie::distance computes, so the check may skip the logarithm (its atan2) without changing a
/// reported number. When the test fails nothing is proved and the caller computes the distance.
///
/// With M = CᵀR, s = ½‖vee(M − Mᵀ)‖ and c = ½(tr M − 1), lie::log takes θ = atan2(s, c) and
/// returns a vector of norm θ(1 ± 10⁻¹⁴) (θ ≥ 10⁻⁴, c > 0) or s(1 + θ²/6 + …) ≤ 1.0001·10⁻⁴
/// (θ < 10⁻⁴). For c > 0, θ = atan(s/c), so s ≤ c·tan(L′) gives θ ≤ L′ = L(1 − 10⁻⁶). The margin
/// 10⁻⁶L ≥ 10⁻⁹ (L ≥ 10⁻³ required) covers the test's own rounding and the difference between its
/// s, c and lie::log's (same formulas, ≈10⁻¹⁵ apart; c ∈ [½, 1 + 10⁻¹²] keeps atan's condition
/// number below 4 and M near orthogonal), far above the ≈10⁻¹⁴ of atan2's and the norm's rounding.

#include "attiguard/lie/so3.hpp"

namespace attiguard::reach {

/// lie::distance(center, R) ≤ limit, proved without atan2 where possible.
class AttitudeBallTest {
 public:
  AttitudeBallTest() = default;
  /// limit: the largest distance that counts as inside (the check's radius·(1 + 10⁻¹²)).
  AttitudeBallTest(const lie::Mat3& center, double limit) noexcept : center_(center), limit_(limit) {
    usable_ = limit >= 1e-3 && limit <= 1.0;
    const double t = usable_ ? std::tan(limit * (1.0 - 1e-6)) : 0.0;
    tan2_ = t * t;
  }

  /// True only when lie::distance(center, R) ≤ limit for the computed distance; false says
  /// nothing (NaN or infinite entries give false).
  [[nodiscard]] bool proves_inside(const lie::Mat3& R) const noexcept {
    if (!usable_) return false;
    const lie::Mat3 M = center_.transpose() * R;
    const double c = 0.5 * (M.trace() - 1.0);
    if (!(c >= 0.5 && c <= 1.0 + 1e-12)) return false;
    const double sx = M(2, 1) - M(1, 2);
    const double sy = M(0, 2) - M(2, 0);
    const double sz = M(1, 0) - M(0, 1);
    const double s2 = 0.25 * (sx * sx + sy * sy + sz * sz);  // s²
    return s2 <= c * c * tan2_;
  }

  /// lie::distance(center, R) − limit, or 0 when proves_inside(R) shows it is ≤ 0.
  [[nodiscard]] double excess_or_zero(const lie::Mat3& R) const noexcept {
    return proves_inside(R) ? 0.0 : lie::distance(center_, R) - limit_;
  }

  [[nodiscard]] const lie::Mat3& center() const noexcept { return center_; }
  [[nodiscard]] double limit() const noexcept { return limit_; }

 private:
  lie::Mat3 center_{lie::Mat3::Identity()};
  double limit_{0.0};
  bool usable_{false};
  double tan2_{0.0};
};

}  // namespace attiguard::reach
