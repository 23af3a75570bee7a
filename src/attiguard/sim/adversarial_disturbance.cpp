// The adversarial disturbance torque (docs/pet-erg.md, section 11, "Adversarial disturbance").

#include "attiguard/sim/adversarial_disturbance.hpp"

#include <Eigen/Eigenvalues>
#include <cstddef>
#include <limits>

namespace attiguard::sim {

namespace {

using lie::Mat3;
using lie::Vec3;

/// Below this norm a rate or a direction counts as zero (its direction is rounding noise).
constexpr double kTiny = 1e-12;

/// v/‖v‖, or zero when ‖v‖ ≤ kTiny.
Vec3 unit_or_zero(const Vec3& v) noexcept {
  const double n = v.norm();
  return n > kTiny ? Vec3(v / n) : Vec3(Vec3::Zero());
}

}  // namespace

AdversaryModel make_adversary(const Mat3& J, std::span<const governor::ConeConstraint> cones,
                              double bound, double weight) noexcept {
  AdversaryModel m;
  m.J_inv = J.inverse();
  Eigen::SelfAdjointEigenSolver<Mat3> eig;
  eig.computeDirect(J);
  m.minor_axis_b = eig.eigenvectors().col(0).normalized();  // eigenvalues ascending
  m.cones = cones;
  m.bound = bound;
  m.weight = weight;
  return m;
}

Vec3 lyapunov_ascent_direction(const AdversaryModel& model, const Mat3& R_ib, const Vec3& omega_b,
                               const Mat3& R_g) noexcept {
  if (omega_b.norm() > kTiny) {
    return omega_b.normalized();
  }
  const Vec3 s = lie::vee(lie::sk(R_ib.transpose() * R_g));
  const Vec3 d = unit_or_zero(model.J_inv * s);
  return d.isZero() ? model.minor_axis_b : d;
}

int nearest_cone(std::span<const governor::ConeConstraint> cones, const Mat3& R_ib) noexcept {
  int best = -1;
  double best_margin = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < cones.size(); ++i) {
    const double m = governor::pointing_margin(cones[i], R_ib);
    if (m < best_margin) {
      best_margin = m;
      best = static_cast<int>(i);
    }
  }
  return best;
}

Vec3 cone_descent_direction(const AdversaryModel& model, const governor::ConeConstraint& cone,
                            const Mat3& R_ib) noexcept {
  const Vec3 v = cone.axis_b.cross(R_ib.transpose() * cone.direction_i);
  return -unit_or_zero(model.J_inv * v);
}

Vec3 adversarial_torque(const AdversaryModel& model, const Mat3& R_ib, const Vec3& omega_b,
                        const Mat3& R_g) noexcept {
  const Vec3 d_V = lyapunov_ascent_direction(model, R_ib, omega_b, R_g);
  const int i = nearest_cone(model.cones, R_ib);
  const Vec3 d_cone = i < 0 ? Vec3(Vec3::Zero())
                            : cone_descent_direction(model, model.cones[static_cast<std::size_t>(i)], R_ib);
  if (d_cone.isZero()) {
    return model.bound * d_V;
  }
  const Vec3 combined = unit_or_zero(model.weight * d_V + (1.0 - model.weight) * d_cone);
  if (!combined.isZero()) {
    return model.bound * combined;
  }
  return model.bound * (model.weight >= 0.5 ? d_V : d_cone);
}

Vec3 adversarial_torque(const Mat3& R_ib, const Vec3& omega_b, const Mat3& R_g, const Mat3& J,
                        std::span<const governor::ConeConstraint> cones, double bound,
                        double weight) noexcept {
  return adversarial_torque(make_adversary(J, cones, bound, weight), R_ib, omega_b, R_g);
}

}  // namespace attiguard::sim
