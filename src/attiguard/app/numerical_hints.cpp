/// @file numerical_hints.cpp
/// The numerical-failure hints of the kinds rigid_body and pet_erg (app/numerical_hints.hpp).

#include "attiguard/app/numerical_hints.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <string_view>

#include "attiguard/core/errors.hpp"
#include "attiguard/core/four_digits.hpp"
#include "attiguard/governor/attitude_governor.hpp"
#include "attiguard/lie/symmetric_eigen.hpp"
#include "attiguard/scenario/read_pet_erg.hpp"
#include "attiguard/scenario/read_rigid_body.hpp"

namespace attiguard::app {

namespace {

/// "FILE:LINE:COL: TABLE.KEY: message" located at `key` of [table] of `doc` (as an input error
/// would be; at the table when the key was left to its default).
std::string at_key(const scenario::Document& doc, std::string_view table, std::string_view key,
                   const std::string& message) {
  try {
    scenario::fail_in_table(doc, table, key, message);
  } catch (const InputError& e) {
    return e.what();
  }
  return message;
}

/// The fastest rate |λ| [1/s] of the body J under the PD gains kp, kd (linearised about the
/// reference, one principal axis at a time) and of its gyroscopic coupling at |ω0|.
double fastest_rate(const Eigen::Matrix3d& J, double kp, double kd, double omega0) {
  const Eigen::Vector3d m = lie::symmetric_eigenvalues(J);
  double fastest = 0.0;
  for (int i = 0; i < 3; ++i) {
    const std::complex<double> root = std::sqrt(std::complex<double>(kd * kd - 4.0 * kp * m(i)));
    fastest = std::max({fastest, std::abs((-kd - root) / (2.0 * m(i))),
                        std::abs((-kd + root) / (2.0 * m(i)))});
    const double spread = std::abs(m((i + 1) % 3) - m((i + 2) % 3)) / m(i);
    fastest = std::max(fastest, omega0 * spread);
  }
  return fastest;
}

/// The step hint: a fixed step above 2/λ_max.
std::string step_hint(const scenario::Document& doc, const integrate::IntegratorSettings& s,
                      double fastest) {
  if (s.method != integrate::Method::rkmk4 || !(fastest * s.step > 2.0)) return "";
  const double limit = 2.0 / fastest;
  return at_key(doc, "simulation", "step",
                four_digits(s.step) + " s is above the stability limit ~ 2/lambda_max = " +
                    four_digits(limit) + " s of this inertia and these gains (lambda_max ~ " +
                    four_digits(fastest) + " 1/s): use integrator = \"rkmk_dp54\" or step <= " +
                    four_digits(limit));
}

}  // namespace

std::string rigid_body_numerical_hint(const scenario::Document& doc) {
  const sim::RigidBodyScenario sc = scenario::parse_rigid_body(doc);
  const double kp = sc.law == sim::TorqueLaw::pd ? sc.kp : 0.0;
  const double kd = sc.law == sim::TorqueLaw::pd ? sc.kd : 0.0;
  return step_hint(doc, sc.integrator, fastest_rate(sc.J, kp, kd, sc.omega0_b.norm()));
}

std::string pet_erg_numerical_hint(const scenario::Document& doc) {
  const sim::PetErgScenario sc = scenario::parse_pet_erg(doc);
  const governor::GovernorParams p = sim::design_governor(sc).params;
  const double h = sc.integrator.method == integrate::Method::rkmk4 ? sc.integrator.step
                                                                     : sc.integrator.max_step;
  const governor::AttitudeGovernor gov(p, sc.cones);
  const double turn = p.kappa * gov.gamma_d() * h;  // rad per step at the largest margin
  if (p.mode != governor::GovernorMode::none && h > 0.0 && turn > 1.0) {
    return at_key(doc, "erg", "kappa",
                  four_digits(p.kappa) + " turns the reference at up to kappa Gamma_d = " +
                      four_digits(p.kappa * gov.gamma_d()) + " rad/s, " + four_digits(turn) +
                      " rad per integrator step of " + four_digits(h) + " s: use kappa <= " +
                      four_digits(1.0 / (gov.gamma_d() * h)));
  }
  return step_hint(doc, sc.integrator,
                   fastest_rate(p.J, p.gains.kp, p.gains.kd, sc.omega0_b.norm()));
}

}  // namespace attiguard::app
