#pragma once
/// @file default_gains.hpp
/// The PET-ERG's parameters derived from the craft when the scenario leaves them out
/// (docs/pet-erg.md, section 8, "Defaults derived from the craft"): the PD gains k_p, k_d of
/// [PET-ERG eq. (3)], the DSM gain κ of [PET-ERG eqs. (4), (6)], the sampling period T_s and the
/// trigger margin c_Γ of [PET-ERG eqs. (5)-(6)], from the inertia J, the torque the craft can
/// command in every direction, the slew and the flight-loop period. The same dimensionless closed
/// loop on a 10⁻² kg·m² CubeSat and a 10⁷ kg·m² station: every value is a dimensionless constant
/// times the craft's own scales. Set-up code: may throw SetupError, never runs per step.

#include <optional>

#include "attiguard/lie/so3.hpp"

namespace attiguard::governor {

/// The craft's quantities the defaults are derived from (docs/pet-erg.md, section 8).
struct CraftScales {
  lie::Mat3 J{lie::Mat3::Identity()};  ///< inertia [kg·m²]
  double tau_max{1.0};                  ///< τ_max of [PET-ERG eq. (2a)] [N·m]
  /// Radius of the largest torque ball inside the wheel polytope {|r_iᵀτ| ≤ u_i}, min_i u_i/‖r_i‖
  /// [N·m]; 0 without wheels.
  double wheel_torque_radius{0.0};
  double disturbance_bound{0.0};  ///< d̄ of the flight loop's disturbance [N·m] (0: none)
  double slew_angle{0.0};         ///< the largest slew of the scenario [rad]
  double initial_kinetic_energy{0.0};  ///< ½ω₀ᵀJω₀ of the initial state [J]
  double control_period{0.0};     ///< flight-loop period h [s]; 0: the continuous-time loop
  /// The narrowest repulsive band of the cones as an angle, min_i (ζ_i − δ_i)/sin θ_c,i [rad]
  /// (0 without cones): the reference must not cross it in one integration step.
  double narrowest_band{0.0};
  /// θ_ref is multiplied by it (> 1: a softer loop, k_p ∝ 1/softening; < 1: stiffer). The reader
  /// chooses it so that the robust margins leave room (docs/pet-erg.md, section 8, "Robust
  /// margins").
  double softening{1.0};
};

/// The values the scenario gives; a value left out (nullopt) is derived.
struct GivenGovernorValues {
  std::optional<double> kp, kd, kappa, Ts, c_gamma, epsilon;
};

/// The dimensionless constants of the derivation (docs/pet-erg.md, section 8).
struct DefaultGainConstants {
  double stiffness{8.0};        ///< c_p = k_p θ_ref / τ_eff
  double damping_ratio{0.5};    ///< ζ = k_d / (2√(k_p J_d)), J_d = √(J_min J_max)
  double min_angle{0.2};        ///< floor of θ_ref [rad] (holds and tiny slews)
  double rate_gain{5.0};        ///< κ̂ = κ Γ_d / ω_ref
  double sample_fraction{0.25}; ///< T_s ω_n
  double c_gamma{1.2};          ///< c_Γ
  /// ε = κΓ_d/(r ω_n): near R_d the reference converges at r times the PD loop's ω_n at most
  /// (not faster than the loop and the integrator resolve); never below epsilon_min.
  double reference_rate_ratio{5.0};
  double epsilon_min{1e-3};
  double bandwidth_period{0.1}; ///< cap on √(k_p/J_min)·h in the flight loop
  double damping_period{0.2};   ///< cap on k_d h/J_min in the flight loop
  double energy_share{0.5};     ///< ½ω₀ᵀJω₀ at most this share of Γ_d (else θ_ref grows)
  /// With robust margins: Γ_min at most this share of (1 − δ)Γ_d' (else the loop is softened)
  double robust_share{0.25};
};

/// The governor's parameters with the scales they were derived from (docs/pet-erg.md,
/// section 8); `check` prints and summary.json records them.
struct DerivedGovernorValues {
  double kp{0.0}, kd{0.0}, kappa{0.0}, Ts{0.0}, c_gamma{0.0}, epsilon{0.0};
  bool kp_derived{false}, kd_derived{false}, kappa_derived{false}, Ts_derived{false},
      c_gamma_derived{false}, epsilon_derived{false};
  double torque_scale{0.0};      ///< τ_eff: the torque commandable in every direction [N·m]
  double reference_angle{0.0};   ///< θ_ref [rad]
  double softening{1.0};         ///< CraftScales::softening the values were derived with
  double time_scale{0.0};        ///< t* = √(J_max θ_ref / τ_eff) [s]
  double rate_scale{0.0};        ///< ω_ref = θ_ref / t* [rad/s]
  double natural_frequency{0.0}; ///< ω_n = √(k_p / J_max) [rad/s]
  double damping_ratio{0.0};     ///< ζ = k_d / (2√(k_p J_d)), J_d = √(J_min J_max)
  double gamma_d_estimate{0.0};  ///< Γ_d of the ball τ_eff (the scale of κ) [J]
  /// √(k_p/J_min)·h and k_d h/J_min: the fast PD pole against the flight-loop period (0 without).
  double bandwidth_period{0.0};
  double damping_period{0.0};
  bool limited_by_control_period{false};  ///< the flight-loop caps lowered k_p
  /// The integration step a simulation takes when the scenario gives none [s]:
  /// min(T_s/2, 0.1/ω_fast, 0.1 w/(κΓ_d), h), ω_fast = max(√(k_p/J_min), k_d/J_min, κΓ_d/ε) (the
  /// fastest rate of the closed loop: the PD poles and the reference's approach to R_d), w the
  /// narrowest repulsive band (the reference, at most κΓ_d fast, crosses a tenth of it per step).
  double integrator_step{0.0};
  bool integrator_step_derived{false};  ///< set by the reader when [simulation] step is absent
  [[nodiscard]] bool any_derived() const noexcept {
    return kp_derived || kd_derived || kappa_derived || Ts_derived || c_gamma_derived ||
           epsilon_derived;
  }
};

/// J_d = √(J_min J_max): the inertia the damping ratio ζ of the derived k_d refers to
/// (docs/pet-erg.md, section 8): ζ(J_max/J_min)^{1/4} on the least-inertia axis, ζ(J_min/J_max)^{1/4}
/// on the largest, so that neither term of Γ_d (the position term τ²/(2k_p) and the damping term
/// λ_min τ²/(2k_d²)) alone caps the rate.
[[nodiscard]] double damping_inertia(double J_min, double J_max) noexcept;

/// τ_eff = min(τ_max, wheel_torque_radius) − d̄: the torque the PD law may use in every direction
/// (docs/pet-erg.md, section 8). Throws SetupError when nothing is left.
[[nodiscard]] double effective_torque(const CraftScales& craft);

/// Derives every value `given` leaves out from `craft` (docs/pet-erg.md, section 8):
///   θ_ref = max(slew, min_angle), t* = √(J_max θ_ref/τ_eff), ω_ref = θ_ref/t*,
///   k_p = c_p τ_eff/θ_ref, k_d = 2ζ√(k_p J_d), κ = κ̂ ω_ref/Γ_d(k_p, k_d, τ_eff),
///   T_s = T̂_s/ω_n (a multiple of h in the flight loop), c_Γ = 1.2,
///   ε = max(ε_min, κΓ_d/(r ω_n));
/// in the flight loop k_p is lowered until √(k_p/J_min) h and k_d h/J_min are within their caps,
/// and θ_ref grows until the initial kinetic energy is at most a share of Γ_d. Given values are
/// kept as they are. Throws SetupError for non-finite or non-positive inputs.
[[nodiscard]] DerivedGovernorValues derive_governor_values(const CraftScales& craft,
                                                           const GivenGovernorValues& given,
                                                           const DefaultGainConstants& k = {});

}  // namespace attiguard::governor
