#include "attiguard/reach/boundary.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "attiguard/core/errors.hpp"
#include "attiguard/reach/geodesic.hpp"
#include "attiguard/reach/metrics.hpp"

namespace attiguard::reach {

namespace {

/// w(0) of boundary point j of `points`: r u/√(uᵀQu), u the j-th direction of a Fibonacci lattice.
Vec3 initial_velocity(const Mat3& Q, double r, int points, int j) {
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  const double z = 1.0 - (2.0 * j + 1.0) / points;
  const double rad = std::sqrt(std::max(0.0, 1.0 - z * z));
  const Vec3 u(rad * std::cos(golden * j), rad * std::sin(golden * j), z);
  return r * u / std::sqrt(u.dot(Q * u));
}

}  // namespace

bool ball_fits_chart(const Mat3& Q, double r, const Mat3& Rc, int chart, double margin) {
  return chart_coordinates(chart, Rc).norm() + attitude_enclosure_radius(Q, r) <
         std::numbers::pi - margin;
}

std::vector<Vec3> ball_boundary(const Mat3& Q, double r, const Mat3& Rc, int chart, int points,
                                int ode_steps) {
  if (!ball_fits_chart(Q, r, Rc, chart)) {
    std::ostringstream os;
    os << "metric ball of radius " << r << " (bi-invariant enclosure "
       << attitude_enclosure_radius(Q, r) << " rad) leaves exp chart " << chart
       << ": it does not fit in a single chart; partition the initial set or shorten the horizon";
    throw NumericalError(os.str());
  }
  const Vec3 r0 = chart_coordinates(chart, Rc);
  std::vector<Vec3> out;
  for (int j = 0; j < points; ++j) {
    out.push_back(chart_geodesic_endpoint(Q, chart, r0, initial_velocity(Q, r, points, j), ode_steps));
  }
  return out;
}

bool ball_covers_rotations(const Mat3& Q, double r) { return r / std::sqrt(lambda_max(Q)) >= std::numbers::pi; }

std::vector<AtlasPoint> ball_boundary_atlas(const Mat3& Q, double r, const Mat3& Rc, int points, int ode_steps) {
  std::vector<AtlasPoint> out;
  if (ball_covers_rotations(Q, r)) return out;
  for (int j = 0; j < points; ++j) {
    const Mat3 R1 = geodesic_endpoint(Q, Rc, initial_velocity(Q, r, points, j), ode_steps);
    const int chart = best_chart(R1);
    out.push_back({chart, chart_coordinates(chart, R1)});
  }
  return out;
}

}  // namespace attiguard::reach
