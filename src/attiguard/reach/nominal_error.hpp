#pragma once
/// @file nominal_error.hpp
/// A bound on the integration error of one sub-step of ConReach's nominal trajectory
/// (docs/reach.md, "Nominal error bound"): for the exact solution x*(t) of the closed loop that
/// starts at the computed nominal point p0 = (R_0, ω_0) at time s, and the computed nominal
/// point p1 at s + h,
///   |ω*_k(s+h) − ω_1,k| ≤ ε_k,   ‖ω*(s+h) − ω_1‖ ≤ ε_ω,   d(R*(s+h), R_1) ≤ ε_R.
/// Method: the Taylor polynomial of order p of x* at s (exact recursion of the polynomial field,
/// polynomial_field.hpp) with the Lagrange remainder enclosed by the interval Taylor coefficient
/// of order p+1 over an a-priori enclosure of x* on [s, s+h] (the tube's Picard–Lindelöf box),
/// plus a rounding-error term γ·Σ_k |x_[k]| h^k for the polynomial's evaluation.

#include <optional>
#include <string>

#include "attiguard/reach/deviation.hpp"
#include "attiguard/reach/interval.hpp"
#include "attiguard/reach/polynomial_field.hpp"

namespace attiguard::reach {

/// ε = (ε_1, ε_2, ε_3, ε_ω, ε_R), laid out like the tube's deviation z (deviation.hpp).
struct NominalStepError {
  Deviation bound;         ///< ε_k in d_omega_b, ε_ω in e_omega_b, ε_R in e_R
  int order{0};            ///< Taylor order p used
  double remainder{0.0};   ///< largest Lagrange remainder bound (entries of R and ω)
};

/// The bound of the file comment for the sub-step from (R0, ω0) to (R1, ω1) of length h, given
/// an a-priori enclosure of x* on [s, s+h]: ω ∈ omega_box and d(R, R0) ≤ attitude_radius.
/// Empty, with `why` set, when no finite bound can be established (then the step cannot be
/// proved).
[[nodiscard]] std::optional<NominalStepError> nominal_step_error(
    const PolynomialField& field, const lie::Mat3& R0, const lie::Vec3& omega0, const lie::Mat3& R1,
    const lie::Vec3& omega1, double h, const Box3& omega_box, double attitude_radius,
    std::string& why);

}  // namespace attiguard::reach
