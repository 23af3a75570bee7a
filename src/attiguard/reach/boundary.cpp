#include "attiguard/reach/boundary.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

#include "attiguard/core/errors.hpp"
#include "attiguard/reach/geodesic.hpp"
#include "attiguard/reach/metrics.hpp"

namespace attiguard::reach {

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
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (int j = 0; j < points; ++j) {
    const double z = 1.0 - (2.0 * j + 1.0) / points;
    const double rad = std::sqrt(std::max(0.0, 1.0 - z * z));
    const Vec3 u(rad * std::cos(golden * j), rad * std::sin(golden * j), z);
    const Vec3 w0 = r * u / std::sqrt(u.dot(Q * u));
    out.push_back(chart_geodesic_endpoint(Q, chart, r0, w0, ode_steps));
  }
  return out;
}

}  // namespace attiguard::reach
