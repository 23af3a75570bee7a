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

/// How ṡ was chosen (docs/pet-erg.md, section 16.1, "Choice of ṡ").
enum class RateRule {
  jump,        ///< a faster rate at once (V⁺ exact)
  accelerate,  ///< s̈ = +a over the period
  coast,       ///< s̈ = 0
  brake,       ///< no rule admissible: s̈ < 0 as hard as the torque allows now (best effort)
};

/// The rate chosen at a sampling instant and the figures it was chosen on (docs/pet-erg.md,
/// section 16.1, "Choice of ṡ").
struct RateChoice {
  double rate{0.0};          ///< ṡ ∈ [0, 1] at the instant
  double accel{0.0};         ///< s̈ [1/s] held to the next instant (ṡ kept within [0, 1])
  double V{0.0};             ///< V⁺(ṡ): the tracking law's V against the reference at ṡ
  double gamma_g{0.0};       ///< Γ_g over the plan ahead
  double torque_bound{0.0};  ///< bound on ‖τ‖ over {V ≤ V⁺/(1 − ε)} at ṡ, s̈ [N·m]
  RateRule rule{RateRule::coast};
  bool admissible{false};    ///< V⁺ ≤ (1 − ε)Γ_g and torque_bound ≤ τ_max
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

  /// The bound on ‖τ‖ over the level set {V ≤ Γ} at the rate ṡ and the clock's acceleration s̈
  /// (docs/pet-erg.md, section 16.1, "Torque"): the coarse bound (both errors at the full Γ)
  /// when it is within τ_max, else the bound over the 16 cells of the split of Γ.
  [[nodiscard]] double torque_bound(double gamma, double rate, const PlanWindow& w,
                                    double accel = 0.0) const noexcept;

  /// The tracking law's torque beyond its feedback −k_R e_R − k_Ω e_Ω and the reference's
  /// torque, for an attitude error angle θ and a rate error ‖e_Ω‖ ≤ E at ṡ, s̈ over the window
  /// (docs/pet-erg.md, section 16.1, "Torque"): θ (λ_max − λ_min)(ṡ²(‖ω_p‖² + ‖ω̇_p‖) + |s̈|‖ω_p‖)
  /// + ½(λ_max − λ_min) E² + (2λ_max − λ_min) E ṡ ‖ω_p‖.
  [[nodiscard]] double feedforward_error(double theta, double E, double rate, const PlanWindow& w,
                                         double accel = 0.0) const noexcept;
  /// The reference's torque bound over the window, ṡ² max‖τ_p‖ + |s̈| λ_max max‖ω_p‖
  /// (docs/pet-erg.md, section 16.1, "Torque").
  [[nodiscard]] double reference_torque(double rate, const PlanWindow& w, double accel = 0.0) const noexcept;

  /// a: the largest |s̈| of the clock [1/s], 4/T_p (docs/pet-erg.md, section 16.1).
  [[nodiscard]] double clock_acceleration() const noexcept { return accel_max_; }

  /// cone_threshold(ahead(σ)), from a table (docs/pet-erg.md, section 16.1, "Choice of ṡ").
  [[nodiscard]] double cone_threshold_ahead(double sigma) const noexcept;

  /// The plan's extremes over everything ahead of σ, [σ, T_p] (docs/pet-erg.md, section 16.1,
  /// "Choice of ṡ"): a table look-up; the thresholds of it do not fall as σ grows.
  [[nodiscard]] PlanWindow ahead(double sigma) const noexcept;

  /// The clock's rate and acceleration at a sampling instant, at plan time σ, for the body
  /// (R, ω), the clock running at ṡ = `rate` (docs/pet-erg.md, section 16.1, "Choice of ṡ"),
  /// every rule checked over the plan ahead of σ with V ≤ (1 − ε)Γ_g and the torque bound of
  /// {V ≤ V/(1 − ε)} within τ_max, the first that holds:
  ///   jump: the fastest of 1, 31/32, … above ṡ whose V⁺ (exact, with the jump) holds;
  ///   accelerate: s̈ = a with the bound at min(1, ṡ + a T_s);
  ///   coast: s̈ = 0 (admissible at every instant in the exact continuous loop if it was at the
  ///   previous one);
  ///   brake: none holds (a disturbance or an error beyond the model): the strongest of
  ///   s̈ = −a, −a/2, … whose tracking torque now is within τ_max (else the smallest), with
  ///   admissible = false.
  [[nodiscard]] RateChoice choose(double sigma, const lie::Mat3& R_ib, const lie::Vec3& omega_b,
                                  double rate) const noexcept;
  /// choose() with the plan's sample at σ already evaluated (plan().evaluate(σ)).
  [[nodiscard]] RateChoice choose(const SlewPlanSample& at_sigma, double sigma, const lie::Mat3& R_ib,
                                  const lie::Vec3& omega_b, double rate) const noexcept;

  /// choose(σ, R, ω, 0).rate: the rate a clock at rest is given (docs/pet-erg.md, section 16.1,
  /// "Choice of ṡ").
  [[nodiscard]] double choose_rate(double sigma, const lie::Mat3& R_ib,
                                   const lie::Vec3& omega_b) const noexcept {
    return choose(sigma, R_ib, omega_b, 0.0).rate;
  }

  /// The plan flown (docs/pet-erg.md, section 16.1).
  [[nodiscard]] const SlewPlan& plan() const noexcept { return plan_; }
  /// The tracking gains (docs/pet-erg.md, section 16).
  [[nodiscard]] const control::TrackingGains& gains() const noexcept { return gains_; }
  /// The torque bound τ_max [N·m].
  [[nodiscard]] double tau_max() const noexcept { return tau_max_; }
  /// The safety factor ε.
  [[nodiscard]] double epsilon() const noexcept { return epsilon_; }

  /// The tracking reference at plan time σ flown at the rate ṡ with the clock's acceleration s̈:
  /// R_p(σ), ṡ ω_p(σ), ṡ² ω̇_p(σ) + s̈ ω_p(σ); at σ ≥ T_p, R_d at rest (the hold).
  [[nodiscard]] control::TrackingReference reference(double sigma, double rate,
                                                     double accel = 0.0) const noexcept;
  /// reference() from the plan's sample at σ (plan().evaluate(σ), or plan().rates(σ) when only
  /// the rates are used).
  [[nodiscard]] control::TrackingReference reference(const SlewPlanSample& at_sigma, double sigma,
                                                     double rate, double accel) const noexcept;

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
  double accel_max_{0.0};
  std::vector<IntervalExtremes> extremes_;  ///< per interval of the plan
  std::vector<IntervalExtremes> suffix_;    ///< over intervals k … N − 1 (the plan ahead)
  std::vector<double> suffix_gamma_g_;      ///< Γ_g of suffix_ (no cosine per step)
  [[nodiscard]] int interval_of(double t) const noexcept;
  /// The braking rule's s̈ (see choose).
  [[nodiscard]] double brake_acceleration(double sigma, const lie::Mat3& R_ib,
                                          const lie::Vec3& omega_b, double rate) const noexcept;
};

}  // namespace attiguard::governor
