#pragma once
/// @file planned_governor.hpp
/// The flight-loop object of the `planned` governor mode (docs/pet-erg.md, section 16.2): a
/// planned slew flown by the tracking law with feedforward (control/so3_tracking.hpp) at the
/// reference R_p(σ), its clock σ advanced at the rate ṡ the progress governor chooses at each
/// sampling instant (progress_governor.hpp) and held between them. At σ = T_p the reference is
/// R_d at rest: the tracking law is the PD hold.
///
/// Set-up (the constructor) may throw and allocates the progress governor's tables; step() is
/// noexcept and allocation-free:
///
///   PlannedGovernor gov(plan, cones, {gains, tau_max, T_s, epsilon});   // once, offline
///   gov.reset(t0);
///   loop: const PlannedOutput& out = gov.step(t, R_ib, omega_b);       // out.tau_b, out.sigma, …

#include <algorithm>
#include <limits>
#include <optional>
#include <span>

#include "attiguard/control/so3_tracking.hpp"
#include "attiguard/governor/progress_governor.hpp"
#include "attiguard/governor/torque_slabs.hpp"

namespace attiguard::governor {

/// The robust margins of the planned mode (docs/pet-erg.md, section 16.3): the clock rate the
/// design flies the plan at, the peaks of the tracking errors it proved and the torque bound.
/// With them the clock waits at σ = 0 until the measured errors pass the gate, then jumps to that
/// rate (the plan is at rest there: the errors do not change) and coasts; every choice checks the measured errors against the peaks plus the
/// sensors' errors.
struct PlannedRobust {
  double rate{1.0};                ///< ṡ the clock runs at after the start, in (0, 1]
  double attitude_error{0.0};      ///< ‖e_R‖ ≤ this in the analysis frame R B
  double rate_error{0.0};          ///< ‖e_Ω‖ ≤ this [rad/s]
  double attitude_allowance{0.0};  ///< the measured ‖e_R‖'s error (σ_n) [rad]
  double rate_allowance{0.0};      ///< the measured ‖e_Ω‖'s error (σ_ω + σ_n ‖ω_d‖) [rad/s]
  double torque_bound{0.0};        ///< the command's bound over the flight [N·m]
  double gate_attitude{0.0};       ///< the clock starts once the measured ‖e_R‖ ≤ this …
  double gate_rate{0.0};           ///< … and the measured ‖e_Ω‖ ≤ this [rad/s]
  /// The command's largest gauge against the wheels' slabs (TorqueSlabs), ≤ 1; 0 without wheels
  double torque_ratio{0.0};
};

/// max(‖e_R‖/attitude, ‖e_Ω‖/rate): the tracking errors against bounds on them, ≤ 1 when both
/// hold (docs/pet-erg.md, section 16.3); a zero bound admits only a zero error.
[[nodiscard]] inline double tracking_error_ratio(const control::TrackingError& e, double attitude,
                                                 double rate) noexcept {
  constexpr double kTiny = std::numeric_limits<double>::min();
  return std::max(e.e_R.norm() / std::max(kTiny, attitude), e.e_Omega.norm() / std::max(kTiny, rate));
}

/// Parameters of the planned mode (docs/pet-erg.md, section 16.2).
struct PlannedGovernorParams {
  control::TrackingGains gains;  ///< k_R [N·m], k_Ω [N·m·s] of the tracking law
  double tau_max{1.0};           ///< the torque bound the level set keeps [N·m]
  double sample_period{0.1};     ///< T_s: ṡ is chosen every T_s and held [s]
  double epsilon{0.05};          ///< safety factor ε ∈ [0, 1) of the thresholds
  /// The flight loop's period h [s] (0: the continuous-time loop): the torque is held over
  /// [t_k, t_{k+1}), so the feedforward takes the plan's acceleration at the hold's middle.
  double control_period{0.0};
  /// 0 or 1: a torque computed at t_k acts from t_{k+1} (docs/pet-erg.md, section 11). With 1,
  /// step() predicts the state at t_{k+1} from the measurement and the torque acting until then
  /// and computes the torque for that instant (docs/pet-erg.md, section 16.2, "Flight loop").
  int delay_periods{0};
  /// Robust margins (docs/pet-erg.md, section 16.3); empty: the nominal thresholds of 16.1.
  std::optional<PlannedRobust> robust;
  /// The set the command is saturated to: with no slabs (the default) the ball ‖τ‖ ≤ tau_max;
  /// with robust margins and wheels the wheels' slabs within the declared τ_max (docs/pet-erg.md,
  /// section 16.3, "Wheels").
  TorqueSlabs slabs{};
};

/// The plan's clock between two sampling instants (docs/pet-erg.md, section 16.1): from σ_k at
/// t_k with ṡ_k and s̈_k, ṡ kept within [0, 1] (s̈ ends when ṡ reaches 0 or 1), σ within
/// [0, T_p].
struct ProgressClock {
  double t_k{0.0};
  double sigma_k{0.0};
  double rate_k{0.0};
  double accel_k{0.0};
  double duration{0.0};  ///< T_p

