#pragma once
/// @file attitude_governor.hpp
/// The combined flight-loop API of the PET-ERG paper: PD law [PET-ERG eq. (3)] as the inner loop, the dynamic
/// safety margin with Γ = min{Γ_d, Γ_g(R_g), k_p(2 − ε_Γ)}, the navigation field and the reference
/// update, either continuous (4), periodic event-triggered [PET-ERG eqs. (5)-(6)], or none (plain PD to R_d).
///
/// Set-up (the constructor: validation and the offline Γ_d) may throw and allocate nothing after
/// it returns; every per-step function is noexcept and allocation-free (fixed-capacity cone
/// storage, no std::function), so the class can run inside a flight loop without the simulator:
///
///   AttitudeGovernor gov(params, cones);        // once, offline
///   gov.reset(t0, R0);                          // R_g(t0) = R0 (paper Sec. IV-A)
///   loop: const GovernorOutput& out = gov.step(t, R_ib, omega_b, R_d_of_t);
///         apply(out.tau_b);                     // out.R_g, out.V, out.gamma, out.trigger, …

#include <array>
#include <optional>
#include <span>

#include "attiguard/control/pd_so3.hpp"
#include "attiguard/core/name_table.hpp"
#include "attiguard/governor/cone_constraint.hpp"
#include "attiguard/governor/pet_erg.hpp"
#include "attiguard/governor/robust_margin.hpp"
#include "attiguard/governor/saddle_tie_break.hpp"
#include "attiguard/governor/torque_threshold.hpp"

