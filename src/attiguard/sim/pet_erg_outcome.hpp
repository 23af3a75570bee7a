#pragma once
/// @file pet_erg_outcome.hpp
/// How a `pet_erg` run ended (docs/pet-erg.md, "Outcomes"): converged, stalled (the reference
/// R_g stopped short of R_d), not converged by the end of the run, or chattering (R_g reverses
/// its direction of motion step after step). Decided from the convergence time and from the
/// motion of R_g over the last half of the run, which ReferenceMotion records.

#include <string_view>

#include "attiguard/core/name_table.hpp"
#include "attiguard/lie/so3.hpp"

namespace attiguard::sim {

/// The outcome of a pet_erg run (docs/pet-erg.md, "Outcomes").
enum class PetErgOutcome {
  converged,             ///< φ(R_dᵀR) ≤ tolerance from convergence_time to the end
  stalled,               ///< R_g stopped short of R_d (a local minimum of the potential, or V ≥ Γ)
  not_converged_by_end,  ///< still moving towards R_d when the run ended
  chattering,            ///< R_g reverses its direction of motion on many steps (a stiff update)
};

/// Names of PetErgOutcome in summary.json (`outcome`), stdout and runs.csv.
inline constexpr NameTable<PetErgOutcome, 4> kPetErgOutcomeNames{
    {{{PetErgOutcome::converged, "converged"},
      {PetErgOutcome::stalled, "stalled"},
      {PetErgOutcome::not_converged_by_end, "not_converged_by_end"},
      {PetErgOutcome::chattering, "chattering"}}}};

/// Smallest step of R_g [rad] that counts as a move (below it R_g is at rest up to rounding).
inline constexpr double kReferenceMoveFloor = 1e-9;

/// The motion of the reference R_g over a window [t_start, end] of a run (docs/pet-erg.md,
/// "Outcomes"): how far it moved from where it was at t_start, how many steps moved it by more
/// than kReferenceMoveFloor, and on how many of those the direction of motion reversed
/// (consecutive steps log(R_{k-1}ᵀR_k) with a negative inner product). Allocation-free.
class ReferenceMotion {
 public:
  /// Records from t_start on (docs/pet-erg.md, "Outcomes").
  explicit ReferenceMotion(double t_start = 0.0) noexcept : t_start_(t_start) {}
  /// R_g at time t (non-decreasing t; observations before t_start are ignored).
  void observe(double t, const lie::Mat3& R_g) noexcept;
  /// Bi-invariant distance from R_g(t_start) to the last observed R_g [rad].
  [[nodiscard]] double displacement() const noexcept;
  /// Steps that moved R_g by more than kReferenceMoveFloor.
  [[nodiscard]] long moves() const noexcept { return moves_; }
  /// Moves whose direction reversed with respect to the previous move.
  [[nodiscard]] long reversals() const noexcept { return reversals_; }
  /// Sum of the moves [rad] (≥ displacement()).
  [[nodiscard]] double path_length() const noexcept { return path_length_; }
  /// Largest single move [rad].
  [[nodiscard]] double largest_move() const noexcept { return largest_move_; }

 private:
  double t_start_{0.0};
  bool started_{false};
  lie::Mat3 first_{lie::Mat3::Identity()};
  lie::Mat3 last_{lie::Mat3::Identity()};
  lie::Vec3 last_move_{lie::Vec3::Zero()};
  long moves_{0};
  long reversals_{0};
  double path_length_{0.0};
  double largest_move_{0.0};
};

/// What the outcome is decided from (docs/pet-erg.md, "Outcomes").
struct OutcomeEvidence {
  bool governed{true};          ///< false in mode none (R_g = R_d, no reference of its own)
  double convergence_time{-1};  ///< −1 when the end is not within the tolerance
  double distance_left{0.0};    ///< d(R_g, R_d) at the end [rad]
  double distance_tolerance{0.0};  ///< the distance that counts as R_g at R_d [rad]
  ReferenceMotion last_half;    ///< R_g over the last half of the run
};

/// Rules (docs/pet-erg.md, "Outcomes"), first match wins: converged when convergence_time ≥ 0;
/// chattering when over the last half R_g reversed its direction at least twice, its path
/// is at least 10 distance_tolerance long and at least 4 times its net displacement (it goes
/// back and forth; a jitter of a reference held at a local minimum of the potential is far
/// shorter); stalled when R_g is farther than distance_tolerance from R_d and moved less than
/// 1 % of that distance over the last half; otherwise not_converged_by_end.
[[nodiscard]] PetErgOutcome classify_outcome(const OutcomeEvidence& e) noexcept;

}  // namespace attiguard::sim
