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

/// A boundary point and the exp chart its coordinates are in.
struct AtlasPoint {
  int chart{0};
  Vec3 r{Vec3::Zero()};
};

/// True when B_Q(R_c, r) is all of SO(3): r/√λ_max(Q) ≥ π, so the ball holds the bi-invariant
/// ball of radius π, which is SO(3) (docs/reach.md, "Representation"). Such a ball has no boundary.
[[nodiscard]] bool ball_covers_rotations(const Mat3& Q, double r);

/// Boundary points of B_Q(R_c, r) for a ball that fits no single chart ("beyond one chart",
/// docs/reach.md "Representation"): each geodesic of (24) is integrated on SO(3) itself
/// (geodesic_endpoint: no chart to leave) and its endpoint given in the chart where it is
/// nearest the chart's centre (best_chart). Same Fibonacci directions as ball_boundary. None
/// for a ball that covers SO(3) (ball_covers_rotations).
[[nodiscard]] std::vector<AtlasPoint> ball_boundary_atlas(const Mat3& Q, double r, const Mat3& Rc, int points,
                                                          int ode_steps = 64);

}  // namespace attiguard::reach
