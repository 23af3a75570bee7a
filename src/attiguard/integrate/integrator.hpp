#pragma once
/// @file integrator.hpp
/// Fixed-step RKMK4 and adaptive RKMK Dormand–Prince 5(4) on SO(3)ᴷ × Rᴺ, stepping exactly onto
/// requested instants (sampling times, phase switches) with a callback there.

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <sstream>

#include "attiguard/core/errors.hpp"
#include "attiguard/integrate/integrator_settings.hpp"
#include "attiguard/integrate/rkmk_step.hpp"

namespace attiguard::integrate {

/// Counters of one integrator's work.
struct IntegrationStats {
  long accepted_steps{0};
  long rejected_steps{0};
  long evaluations{0};  ///< calls of the vector field
};

/// Advances a State (a ProductState) under a vector field f(t, y) → Tangent of body velocities.
///
/// Fixed step (Method::rkmk4): each interval [t, t_target] is split into ⌈(t_target − t)/step⌉
/// equal steps, so the integrator lands exactly on t_target. Adaptive (Method::rkmk_dp54): the
/// local error Ω1 − Ω̂1 of the embedded pair, measured in the chart at the step's start with the
/// weights 1/(abs_tol + rel_tol·scale) (scale 1 for rotation components, max(|x0|, |x1|) for
/// Euclidean ones, RMS norm), is kept ≤ 1 with the standard controller
/// h ← h · min(5, max(0.2, 0.9 err^(−1/5))); the last step is shortened to end at t_target.
/// Throws NumericalError when the state becomes non-finite, the step falls below min_step or
/// max_steps is exceeded.
template <class State>
class RkmkIntegrator {
 public:
  using Tangent = typename State::Tangent;

  explicit RkmkIntegrator(const IntegratorSettings& settings)
      : settings_(settings), h_(settings.step) {}

  /// Integrates y from t to t_target (> t), setting t = t_target exactly on return.
  /// on_step(t, y) is called after every accepted step (including the last).
  template <class F, class OnStep>
  void advance_to(F&& f, State& y, double& t, double t_target, OnStep&& on_step) {
    if (!(t_target > t)) {
      return;
    }
    auto counted = [&](double tt, const State& yy) -> Tangent {
      ++stats_.evaluations;
      return f(tt, yy);
    };
    if (settings_.method == Method::rkmk4) {
      advance_fixed(counted, y, t, t_target, on_step);
    } else {
      advance_adaptive(counted, y, t, t_target, on_step);
    }
  }

  /// Forget the cached f(t, y): call after changing y or the vector field between calls of
  /// advance_to (a discrete jump). advance_to itself keeps the cache only while it is valid.
  void invalidate_cache() noexcept { have_f_ = false; }

  [[nodiscard]] const IntegrationStats& stats() const noexcept { return stats_; }
  /// The step the adaptive controller will try next [s].
  [[nodiscard]] double next_step() const noexcept { return h_; }

 private:
  template <class F, class OnStep>
  void advance_fixed(F& f, State& y, double& t, double t_target, OnStep& on_step) {
    const double span = t_target - t;
    const double n_real = std::ceil(span / settings_.step * (1.0 - 1e-12));
    const long n = std::max(1L, static_cast<long>(n_real));
    const double h = span / static_cast<double>(n);
    const double t_start = t;
    for (long i = 1; i <= n; ++i) {
      check_budget(t);
      const double t0 = t_start + static_cast<double>(i - 1) * h;
      y = rkmk_step<State>(f, classical_rk4, t0, y, h, f(t0, y)).y;
      t = i == n ? t_target : t_start + static_cast<double>(i) * h;
      ++stats_.accepted_steps;
      check_finite(y, t);
      on_step(t, static_cast<const State&>(y));
    }
    have_f_ = false;
  }

