#pragma once
/// @file rkmk_step.hpp
/// One step of an explicit Runge–Kutta–Munthe-Kaas method on SO(3)ᴷ × Rᴺ.
///
/// For ẏ = f(t, y) with body velocities (Ṙ_j = R_j ξ̂_j), write y(t0 + s) = y0 ⊕ Ω(s). Then
/// Ω̇ = dexpinv_body(Ω, f(t0 + s, y0 ⊕ Ω)) is an ODE on a vector space, which the RK tableau
/// advances; the step ends with y1 = y0 ⊕ Ω1, which lies on the manifold exactly (no
/// re-projection). With the exact dexpinv the RKMK method keeps the order of its tableau
/// (Munthe-Kaas, "Runge–Kutta methods on Lie groups", BIT 38 (1998) 92–111).
/// Allocation-free.

#include <array>

#include "attiguard/integrate/butcher_tableau.hpp"
#include "attiguard/integrate/product_state.hpp"

namespace attiguard::integrate {

/// Result of one RKMK step.
template <class State>
struct RkmkStepResult {
  State y;                          ///< new state y0 ⊕ Ω1
  typename State::Tangent error;    ///< Ω1 − Ω̂1 (embedded pair) in the chart at y0; 0 otherwise
  typename State::Tangent f_end;    ///< f(t0 + h, y) when the last stage is at the new point (FSAL)
  bool has_f_end{false};
};

/// One RKMK step of tableau `tab` from (t0, y0) with step h.
/// `f0` is f(t0, y0) (callers cache it: first same as last); f is called S − 1 more times.
template <class State, int S, class F>
[[nodiscard]] RkmkStepResult<State> rkmk_step(F& f, const ButcherTableau<S>& tab, double t0,
                                              const State& y0, double h,
                                              const typename State::Tangent& f0) {
  using Tangent = typename State::Tangent;
  constexpr int K = State::num_rotations;
  constexpr int N = State::num_euclidean;
  std::array<Tangent, S> k;
  k[0] = f0;  // Ω = 0: dexpinv is the identity
  Tangent last_raw = f0;
  for (int i = 1; i < S; ++i) {
    Tangent Omega = Tangent::Zero();
    for (int j = 0; j < i; ++j) {
      if (tab.a[i][j] != 0.0) {
        Omega += (h * tab.a[i][j]) * k[j];
      }
    }
    // exp(Ω_j) for the stage's point and J_r⁻¹(Ω_j) for dexpinv share lie::chart_coefficients.
    const StageChart<K, N> chart = stage_chart<K, N>(y0, Omega);
    last_raw = f(t0 + tab.c[i] * h, chart.point);
    k[i] = chart.dexpinv(last_raw);
  }
  bool has_embedded = false;
  for (double bh : tab.b_hat) {
    has_embedded = has_embedded || bh != 0.0;
  }
  Tangent Omega1 = Tangent::Zero();
  Tangent err = Tangent::Zero();
  for (int i = 0; i < S; ++i) {
    Omega1 += (h * tab.b[i]) * k[i];
    if (has_embedded) {
      err += (h * (tab.b[i] - tab.b_hat[i])) * k[i];
    }
  }
  RkmkStepResult<State> out{retract<K, N>(y0, Omega1), Tangent::Zero(), last_raw, false};
  if (has_embedded) {
    out.error = err;
  }
  // First same as last: the last stage sits at the new point when its a-row equals b and c = 1.
  out.has_f_end = tab.c[S - 1] == 1.0 && tab.a[S - 1] == tab.b;
  return out;
}

/// One classical RKMK4 step (order 4): 4 evaluations of f.
template <class State, class F>
[[nodiscard]] State rkmk4_step(F& f, double t0, const State& y0, double h) {
  return rkmk_step<State>(f, classical_rk4, t0, y0, h, f(t0, y0)).y;
}

}  // namespace attiguard::integrate