namespace attiguard::governor {

/// Which reference update runs above the PD law.
enum class GovernorMode {
  pet,         ///< periodic event-triggered ERG, [PET-ERG eqs. (5)-(6)]
  continuous,  ///< continuous-time ERG, [PET-ERG eq. (4)]
  none,        ///< no governor: the PD law [PET-ERG eq. (3)] tracks R_d directly (constraints not enforced)
  /// a planned slew flown by the tracking law under the progress governor (docs/pet-erg.md,
  /// section 16.2; planned_governor.hpp): not an AttitudeGovernor mode (its constructor refuses it)
  planned,
};

/// Names of GovernorMode in scenario files (`governor = "pet"`), summaries and the Python
/// bindings (docs/scenario-format.md, "pet_erg").
inline constexpr NameTable<GovernorMode, 4> kGovernorModeNames{
    {{{GovernorMode::pet, "pet"},
      {GovernorMode::continuous, "continuous"},
      {GovernorMode::none, "none"},
      {GovernorMode::planned, "planned"}}}};

/// Parameters of the PD law [PET-ERG eq. (3)] and the governor (PET-ERG paper, Secs. III–V).
struct GovernorParams {
  GovernorMode mode{GovernorMode::pet};
  control::PdGains gains{5.0, 1.0};  ///< k_p, k_d of [PET-ERG eq. (3)]
  Mat3 J{Mat3::Identity()};          ///< inertia [kg·m²] (V of Sec. III-A, Γ_d)
  double tau_max{1.0};               ///< τ_max of [PET-ERG eq. (2a)] [N·m]
  double kappa{1.0};                 ///< κ of the DSM and of [PET-ERG eqs. (4), (6)]
  double c_gamma{3.0};               ///< c_Γ > 1 of the trigger [PET-ERG eq. (5)]
  double Ts{0.5};                    ///< sampling period T_s of [PET-ERG eqs. (5)-(6)] [s]
  double epsilon{1e-3};              ///< ε of the normalisation max{‖ρ_n‖, ε} in [PET-ERG eqs. (4), (6)]
  double epsilon_gamma{0.1};         ///< ε_Γ ∈ (0, 2) of Γ's cap k_p(2 − ε_Γ)
  /// step() only: the reference move of one control step is at most ‖ρ_n‖ long (it cannot
  /// overshoot the field's equilibrium however large κ(Γ − V) dt is) and is shortened by halving
  /// until V ≤ Γ holds at its end instead of being dropped (docs/pet-erg.md, "Discrete reference
  /// update"). false keeps the plain zero-order hold with rejection.
  bool bounded_step{false};
  /// The saddle tie-break of the navigation field (docs/pet-erg.md, section 4, "Saddles: the
  /// tie-break"); false turns it off (tests compare with the field without it).
  bool saddle_tie_break{true};
  /// A second torque constraint, a polytope {|r_iᵀτ| ≤ u_i} (e.g. a reaction-wheel array,
  /// docs/pet-erg.md, section 12): when set, Γ_d is min{Γ_d(‖τ‖ ≤ τ_max), Γ_d(polytope)}, its
  /// value computed offline by compute_polytope_torque_threshold. 0: no polytope.
  double polytope_gamma_d{0.0};
  /// Robust margins (docs/pet-erg.md, section 13), computed offline by compute_robust_margin
  /// for torque limits already reduced by its command error (the caller sets tau_max and
  /// polytope_gamma_d to the reduced ones). When set: the level compared with Γ is the strict
  /// Lyapunov function W = V − ε ωᵀJ sk(RᵀR_g)^∨ plus the measurement margin e_W, Γ becomes
  /// Γ_W = (1 − δ) min{Γ_d, Γ_g, k_p(2 − ε_Γ)}, a move of R_g is at most Δ_max long and is taken
  /// only where Γ_W > Γ_min.
  std::optional<RobustMargin> robust;
};

/// Everything the governor knows at one instant (PET-ERG paper notation).
struct GovernorOutput {
  Vec3 tau_b{Vec3::Zero()};        ///< PD torque [PET-ERG eq. (3)] towards R_g [N·m]
  Mat3 R_g{Mat3::Identity()};      ///< auxiliary reference (R_d itself in mode none)
  Vec3 xi_g{Vec3::Zero()};         ///< body rate of R_g, Ṙ_g = R_g ξ̂ ([PET-ERG eq. (4)] or (6)) [rad/s]
  /// navigation field ρ_n(R_d, R_g) (Sec. III-B.2), with an active saddle tie-break the field
  /// with the detour, ρ_n + σ g ‖ρ_a‖ ĥ (docs/pet-erg.md, section 4, "Saddles: the tie-break")
  Vec3 rho{Vec3::Zero()};
  double V{0.0};                   ///< Lyapunov function V(R, ω, R_g) (Sec. III-A)
  /// The level compared with Γ: V, or W = V − ε ωᵀJ s with robust margins (docs/pet-erg.md,
  /// section 13; without the measurement margin)
  double W{0.0};
  double gamma_d{0.0};             ///< Γ_d (constant)
  double gamma_g{0.0};             ///< Γ_g(R_g) = min over cones (+∞ without cones)
  double gamma{0.0};               ///< Γ(R_g) = min{Γ_d, Γ_g, k_p(2 − ε_Γ)} (× (1 − δ) robust)
  bool trigger{true};              ///< flag of [PET-ERG eq. (5)] held on the current sampling interval
  bool sampled{false};             ///< true when this call evaluated (5) (a sampling instant)
  /// The saddle tie-break held on the current sampling interval (docs/pet-erg.md, section 4)
  TieBreak tie_break{};
  bool tie_break_started{false};   ///< step() only: a tie-break started at this call
  int cone_count{0};
  std::array<double, kMaxCones> margins{};  ///< a_cᵀ R a_b − cos θ_c of each cone, [PET-ERG eq. (2b)]
  /// Smallest margin of [PET-ERG eq. (2b)] over the cones [PET-ERG eq. (2b)]; +∞ without cones.
  [[nodiscard]] double min_margin() const noexcept;
};

/// What the closed-loop field of [PET-ERG eqs. (1), (3)-(6)] reads from the governor at one
/// instant: the PD torque and the reference rate, nothing else (AttitudeGovernor::rates).
struct GovernorRates {
  Vec3 tau_b{Vec3::Zero()};  ///< PD torque [PET-ERG eq. (3)] towards R_g (R_d in mode none) [N·m]
  Vec3 xi_g{Vec3::Zero()};   ///< body rate of R_g, [PET-ERG eq. (6)] in mode pet, (4) in mode continuous [rad/s]
};

/// What figures() or rates() computed at one state, for a later call at a bit-identical state
/// (docs/performance.md, "Shared cone cosines"): Γ_g and the cones' cosines a_cᵀR_g a_b at the
/// reference R_g [PET-ERG Sec. III-B], and τ [PET-ERG eq. (3)] and V [PET-ERG Sec. III-A] at
/// (R, ω, R_g). A caller keeps one per loop; a call reads an entry only where its inputs equal the
/// stored ones bit for bit, so its results are those it would compute. Allocation-free.
struct GovernorMemo {
  bool has_reference{false};  ///< R_g, gamma_g and cosines are set
  bool has_state{false};      ///< R_ib, omega_b, tau_b and V are set (for R_g)
  Mat3 R_g{Mat3::Identity()};
  double gamma_g{0.0};
  std::array<double, kMaxCones> cosines{};
  Mat3 R_ib{Mat3::Identity()};
  Vec3 omega_b{Vec3::Zero()};
  Vec3 tau_b{Vec3::Zero()};
  double V{0.0};
};

/// PD law [PET-ERG eq. (3)] + [PET-ERG eqs. (5)-(6)] / ERG [PET-ERG eq. (4)], as one flight-loop object.
class AttitudeGovernor {
 public:
  /// Validates the parameters and cones and computes Γ_d offline [PET-ERG Sec. III-B.1].
  /// Throws SetupError (core/errors.hpp) with a one-line reason (set-up code only).
  AttitudeGovernor(const GovernorParams& params, std::span<const ConeConstraint> cones);

