#pragma once
/// @file progress_governor.hpp
/// The governed progress of a planned slew (docs/pet-erg.md, section 16.1): the plan's clock
/// σ runs at the rate ṡ ∈ [0, 1], chosen at sampling instants so that the level set of the
/// tracking law's V (control/so3_tracking.hpp) keeps every cone and ‖τ‖ ≤ τ_max over the
/// period. The thresholds Γ_g (cones) and Γ_d(ṡ) (torque) and the choice of ṡ; the `planned`
/// governor mode that uses them is issue 44's next part. Construction is set-up code (it
/// allocates the plan's per-interval tables); the queries allocate nothing and throw nothing.

#include <span>
#include <vector>

#include "attiguard/control/so3_tracking.hpp"
#include "attiguard/governor/cone_constraint.hpp"
#include "attiguard/governor/slew_plan.hpp"

namespace attiguard::governor {

/// The plan's largest rate, acceleration and torque and its smallest cone margin over
/// σ ∈ [from, to] (docs/pet-erg.md, section 16.1, "window").
struct PlanWindow {
  double omega_max{0.0};       ///< max ‖ω_p‖ [rad/s]
  double omega_dot_max{0.0};   ///< max ‖ω̇_p‖ [rad/s²]
  double tau_max{0.0};         ///< max ‖τ_p‖ [N·m]
  double cone_margin_min{0.0}; ///< min over cones of θ_c − ∠(a_c, R_p a_b) [rad]
};

/// The progress governor of a plan (docs/pet-erg.md, section 16.1).
class ProgressGovernor {
 public:
  /// Set-up: the plan, its cones, the torque bound τ_max [N·m], the tracking gains, the sampling
  /// period T_s [s], the safety factor ε ∈ [0, 1) and the points per interval at which the
  /// plan's tables are sampled (their values are widened by the interpolant's change between
  /// points: see the .cpp). Throws SetupError for a plan without intervals, τ_max ≤ 0, gains ≤ 0,
  /// T_s ≤ 0 or ε ∉ [0, 1).
  ProgressGovernor(const SlewPlan& plan, std::span<const ConeConstraint> cones, double tau_max,
                   const control::TrackingGains& gains, double sample_period, double epsilon,
                   int points_per_interval = 20);

  /// The plan's extremes over σ ∈ [from, to] (clamped to [0, T_p]).
  [[nodiscard]] PlanWindow window(double from, double to) const noexcept;

  /// Γ_g = k_R (1 − cos m) for the window's smallest cone margin m (0 when m ≤ 0; the largest
  /// value 2 k_R without cones) (docs/pet-erg.md, section 16.1, "Cones").
  [[nodiscard]] double cone_threshold(const PlanWindow& w) const noexcept;

  /// Γ_d(ṡ): the largest Γ whose level set keeps ‖τ‖ ≤ τ_max at the rate ṡ over the window
  /// (docs/pet-erg.md, section 16.1, "Torque"); 0 when even Γ = 0 does not.
  [[nodiscard]] double torque_threshold(double rate, const PlanWindow& w) const noexcept;

  /// The bound on ‖τ‖ over the level set {V ≤ Γ} at the rate ṡ (docs/pet-erg.md, section 16.1).
  [[nodiscard]] double torque_bound(double gamma, double rate, const PlanWindow& w) const noexcept;

  /// The rate ṡ ∈ [0, 1] at a sampling instant, at plan time σ, for the body (R, ω): the largest
  /// of 0, 1/32, …, 1 with V⁺(ṡ) ≤ (1 − ε) min{Γ_g, Γ_d(ṡ)} over the window the period reaches;
  /// 0 when none is (docs/pet-erg.md, section 16.1, "Choice of ṡ").
  [[nodiscard]] double choose_rate(double sigma, const lie::Mat3& R_ib,
                                   const lie::Vec3& omega_b) const noexcept;

  /// The tracking reference at plan time σ flown at the rate ṡ: R_p(σ), ṡ ω_p(σ), ṡ² ω̇_p(σ);
  /// at σ ≥ T_p, R_d at rest (the hold).
  [[nodiscard]] control::TrackingReference reference(double sigma, double rate) const noexcept;

 private:
  struct IntervalExtremes {
    double omega_max, omega_dot_max, tau_max, cone_margin_min;
  };
  SlewPlan plan_;
  lie::Mat3 J_b_;
  double lambda_min_{1.0}, lambda_max_{1.0};
  double tau_max_;
  control::TrackingGains gains_;
  double sample_period_;
  double epsilon_;
  std::vector<IntervalExtremes> extremes_;  ///< per interval of the plan
};

}  // namespace attiguard::governor
