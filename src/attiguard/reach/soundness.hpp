#pragma once
/// @file soundness.hpp
/// Empirical soundness check of ConReach results: simulate sampled initial states of the whole
/// initial set and verify that at every t_i each state lies in the computed ball of its cell,
/// using the upper bound of d_Q (metrics.hpp), i.e. √(d_Q,up² + d_P²) ≤ r_i, and that at every
/// sub-step time it lies in the state-tube segments that start or end there (attitude ball and
/// ω box) and in the U_i of its step (ω box and attitude ball): the sets the safety check uses.
/// Half of the samples lie on the boundary of the initial set (‖log(R0ᵀR)‖ = a, ‖ω − ω0‖ = b),
/// the rest inside.

#include <atomic>
#include <cstdint>
#include <vector>

#include "attiguard/reach/conreach.hpp"

namespace attiguard::reach {

struct SoundnessSettings {
  long samples{10000};
  std::uint64_t seed{1};
  double step{0.01};  ///< RKMK4 step of the sample simulations [s]
  int keep{20};       ///< trajectories kept (at every sub-step time) for plots
  int threads{0};     ///< 0: hardware concurrency
  /// When set and true (e.g. the program's interruption flag, docs/errors.md), no further sample
  /// is started: the report then covers the samples checked so far and says `stopped`.
  const std::atomic<bool>* stop{nullptr};
};

/// One simulated trajectory at the nominal's sub-step times.
struct SampleTrajectory {
  std::vector<double> t;
  std::vector<Mat3> R;
  std::vector<Vec3> omega;
};

struct SoundnessReport {
  long samples{0};           ///< samples checked (all of the settings' unless stopped)
  bool stopped{false};       ///< the settings' stop flag ended the check early
  long inside{0};            ///< samples inside their ball at every t_i
  double max_ratio{0.0};     ///< max over samples and t_i of (upper distance)/r_i
  double first_violation_time{-1.0};  ///< -1 when none
  long tube_inside{0};        ///< samples inside every tube segment and U_i at every sub-step time
  double tube_max_excess{0.0};  ///< largest distance outside a segment or U_i (ω: per axis; R: rad)
  double tube_first_violation_time{-1.0};  ///< -1 when none
  std::vector<SampleTrajectory> kept;
  double wall_time_s{0.0};
};

/// Samples `whole` and checks each sample against the cell (of `cells`/`results`, same order)
/// whose initial set contains it.
[[nodiscard]] SoundnessReport check_soundness(const ClosedLoop& loop, const InitialSet& whole,
                                              const std::vector<InitialSet>& cells,
                                              const std::vector<ReachResult>& results,
                                              const SoundnessSettings& settings);

}  // namespace attiguard::reach
