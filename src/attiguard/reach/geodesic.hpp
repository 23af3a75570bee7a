#pragma once
/// @file geodesic.hpp
/// Geodesics of (SO(3), G_Q) and the exp atlas [ConReach Sec. 5]:
///  - reduced geodesic [ConReach eq. (21)]/(24):  Q ẇ = −w × Q w,  Ṙ = R ŵ;
///  - exp atlas: chart i ∈ {0,1,2,3}, Ψ_i(R) = log(Λ(s_i) R)^∨, Ψ_i⁻¹(r) = Λ(s_i) exp(r̂),
///    Λ(s) = diag(s), s_0 = (1,1,1), s_1 = (1,−1,−1), s_2 = (−1,1,−1), s_3 = (−1,−1,1);
///  - geodesic dynamics in a chart (26):  ṙ = f(r) w,  ẇ = −Q⁻¹ ŵ Q w,  with
///    f(r) = I + ½ r̂ + r̂²/‖r‖² − sin‖r‖/(2‖r‖(1 − cos‖r‖)) r̂²  (= J_r⁻¹(r)).
/// By Prop. 8 / Thm. 10, B_Q(R0, r) is the set of endpoints at time 1 of [ConReach eq. (24)]/(26) started at
/// R0 with w(0) in the ellipsoid wᵀQw < r².

#include <array>

#include "attiguard/reach/interval.hpp"

namespace attiguard::reach {

/// ẇ of the reduced geodesic [ConReach eq. (21)]: −Q⁻¹(w × Qw). Q must be SPD.
[[nodiscard]] Vec3 reduced_geodesic_rate(const Mat3& Q, const Vec3& w);

/// Λ(s_i) of chart i (a rotation by 0 or π about a coordinate axis).
[[nodiscard]] Mat3 chart_lambda(int chart);
/// Ψ_i(R) = log(Λ(s_i) R)^∨ (‖·‖ ≤ π).
[[nodiscard]] Vec3 chart_coordinates(int chart, const Mat3& R);
/// Ψ_i⁻¹(r) = Λ(s_i) exp(r̂).
[[nodiscard]] Mat3 chart_inverse(int chart, const Vec3& r);
/// The chart in which R has the smallest ‖Ψ_i(R)‖ (docs/errata.md, ConReach 5).
[[nodiscard]] int best_chart(const Mat3& R);
/// f(r) of [ConReach eq. (26)] in the paper's closed form (series for small ‖r‖); requires ‖r‖ < 2π.
[[nodiscard]] Mat3 exp_atlas_f(const Vec3& r);

/// Endpoint R(1) of the geodesic (24) from R0 with initial reduced velocity w0 (RKMK4 on
/// SO(3) × R³ with equal steps, at least `steps` and at least geodesic_steps(Q, w0)). Its
/// G_Q-length is √(w0ᵀQw0) (w is Q-norm preserving). Throws NumericalError when more than
/// kMaxGeodesicSteps steps would be needed.
[[nodiscard]] Mat3 geodesic_endpoint(const Mat3& Q, const Mat3& R0, const Vec3& w0, int steps = 64);

/// Most RKMK4 steps geodesic_endpoint takes for one geodesic.
inline constexpr double kMaxGeodesicSteps = 1e5;

/// The steps geodesic_endpoint needs for w0 (docs/reach.md, "Representation"): w keeps wᵀQw, so
/// ‖w‖ ≤ ‖w0‖√κ (κ = λ_max/λ_min of Q), and (24) turns w at the rate ‖ẇ‖/‖w‖ ≤ (κ − 1)‖w‖
/// (w × Qw = w × (Q − λ_min I)w); each step then turns R and w by at most 0.1 rad.
[[nodiscard]] double geodesic_steps(const Mat3& Q, const Vec3& w0);

/// Endpoint r(1) of [ConReach eq. (26)] in chart `chart` from r(0) = Ψ_chart(R0), w(0) = w0 (classical RK4
/// in R⁶, `steps` equal steps). Throws NumericalError when the curve reaches ‖r‖ ≥ π − 1e-6
/// (it leaves the chart).
[[nodiscard]] Vec3 chart_geodesic_endpoint(const Mat3& Q, int chart, const Vec3& r0, const Vec3& w0,
                                           int steps = 64);

}  // namespace attiguard::reach