  // ---- pure functions of the state (PET-ERG paper notation), noexcept and allocation-free ----

  /// V(R, ω, R_g) = ½ωᵀJω + k_p φ(RᵀR_g) [PET-ERG Sec. III-A].
  [[nodiscard]] double lyapunov(const Mat3& R_ib, const Vec3& omega_b, const Mat3& R_g) const noexcept;
  /// PD torque τ = k_p sk(RᵀR_g)^∨ − k_d ω [PET-ERG eq. (3)].
  [[nodiscard]] Vec3 torque(const Mat3& R_ib, const Vec3& omega_b, const Mat3& R_g) const noexcept;
  /// Γ_g(R_g), the minimum over the cones (PET-ERG paper, Sec. III-B.1; +∞ without cones).
  [[nodiscard]] double gamma_g(const Mat3& R_g) const noexcept;
  /// Γ(R_g) = min{Γ_d, Γ_g(R_g), k_p(2 − ε_Γ)} [PET-ERG Sec. III-B.1]; with robust
  /// margins Γ_W = (1 − δ) times it (docs/pet-erg.md, section 13).
  [[nodiscard]] double gamma(const Mat3& R_g) const noexcept;
  /// The level compared with Γ: V, or with robust margins W = V − ε ωᵀJ sk(RᵀR_g)^∨
  /// (docs/pet-erg.md, section 13).
  [[nodiscard]] double level(const Mat3& R_ib, const Vec3& omega_b, const Mat3& R_g) const noexcept;
  /// ρ_n(R_d, R_g) = −grad(P_a + Σ P_r) [PET-ERG Sec. III-B.2], its attraction floored at
  /// min(ε, kTieBreakFloorCap) near a half turn (docs/pet-erg.md, section 4, "Half-turns").
  [[nodiscard]] Vec3 navigation_field(const Mat3& R_g, const Mat3& R_d) const noexcept;
  /// Trigger condition [PET-ERG eq. (5)]: Γ(R_g) − c_Γ V ≥ 0 [PET-ERG eq. (5)]; with robust margins
  /// V → W + e_W of the measured state (docs/pet-erg.md, section 13).
  [[nodiscard]] bool trigger_condition(const Mat3& R_ib, const Vec3& omega_b,
                                       const Mat3& R_g) const noexcept;
  /// The full evaluation at one instant with the held trigger flag `flag`: τ (3), V, Γ's, ρ_n,
  /// the reference rate ξ of [PET-ERG eq. (6)] in mode pet (of [PET-ERG eq. (4)] in mode continuous; 0 in mode none, where
  /// R_g is replaced by R_d) and the margins of [PET-ERG eq. (2b)] [PET-ERG eqs. (3)-(6)].
  /// `tie`: the saddle tie-break held on the sampling interval; when active, ξ follows the field
  /// with the detour (docs/pet-erg.md, section 4, "Saddles: the tie-break").
  [[nodiscard]] GovernorOutput evaluate(const Mat3& R_ib, const Vec3& omega_b, const Mat3& R_g,
                                        const Mat3& R_d, bool flag, const TieBreak& tie = {}) const noexcept;
  /// evaluate() without ρ_n and ξ (both left 0): τ (3), V, W, Γ's, the flag and the margins of
  /// [PET-ERG eq. (2b)], bit for bit those of evaluate(), for the simulator's figures at the
  /// integrator's steps where no output row needs ρ_n (docs/performance.md, "Lean core (issue 48,
  /// item 2)") [PET-ERG eqs. (3), (5), (2b)].
  [[nodiscard]] GovernorOutput figures(const Mat3& R_ib, const Vec3& omega_b, const Mat3& R_g,
                                       const Mat3& R_d, bool flag, const TieBreak& tie = {}) const noexcept;
  /// figures() that also stores Γ_g, the cones' cosines, τ and V of this state in `memo` for a
  /// later rates() at the same state (the monitor and the next step's first stage);
  /// [PET-ERG eqs. (3), (5), (2b)], the output bit for bit figures()'s.
  [[nodiscard]] GovernorOutput figures(const Mat3& R_ib, const Vec3& omega_b, const Mat3& R_g,
                                       const Mat3& R_d, bool flag, const TieBreak& tie,
                                       GovernorMemo& memo) const noexcept;
  /// τ and ξ of evaluate() alone, bit for bit the same, for the integrator's stages
  /// [PET-ERG eqs. (3)-(6)]: no margins of [PET-ERG eq. (2b)], Γ_g once, and V, Γ and ρ_n only
  /// where ξ needs them (not with the flag of [PET-ERG eq. (5)] down, ρ_n not when Γ ≤ V).
  [[nodiscard]] GovernorRates rates(const Mat3& R_ib, const Vec3& omega_b, const Mat3& R_g, const Mat3& R_d,
                                    bool flag, const TieBreak& tie = {}) const noexcept;
  /// rates() reading Γ_g, the cosines, τ and V from `memo` where its inputs are the stored ones bit
  /// for bit, and storing Γ_g and the cosines of a new R_g there: the same τ and ξ of
  /// [PET-ERG eqs. (3)-(6)] (docs/performance.md, "Shared cone cosines").
  [[nodiscard]] GovernorRates rates(const Mat3& R_ib, const Vec3& omega_b, const Mat3& R_g, const Mat3& R_d,
                                    bool flag, const TieBreak& tie, GovernorMemo& memo) const noexcept;
  /// The saddle tie-break at a sampling instant for R_g and R_d (update_tie_break with the floor
  /// min(ε, kTieBreakFloorCap) on ‖ρ_a‖; docs/pet-erg.md, section 4, "Saddles: the tie-break"); the state of the flight
  /// loop is not changed.
  [[nodiscard]] TieBreakUpdate tie_break_update(const TieBreak& held, const Mat3& R_g,
                                                const Mat3& R_d) const noexcept;

