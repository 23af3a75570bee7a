#pragma once
/// @file adversarial_disturbance.hpp
/// The adversarial (worst-case) disturbance torque of `[imperfections] disturbance =
/// "adversarial"` (docs/pet-erg.md, section 11, "Adversarial disturbance"): chosen from the true
/// state (R, ω) and the governor's reference R_g as the worst case within ‖d‖ ≤ d̄ for two aims,
/// raising the Lyapunov function V of the PET-ERG paper (Sec. III-A) and driving the constrained
/// body axis towards the nearest cone boundary (2b). It needs the cones, so it lives in sim/ and
/// not in dynamics/. Header-only, on fixed-size Eigen types and the flight layers alone: the
/// evaluation is allocation-free and noexcept (it runs inside the integrator's vector field; test
/// `AllocationFree.AdversarialDisturbanceInAFlightLoop`).

#include <Eigen/Eigenvalues>
#include <cstddef>
#include <limits>
#include <span>

#include "attiguard/core/name_table.hpp"
#include "attiguard/governor/cone_constraint.hpp"
#include "attiguard/lie/so3.hpp"

namespace attiguard::sim {

/// When the adversarial disturbance is recomputed (docs/pet-erg.md, section 11): at each control
/// instant and held over the control period, or at every evaluation of the vector field.
enum class DisturbanceUpdate { control, continuous };

/// Names of DisturbanceUpdate in scenario files (`[imperfections] disturbance_update`).
inline constexpr NameTable<DisturbanceUpdate, 2> kDisturbanceUpdateNames{
    {{{DisturbanceUpdate::control, "control"}, {DisturbanceUpdate::continuous, "continuous"}}}};

/// The scenario's settings of the adversary (`[imperfections]`, docs/scenario-format.md).
struct AdversarySettings {
  DisturbanceUpdate update{DisturbanceUpdate::control};  ///< `disturbance_update`
  double weight{0.5};  ///< `adversary_weight` w ∈ [0, 1]: 1 = only the V aim, 0 = only the cone aim
};

/// What the adversary knows, precomputed once (set-up; docs/pet-erg.md, section 11).
namespace detail {

/// Below this norm a rate or a direction counts as zero (its direction is rounding noise).
inline constexpr double kAdversaryTiny = 1e-12;

/// v/‖v‖, or zero when ‖v‖ ≤ kAdversaryTiny.
[[nodiscard]] inline lie::Vec3 unit_or_zero(const lie::Vec3& v) noexcept {
  const double n = v.norm();
  return n > kAdversaryTiny ? lie::Vec3(v / n) : lie::Vec3(lie::Vec3::Zero());
}

}  // namespace detail

struct AdversaryModel {
  lie::Mat3 J_inv{lie::Mat3::Identity()};           ///< J⁻¹ [1/(kg·m²)]
  lie::Vec3 minor_axis_b{lie::Vec3::UnitX()};       ///< unit eigenvector of J's smallest moment
  std::span<const governor::ConeConstraint> cones;  ///< the pointing constraints [PET-ERG eq. (2b)]
  double bound{0.0};                                ///< d̄ [N·m]
  double weight{0.5};                               ///< w of the combination
};

/// The model of inertia J (symmetric positive definite), cones (must outlive the model), bound
/// d̄ ≥ 0 and weight w ∈ [0, 1] (docs/pet-erg.md, section 11).
[[nodiscard]] inline AdversaryModel make_adversary(const lie::Mat3& J,
                                                   std::span<const governor::ConeConstraint> cones,
                                                   double bound, double weight) noexcept {
  AdversaryModel m;
  m.J_inv = J.inverse();
  Eigen::SelfAdjointEigenSolver<lie::Mat3> eig;
  eig.computeDirect(J);
  m.minor_axis_b = eig.eigenvectors().col(0).normalized();  // eigenvalues ascending
  m.cones = cones;
  m.bound = bound;
  m.weight = weight;
  return m;
}

/// Aim (a): the unit d maximising the rise of V = ½ωᵀJω + k_p φ(RᵀR_g) (PET-ERG paper,
/// Sec. III-A), whose derivative depends on d only through ωᵀd: ω/‖ω‖. For ‖ω‖ ≤ 1e-12 rad/s
/// (V̇ does not depend on d) the maximiser of the leading term k_p dᵀJ⁻¹s of V̈ with
/// s = sk(RᵀR_g)^∨, i.e. unit(J⁻¹s); for s = 0 too, the maximiser of V̈ = dᵀJ⁻¹d, J's minor axis
/// (docs/pet-erg.md, section 11).
[[nodiscard]] inline lie::Vec3 lyapunov_ascent_direction(const AdversaryModel& model,
                                                         const lie::Mat3& R_ib,
                                                         const lie::Vec3& omega_b,
                                                         const lie::Mat3& R_g) noexcept {
  if (omega_b.norm() > detail::kAdversaryTiny) {
    return omega_b.normalized();
  }
  const lie::Vec3 s = lie::vee(lie::sk(R_ib.transpose() * R_g));
  const lie::Vec3 d = detail::unit_or_zero(model.J_inv * s);
  return d.isZero() ? model.minor_axis_b : d;
}

/// The cone of smallest margin a_cᵀ R a_b − cos θ_c [PET-ERG eq. (2b)], or −1 without cones.
[[nodiscard]] inline int nearest_cone(std::span<const governor::ConeConstraint> cones,
                                      const lie::Mat3& R_ib) noexcept {
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

/// Aim (b): the unit d minimising m̈ of the margin m = a_cᵀ R a_b − cos θ_c of `cone`: ṁ = vᵀω
/// with v = a_b × Rᵀa_c, so m̈ contains vᵀJ⁻¹d, minimised over the ball by d = −unit(J⁻¹v);
/// zero when v = 0 (a_b along ±Rᵀa_c: no first-order effect), docs/pet-erg.md, section 11.
[[nodiscard]] inline lie::Vec3 cone_descent_direction(const AdversaryModel& model,
                                                      const governor::ConeConstraint& cone,
                                                      const lie::Mat3& R_ib) noexcept {
  const lie::Vec3 v = cone.axis_b.cross(R_ib.transpose() * cone.direction_i);
  return -detail::unit_or_zero(model.J_inv * v);
}

/// d = d̄ · unit(w d_V + (1 − w) d_cone) (docs/pet-erg.md, section 11): d_V of aim (a), d_cone of
/// aim (b) for the nearest cone; without cones, or when d_cone = 0, d̄ d_V; when w d_V +
/// (1 − w) d_cone vanishes, the aim of the larger weight (d_V at w = ½). ‖d‖ ≤ d̄ always, = d̄
/// except at a fully degenerate state.
[[nodiscard]] inline lie::Vec3 adversarial_torque(const AdversaryModel& model,
                                                  const lie::Mat3& R_ib, const lie::Vec3& omega_b,
                                                  const lie::Mat3& R_g) noexcept {
  const lie::Vec3 d_V = lyapunov_ascent_direction(model, R_ib, omega_b, R_g);
  const int i = nearest_cone(model.cones, R_ib);
  const lie::Vec3 d_cone =
      i < 0 ? lie::Vec3(lie::Vec3::Zero())
            : cone_descent_direction(model, model.cones[static_cast<std::size_t>(i)], R_ib);
  if (d_cone.isZero()) {
    return model.bound * d_V;
  }
  const lie::Vec3 combined =
      detail::unit_or_zero(model.weight * d_V + (1.0 - model.weight) * d_cone);
  if (!combined.isZero()) {
    return model.bound * combined;
  }
  return model.bound * (model.weight >= 0.5 ? d_V : d_cone);
}

/// The same from the raw data (for tests): true R, ω, the reference R_g, inertia J, the cones,
/// d̄ and w (docs/pet-erg.md, section 11).
[[nodiscard]] inline lie::Vec3 adversarial_torque(const lie::Mat3& R_ib, const lie::Vec3& omega_b,
                                                  const lie::Mat3& R_g, const lie::Mat3& J,
                                                  std::span<const governor::ConeConstraint> cones,
                                                  double bound, double weight) noexcept {
  return adversarial_torque(make_adversary(J, cones, bound, weight), R_ib, omega_b, R_g);
}

}  // namespace attiguard::sim
