#pragma once
/// @file simulate.hpp
/// The nominal and sampled trajectories of ConReach [ConReach Alg. 1, "Sim"]: RKMK4 on
/// SO(3) × R³ of a closed loop (closed_loop.hpp), stopping exactly at given times.

#include <functional>
#include <vector>

#include "attiguard/reach/closed_loop.hpp"

namespace attiguard::reach {

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
