#include "attiguard/sim/rigid_body_run.hpp"

#include <array>
#include <chrono>
#include <cmath>

#include "attiguard/control/pd_so3.hpp"
#include "attiguard/dynamics/attitude_state.hpp"
#include "attiguard/integrate/integrator.hpp"
#include "attiguard/io/csv_writer.hpp"
#include "attiguard/io/json_file.hpp"
#include "attiguard/lie/quaternion.hpp"
#include "attiguard/sim/time_grid.hpp"

namespace attiguard::sim {

namespace {

using dynamics::AttitudeState;
using lie::Mat3;
using lie::Vec3;

const char* law_name(scenario::TorqueLaw law) {
  switch (law) {
    case scenario::TorqueLaw::free:
      return "free";
    case scenario::TorqueLaw::constant_torque:
      return "constant_torque";
    case scenario::TorqueLaw::pd:
      return "pd";
  }
  return "?";
}

const char* method_name(integrate::Method m) {
  return m == integrate::Method::rkmk4 ? "rkmk4" : "rkmk_dp54";
}

/// The torque law of the scenario as a function of the state.
struct TorqueLaw {
  const scenario::RigidBodyScenario& sc;
  [[nodiscard]] Vec3 operator()(const AttitudeState& y) const noexcept {
    switch (sc.law) {
      case scenario::TorqueLaw::pd:
        return control::pd_torque(y.R[0], y.x, sc.R_ref_ib, {sc.kp, sc.kd});
      case scenario::TorqueLaw::constant_torque:
        return sc.torque_b;
      case scenario::TorqueLaw::free:
        break;
    }
    return Vec3::Zero();
  }
};

}  // namespace

nlohmann::json run_rigid_body(const scenario::RigidBodyScenario& sc,
                              const std::filesystem::path& out_dir) {
  const auto wall_start = std::chrono::steady_clock::now();
  const dynamics::RigidBody body(sc.J);
  const TorqueLaw torque{sc};
  // Distances are measured to the PD reference, or to the initial attitude for the other laws.
  const Mat3 R_target = sc.law == scenario::TorqueLaw::pd ? sc.R_ref_ib : sc.R0_ib;

  io::ensure_directory(out_dir);
  io::CsvWriter csv(out_dir / "trajectory.csv",
                    {"t", "q_w", "q_x", "q_y", "q_z", "omega_x", "omega_y", "omega_z", "tau_x",
                     "tau_y", "tau_z", "attitude_error_rad", "phi", "energy", "V", "h_x", "h_y",
                     "h_z"});
  auto lyapunov = [&](const AttitudeState& y) {
    return sc.law == scenario::TorqueLaw::pd
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
    csv.row(row);
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
  csv.close();

  const Mat3 R_err = y.R[0].transpose() * R_target;
  nlohmann::json summary;
  summary["kind"] = "rigid_body";
  summary["name"] = sc.name;
  summary["law"] = law_name(sc.law);
  summary["integrator"] = method_name(sc.integrator.method);
  summary["duration"] = sc.duration;
  summary["steps"] = stats.accepted_steps;
  summary["rejected_steps"] = stats.rejected_steps;
  summary["evaluations"] = stats.evaluations;
  summary["output_rows"] = csv.rows();
  summary["final_attitude_error"] = lie::phi(R_err);
  summary["final_attitude_error_rad"] = lie::log(R_err).norm();
  summary["final_omega_norm"] = y.x.norm();
  summary["max_torque_norm"] = max_torque;
  summary["final_orthonormality_error"] = lie::orthonormality_error(y.R[0]);
  if (sc.law == scenario::TorqueLaw::free) {
    summary["max_energy_drift_rel"] = E0 > 0.0 ? max_energy_drift / E0 : max_energy_drift;
    summary["max_momentum_drift_rel"] =
        h0.norm() > 0.0 ? max_momentum_drift / h0.norm() : max_momentum_drift;
  }
  summary["wall_time_s"] =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  io::write_json(out_dir / "summary.json", summary);
  return summary;
}

}  // namespace attiguard::sim