  template <class F, class OnStep>
  void advance_adaptive(F& f, State& y, double& t, double t_target, OnStep& on_step) {
    while (t < t_target) {
      check_budget(t);
      if (!have_f_) {
        f_cached_ = f(t, y);
        have_f_ = true;
      }
      double h = std::min(h_, cap());
      bool last = false;
      if (t + 1.0000001 * h >= t_target) {
        h = t_target - t;
        last = true;
      }
      const auto step = rkmk_step<State>(f, dormand_prince_54, t, y, h, f_cached_);
      const double err = error_norm(y, step.y, step.error);
      if (err <= 1.0 && step.y.all_finite()) {
        y = step.y;
        t = last ? t_target : t + h;
        f_cached_ = step.f_end;
        ++stats_.accepted_steps;
        on_step(t, static_cast<const State&>(y));
        const double grow = err > 0.0 ? 0.9 * std::pow(err, -0.2) : 5.0;
        const double proposed = h * std::clamp(grow, 0.2, 5.0);
        h_ = last ? std::max(h_, proposed) : proposed;  // a truncated last step says little
      } else {
        ++stats_.rejected_steps;
        const double shrink = std::isfinite(err) ? 0.9 * std::pow(err, -0.2) : 0.2;
        h_ = h * std::clamp(shrink, 0.2, 1.0);
        if (h_ < settings_.min_step) {
          std::ostringstream os;
          os << "integrator: step size fell below " << settings_.min_step << " s at t = " << t
             << " s (stiff or diverging dynamics, or a non-finite state)";
          throw NumericalError(os.str());
        }
      }
    }
  }

  [[nodiscard]] double cap() const noexcept {
    return settings_.max_step > 0.0 ? settings_.max_step : std::numeric_limits<double>::infinity();
  }

  [[nodiscard]] double error_norm(const State& y0, const State& y1, const Tangent& e) const noexcept {
    double sum = 0.0;
    for (int i = 0; i < 3 * State::num_rotations; ++i) {
      const double w = e(i) / (settings_.abs_tol + settings_.rel_tol);
      sum += w * w;
    }
    for (int i = 0; i < State::num_euclidean; ++i) {
      const double scale = std::max(std::abs(y0.x(i)), std::abs(y1.x(i)));
      const double w = e(3 * State::num_rotations + i) / (settings_.abs_tol + settings_.rel_tol * scale);
      sum += w * w;
    }
    return std::sqrt(sum / static_cast<double>(std::max(1, State::tangent_dim)));
  }

  void check_budget(double t) const {
    if (stats_.accepted_steps >= settings_.max_steps) {
      std::ostringstream os;
      os << "integrator: more than " << settings_.max_steps << " steps at t = " << t << " s";
      throw NumericalError(os.str());
    }
  }

  static void check_finite(const State& y, double t) {
    if (!y.all_finite()) {
      std::ostringstream os;
      os << "integrator: non-finite state at t = " << t << " s (divergence)";
      throw NumericalError(os.str());
    }
  }

  IntegratorSettings settings_;
  double h_;
  Tangent f_cached_{Tangent::Zero()};
  bool have_f_{false};
  IntegrationStats stats_{};
};

/// Integrates from t0 through each of the increasing `stop_times` (all > t0), landing exactly on
/// each; on_stop(t, y) is called there and may change y (a jump) or return false to end early.
/// on_step(t, y) is called after every accepted step. Returns the integrator's counters.
template <class State, class F, class OnStop, class OnStep>
IntegrationStats integrate(F&& f, State& y, double t0, std::span<const double> stop_times,
                           const IntegratorSettings& settings, OnStop&& on_stop, OnStep&& on_step) {
  RkmkIntegrator<State> integrator(settings);
  double t = t0;
  for (double t_stop : stop_times) {
    integrator.advance_to(f, y, t, t_stop, on_step);
    const bool go_on = on_stop(t, y);
    integrator.invalidate_cache();
    if (!go_on) {
      break;
    }
  }
  return integrator.stats();
}

}  // namespace attiguard::integrate
