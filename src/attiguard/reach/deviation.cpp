#include "attiguard/reach/deviation.hpp"

#include <algorithm>
#include <cmath>

namespace attiguard::reach {

Deviation Deviation::of_balls(double attitude_radius, double omega_radius) {
  return {lie::Vec3::Constant(omega_radius), omega_radius, attitude_radius};
}

Deviation::Vector Deviation::vector() const {
  Vector z;
  z << d_omega_b(0), d_omega_b(1), d_omega_b(2), e_omega_b, e_R;
  return z;
}

Deviation Deviation::from_vector(const Vector& z) { return {z.head<3>(), z(3), z(4)}; }

lie::Vec3 Deviation::omega_half_widths() const { return d_omega_b.cwiseMin(e_omega_b); }

Deviation Deviation::min(const Deviation& other) const {
  return {d_omega_b.cwiseMin(other.d_omega_b), std::min(e_omega_b, other.e_omega_b),
          std::min(e_R, other.e_R)};
}

bool Deviation::all_finite() const {
  return d_omega_b.allFinite() && std::isfinite(e_omega_b) && std::isfinite(e_R);
}

bool Deviation::operator==(const Deviation& other) const {
  return d_omega_b == other.d_omega_b && e_omega_b == other.e_omega_b && e_R == other.e_R;
}

}  // namespace attiguard::reach
