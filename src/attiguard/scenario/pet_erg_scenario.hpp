#pragma once
/// @file pet_erg_scenario.hpp
/// Scenario kind `pet_erg`: constrained attitude control with the PD law (3) and the periodic
/// event-triggered (5)-(6), continuous (4), or no reference governor of the PET-ERG paper.
/// Keys: docs/scenario-format.md, section "pet_erg".

#include <string>
#include <vector>

#include "attiguard/governor/attitude_governor.hpp"
#include "attiguard/scenario/table_reader.hpp"
#include "attiguard/governor/reference_schedule.hpp"
#include "attiguard/integrate/integrator_settings.hpp"
#include "attiguard/lie/so3.hpp"
#include "attiguard/scenario/document.hpp"

namespace attiguard::scenario {

/// Everything a `pet_erg` run needs, validated (including the admissibility checks below).
struct PetErgScenario {
  std::string name;
  governor::GovernorParams params;            ///< governor, [body], [control], [erg]
  std::vector<governor::ConeConstraint> cones;  ///< [[cones]] (at most governor::kMaxCones)
  lie::Mat3 R0_ib{lie::Mat3::Identity()};     ///< [initial] attitude
  lie::Vec3 omega0_b{lie::Vec3::Zero()};      ///< [initial] omega_b [rad/s]
  lie::Mat3 R_g0{lie::Mat3::Identity()};      ///< [initial] reference (default: attitude)
  governor::ReferenceSchedule desired;        ///< [desired] attitude or schedule
  double duration{0.0};                       ///< [simulation] duration [s]
  double output_interval{0.0};                ///< [simulation] output_interval [s]
  double convergence_tolerance{1e-4};         ///< [simulation] convergence_tolerance: on φ(R_dᵀR)
  integrate::IntegratorSettings integrator;   ///< [simulation] integrator keys
};

/// The text of a governor mode: "pet" (PET-ERG paper, eqs. (5)-(6)), "continuous" (eq. (4)) or
/// "none" (PD law (3) alone).
[[nodiscard]] const char* governor_mode_name(governor::GovernorMode mode) noexcept;

/// Parses and validates a `pet_erg` document (PET-ERG paper, Sec. V and Theorem 1); rejects
/// unknown keys. Besides the types and ranges
/// of every key it rejects, with InputError naming file:line:col and key:
///   - a desired attitude (or schedule waypoint) that violates a cone, or that lies where the
///     repulsive potential is active (a_cᵀR_d a_b < ζ: the reference could not converge to it);
///   - an initial reference outside the field's domain (a_cᵀR_g(0)a_b ≤ δ);
///   - an initial state that is not admissible, V(R_0, ω_0, R_g(0)) > Γ(R_g(0)) (Theorem 1).
[[nodiscard]] PetErgScenario parse_pet_erg(const Document& doc);

/// One [[cones]] table: constraint (2b) of the PET-ERG paper, keep-in (θ_c) or keep-out (α,
/// stored as the keep-in cone of π − α). Throws InputError. Shared with the `mission` kind.
[[nodiscard]] governor::ConeConstraint parse_cone(const TableReader& t);

/// Reads the optional `[erg]` table of `root` into `params` (PET-ERG paper: κ of (4)/(6), c_Γ and
/// T_s of (5)-(6), ε of the navigation field, ε_Γ of the cap k_p(2 − ε_Γ)); keys left out keep
/// the values in `params`; unknown keys are errors. Shared by kinds `pet_erg` and `mission`.
void parse_erg_table(const TableReader& root, governor::GovernorParams& params);

}  // namespace attiguard::scenario
