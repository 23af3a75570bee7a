#include "attiguard/sim/time_grid.hpp"

#include <cmath>

namespace attiguard::sim {

std::vector<double> uniform_instants(double duration, double interval) {
  std::vector<double> out;
  const auto n = static_cast<long>(std::floor(duration / interval));
  out.reserve(static_cast<std::size_t>(n) + 1);
  for (long k = 1; k <= n; ++k) {
    const double t = static_cast<double>(k) * interval;
    if (t < duration - 1e-9 * interval) {
      out.push_back(t);
    }
  }
  out.push_back(duration);
  return out;
}

}  // namespace attiguard::sim
