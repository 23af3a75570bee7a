#pragma once
/// The contraction-reachability paper's Sec. 6 example (examples/conreach_paper.toml) with a
/// shorter horizon, shared by the reach tests that need a quick, exact-flow ConReach result.

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

}  // namespace attiguard::test
