#pragma once
/// @file adversarial.hpp
/// An adversarial soundness and tightness check of ConReach results (docs/reach.md,
/// "Adversarial check"): instead of sampling, it *optimises* the initial state of each cell to
/// (a) maximise the distance ratio √(d_Q,up² + d_P²)/r_i over the t_i > 0 (a ratio above 1 is a
/// state that escapes its ball; at t_0 the ball is the initial set's covering ball), and (b) maximise the attitude and per-axis ω spread of the true
/// reachable set at the last t_i, which divided into the claimed enclosure gives the tightness
/// figures. Multi-start adaptive random search on the boundary of the initial set
/// (‖log(R0ᵀR)‖ = a, ‖ω − ω0‖ = b: the set's extreme states), trajectories by RKMK4.

#include <atomic>
#include <cstdint>
#include <vector>

#include "attiguard/reach/conreach.hpp"

namespace attiguard::reach {

struct AdversarialSettings {
  int starts{8};          ///< random starts per objective and cell
  int iterations{40};     ///< perturbations tried per start
  double step{0.01};      ///< RKMK4 step of the trajectories [s]
  std::uint64_t seed{1};
  int threads{0};         ///< 0: hardware concurrency
  /// When set and true (the program's interruption flag), no further start is taken: the report
  /// then covers the starts searched so far and says `stopped`.
  const std::atomic<bool>* stop{nullptr};
};

struct AdversarialReport {
  bool stopped{false};            ///< the settings' stop flag ended the search early
  long evaluations{0};            ///< trajectories integrated
  double worst_ratio{0.0};        ///< max over cells, t_i > 0 and the optimised states
  double worst_ratio_time{0.0};   ///< the t_i where it was found
  double attitude_spread{0.0};    ///< max d(R_n(T), R(T)) found (first cell's nominal)
  double attitude_claimed{0.0};   ///< the claimed bi-invariant attitude radius at T
  Vec3 omega_spread{Vec3::Zero()};   ///< max |ω_k(T) − ω_n,k(T)| found
  Vec3 omega_claimed{Vec3::Zero()};  ///< the claimed half-widths at T
  double wall_time_s{0.0};
};

/// Runs the check over every cell (cells[i] ↔ results[i]).
[[nodiscard]] AdversarialReport adversarial_check(const ClosedLoop& loop,
                                                  const std::vector<InitialSet>& cells,
                                                  const std::vector<ReachResult>& results,
                                                  const AdversarialSettings& settings);

}  // namespace attiguard::reach
