#include "attiguard/control/rct_allocation.hpp"

#include <algorithm>
#include <cmath>

namespace attiguard::control {

AllocationMatrix rct_allocation_matrix() noexcept {
  AllocationMatrix B;
  B << 1, -1, 0, 0, 0, 0,  //
      0, 0, 1, -1, 0, 0,   //
      0, 0, 0, 0, 1, -1;
  return B;
}

RctVector rct_pseudo_inverse(const lie::Vec3& f_b) noexcept {
  return 0.5 * rct_allocation_matrix().transpose() * f_b;  // B Bᵀ = 2 I
}

RctVector rct_allocate(const lie::Vec3& f_b) noexcept {
  RctVector T = rct_pseudo_inverse(f_b);
  for (int k = 0; k < 3; ++k) {
    // Null-space direction of B for the pair (2k, 2k+1) is [1, 1]: shift by |f_k|/2.
    const double shift = 0.5 * std::abs(f_b(k));
    T(2 * k) += shift;
    T(2 * k + 1) += shift;
  }
  return T;
}

RctVector rct_bang_bang(const RctVector& T, double f_max, double threshold) noexcept {
  RctVector out;
  for (int j = 0; j < 6; ++j) {
    out(j) = T(j) >= threshold * f_max && T(j) > 0.0 ? f_max : 0.0;
  }
  return out;
}

lie::Vec3 rct_body_force(const RctVector& T) noexcept { return rct_allocation_matrix() * T; }

}  // namespace attiguard::control
