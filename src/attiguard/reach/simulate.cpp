#include "attiguard/reach/simulate.hpp"

namespace attiguard::reach {

void simulate_from(const ClosedLoop& loop, double t_start, const Mat3& R0, const Vec3& omega0,
                   const std::vector<double>& times, double h,
                   const std::function<void(std::size_t, const Mat3&, const Vec3&)>& on_stop) {
  simulate_stops(loop, t_start, R0, omega0, times, h, on_stop);
}

void simulate(const ClosedLoop& loop, const Mat3& R0, const Vec3& omega0,
              const std::vector<double>& times, double h,
              const std::function<void(std::size_t, const Mat3&, const Vec3&)>& on_stop) {
  simulate_from(loop, 0.0, R0, omega0, times, h, on_stop);
}

}  // namespace attiguard::reach
