#include "attiguard/governor/saddle_tie_break.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "attiguard/governor/navigation_field.hpp"

namespace attiguard::governor {

namespace {

/// The held cone, if its index names one of `cones`.
const ConeConstraint* held_cone(const TieBreak& tie, std::span<const ConeConstraint> cones) noexcept {
  if (!tie.active || tie.cone < 0 || static_cast<std::size_t>(tie.cone) >= cones.size()) return nullptr;
  return &cones[static_cast<std::size_t>(tie.cone)];
}

/// The active cone (c_i < ζ_i) with the largest ‖ρ_r,i‖ (the first of equals), −1 if none.
int strongest_active_cone(std::span<const ConeConstraint> cones, const Mat3& R_g) noexcept {
  int best = -1;
  double best_norm = -1.0;
  for (std::size_t i = 0; i < cones.size(); ++i) {
    if (!(cone_cosine(cones[i], R_g) < cones[i].zeta)) continue;
    const double n = repulsive_field(cones[i], R_g).norm();
    if (n > best_norm) {
      best = static_cast<int>(i);
      best_norm = n;
    }
  }
  return best;
}

/// The look-ahead of one side σ: the largest Σ_{j≠i} P_r,j met while the body axis is carried a
/// quarter turn around cone i at constant c_i, R = exp(θ â_c,i) R_g, θ = σ k π/(2 K), k = 1..K
/// (θ > 0 is the side of +ĥ_i: the body rate of exp(θ â_c) R_g is R_gᵀa_c, whose component
/// across a_b is along ĥ_i). 0 when no other band is met.
double side_barrier(std::span<const ConeConstraint> cones, std::size_t i, const Mat3& R_g, double sign) noexcept {
  constexpr int kSteps = 18;
  double barrier = 0.0;
  for (int k = 1; k <= kSteps; ++k) {
    const double theta = sign * (std::numbers::pi / 2.0) * static_cast<double>(k) / kSteps;
    const Mat3 R = lie::exp(theta * cones[i].direction_i) * R_g;
    double p = 0.0;
    for (std::size_t j = 0; j < cones.size(); ++j) {
      if (j != i) p += repulsive_potential(cones[j], R);
    }
    barrier = std::max(barrier, p);
  }
  return barrier;
}

}  // namespace

Vec3 tie_break_direction(const ConeConstraint& cone, const Mat3& R_g) noexcept {
  const Vec3 a_cb = R_g.transpose() * cone.direction_i;
  const Vec3 h = a_cb - cone.axis_b.dot(a_cb) * cone.axis_b;
  const double n = h.norm();
  // a_b (anti)parallel to a_cb: every direction is tangent, none is singled out.
  if (!(n > 1e-12)) return Vec3::Zero();
  return h / n;
}

TieBreakUpdate update_tie_break(const TieBreak& held, std::span<const ConeConstraint> cones,
                                const Mat3& R_g, const Mat3& R_d, double floor) noexcept {
  TieBreakUpdate u;
  u.state = held;
  const double attraction = attractive_field(R_g, R_d).norm();
  const Vec3 rho_n = navigation_field(cones, R_g, R_d);
  if (held.active) {
    const ConeConstraint* cone = held_cone(held, cones);
    bool release = cone == nullptr || !(attraction > floor) || !(cone_cosine(*cone, R_g) < cone->zeta);
    if (!release) {
      const Vec3 h = tie_break_direction(*cone, R_g);
      // The natural field now takes R_g around by itself (or ĥ is undefined).
      release = h.isZero() || rho_n.dot(held.sign * h) >= kTieBreakRelease * attraction;
    }
    if (release) {
      u.state = TieBreak{};
      u.released = true;
    }
    return u;
  }
  if (!(attraction > floor) || !(rho_n.norm() <= kTieBreakBalance * attraction)) return u;
  const int i = strongest_active_cone(cones, R_g);
  if (i < 0) return u;
  const Vec3 h = tie_break_direction(cones[static_cast<std::size_t>(i)], R_g);
  if (h.isZero()) return u;
  // A clear tangential component takes R_g around the cone by itself (ξ is normalised): no stall.
  if (std::abs(rho_n.dot(h)) > kTieBreakClearTangent * attraction) return u;
  // The side: away from the other cones' bands met a quarter turn around cone i, if they differ;
  // else the lower P at R_g exp(±η ĥ); equal to rounding (exact symmetry): +1.
  const auto lower = [](double minus, double plus) {
    const double tie = 1e-12 * (1.0 + std::abs(plus) + std::abs(minus));
    return minus < plus - tie ? -1.0 : (plus < minus - tie ? 1.0 : 0.0);
  };
  const std::size_t ci = static_cast<std::size_t>(i);
  double sign = lower(side_barrier(cones, ci, R_g, -1.0), side_barrier(cones, ci, R_g, 1.0));
  if (sign == 0.0) {
    sign = lower(navigation_potential(cones, R_g * lie::exp(-kTieBreakProbe * h), R_d),
                 navigation_potential(cones, R_g * lie::exp(kTieBreakProbe * h), R_d));
  }
  if (sign == 0.0) sign = 1.0;
  // Only a saddle is broken: at a minimum of P (e.g. between two overlapping bands) P rises on
  // both sides and the stall is real.
  const double p_here = navigation_potential(cones, R_g, R_d);
  const double p_side = navigation_potential(cones, R_g * lie::exp(sign * kTieBreakProbe * h), R_d);
  if (!(p_side < p_here)) return u;
  u.state = TieBreak{true, i, sign};
  u.started = true;
  return u;
}

Vec3 tie_break_field(const TieBreak& tie, std::span<const ConeConstraint> cones, const Mat3& R_g,
                     const Mat3& R_d, const Vec3& rho_n) noexcept {
  const ConeConstraint* cone = held_cone(tie, cones);
  if (cone == nullptr) return rho_n;
  const double attraction = attractive_field(R_g, R_d).norm();
  return rho_n + (tie.sign * kTieBreakDetourGain * attraction) * tie_break_direction(*cone, R_g);
}

}  // namespace attiguard::governor
