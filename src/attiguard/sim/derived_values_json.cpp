#include "attiguard/sim/derived_values_json.hpp"

#include <numbers>

#include "attiguard/core/four_digits.hpp"
#include "attiguard/core/shortest_number.hpp"

namespace attiguard::sim {

namespace {

constexpr double kDegrees = 180.0 / std::numbers::pi;

/// "  kp = 0.0123 (derived)\n".
std::string value_line(const char* key, double value, bool derived) {
  return std::string("  ") + key + " = " + shortest_number(value) + (derived ? " (derived)\n" : " (given)\n");
}

}  // namespace

nlohmann::json derived_values_json(const governor::DerivedGovernorValues& d) {
  nlohmann::json derived = nlohmann::json::array();
  if (d.kp_derived) derived.push_back("kp");
  if (d.kd_derived) derived.push_back("kd");
  if (d.kappa_derived) derived.push_back("kappa");
  if (d.Ts_derived) derived.push_back("sampling_period");
  if (d.c_gamma_derived) derived.push_back("c_gamma");
  if (d.epsilon_derived) derived.push_back("epsilon");
  if (d.integrator_step_derived) derived.push_back("step");
  nlohmann::json j;
  j["derived"] = derived;
  j["torque_scale"] = d.torque_scale;
  j["reference_angle_deg"] = d.reference_angle * kDegrees;
  j["softening"] = d.softening;
  j["time_scale"] = d.time_scale;
  j["rate_scale"] = d.rate_scale;
  j["natural_frequency"] = d.natural_frequency;
  j["damping_ratio"] = d.damping_ratio;
  j["gamma_d_estimate"] = d.gamma_d_estimate;
  j["bandwidth_period"] = d.bandwidth_period;
  j["damping_period"] = d.damping_period;
  j["limited_by_control_period"] = d.limited_by_control_period;
  j["integrator_step"] = d.integrator_step;
  return j;
}

std::string derived_values_report(const governor::DerivedGovernorValues& d) {
  std::string out = "governor values (docs/pet-erg.md, section 8):\n";
  out += value_line("control.kp", d.kp, d.kp_derived);
  out += value_line("control.kd", d.kd, d.kd_derived);
  out += value_line("erg.kappa", d.kappa, d.kappa_derived);
  out += value_line("erg.sampling_period", d.Ts, d.Ts_derived);
  out += value_line("erg.c_gamma", d.c_gamma, d.c_gamma_derived);
  out += value_line("erg.epsilon", d.epsilon, d.epsilon_derived);
  if (d.integrator_step_derived) out += value_line("simulation.step", d.integrator_step, true);
  out += "  scales: torque " + four_digits(d.torque_scale) + " N m, reference angle " +
         four_digits(d.reference_angle * kDegrees) + " deg, time sqrt(J_max theta/tau) " +
         four_digits(d.time_scale) + " s, natural frequency " +
         four_digits(d.natural_frequency) + " rad/s, damping ratio " +
         four_digits(d.damping_ratio) + "\n";
  if (d.softening != 1.0) {
    out += "  reference angle scaled " + four_digits(d.softening) + "x for the robust margins\n";
  }
  if (d.bandwidth_period > 0.0) {
    out += "  flight loop: sqrt(kp/J_min) h = " + four_digits(d.bandwidth_period) +
           ", kd h/J_min = " + four_digits(d.damping_period) +
           (d.limited_by_control_period ? " (kp lowered to the control period's caps)\n" : "\n");
  }
  return out;
}

}  // namespace attiguard::sim