  /// How long s̈_k acts after t_k before ṡ reaches 0 or 1 (+∞ when s̈_k = 0).
  [[nodiscard]] double accel_time() const noexcept;
  /// ṡ(t).
  [[nodiscard]] double rate_at(double t) const noexcept;
  /// s̈(t): s̈_k until ṡ reaches 0 or 1, then 0 (and 0 once σ = T_p).
  [[nodiscard]] double accel_at(double t) const noexcept;
  /// σ(t) = σ_k + ∫ ṡ, at most T_p.
  [[nodiscard]] double sigma_at(double t) const noexcept;
};

/// Everything the planned mode knows at one instant (docs/pet-erg.md, section 16.2).
struct PlannedOutput {
  /// The torque commanded [N·m]: the tracking law's, scaled onto ‖τ‖ = τ_max (or onto the
  /// wheels' slabs, PlannedGovernorParams::slabs) where it asks for more (the flight software's
  /// saturation; docs/pet-erg.md, section 16.2, "Saturation")
  lie::Vec3 tau_b{lie::Vec3::Zero()};
  double demand_ratio{0.0};                ///< ‖τ‖/τ_max (with slabs: their gauge) the law asked for (> 1: saturated)
  control::TrackingReference reference;    ///< R_p(σ), ṡ ω_p(σ), ṡ² ω̇_p(σ) (R_d at rest at σ ≥ T_p)
  double sigma{0.0};                       ///< the plan's clock σ ∈ [0, T_p] [s]
  double rate{0.0};                        ///< ṡ at the instant
  double accel{0.0};                       ///< s̈ at the instant [1/s]
  double V{0.0};                           ///< the tracking law's V against the reference
  RateChoice choice;                       ///< the last sampling instant's choice
  bool sampled{false};                     ///< this call chose ṡ
};

/// The planned mode's governor (docs/pet-erg.md, section 16.2).
class PlannedGovernor {
 public:
  /// Throws SetupError as ProgressGovernor, or for control_period < 0, delay_periods ∉ {0, 1}
  /// or a delay without a control period (set-up code only).
  PlannedGovernor(const SlewPlan& plan, std::span<const ConeConstraint> cones,
                  const PlannedGovernorParams& params);

  /// Starts the clock at σ = 0, ṡ = 0 at time t0; the first sampling instant is t0.
  void reset(double t0) noexcept;

  /// One control step at time t (non-decreasing): the clock advanced to t, ṡ and s̈ chosen when
  /// a sampling instant has been reached (ProgressGovernor::choose); with delay_periods = 1 all of
  /// it for the state predicted at t + h, when the torque will act, then the tracking law's torque at (R_ib, ω_b) against
  /// the reference at σ (docs/pet-erg.md, section 16.2). Calls reset(t) first if reset was never
  /// called.
  ///
  /// `wheel_momentum_b` = A h, the wheels' momentum in the body frame [N·m·s] when the flight
  /// software knows it: the law then cancels the whole gyroscopic torque ω × (Jω + A h) and the
  /// prediction uses it (docs/pet-erg.md, section 16.3; the robust margins assume it).
  const PlannedOutput& step(double t, const lie::Mat3& R_ib, const lie::Vec3& omega_b,
                            const lie::Vec3& wheel_momentum_b) noexcept;
  /// step() without wheel momentum (a rigid body, or momentum the software does not know).
  const PlannedOutput& step(double t, const lie::Mat3& R_ib, const lie::Vec3& omega_b) noexcept {
    return step(t, R_ib, omega_b, kNoMomentum);
  }

  /// The reference at plan time σ flown at the rate ṡ with the clock's acceleration s̈ and the
  /// tracking law's torque and V there (a pure function of the state; the continuous-time
  /// loop's field).
  [[nodiscard]] PlannedOutput evaluate(double sigma, double rate, double accel, const lie::Mat3& R_ib,
                                       const lie::Vec3& omega_b) const noexcept;

  /// The clock as set at the last sampling instant.
  [[nodiscard]] const ProgressClock& clock() const noexcept { return clock_; }

  /// The last step's output.
  [[nodiscard]] const PlannedOutput& output() const noexcept { return out_; }
  /// The progress governor (thresholds, windows).
  [[nodiscard]] const ProgressGovernor& progress() const noexcept { return progress_; }
  /// The parameters.
  [[nodiscard]] const PlannedGovernorParams& params() const noexcept { return params_; }

 private:
  static inline const lie::Vec3 kNoMomentum = lie::Vec3::Zero();
  ProgressGovernor progress_;
  PlannedGovernorParams params_;
  /// o.tau_b = the law's torque `law_b` scaled onto ‖τ‖ = τ_max when larger; o.demand_ratio.
  void saturate(const lie::Vec3& law_b, PlannedOutput& o) const noexcept;
  /// The robust mode's choice (docs/pet-erg.md, section 16.3): jump to ṡ = 1 from rest at σ = 0,
  /// else coast; V of the choice is W̃ of the measurement against the reference at t.
  [[nodiscard]] RateChoice robust_choice(double t, double sigma_act, double rate_act, const lie::Mat3& R_ib,
                                         const lie::Vec3& omega_b) const noexcept;
  /// The state one period ahead under the torque acting now (delay compensation).
  void predict(const lie::Mat3& R_ib, const lie::Vec3& omega_b, const lie::Vec3& wheel_momentum_b,
               lie::Mat3& R_next, lie::Vec3& omega_next) const noexcept;

  PlannedOutput out_;
  ProgressClock clock_;
  lie::Mat3 J_inv_b_{lie::Mat3::Identity()};
  lie::Vec3 acting_b_{lie::Vec3::Zero()};   ///< the torque acting until the next instant
  lie::Vec3 pending_b_{lie::Vec3::Zero()};  ///< the last torque computed (acts next, delayed)
  double next_sample_{0.0};
  bool started_{false};
};

}  // namespace attiguard::governor
