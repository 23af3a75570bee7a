#include "attiguard/sim/rigid_body_run.hpp"

#include <array>
#include <cmath>

#include "attiguard/control/pd_so3.hpp"
#include "attiguard/dynamics/attitude_state.hpp"
#include "attiguard/integrate/integrator.hpp"
#include "attiguard/lie/quaternion.hpp"
#include "attiguard/sim/time_grid.hpp"

namespace attiguard::sim {

namespace {

using dynamics::AttitudeState;
using lie::Mat3;
using lie::Vec3;

/// The torque law of the scenario as a function of the state.
struct TorqueOf {
  const RigidBodyScenario& sc;
  [[nodiscard]] Vec3 operator()(const AttitudeState& y) const noexcept {
    switch (sc.law) {
      case TorqueLaw::pd:
        return control::pd_torque(y.R[0], y.x, sc.R_ref_ib, {sc.kp, sc.kd});
      case TorqueLaw::constant_torque:
        return sc.torque_b;
      case TorqueLaw::free:
        break;
    }
    return Vec3::Zero();
  }
};

}  // namespace

RigidBodyResult simulate_rigid_body(const RigidBodyScenario& sc, io::RowSink& rows) {
  const dynamics::RigidBody body(sc.J);
  const TorqueOf torque{sc};
  // Distances are measured to the PD reference, or to the initial attitude for the other laws.
  const Mat3 R_target = sc.law == TorqueLaw::pd ? sc.R_ref_ib : sc.R0_ib;

  RigidBodyResult r;
  rows.begin({"t", "q_w", "q_x", "q_y", "q_z", "omega_x", "omega_y", "omega_z", "tau_x", "tau_y",
              "tau_z", "attitude_error_rad", "phi", "energy", "V", "h_x", "h_y", "h_z"});
  auto lyapunov = [&](const AttitudeState& y) {
    return sc.law == TorqueLaw::pd
               ? control::pd_lyapunov(body.inertia(), y.R[0], y.x, sc.R_ref_ib, {sc.kp, sc.kd})
               : body.kinetic_energy(y.x);
  };
  auto log_row = [&](double t, const AttitudeState& y) {
    const lie::Quat q = lie::rotation_to_quat(y.R[0]);
    const Vec3 tau = torque(y);
    const Vec3 h = body.angular_momentum_i(y.R[0], y.x);
    const Mat3 R_err = y.R[0].transpose() * R_target;
    const std::array<double, 18> row{t,
                                     q(0), q(1), q(2), q(3),
                                     y.x(0), y.x(1), y.x(2),
                                     tau(0), tau(1), tau(2),
                                     lie::log(R_err).norm(),
                                     lie::phi(R_err),
                                     body.kinetic_energy(y.x),
                                     lyapunov(y),
                                     h(0), h(1), h(2)};
    rows.row(row);
    ++r.output_rows;
  };

  AttitudeState y;
  y.R[0] = sc.R0_ib;
  y.x = sc.omega0_b;
  const double E0 = body.kinetic_energy(y.x);
  const Vec3 h0 = body.angular_momentum_i(y.R[0], y.x);
  double max_torque = torque(y).norm();
  double max_energy_drift = 0.0;
  double max_momentum_drift = 0.0;
  log_row(0.0, y);

  auto field = [&](double, const AttitudeState& s) {
    return dynamics::attitude_derivative(body, s, torque(s));
  };
  auto on_step = [&](double, const AttitudeState& s) {
    max_torque = std::max(max_torque, torque(s).norm());
    max_energy_drift = std::max(max_energy_drift, std::abs(body.kinetic_energy(s.x) - E0));
    max_momentum_drift =
        std::max(max_momentum_drift, (body.angular_momentum_i(s.R[0], s.x) - h0).norm());
  };
  auto on_output = [&](double t, AttitudeState& s) {
    log_row(t, s);
    return true;
  };
  const std::vector<double> instants = uniform_instants(sc.duration, sc.output_interval);
  const integrate::IntegrationStats stats =
      integrate::integrate(field, y, 0.0, instants, sc.integrator, on_output, on_step);
  r.R_end = y.R[0];
  r.omega_end = y.x;
  r.R_target = R_target;
  r.E0 = E0;
  r.h0_norm = h0.norm();
  r.max_torque_norm = max_torque;
  r.max_energy_drift = max_energy_drift;
  r.max_momentum_drift = max_momentum_drift;
  r.steps = stats.accepted_steps;
  r.rejected_steps = stats.rejected_steps;
  r.evaluations = stats.evaluations;
  return r;
}

nlohmann::json rigid_body_summary(const RigidBodyScenario& sc, const RigidBodyResult& r) {
  const Mat3 R_err = r.R_end.transpose() * r.R_target;
  nlohmann::json summary;
  summary["kind"] = "rigid_body";
  summary["name"] = sc.name;
  summary["law"] = std::string(kTorqueLawNames.name(sc.law));
  summary["integrator"] = std::string(integrate::kMethodNames.name(sc.integrator.method));
  summary["duration"] = sc.duration;
  summary["steps"] = r.steps;
  summary["rejected_steps"] = r.rejected_steps;
  summary["evaluations"] = r.evaluations;
  summary["output_rows"] = r.output_rows;
  summary["final_attitude_error"] = lie::phi(R_err);
  summary["final_attitude_error_rad"] = lie::log(R_err).norm();
  summary["final_omega_norm"] = r.omega_end.norm();
  summary["max_torque_norm"] = r.max_torque_norm;
  summary["final_orthonormality_error"] = lie::orthonormality_error(r.R_end);
  if (sc.law == TorqueLaw::free) {
    summary["max_energy_drift_rel"] = r.E0 > 0.0 ? r.max_energy_drift / r.E0 : r.max_energy_drift;
    summary["max_momentum_drift_rel"] =
        r.h0_norm > 0.0 ? r.max_momentum_drift / r.h0_norm : r.max_momentum_drift;
  }
  return summary;
}

}  // namespace attiguard::sim
