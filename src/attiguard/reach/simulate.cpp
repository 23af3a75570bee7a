#include "attiguard/reach/simulate.hpp"

#include <span>

#include "attiguard/integrate/integrator.hpp"
#include "attiguard/integrate/product_state.hpp"

namespace attiguard::reach {

void simulate_from(const ClosedLoop& loop, double t_start, const Mat3& R0, const Vec3& omega0,
                   const std::vector<double>& times, double h,
                   const std::function<void(std::size_t, const Mat3&, const Vec3&)>& on_stop) {
  using State = integrate::ProductState<1, 3>;
  State y;
  y.R[0] = R0;
  y.x = omega0;
  std::size_t first = 0;
  if (!times.empty() && times.front() <= t_start) {
    on_stop(0, R0, omega0);
    first = 1;
  }
  if (first >= times.size()) return;
  integrate::IntegratorSettings s;
  s.method = integrate::Method::rkmk4;
  s.step = h;
  auto f = [&loop](double, const State& st) {
    State::Tangent d;
    d.head<3>() = st.x;
    d.tail<3>() = loop.omega_dot(st.R[0], st.x);
    return d;
  };
  std::size_t idx = first;
  const std::span<const double> stops(times.data() + first, times.size() - first);
  integrate::integrate(
      f, y, t_start, stops, s,
      [&](double, const State& st) {
        on_stop(idx++, st.R[0], st.x);
        return true;
      },
      [](double, const State&) {});
}

void simulate(const ClosedLoop& loop, const Mat3& R0, const Vec3& omega0,
              const std::vector<double>& times, double h,
              const std::function<void(std::size_t, const Mat3&, const Vec3&)>& on_stop) {
  simulate_from(loop, 0.0, R0, omega0, times, h, on_stop);
}

}  // namespace attiguard::reach
