#pragma once
/// @file butcher_tableau.hpp
/// Explicit Runge–Kutta coefficient tables used by the RKMK integrators.

#include <array>

namespace attiguard::integrate {

/// Explicit Butcher tableau with S stages: a (strictly lower triangular), b, c, and optional
/// embedded weights b_hat (all zero when the method has no embedded pair).
template <int S>
struct ButcherTableau {
  static constexpr int stages = S;
  std::array<std::array<double, S>, S> a{};
  std::array<double, S> b{};
  std::array<double, S> b_hat{};
  std::array<double, S> c{};
};

/// The classical fourth-order Runge–Kutta method (order 4 as an RKMK method with exact dexpinv).
inline constexpr ButcherTableau<4> classical_rk4{
    .a = {{{0, 0, 0, 0}, {0.5, 0, 0, 0}, {0, 0.5, 0, 0}, {0, 0, 1, 0}}},
    .b = {1.0 / 6, 1.0 / 3, 1.0 / 3, 1.0 / 6},
    .b_hat = {},
    .c = {0, 0.5, 0.5, 1},
};

/// Dormand & Prince (1980) 5(4) pair: b gives the fifth-order solution (propagated), b_hat the
/// embedded fourth-order one (error estimate). The last stage is evaluated at the new point
/// (first same as last).
inline constexpr ButcherTableau<7> dormand_prince_54{
    .a = {{{0, 0, 0, 0, 0, 0, 0},
           {1.0 / 5, 0, 0, 0, 0, 0, 0},
           {3.0 / 40, 9.0 / 40, 0, 0, 0, 0, 0},
           {44.0 / 45, -56.0 / 15, 32.0 / 9, 0, 0, 0, 0},
           {19372.0 / 6561, -25360.0 / 2187, 64448.0 / 6561, -212.0 / 729, 0, 0, 0},
           {9017.0 / 3168, -355.0 / 33, 46732.0 / 5247, 49.0 / 176, -5103.0 / 18656, 0, 0},
           {35.0 / 384, 0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84, 0}}},
    .b = {35.0 / 384, 0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84, 0},
    .b_hat = {5179.0 / 57600, 0, 7571.0 / 16695, 393.0 / 640, -92097.0 / 339200, 187.0 / 2100,
              1.0 / 40},
    .c = {0, 1.0 / 5, 3.0 / 10, 4.0 / 5, 8.0 / 9, 1, 1},
};

}  // namespace attiguard::integrate
