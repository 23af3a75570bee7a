#pragma once
/// @file boundary.hpp
/// Representation of metric balls [ConReach Sec. 5]: the boundary of
/// B_Q(R_c, r) in an exp chart, obtained by integrating the chart geodesic dynamics [ConReach eq. (26)] to
/// t = 1 from r(0) = Ψ_i(R_c) and w(0) on the ellipsoid wᵀQw = r² (Thm. 10). The directions of
/// w(0) are a Fibonacci lattice on the sphere.

#include <vector>

#include "attiguard/reach/interval.hpp"

namespace attiguard::reach {

/// True when B_Q(R_c, r) lies inside chart i: ‖Ψ_i(R_c)‖ + r/√λ_min(Q) < π − margin (the ball
/// is inside the bi-invariant ball of that radius, inclusion fact 2).
[[nodiscard]] bool ball_fits_chart(const Mat3& Q, double r, const Mat3& Rc, int chart,
                                   double margin = 1e-3);

/// Boundary points (in chart coordinates) of B_Q(R_c, r). Throws NumericalError when the ball
/// does not fit in the chart.
[[nodiscard]] std::vector<Vec3> ball_boundary(const Mat3& Q, double r, const Mat3& Rc, int chart,
                                              int points, int ode_steps = 32);

}  // namespace attiguard::reach
