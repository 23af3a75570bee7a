#pragma once
/// @file integrator_settings.hpp
/// User-facing choice of integrator and its parameters (scenario table `[simulation]`).

#include "attiguard/core/name_table.hpp"

namespace attiguard::integrate {

/// Which Runge–Kutta–Munthe-Kaas scheme advances a simulation.
enum class Method {
  rkmk4,      ///< classical RK4 coefficients, fixed step `step` (order 4)
  rkmk_dp54,  ///< Dormand–Prince 5(4) coefficients, adaptive step from abs_tol / rel_tol
};

/// Names of Method in scenario files (`[simulation] integrator`) and summaries
/// (docs/scenario-format.md, "Integrator keys").
inline constexpr NameTable<Method, 2> kMethodNames{
    {{{Method::rkmk4, "rkmk4"}, {Method::rkmk_dp54, "rkmk_dp54"}}}};

/// Integrator parameters; defaults are sane for spacecraft attitude problems.
struct IntegratorSettings {
  Method method{Method::rkmk4};
  double step{1e-2};        ///< fixed step of rkmk4; initial step guess of rkmk_dp54 [s]
  double abs_tol{1e-9};     ///< rkmk_dp54 absolute tolerance
  double rel_tol{1e-9};     ///< rkmk_dp54 relative tolerance
  double min_step{1e-12};   ///< rkmk_dp54 gives up (NumericalError) below this step [s]
  double max_step{0.0};     ///< rkmk_dp54 step cap [s]; 0 = no cap
  long max_steps{50'000'000};  ///< hard cap on the number of accepted steps of one run
};

}  // namespace attiguard::integrate