  // ---- the stateful flight loop ----

  /// Starts at time t0 with R_g(t0) = R_g0 (the paper uses R_g(t0) = R(t0), Sec. IV-A); the
  /// first sampling instant of [PET-ERG eq. (5)] is t0.
  void reset(double t0, const Mat3& R_g0) noexcept;
  /// One control step at time t (non-decreasing across calls) with the measured R, ω and the
  /// current R_d(t) (PET-ERG paper, Fig. 1): moves R_g over [t_prev, t] with the rate of the
  /// previous call (zero-order hold, R_g ← R_g exp((t − t_prev) ξ̂), a move that would leave
  /// V > Γ is not taken), evaluates (5) and the saddle tie-break (docs/pet-erg.md, section 4)
  /// when a sampling instant t_k has been reached (in modes pet and continuous), and returns
  /// τ (3) with all diagnostics. Calls reset(t, R_ib) first if reset was never called.
  /// With params.bounded_step the move is bounded and shortened instead (docs/pet-erg.md,
  /// "Discrete reference update").
  const GovernorOutput& step(double t, const Mat3& R_ib, const Vec3& omega_b,
                             const Mat3& R_d) noexcept;

  /// The current auxiliary reference R_g of the flight loop [PET-ERG eq. (6)].
  [[nodiscard]] const Mat3& reference() const noexcept { return R_g_; }
  /// The trigger flag of [PET-ERG eq. (5)] held on the current sampling interval [PET-ERG eq. (6)].
  [[nodiscard]] bool trigger_flag() const noexcept { return flag_; }
  /// The saddle tie-break held on the current sampling interval (docs/pet-erg.md, section 4).
  [[nodiscard]] const TieBreak& tie_break() const noexcept { return tie_; }
  /// The output of the last step [PET-ERG eqs. (3)-(6)].
  [[nodiscard]] const GovernorOutput& last() const noexcept { return out_; }

