#include "attiguard/guidance/craft_defaults.hpp"

#include <numbers>
#include <algorithm>
#include <cmath>

namespace attiguard::guidance {

namespace {
constexpr double kPi = std::numbers::pi;
}  // namespace

double craft_pointing_tolerance(const CraftLimits& c) noexcept {
  const double alpha = std::clamp(0.5 * c.f_max / c.T_max, 2e-3, 0.05);
  return std::sin(0.5 * alpha);
}

double craft_braking_margin(const CraftLimits& c, double cruise_speed) noexcept {
  return std::clamp(1.0 / (1.0 + 4.0 * c.a_main() * c.control_period / cruise_speed), 0.5, 0.95);
}

double craft_main_cutoff_speed(const CraftLimits& c, double cruise_speed) noexcept {
  return std::min(c.a_main() * c.control_period, 0.5 * cruise_speed);
}

double craft_projection_blend_speed(const CraftLimits& c) noexcept {
  return 2.5 * c.a_main() * c.control_period;
}

double rct_stopping_distance(const CraftLimits& c, double speed) noexcept {
  return speed * speed / c.a_rct();
}

double craft_replan_distance(const CraftLimits& c, double cutoff_speed, double position_accuracy,
                             double arrival_radius, double slew_time) noexcept {
  return std::max({25.0 * position_accuracy, 10.0 * arrival_radius,
                   4.0 * rct_stopping_distance(c, cutoff_speed), 0.5 * c.a_rct() * slew_time * slew_time});
}

control::RctPositionGains craft_rct_gains(const CraftLimits& c, double speed_accuracy,
                                          double position_accuracy) noexcept {
  control::RctPositionGains g;
  g.kappa_d = c.a_rct() / speed_accuracy;
  g.kappa_p = craft_kappa_p(c, g.kappa_d, position_accuracy);
  // κ_p raised to a_rct/δ_p would steepen the line beyond λ (an underdamped limit cycle of the
  // on/off thrusters): raise κ_d with it.
  g.kappa_d = std::max(g.kappa_d, g.kappa_p / craft_rct_slope(c, position_accuracy));
  return g;
}

double craft_rct_braking_acceleration(const CraftLimits& c) noexcept { return 0.5 * c.a_rct(); }

double craft_rct_slope(const CraftLimits& c, double position_accuracy) noexcept {
  return std::min(std::sqrt(c.a_rct() / (12.5 * position_accuracy)), 0.1 / c.control_period);
}

double craft_kappa_p(const CraftLimits& c, double kappa_d, double position_accuracy) noexcept {
  return std::max(craft_rct_slope(c, position_accuracy) * kappa_d, c.a_rct() / position_accuracy);
}

double rct_position_dead_band(const CraftLimits& c, const control::RctPositionGains& g,
                              double threshold) noexcept {
  return g.kappa_p > 0.0 ? threshold * c.a_rct() / g.kappa_p : HUGE_VAL;
}

double rct_speed_dead_band(const CraftLimits& c, const control::RctPositionGains& g,
                           double threshold) noexcept {
  return threshold * c.a_rct() / g.kappa_d;
}

double rct_speed_quantum(const CraftLimits& c) noexcept { return c.a_rct() * c.control_period; }

double main_speed_left(const CraftLimits& c, double cutoff_speed) noexcept {
  return std::max(cutoff_speed, 0.5 * c.a_main() * c.control_period);
}

double wheel_half_turn_time(const CraftLimits& c) noexcept {
  return c.max_wheel_torque > 0.0 ? 2.0 * std::sqrt(kPi * c.J_max / c.max_wheel_torque) : 0.0;
}

control::QuaternionPidGains craft_attitude_gains(const CraftLimits& c) noexcept {
  double omega_n = std::min(0.3, 0.1 / c.control_period);
  if (c.max_wheel_torque > 0.0) {
    omega_n = std::min(omega_n, std::sqrt(c.max_wheel_torque / (2.0 * c.J_max)));
  }
  control::QuaternionPidGains g;
  g.kp = 2.0 * omega_n * omega_n * c.J_max;
  g.kd = 4.0 * omega_n * c.J_max;
  g.ki = 0.0;
  g.integral_zone = 0.0;
  g.shaped = true;
  g.shaping = c.J / c.J_max;
  g.shaping_scale = c.J_max;
  return g;
}

double craft_slew_time(const CraftLimits& c, const control::QuaternionPidGains& gains) noexcept {
  const double omega_n = std::sqrt(gains.kp / (2.0 * c.J_max));
  return std::max(10.0 / omega_n, wheel_half_turn_time(c));
}

}  // namespace attiguard::guidance
