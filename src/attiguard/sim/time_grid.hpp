#pragma once
/// @file time_grid.hpp
/// Output and sampling instants of a simulation.

#include <vector>

namespace attiguard::sim {

/// The instants k·interval (k = 1, 2, …) strictly inside (0, duration), then `duration` itself.
/// Instants within 1e-9·interval of `duration` are merged into it. interval > 0, duration > 0.
[[nodiscard]] std::vector<double> uniform_instants(double duration, double interval);

}  // namespace attiguard::sim
