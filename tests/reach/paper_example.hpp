#pragma once
/// The contraction-reachability paper's Sec. 6 example (examples/conreach_paper.toml) with a
/// shorter horizon, shared by the reach tests that need a quick, exact-flow ConReach result, and
/// its loop and initial set on their own.

#include "attiguard/reach/conreach.hpp"

namespace attiguard::test {

struct PaperReach {
  reach::LinearOmegaLoop loop{reach::Vec3(-2, -1, -3).asDiagonal()};
  reach::InitialSet initial{reach::Mat3::Identity(), 0.1, reach::Vec3(0.65, 0.54, 0.61), 0.1};
  reach::ReachResult result;
  /// ConReach over [0, horizon] with `steps` steps (other settings at their defaults).
  PaperReach(double horizon, int steps) {
    reach::ConReachSettings s;
    s.horizon = horizon;
    s.steps = steps;
    result = reach::run_conreach(loop, initial, s);
  }
};

/// ω̇ = diag(−2, −1, −3) ω (the paper's linear ω-dynamics, docs/reach.md "Closed loops").
inline const reach::LinearOmegaLoop& paper_loop() {
  static const reach::LinearOmegaLoop loop(reach::Vec3(-2, -1, -3).asDiagonal());
  return loop;
}

/// B_I(I, 0.1) × B(ω0, 0.1), ω0 = (0.65, 0.54, 0.61) rad/s.
inline reach::InitialSet paper_set() {
  return {reach::Mat3::Identity(), 0.1, reach::Vec3(0.65, 0.54, 0.61), 0.1};
}

}  // namespace attiguard::test
