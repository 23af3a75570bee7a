// A flight loop written by a downstream user against the installed attiguard::flight: the
// numerical example of Sec. V of the PET-ERG paper (the values of examples/pet_erg_paper.toml,
// written out here), the PD law (3) + PET-ERG (5)-(6) of AttitudeGovernor at 100 Hz with the
// torque held between steps, and the plant (1) propagated by ten Lie-Euler sub-steps. Exit 0
// when the pointing cone (2b), the torque bound (2a) and V ≤ Γ hold at every step and the
// attitude reaches R_d; exit 1 (with the failing figure) otherwise.
#include <algorithm>
#include <array>
#include <cstdio>
#include <numbers>

#include "attiguard/core/version.hpp"
#include "attiguard/dynamics/rigid_body.hpp"
#include "attiguard/governor/attitude_governor.hpp"
#include "attiguard/lie/axis_angle.hpp"
#include "attiguard/lie/so3.hpp"

namespace ag = attiguard;
using ag::lie::Mat3;
using ag::lie::Vec3;

int main() {
  ag::governor::GovernorParams params;  // [control] and [erg] of the paper scenario
  params.mode = ag::governor::GovernorMode::pet;
  params.gains = {5.0, 1.0};
  params.J = Vec3(1.0, 2.0, 3.0).asDiagonal();
  params.tau_max = 2.5;
  params.kappa = 1.0;
  params.c_gamma = 3.0;
  params.Ts = 0.5;
  params.epsilon = 1e-3;
  params.epsilon_gamma = 0.1;
  const std::array cones{ag::governor::keep_in_cone(
      Vec3::UnitZ(), Vec3(-0.791, 0.061, -0.609), 160.0 * std::numbers::pi / 180.0)};
  ag::governor::AttitudeGovernor gov(params, cones);
  const ag::dynamics::RigidBody body(params.J);

  const Mat3 R_d = ag::lie::rotation_from_axis_angle({Vec3::UnitY(), std::numbers::pi / 2.0});
  Mat3 R_ib = Mat3::Identity();
  Vec3 omega_b(0.2, 0.3, 0.4);
  const double dt = 0.01;
  const int substeps = 10;
  double min_margin = 1e300;
  double max_excess = -1e300;  // max of V − Γ
  double max_torque = 0.0;
  gov.reset(0.0, R_ib);
  for (int k = 0; k <= 6000; ++k) {  // 60 s
    const ag::governor::GovernorOutput& out = gov.step(k * dt, R_ib, omega_b, R_d);
    min_margin = std::min(min_margin, out.min_margin());
    max_excess = std::max(max_excess, out.V - out.gamma);
    max_torque = std::max(max_torque, out.tau_b.norm());
    for (int s = 0; s < substeps; ++s) {
      omega_b += (dt / substeps) * body.angular_acceleration(omega_b, out.tau_b);
      R_ib = R_ib * ag::lie::exp((dt / substeps) * omega_b);
    }
  }
  const double final_error = ag::lie::distance(R_ib, R_d);
  std::printf("attiguard %s: min cone margin %.6f, max V - Gamma %.3e, max |tau| %.4f N m, "
              "final error %.3e rad\n",
              ag::version_string, min_margin, max_excess, max_torque, final_error);
  const bool ok = min_margin > 0.0 && max_excess <= 1e-9 && max_torque <= params.tau_max &&
                  final_error < 1e-3;
  return ok ? 0 : 1;
}
