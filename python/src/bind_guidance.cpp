/// @file bind_guidance.cpp
/// The waypoint mission state machine (Algorithm 1, [Waypoint eqs. (13)-(30)]) and its
/// quaternion PID [Waypoint eq. (27)], step-able from Python.

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "attiguard/control/quaternion_pid.hpp"
#include "attiguard/core/errors.hpp"
#include "attiguard/scenario/argument_checks.hpp"
#include "attiguard/guidance/waypoint_sequencer.hpp"
#include "bindings.hpp"

namespace py = pybind11;

namespace attiguard::python {
namespace {

using lie::Mat3;
using lie::Quat;
using lie::Vec3;

/// A guidance::WaypointSequencer together with the waypoint storage it points into
/// (waypoint_sequencer.hpp: the span must outlive the sequencer).
struct OwnedMission {
  std::vector<Vec3> waypoints;
  std::unique_ptr<guidance::WaypointSequencer> mission;
};

std::unique_ptr<OwnedMission> make_mission(const std::vector<Vec3>& waypoints, double mass,
                                           double t_max, double f_max, double cruise_speed,
                                           double pointing_tolerance, double kp, double ki,
                                           double kd) {
  // The scenario readers' number checks (scenario/argument_checks.hpp): Mission(mass=0) used
  // to give NaN commands.
  constexpr const char* kLabel = "Mission()";
  for (const auto& [key, value] : {std::pair<const char*, double>{"mass", mass}, {"t_max", t_max},
                                   {"f_max", f_max}, {"cruise_speed", cruise_speed},
                                   {"pointing_tolerance", pointing_tolerance}}) {
    (void)scenario::checked_number(value, key, true, kLabel);
  }
  for (const auto& [key, value] : {std::pair<const char*, double>{"kp", kp}, {"ki", ki}, {"kd", kd}}) {
    (void)scenario::checked_number(value, key, false, kLabel);
  }
  if (waypoints.empty()) {  // as the scenario reader's `waypoints = []` (docs/errors.md)
    throw InputError(std::string(kLabel) + ": waypoints: expected a non-empty list of positions, got an "
                                           "empty list (a mission without waypoints has nothing to fly)");
  }
  for (std::size_t i = 0; i < waypoints.size(); ++i) {
    const std::string key = "waypoints[" + std::to_string(i) + "]";
    try {
      (void)scenario::checked_vector3(waypoints[i], key, kLabel);
    } catch (const InputError& e) {  // the key is a Python index, not a quoted TOML key
      std::string m = e.what();
      if (const auto at = m.find('"' + key + '"'); at != std::string::npos) m.replace(at, key.size() + 2, key);
      throw InputError(m);
    }
  }
  auto owned = std::make_unique<OwnedMission>();
  owned->waypoints = waypoints;
  guidance::MissionParams p;
  p.mass = mass;
  p.T_max = t_max;
  p.f_max = f_max;
  p.cruise_speed = cruise_speed;
  p.pointing_tolerance = pointing_tolerance;
  p.brake_speed = guidance::default_brake_speed(p);  // as in scenario files
  control::QuaternionPidGains g;
  g.kp = kp;
  g.ki = ki;
  g.kd = kd;
  owned->mission = std::make_unique<guidance::WaypointSequencer>(p, g, owned->waypoints);
  return owned;
}

py::dict command_dict(const guidance::MissionCommand& c) {
  py::dict d;
  d["tau_b"] = c.inputs.tau_b;
  d["thrust"] = c.inputs.thrust;
  d["f_rct_b"] = c.inputs.f_rct_b;
  d["mode"] = guidance::mode_name(c.mode);
  d["waypoint"] = c.waypoint;
  d["transition"] = c.transition;
  d["q_id"] = c.q_id;
  d["R_d"] = lie::quat_to_rotation(c.q_id);
  d["omega_d_d"] = c.omega_d_d;
  d["pointing_error"] = c.pointing_error;
  return d;
}

}  // namespace

void bind_guidance(py::module_& m) {
  py::class_<control::QuaternionPid>(m, "QuaternionPid", "Quaternion PID [Waypoint eq. (27)].")
      .def(py::init([](double kp, double ki, double kd) {
             constexpr const char* kLabel = "QuaternionPid()";
             control::QuaternionPidGains g;
             g.kp = scenario::checked_number(kp, "kp", false, kLabel);
             g.ki = scenario::checked_number(ki, "ki", false, kLabel);
             g.kd = scenario::checked_number(kd, "kd", false, kLabel);
             return control::QuaternionPid(g);
           }),
           py::arg("kp") = 20.0, py::arg("ki") = 2.0, py::arg("kd") = 20.0)
      .def("step",
           [](control::QuaternionPid& pid, const Quat& q_ib, const Vec3& w, const Quat& q_id,
              const Vec3& w_d, double dt) {
             constexpr const char* kLabel = "QuaternionPid.step()";
             const Quat q_ib_ok = scenario::checked_unit_quaternion(q_ib, "q_ib", kLabel);
             const Vec3 w_ok = scenario::checked_vector3(w, "omega_b", kLabel);
             const Quat q_id_ok = scenario::checked_unit_quaternion(q_id, "q_id", kLabel);
             const Vec3 w_d_ok = scenario::checked_vector3(w_d, "omega_d_d", kLabel);
             const double dt_ok = scenario::checked_number(dt, "dt", true, kLabel);
             const auto out = pid.step(q_ib_ok, w_ok, q_id_ok, w_d_ok, dt_ok);
             return out.tau_b;
           },
           py::arg("q_ib"), py::arg("omega_b"), py::arg("q_id"), py::arg("omega_d_d"), py::arg("dt"),
           "One sample of [Waypoint eq. (27)]: returns the torque command τ_b [N·m]. Unit quaternions (1e-9), "
           "finite rates, dt finite and > 0 (ValueError naming the argument).")
      .def("reset", &control::QuaternionPid::reset);

  py::class_<OwnedMission>(m, "Mission",
                           "Waypoint guidance state machine [Waypoint Alg. 1].")
      .def(py::init(&make_mission), py::arg("waypoints"), py::arg("mass") = 100.0,
           py::arg("t_max") = 20.0, py::arg("f_max") = 0.5, py::arg("cruise_speed") = 100.0,
           py::arg("pointing_tolerance") = 1e-6, py::arg("kp") = 20.0, py::arg("ki") = 2.0,
           py::arg("kd") = 20.0)
      .def("step",
           [](OwnedMission& o, const Mat3& R, const Vec3& w, const Vec3& p, const Vec3& v, double dt) {
             constexpr const char* kLabel = "Mission.step()";
             guidance::MissionInputs in;
             in.R_ib = scenario::checked_rotation_matrix(R, "R", kLabel);
             in.omega_b = scenario::checked_vector3(w, "omega_b", kLabel);
             in.p_i = scenario::checked_vector3(p, "p_i", kLabel);
             in.v_i = scenario::checked_vector3(v, "v_i", kLabel);
             in.dt = scenario::checked_number(dt, "dt", true, kLabel);
             return command_dict(o.mission->step(in));
           },
           py::arg("R"), py::arg("omega_b"), py::arg("p_i"), py::arg("v_i"), py::arg("dt"),
           "One control sample: mode, desired attitude [Waypoint eqs. (23)-(24)], thrust (13)/(16), RCT [Waypoint eqs. (28)-(30)], τ (27).")
      .def_property_readonly("mode", [](const OwnedMission& o) { return guidance::mode_name(o.mission->mode()); })
      .def_property_readonly("waypoint", [](const OwnedMission& o) { return o.mission->waypoint(); })
      .def_property_readonly("done", [](const OwnedMission& o) { return o.mission->done(); });
}

}  // namespace attiguard::python
