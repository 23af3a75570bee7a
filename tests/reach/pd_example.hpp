#pragma once
/// The PD closed loop of examples/conreach_pd.toml (PET-ERG paper, eq. (3), towards a fixed
/// R_g 20° about z; J = diag(1, 2, 3), k_p = 2, k_d = 3) and its initial set, shared by the
/// reach tests of the PD loop with the product and the coupled metric.

#include <cmath>

#include "attiguard/lie/so3.hpp"
#include "attiguard/reach/closed_loop.hpp"
#include "attiguard/reach/conreach.hpp"

namespace attiguard::test {

/// The PD loop towards R_g = exp(20° ẑ).
inline const reach::PdLoop& pd_loop() {
  static const reach::PdLoop loop(reach::Vec3(1.0, 2.0, 3.0).asDiagonal(), 2.0, 3.0,
                                  lie::exp(reach::Vec3(0.0, 0.0, 20.0 * M_PI / 180.0)));
  return loop;
}

/// The initial set: 0.05 rad around I, 0.05 rad/s around ω = (0.1, −0.05, 0.05) rad/s.
inline reach::InitialSet pd_set() {
  return {reach::Mat3::Identity(), 0.05, reach::Vec3(0.1, -0.05, 0.05), 0.05};
}

}  // namespace attiguard::test