  // ---- constants ----
  /// The parameters of [PET-ERG eqs. (3)-(6)] this governor was built with.
  [[nodiscard]] const GovernorParams& params() const noexcept { return params_; }
  /// The pointing constraints [PET-ERG eq. (2b)] this governor enforces.
  [[nodiscard]] std::span<const ConeConstraint> cones() const noexcept { return cones_.span(); }
  /// Γ_d (certified lower bound of the exact minimum, PET-ERG paper Sec. III-B.1).
  [[nodiscard]] double gamma_d() const noexcept { return gamma_d_; }
  /// Details of the offline computation of Γ_d.
  [[nodiscard]] const TorqueThreshold& torque_threshold() const noexcept { return threshold_; }
  /// The loose closed-form bound on Γ_d (docs/pet-erg.md).
  [[nodiscard]] double gamma_d_loose() const noexcept { return gamma_d_loose_; }
  /// The cap k_p(2 − ε_Γ) of Γ = min{Γ_d, Γ_g, k_p(2 − ε_Γ)} [PET-ERG Sec. III-B.1].
  [[nodiscard]] double gamma_cap() const noexcept { return gamma_cap_; }

 private:
  // The helpers below are `inline` (defined in attitude_governor.cpp, used only there): the
  // library is compiled with -fPIC, where GCC does not inline a function that may be interposed,
  // and rates() and figures() inline them (docs/performance.md, "Shared cone cosines").
  /// Halvings of a reference move tried before it is dropped (bounded_step; 2⁻³⁰ of a step).
  static constexpr int kMaxMoveHalvings = 30;
  /// The bounded move of R_g over dt (docs/pet-erg.md, "Discrete reference update").
  /// `scale` ∈ (0, 1] shortens the allowed length; `applied` receives the move taken (0 if none).
  [[nodiscard]] Mat3 bounded_move(const Mat3& R_ib, const Vec3& omega_b, double dt, double scale,
                                  Vec3& applied) const noexcept;
  /// figures() and, when `memo` is set, its Γ_g, cosines, τ and V stored there [PET-ERG eqs. (3), (5), (2b)].
  [[nodiscard]] inline GovernorOutput figures_into(const Mat3& R_ib, const Vec3& omega_b, const Mat3& R_g,
                                            const Mat3& R_d, bool flag, const TieBreak& tie,
                                            GovernorMemo* memo) const noexcept;
  /// Γ from Γ_g(R_g) already computed: gamma(R_g) without computing Γ_g again [PET-ERG Sec. III-B.1].
  [[nodiscard]] inline double gamma_of(double gamma_g) const noexcept;
  /// ρ_n with the held tie-break's detour (docs/pet-erg.md, section 4) [PET-ERG Sec. III-B.2].
  [[nodiscard]] inline Vec3 held_field(const Mat3& R_g, const Mat3& R_d, const TieBreak& tie) const noexcept;
  /// held_field with the cones' cosines a_cᵀR_g a_b already computed [PET-ERG Sec. III-B.2].
  [[nodiscard]] inline Vec3 held_field(const Mat3& R_g, const Mat3& R_d, const TieBreak& tie,
                                std::span<const double> cosines) const noexcept;
  /// Γ_g(R_g) and the cones' cosines into `memo` unless it holds them for R_g [PET-ERG Sec. III-B.1].
  inline void remember_reference(const Mat3& R_g, GovernorMemo& memo) const noexcept;
  /// The level the decisions use: V, or W + e_W with robust margins (section 13).
  [[nodiscard]] inline double decision_level(const Mat3& R_ib, const Vec3& omega_b, const Mat3& R_g) const noexcept;
  /// May R_g be moved to `candidate` for the measured (R, ω)? V ≤ Γ there; with robust margins
  /// W + e_W ≤ Γ_W and Γ_W > Γ_min (docs/pet-erg.md, section 13).
  [[nodiscard]] bool admissible_move(const Mat3& R_ib, const Vec3& omega_b, const Mat3& candidate) const noexcept;

  GovernorParams params_;
  ConeSet cones_;
  TorqueThreshold threshold_;
  double gamma_d_{0.0};
  double gamma_d_loose_{0.0};
  double gamma_cap_{0.0};
  // flight-loop state
  bool started_{false};
  double t_prev_{0.0};
  Mat3 R_g_{Mat3::Identity()};
  Vec3 last_move_{Vec3::Zero()};  ///< the last move of R_g (bounded_step), body frame of R_g
  double move_scale_{1.0};        ///< reversal scale of the bounded step
  bool flag_{true};
  TieBreak tie_;
  SamplingClock clock_;
  GovernorOutput out_;
};

}  // namespace attiguard::governor
