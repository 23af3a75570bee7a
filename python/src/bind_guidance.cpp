/// @file bind_guidance.cpp
/// The waypoint mission state machine (waypoint paper, Algorithm 1, (13)-(30)) and its
/// quaternion PID (27), step-able from Python.

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "attiguard/control/quaternion_pid.hpp"
#include "attiguard/core/errors.hpp"
#include "attiguard/scenario/argument_checks.hpp"
#include "attiguard/guidance/mission.hpp"
#include "bindings.hpp"

namespace py = pybind11;

namespace attiguard::python {
namespace {

using lie::Mat3;
using lie::Quat;
using lie::Vec3;

/// A Mission together with the waypoint storage it points into (mission.hpp: the span must
/// outlive the mission).
struct OwnedMission {
  std::vector<Vec3> waypoints;
  std::unique_ptr<guidance::Mission> mission;
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
  owned->mission = std::make_unique<guidance::Mission>(p, g, owned->waypoints);
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
  py::class_<control::QuaternionPid>(m, "QuaternionPid", "Quaternion PID (27) of the waypoint paper.")
      .def(py::init([](double kp, double ki, double kd) {
             control::QuaternionPidGains g;
             g.kp = kp;
             g.ki = ki;
             g.kd = kd;
             return control::QuaternionPid(g);
           }),
           py::arg("kp") = 20.0, py::arg("ki") = 2.0, py::arg("kd") = 20.0)
      .def("step",
           [](control::QuaternionPid& pid, const Quat& q_ib, const Vec3& w, const Quat& q_id,
              const Vec3& w_d, double dt) {
             const auto out = pid.step(q_ib, w, q_id, w_d, dt);
             return out.tau_b;
           },
           py::arg("q_ib"), py::arg("omega_b"), py::arg("q_id"), py::arg("omega_d_d"), py::arg("dt"),
           "One sample of (27): returns the torque command τ_b [N·m].")
      .def("reset", &control::QuaternionPid::reset);

  py::class_<OwnedMission>(m, "Mission",
                           "Waypoint guidance state machine (waypoint paper, Algorithm 1).")
      .def(py::init(&make_mission), py::arg("waypoints"), py::arg("mass") = 100.0,
           py::arg("t_max") = 20.0, py::arg("f_max") = 0.5, py::arg("cruise_speed") = 100.0,
           py::arg("pointing_tolerance") = 1e-6, py::arg("kp") = 20.0, py::arg("ki") = 2.0,
           py::arg("kd") = 20.0)
      .def("step",
           [](OwnedMission& o, const Mat3& R, const Vec3& w, const Vec3& p, const Vec3& v, double dt) {
             guidance::MissionInputs in;
             in.R_ib = R;
             in.omega_b = w;
             in.p_i = p;
             in.v_i = v;
             in.dt = dt;
             return command_dict(o.mission->step(in));
           },
           py::arg("R"), py::arg("omega_b"), py::arg("p_i"), py::arg("v_i"), py::arg("dt"),
           "One control sample: mode, desired attitude (23)-(24), thrust (13)/(16), RCT (28)-(30), τ (27).")
      .def_property_readonly("mode", [](const OwnedMission& o) { return guidance::mode_name(o.mission->mode()); })
      .def_property_readonly("waypoint", [](const OwnedMission& o) { return o.mission->waypoint(); })
      .def_property_readonly("done", [](const OwnedMission& o) { return o.mission->done(); });
}

}  // namespace attiguard::python
