/// @file bind_governor.cpp
/// The PET-ERG flight-loop object (PET-ERG paper, eqs. (3)-(6)), its cones (2b), the PD law (3)
/// and the rigid body (Euler's equation), step-able from Python.

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "attiguard/control/pd_so3.hpp"
#include "attiguard/dynamics/rigid_body.hpp"
#include "attiguard/governor/attitude_governor.hpp"
#include "bindings.hpp"

namespace py = pybind11;

namespace attiguard::python {
namespace {

using governor::AttitudeGovernor;
using governor::ConeConstraint;
using governor::GovernorMode;
using governor::GovernorOutput;
using governor::GovernorParams;
using lie::Mat3;
using lie::Vec3;

/// The mode named `name` in governor::kGovernorModeNames (the scenario files' names).
GovernorMode mode_of(const std::string& name) {
  if (const auto mode = governor::kGovernorModeNames.find(name)) return *mode;
  std::string known;
  for (const std::string_view n : governor::kGovernorModeNames.names()) {
    known += (known.empty() ? "\"" : ", \"") + std::string(n) + "\"";
  }
  throw std::invalid_argument("governor mode must be one of " + known + ", got \"" + name + "\"");
}

/// Governor built from keyword arguments (the keys of a pet_erg scenario's [control]/[erg]).
AttitudeGovernor make_governor(const Mat3& J, double kp, double kd, double tau_max,
                               const std::vector<ConeConstraint>& cones, const std::string& mode,
                               double kappa, double c_gamma, double Ts, double epsilon,
                               double epsilon_gamma) {
  GovernorParams p;
  p.mode = mode_of(mode);
  p.gains = control::PdGains{kp, kd};
  p.J = J;
  p.tau_max = tau_max;
  p.kappa = kappa;
  p.c_gamma = c_gamma;
  p.Ts = Ts;
  p.epsilon = epsilon;
  p.epsilon_gamma = epsilon_gamma;
  return AttitudeGovernor(p, cones);
}

std::vector<double> margins_of(const GovernorOutput& o) {
  return std::vector<double>(o.margins.begin(), o.margins.begin() + o.cone_count);
}

}  // namespace

void bind_governor(py::module_& m) {
  py::class_<ConeConstraint>(m, "Cone",
                             "Pointing constraint (2b) of the PET-ERG paper: a_cᵀ R a_b ≥ cos θ_c.")
      .def_readonly("axis_b", &ConeConstraint::axis_b)
      .def_readonly("direction_i", &ConeConstraint::direction_i)
      .def_readonly("theta_c", &ConeConstraint::theta_c)
      .def("margin", [](const ConeConstraint& c, const Mat3& R) { return governor::pointing_margin(c, R); },
           py::arg("R"), "a_cᵀ R a_b − cos θ_c (≥ 0: constraint (2b) holds).")
      .def("__repr__", [](const ConeConstraint& c) {
        return "Cone(theta_c=" + std::to_string(c.theta_c) + ")";
      });
  m.def("keep_in_cone",
        [](const Vec3& a_b, const Vec3& a_i, double theta_c, double delta_offset, double zeta_offset,
           double gain) { return governor::keep_in_cone(a_b, a_i, theta_c, delta_offset, zeta_offset, gain); },
        py::arg("axis_b"), py::arg("direction_i"), py::arg("theta_c"), py::arg("delta_offset") = 0.05,
        py::arg("zeta_offset") = 0.05, py::arg("repulsive_gain") = 1.0,
        "Keep-in cone (2b) of half-angle θ_c [rad] around direction_i (PET-ERG paper).");
  m.def("keep_out_cone",
        [](const Vec3& a_b, const Vec3& avoid_i, double alpha, double delta_offset, double zeta_offset,
           double gain) { return governor::keep_out_cone(a_b, avoid_i, alpha, delta_offset, zeta_offset, gain); },
        py::arg("axis_b"), py::arg("avoid_i"), py::arg("half_angle"), py::arg("delta_offset") = 0.05,
        py::arg("zeta_offset") = 0.05, py::arg("repulsive_gain") = 1.0,
        "Keep-out cone of half-angle α [rad] around avoid_i, as the keep-in cone (2b) of π − α.");

  m.def("pd_torque",
        [](const Mat3& R, const Vec3& w, const Mat3& R_g, double kp, double kd) {
          return control::pd_torque(R, w, R_g, control::PdGains{kp, kd});
        },
        py::arg("R"), py::arg("omega_b"), py::arg("R_g"), py::arg("kp"), py::arg("kd"),
        "PD law (3) of the PET-ERG paper: τ = k_p sk(RᵀR_g)^∨ − k_d ω.");

  py::class_<dynamics::RigidBody>(m, "RigidBody", "Rigid body: J ω̇ = Jω × ω + τ, Ṙ = R ω̂.")
      .def(py::init<const Mat3&>(), py::arg("J"))
      .def_property_readonly("J", &dynamics::RigidBody::inertia)
      .def("angular_acceleration", &dynamics::RigidBody::angular_acceleration, py::arg("omega_b"),
           py::arg("tau_b"), "ω̇ = J⁻¹(Jω × ω + τ) (Euler's equation, PET-ERG paper (1)).")
      .def("kinetic_energy", &dynamics::RigidBody::kinetic_energy, py::arg("omega_b"));

  py::class_<GovernorOutput>(m, "GovernorOutput", "Everything the PET-ERG knows at one instant.")
      .def_readonly("tau_b", &GovernorOutput::tau_b)
      .def_readonly("R_g", &GovernorOutput::R_g)
      .def_readonly("xi_g", &GovernorOutput::xi_g)
      .def_readonly("rho", &GovernorOutput::rho)
      .def_readonly("V", &GovernorOutput::V)
      .def_readonly("gamma_d", &GovernorOutput::gamma_d)
      .def_readonly("gamma_g", &GovernorOutput::gamma_g)
      .def_readonly("gamma", &GovernorOutput::gamma)
      .def_readonly("trigger", &GovernorOutput::trigger)
      .def_readonly("sampled", &GovernorOutput::sampled)
      .def_property_readonly("margins", &margins_of)
      .def_property_readonly("min_margin", &GovernorOutput::min_margin);

  py::class_<AttitudeGovernor>(m, "Governor",
                               "PD law (3) + PET-ERG (5)-(6) / ERG (4) of the PET-ERG paper.")
      .def(py::init(&make_governor), py::arg("J"), py::arg("kp") = 5.0, py::arg("kd") = 1.0,
           py::arg("tau_max") = 1.0, py::arg("cones") = std::vector<ConeConstraint>{},
           py::arg("mode") = "pet", py::arg("kappa") = 1.0, py::arg("c_gamma") = 3.0,
           py::arg("Ts") = 0.5, py::arg("epsilon") = 1e-3, py::arg("epsilon_gamma") = 0.1)
      .def("reset", &AttitudeGovernor::reset, py::arg("t0"), py::arg("R_g0"),
           "Start at t0 with R_g(t0) = R_g0 (PET-ERG paper, Sec. IV-A).")
      .def("step", &AttitudeGovernor::step, py::arg("t"), py::arg("R"), py::arg("omega_b"),
           py::arg("R_d"), py::return_value_policy::copy,
           "One control step (PET-ERG paper, Fig. 1): returns a GovernorOutput with τ (3).")
      .def("evaluate", &AttitudeGovernor::evaluate, py::arg("R"), py::arg("omega_b"), py::arg("R_g"),
           py::arg("R_d"), py::arg("flag"), "Stateless evaluation of (3)-(6) at one state.")
      .def("lyapunov", &AttitudeGovernor::lyapunov, py::arg("R"), py::arg("omega_b"), py::arg("R_g"),
           "V(R, ω, R_g) = ½ωᵀJω + k_p φ(RᵀR_g) (Sec. III-A).")
      .def("gamma", &AttitudeGovernor::gamma, py::arg("R_g"), "Γ(R_g) (Sec. III-B.1).")
      .def("trigger_condition", &AttitudeGovernor::trigger_condition, py::arg("R"),
           py::arg("omega_b"), py::arg("R_g"), "Trigger (5): Γ(R_g) − c_Γ V ≥ 0.")
      .def_property_readonly("reference", &AttitudeGovernor::reference)
      .def_property_readonly("trigger_flag", &AttitudeGovernor::trigger_flag)
      .def_property_readonly("gamma_d", &AttitudeGovernor::gamma_d)
      .def_property_readonly("cones", [](const AttitudeGovernor& g) {
        return std::vector<ConeConstraint>(g.cones().begin(), g.cones().end());
      });
}

}  // namespace attiguard::python
