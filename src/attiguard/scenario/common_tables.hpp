#pragma once
/// @file common_tables.hpp
/// The parts of the scenario schema that several kinds share, each read by one function
/// (docs/scenario-format.md; docs/architecture.md, "Where the configuration structs live"): the
/// header (`kind`, `name`, `description`), the governor block (`governor`, [control] gains,
/// [erg]), one cone table (pet_erg, mission and reach: same keys, defaults, units, messages), the
/// integrator keys of [simulation], and enum-valued keys read through the enum's name table.

#include <array>
#include <cstddef>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "attiguard/core/name_table.hpp"
#include "attiguard/governor/attitude_governor.hpp"
#include "attiguard/governor/default_gains.hpp"
#include "attiguard/integrate/integrator_settings.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/table_reader.hpp"
#include "attiguard/scenario/work_limits.hpp"

namespace attiguard::scenario {

/// Declares the keys a table may hold before any is read (TableReader::has), so that a typo of a
/// required key is reported as that typo rather than as a different key missing.
void declare(const TableReader& table, std::initializer_list<std::string_view> keys);

/// An enum-valued key: its text must be one of the table's names (listed in table order in the
/// message otherwise); `fallback` when absent.
template <class Enum, std::size_t N>
[[nodiscard]] Enum enum_or(const TableReader& t, std::string_view key,
                           const NameTable<Enum, N>& names, Enum fallback) {
  const std::array<std::string_view, N> allowed = names.names();
  return *names.find(t.string_or(key, names.name(fallback), allowed));
}

/// A required enum-valued key.
template <class Enum, std::size_t N>
[[nodiscard]] Enum enum_required(const TableReader& t, std::string_view key,
                                 const NameTable<Enum, N>& names) {
  const std::array<std::string_view, N> allowed = names.names();
  return *names.find(t.string(key, allowed));
}

/// The header of every kind: `kind` must equal `expected_kind`; returns `name` (default: the
/// file's stem, or `default_name` when it has none; must not be empty); reads `description`.
[[nodiscard]] std::string read_header(const TableReader& root, const Document& doc,
                                      std::string_view expected_kind,
                                      std::string_view default_name = "scenario");

/// An angle given as `<key>_deg` (degrees) or `<key>` (radians), exactly one of them; `rule_rad`
/// bounds it in radians (the degree form's bounds are converted).
[[nodiscard]] double angle(const TableReader& t, const std::string& key, const NumberRule& rule_rad);

/// The shared keys of a cone table: `type` ("keep_in", default, or "keep_out"), `axis_b`,
/// `direction_i` (normalised), `half_angle` (rad) or `half_angle_deg`: θ_c ∈ (0, π] of a keep-in
/// cone, α ∈ [0, π) of a keep-out cone (constraint [PET-ERG eq. (2b)]).
struct ConeGeometry {
  bool keep_out{false};
  Eigen::Vector3d axis_b{Eigen::Vector3d::UnitZ()};
  Eigen::Vector3d direction_i{Eigen::Vector3d::UnitZ()};
  double half_angle{0.0};  ///< [rad]
  /// The key the half angle was given as (for messages about it).
  std::string half_angle_key{"half_angle"};
};

/// Reads the shared cone keys of `t` (declares them; the caller declares its own extras).
[[nodiscard]] ConeGeometry read_cone_geometry(const TableReader& t);

/// One [[cones]] table of kinds pet_erg and mission: constraint [PET-ERG eq. (2b)],
/// keep-in (θ_c) or keep-out (α, stored as the keep-in cone of π − α), with the field's
/// delta_offset, zeta_offset and repulsive_gain. Throws InputError.
[[nodiscard]] governor::ConeConstraint parse_cone(const TableReader& t);

/// The optional [[cones]] array of `root` (at most governor::kMaxCones), each read by
/// parse_cone and finished.
[[nodiscard]] std::vector<governor::ConeConstraint> parse_cones(const TableReader& root);

/// Why the initial reference (or, when `reference_given` is false, the initial attitude it
/// defaults to) is outside the navigation field's domain c > δ of cone `index` of `root`'s
/// [[cones]] (c = a_c^T R a_b, [PET-ERG eq. (2b)]), in the cone's own terms: the angle of the body
/// axis from direction_i against the half angle as given (keep-out or keep-in, in its unit), and
/// whether it is inside the forbidden region or only within the field's margin (delta_offset).
[[nodiscard]] std::string cone_domain_message(const TableReader& root, std::size_t index,
                                              const governor::ConeConstraint& cone, double c,
                                              bool reference_given);

/// The governor block shared by kinds pet_erg and mission: `governor` (name table
/// governor::kGovernorModeNames, default "pet"), [control] kp, kd, tau_max (PD law [PET-ERG eq. (3)] and the
/// torque limit [PET-ERG eq. (2a)]), and the optional [erg] table (parse_erg_table). `control_extra` names
/// the kind's own extra [control] keys (declared, read by the caller from the returned table).
/// The inertia J is left to the caller.
/// With Gains::derived_when_absent, k_p and k_d may be left out: they keep the values in `params`
/// until the caller derives them (given_governor_values, docs/pet-erg.md section 8).
enum class Gains { required, derived_when_absent };
TableReader parse_governor_block(const TableReader& root, governor::GovernorParams& params,
                                 std::initializer_list<std::string_view> control_extra = {},
                                 Gains gains = Gains::required);

/// Which of k_p, k_d ([control]) and κ, T_s, c_Γ ([erg]) the file gives, with the values read into
/// `params` by parse_governor_block (docs/pet-erg.md, section 8); the others are derived.
[[nodiscard]] governor::GivenGovernorValues given_governor_values(const TableReader& root,
                                                                 const governor::GovernorParams& params);

/// Copies the given or derived k_p, k_d, κ, T_s, c_Γ into `params` [PET-ERG eqs. (3)-(6)]
/// (docs/pet-erg.md, section 8).
void apply_governor_values(const governor::DerivedGovernorValues& values,
                           governor::GovernorParams& params);

/// Reads the optional `[erg]` table of `root` into `params` (κ of [PET-ERG eqs. (4), (6)], c_Γ and
/// T_s of [PET-ERG eqs. (5)-(6)], ε of the navigation field, ε_Γ of the cap k_p(2 − ε_Γ)); keys left out keep
/// the values in `params`; unknown keys are errors.
void parse_erg_table(const TableReader& root, governor::GovernorParams& params);

/// The governor of `params` and `cones`, with its constructor's validation (Γ_d, cones) errors
/// located at `where` of `t` (or at `t` itself when `where` is empty).
[[nodiscard]] governor::AttitudeGovernor make_governor(const TableReader& t, std::string_view where,
                    const governor::GovernorParams& params,
                    const std::vector<governor::ConeConstraint>& cones);

/// Parses the integrator keys of a `[simulation]` table (integrator, step, abs_tol, rel_tol,
/// max_step); shared by every scenario kind (docs/scenario-format.md, "Integrator keys").
[[nodiscard]] integrate::IntegratorSettings parse_integrator_settings(const TableReader& simulation);

/// The times every simulated kind's `[simulation]` table has (docs/scenario-format.md, "Common
/// rules"): `duration` (> 0, and not past the last date of an ephemeris table), `output_interval`
/// (> 0; `output_interval_default` when left out) and the integrator keys, read in that order.
struct SimulationTimes {
  double duration{0.0};
  double output_interval{0.0};
  integrate::IntegratorSettings integrator;
};
[[nodiscard]] SimulationTimes read_simulation_times(const TableReader& root, const TableReader& simulation,
                                                    double output_interval_default);

/// Rejects an interval `key` of `t` (a step, a period, an output interval) that `duration`
/// would need more than the limit in force of `limit` times (work_limits.hpp; `what`:
/// "integrator steps", "output rows", …), with the predicted count and the flag that raises the
/// limit in the message; `t.fail` when present, a "set it" message when defaulted.
void require_countable(const TableReader& t, std::string_view key, double value, double duration,
                       WorkLimit limit, std::string_view what);

/// Rejects a reach partition of `attitude_cells`³ × `omega_cells`³ cells (at most that many: the
/// grid points outside the ball are dropped) whose `steps` reachability steps each exceed the
/// reach cell-step limit in force (WorkLimit::reach_cells), located at `key` of `partition`.
void require_cell_budget(const TableReader& partition, std::string_view key, int attitude_cells,
                         int omega_cells, int steps);

/// require_countable for the integrator: `step` of a fixed-step method, `max_step` (when set)
/// of rkmk_dp54.
void require_step_budget(const TableReader& simulation, const integrate::IntegratorSettings& s,
                         double duration);

/// Rejects `key` of [simulation] (present, or defaulted: then the message asks to set it) when
/// its value exceeds the duration.
void require_at_most_duration(const TableReader& simulation, std::string_view key, double value,
                              double duration);

}  // namespace attiguard::scenario
