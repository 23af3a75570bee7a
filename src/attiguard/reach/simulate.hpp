#pragma once
/// @file simulate.hpp
/// The nominal and sampled trajectories of ConReach [ConReach Alg. 1, "Sim"]: RKMK4 on
/// SO(3) × R³ of a closed loop (closed_loop.hpp), stopping exactly at given times.

#include <functional>
#include <span>
#include <vector>

#include "attiguard/integrate/integrator.hpp"
#include "attiguard/integrate/product_state.hpp"
#include "attiguard/reach/closed_loop.hpp"

namespace attiguard::reach {

/// simulate_from with the callback as a template parameter: no std::function call per stop
/// (the sampled soundness check's inner loop, docs/performance.md "ConReach"); the same
/// integration, bit for bit.
template <class OnStop>
void simulate_stops(const ClosedLoop& loop, double t_start, const Mat3& R0, const Vec3& omega0,
                    const std::vector<double>& times, double h, OnStop&& on_stop) {
  using State = integrate::ProductState<1, 3>;
  State y;
  y.R[0] = R0;
  y.x = omega0;
  std::size_t first = 0;
  if (!times.empty() && times.front() <= t_start) {
    on_stop(std::size_t{0}, R0, omega0);
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

/// Simulates X from (R0, ω0) at time t_start with RKMK4 (step h), calling on_stop(i, R, ω)
/// exactly at every times[i] (increasing; times[0] == t_start is reported first, unchanged).
/// The fixed-step integrator lands on every stop, so a simulation restarted from a stop with
/// t_start = that stop continues bit for bit (docs/reach.md, "Adaptive steps").
void simulate_from(const ClosedLoop& loop, double t_start, const Mat3& R0, const Vec3& omega0,
                   const std::vector<double>& times, double h,
                   const std::function<void(std::size_t, const Mat3&, const Vec3&)>& on_stop);

/// simulate_from with t_start = 0.
void simulate(const ClosedLoop& loop, const Mat3& R0, const Vec3& omega0,
              const std::vector<double>& times, double h,
              const std::function<void(std::size_t, const Mat3&, const Vec3&)>& on_stop);

}  // namespace attiguard::reach
