/// @file bind_governor.cpp
/// The PET-ERG flight-loop object [PET-ERG eqs. (3)-(6)], its cones [PET-ERG eq. (2b)], the PD law [PET-ERG eq. (3)]
/// and the rigid body (Euler's equation), step-able from Python.

#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include <optional>
#include <utility>

#include <nlohmann/json.hpp>
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "attiguard/control/pd_so3.hpp"
#include "attiguard/dynamics/rigid_body.hpp"
#include "attiguard/core/errors.hpp"
#include "attiguard/governor/attitude_governor.hpp"
#include "attiguard/governor/governor_design.hpp"
#include "attiguard/io/json_values.hpp"
#include "attiguard/scenario/argument_checks.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/read_pet_erg.hpp"
#include "attiguard/sim/pet_erg_scenario.hpp"
#include "bindings.hpp"

namespace py = pybind11;

namespace attiguard::python {
namespace {

using governor::AttitudeGovernor;
using governor::ConeConstraint;
using governor::GovernorOutput;
using governor::GovernorParams;
using lie::Mat3;
using lie::Vec3;

/// A cone from keyword arguments, validated by the file reader's cone check
/// (scenario/argument_checks.hpp): exactly one of half_angle_deg and half_angle_rad.
ConeConstraint make_cone(bool keep_out, const Vec3& axis_b, const Vec3& direction_i,
                         const std::optional<double>& half_angle_deg,
                         const std::optional<double>& half_angle_rad, double delta_offset,
                         double zeta_offset, double repulsive_gain) {
  const std::string label = keep_out ? "keep_out_cone()" : "keep_in_cone()";
  if (half_angle_deg.has_value() == half_angle_rad.has_value()) {
    throw InputError(label + ": give exactly one of half_angle_deg (degrees) and half_angle_rad "
                             "(radians)" + (half_angle_deg ? ", not both" : ""));
  }
  nlohmann::json cone = {{"type", keep_out ? "keep_out" : "keep_in"},
                         {"axis_b", io::json_array(axis_b)},
                         {"direction_i", io::json_array(direction_i)},
                         {"delta_offset", delta_offset},
                         {"zeta_offset", zeta_offset},
                         {"repulsive_gain", repulsive_gain}};
  if (half_angle_deg) cone["half_angle_deg"] = *half_angle_deg;
  if (half_angle_rad) cone["half_angle"] = *half_angle_rad;
  try {
    return scenario::checked_cone(cone, label);
  } catch (const InputError& e) {  // the argument names of Python: cone.half_angle -> half_angle_rad
    std::string m = e.what();
    for (const auto& [from, to] : {std::pair<std::string, std::string>{"cone.half_angle:", "half_angle_rad:"},
                                   {"cone.", ""}, {"half_angle is in radians", "half_angle_rad is in radians"}}) {
      for (auto at = m.find(from); at != std::string::npos; at = m.find(from, at + to.size())) {
        m.replace(at, from.size(), to);
      }
    }
    throw InputError(m);
  }
}

/// The scenario key paths of a Governor's arguments -> the argument names.
std::string with_argument_names(std::string m) {
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"erg.sampling_period", "Ts"},
                                 {"control.", ""}, {"erg.", ""}, {": inertia:", ": J:"},
                                 {": governor:", ": mode:"}}) {
    for (auto at = m.find(from); at != std::string::npos; at = m.find(from, at + to.size())) {
      m.replace(at, from.size(), to);
    }
  }
  return m;
}

/// The design arguments of Governor() beyond the governor block (docs/pet-erg.md, sections
/// 10-13): the flight-loop period, the wheels, the margins and the imperfection bounds.
struct DesignArgs {
  double control_period{0.0};
  std::vector<py::dict> wheels;
  std::string margins{"nominal"};
  governor::ImperfectionBounds bounds;
  double robust_reference_step{0.0};
};

/// A number of a wheel's dict: a Python int or float (not a str or bool), else TypeError.
double wheel_number(const py::dict& wheel, const char* key, const std::string& where) {
  const py::object v = wheel[key];
  if (py::isinstance<py::bool_>(v) || !(py::isinstance<py::float_>(v) || py::isinstance<py::int_>(v))) {
    throw py::type_error("Governor(): " + where + "." + key + ": must be a number");
  }
  return v.cast<double>();
}

/// wheels[i] of Governor(): a dict with the keys of a [[wheels]] table (axis_b, torque_max,
/// momentum_max, optional momentum; docs/pet-erg.md, section 12), checked as the file reader
/// does: a finite non-zero axis (normalised), positive limits, |momentum| <= momentum_max.
dynamics::ReactionWheel checked_wheel(const py::dict& wheel, std::size_t i) {
  constexpr const char* kLabel = "Governor()";
  const std::string where = "wheels[" + std::to_string(i) + "]";
  for (const auto& [key, value] : wheel) {
    (void)value;
    const std::string k = py::str(key).cast<std::string>();
    if (k != "axis_b" && k != "torque_max" && k != "momentum_max" && k != "momentum") {
      throw InputError(std::string(kLabel) + ": " + where + ": unknown key '" + k +
                       "' (axis_b, torque_max, momentum_max, momentum)");
    }
  }
  for (const char* key : {"axis_b", "torque_max", "momentum_max"}) {
    if (!wheel.contains(key)) throw InputError(std::string(kLabel) + ": " + where + ": missing " + key);
  }
  Vec3 axis = Vec3::Zero();
  try {
    axis = wheel["axis_b"].cast<Vec3>();
  } catch (const py::cast_error&) {
    throw py::type_error(std::string(kLabel) + ": " + where + ".axis_b: must be 3 numbers");
  }
  axis = scenario::checked_vector3(axis, where + ".axis_b", kLabel);
  if (!(axis.norm() > 0.0) || !std::isfinite(axis.norm())) {
    throw InputError(std::string(kLabel) + ": " + where + ".axis_b: must be a non-zero direction");
  }
  dynamics::ReactionWheel w;
  w.axis_b = axis / axis.norm();
  w.torque_max = scenario::checked_number(wheel_number(wheel, "torque_max", where), where + ".torque_max", true, kLabel);
  w.momentum_max =
      scenario::checked_number(wheel_number(wheel, "momentum_max", where), where + ".momentum_max", true, kLabel);
  if (wheel.contains("momentum")) {
    w.momentum0 = wheel_number(wheel, "momentum", where);
    if (!std::isfinite(w.momentum0) || std::abs(w.momentum0) > w.momentum_max) {
      throw InputError(std::string(kLabel) + ": " + where + ".momentum: must be finite with |momentum| <= momentum_max");
    }
  }
  return w;
}

/// The inputs of governor::design from the governor block `p`, `cones` and the design arguments,
/// each checked (finite, non-negative bounds; delay 0 or 1; margins "nominal" or "robust").
governor::GovernorDesignInputs design_inputs(const GovernorParams& p, const std::vector<ConeConstraint>& cones,
                                             const DesignArgs& a) {
  constexpr const char* kLabel = "Governor()";
  governor::GovernorDesignInputs in;
  in.params = p;
  in.cones = cones;
  for (std::size_t i = 0; i < a.wheels.size(); ++i) in.wheels.push_back(checked_wheel(a.wheels[i], i));
  in.control_period = scenario::checked_number(a.control_period, "control_period", false, kLabel);
  const std::optional<governor::Margins> margins = governor::kMarginsNames.find(a.margins);
  if (!margins) {
    throw InputError(std::string(kLabel) + ": margins: must be \"nominal\" or \"robust\", got '" + a.margins + "'");
  }
  in.margins = *margins;
  const governor::ImperfectionBounds& b = a.bounds;
  in.bounds.disturbance = scenario::checked_number(b.disturbance, "disturbance_bound", false, kLabel);
  in.bounds.attitude_bias = scenario::checked_number(b.attitude_bias, "attitude_bias_bound", false, kLabel);
  in.bounds.attitude_noise = scenario::checked_number(b.attitude_noise, "attitude_noise", false, kLabel);
  in.bounds.rate_bias = scenario::checked_number(b.rate_bias, "rate_bias_bound", false, kLabel);
  in.bounds.rate_noise = scenario::checked_number(b.rate_noise, "rate_noise", false, kLabel);
  in.bounds.torque_quantum = scenario::checked_number(b.torque_quantum, "torque_quantum", false, kLabel);
  if (b.delay_periods != 0 && b.delay_periods != 1) {
    throw InputError(std::string(kLabel) + ": delay_periods: must be 0 or 1, got " + std::to_string(b.delay_periods));
  }
  in.bounds.delay_periods = b.delay_periods;
  in.max_reference_step = scenario::checked_number(a.robust_reference_step, "robust_reference_step", false, kLabel);
  // As the scenario reader's [control] robust_reference_step: it caps the reference lag of a
  // delayed command only (docs/pet-erg.md, section 13), so it is refused without the delay.
  if (in.max_reference_step > 0.0 && b.delay_periods == 0) {
    throw InputError(std::string(kLabel) + ": robust_reference_step: only used with delay_periods = 1 (it caps the "
                     "reference lag of a delayed command; without the delay there is none)");
  }
  return in;
}

/// The design figures of a governor (docs/pet-erg.md, sections 12-13), for Governor.design.
py::dict design_dict(const governor::GovernorDesign& d) {
  py::dict out;
  out["wheel_gamma_d"] = d.wheels.gamma_d;
  out["wheel_gamma_d_upper"] = d.wheels.gamma_d_upper;
  out["wheel_binding"] = d.wheels.binding;
  out["tau_max_reduced"] = d.tau_max_reduced;
  out["wheel_gamma_d_reduced"] = d.wheel_gamma_d_reduced;
  out["bounded_step"] = d.params.bounded_step;
  out["tau_max"] = d.params.tau_max;
  out["polytope_gamma_d"] = d.params.polytope_gamma_d;
  return out;
}

/// A Governor for Python: the flight-loop object plus the checks of its calls (reset before
/// step, time never backwards, rotations and finite vectors: scenario/argument_checks.hpp).
/// Set-up code, not the flight loop: the checks allocate.
class PyGovernor {
 public:
  /// The governor of governor::design (docs/pet-erg.md, sections 10-13) from plain values: the
  /// governor block, the cones and the design arguments.
  PyGovernor(const Mat3& J, double kp, double kd, double tau_max,
             const std::vector<ConeConstraint>& cones, const std::string& mode, double kappa,
             double c_gamma, double Ts, double epsilon, double epsilon_gamma, const DesignArgs& args)
      : PyGovernor(make(J, kp, kd, tau_max, cones, mode, kappa, c_gamma, Ts, epsilon, epsilon_gamma, args)) {}

  /// The governor exactly as the flight loop of a `pet_erg` scenario builds it: its wheels'
  /// polytope, the bounded step with control_period > 0, and with margins = "robust" the robust
  /// margins, reduced limits and tightened cones (docs/pet-erg.md, sections 10-13).
  static PyGovernor from_scenario(const std::string& path) {
    const sim::PetErgScenario sc = scenario::parse_pet_erg(scenario::load_document(path));
    return PyGovernor(sim::design_governor(sc));
  }

  void reset(double t0, const Mat3& R_g0) {
    if (!std::isfinite(t0)) throw InputError(std::string(kLabelReset) + ": t0: must be finite");
    gov_.reset(t0, scenario::checked_rotation_matrix(R_g0, "R_g0", kLabelReset));
    last_t_ = t0;
    started_ = true;
  }

  GovernorOutput step(double t, const Mat3& R, const Vec3& omega_b, const Mat3& R_d) {
    check_step_time(kLabelStep, "reset(t0, R_g0)", started_, t, last_t_);
    const Mat3 R_ok = scenario::checked_rotation_matrix(R, "R", kLabelStep);
    const Vec3 w_ok = scenario::checked_vector3(omega_b, "omega_b", kLabelStep);
    const Mat3 R_d_ok = scenario::checked_rotation_matrix(R_d, "R_d", kLabelStep);
    last_t_ = t;
    return gov_.step(t, R_ok, w_ok, R_d_ok);
  }

  [[nodiscard]] const AttitudeGovernor& governor() const noexcept { return gov_; }
  /// The design the governor was built from (docs/pet-erg.md, sections 12-13).
  [[nodiscard]] const governor::GovernorDesign& design() const noexcept { return design_; }

 private:
  explicit PyGovernor(governor::GovernorDesign d)
      : design_(std::move(d)), gov_(checked(design_)) {}

  /// The governor of a design, its constructor's errors labelled (scenario/argument_checks.hpp).
  static AttitudeGovernor checked(const governor::GovernorDesign& d) {
    try {
      return scenario::checked_governor(d.params, d.cones, "Governor()");
    } catch (const InputError& e) {
      throw InputError(with_argument_names(e.what()));
    }
  }

  static constexpr const char* kLabelReset = "Governor.reset()";
  static constexpr const char* kLabelStep = "Governor.step()";

  static governor::GovernorDesign make(const Mat3& J, double kp, double kd, double tau_max,
                                       const std::vector<ConeConstraint>& cones, const std::string& mode,
                                       double kappa, double c_gamma, double Ts, double epsilon,
                                       double epsilon_gamma, const DesignArgs& design_args) {
    const nlohmann::json args = {
        {"governor", mode},
        {"inertia", io::json_rows(J)},
        {"control", {{"kp", kp}, {"kd", kd}, {"tau_max", tau_max}}},
        {"erg", {{"kappa", kappa}, {"c_gamma", c_gamma}, {"sampling_period", Ts},
                 {"epsilon", epsilon}, {"epsilon_gamma", epsilon_gamma}}}};
    GovernorParams p;
    try {
      p = scenario::checked_governor_params(args, "Governor()");
    } catch (const InputError& e) {
      throw InputError(with_argument_names(e.what()));
    }
    const governor::GovernorDesignInputs in = design_inputs(p, cones, design_args);
    try {
      return governor::design(in);
    } catch (const SetupError& e) {
      throw InputError(std::string("Governor(): ") + e.what());
    }
  }

  governor::GovernorDesign design_;
  AttitudeGovernor gov_;
  bool started_{false};
  double last_t_{0.0};
};

/// The state arguments (R, omega_b, R_g) of the governor's stateless evaluations, checked.
struct State {
  Mat3 R;
  Vec3 omega_b;
  Mat3 R_g;
};
State checked_state(const Mat3& R, const Vec3& w, const Mat3& R_g, const char* label) {
  return State{scenario::checked_rotation_matrix(R, "R", label),
               scenario::checked_vector3(w, "omega_b", label),
               scenario::checked_rotation_matrix(R_g, "R_g", label)};
}

std::vector<double> margins_of(const GovernorOutput& o) {
  return std::vector<double>(o.margins.begin(), o.margins.begin() + o.cone_count);
}

}  // namespace

namespace {

/// Cone (constraint [PET-ERG eq. (2b)]), keep_in_cone, keep_out_cone.
void bind_cones(py::module_& m) {
  py::class_<ConeConstraint>(m, "Cone",
                             "Pointing constraint [PET-ERG eq. (2b)]: a_cᵀ R a_b ≥ cos θ_c.")
      .def_readonly("axis_b", &ConeConstraint::axis_b)
      .def_readonly("direction_i", &ConeConstraint::direction_i)
      .def_readonly("theta_c", &ConeConstraint::theta_c)
      .def("margin", [](const ConeConstraint& c, const Mat3& R) {
             return governor::pointing_margin(c, scenario::checked_rotation_matrix(R, "R", "Cone.margin()"));
           },
           py::arg("R"), "a_cᵀ R a_b − cos θ_c (≥ 0: constraint [PET-ERG eq. (2b)] holds).")
      .def("__repr__", [](const ConeConstraint& c) {
        return "Cone(theta_c=" + std::to_string(c.theta_c) + ")";
      });
  m.def("keep_in_cone",
        [](const Vec3& a_b, const Vec3& a_i, std::optional<double> deg, std::optional<double> rad,
           double delta_offset, double zeta_offset, double gain) {
          return make_cone(false, a_b, a_i, deg, rad, delta_offset, zeta_offset, gain);
        },
        py::arg("axis_b"), py::arg("direction_i"), py::kw_only(), py::arg("half_angle_deg") = py::none(),
        py::arg("half_angle_rad") = py::none(), py::arg("delta_offset") = 0.05,
        py::arg("zeta_offset") = 0.05, py::arg("repulsive_gain") = 1.0,
        "Keep-in cone [PET-ERG eq. (2b)] of half-angle θ_c around direction_i (PET-ERG paper): exactly one of "
        "half_angle_deg, half_angle_rad; checked as a [[cones]] table of a scenario file.");
  m.def("keep_out_cone",
        [](const Vec3& a_b, const Vec3& avoid_i, std::optional<double> deg, std::optional<double> rad,
           double delta_offset, double zeta_offset, double gain) {
          return make_cone(true, a_b, avoid_i, deg, rad, delta_offset, zeta_offset, gain);
        },
        py::arg("axis_b"), py::arg("direction_i"), py::kw_only(), py::arg("half_angle_deg") = py::none(),
        py::arg("half_angle_rad") = py::none(), py::arg("delta_offset") = 0.05,
        py::arg("zeta_offset") = 0.05, py::arg("repulsive_gain") = 1.0,
        "Keep-out cone of half-angle α around direction_i, as the keep-in cone [PET-ERG eq. (2b)] of π − α: "
        "exactly one of half_angle_deg, half_angle_rad; checked as a [[cones]] table.");

}

/// pd_torque (PD law [PET-ERG eq. (3)]), RigidBody (Euler's [PET-ERG eq. (1)]), GovernorOutput.
void bind_pd_body_output(py::module_& m) {
  m.def("pd_torque",
        [](const Mat3& R, const Vec3& w, const Mat3& R_g, double kp, double kd) {
          constexpr const char* kLabel = "pd_torque()";
          const Mat3 R_ok = scenario::checked_rotation_matrix(R, "R", kLabel);
          const Vec3 w_ok = scenario::checked_vector3(w, "omega_b", kLabel);
          const Mat3 R_g_ok = scenario::checked_rotation_matrix(R_g, "R_g", kLabel);
          const double kp_ok = scenario::checked_number(kp, "kp", true, kLabel);
          const double kd_ok = scenario::checked_number(kd, "kd", true, kLabel);
          return control::pd_torque(R_ok, w_ok, R_g_ok, control::PdGains{kp_ok, kd_ok});
        },
        py::arg("R"), py::arg("omega_b"), py::arg("R_g"), py::arg("kp"), py::arg("kd"),
        "PD law [PET-ERG eq. (3)]: τ = k_p sk(RᵀR_g)^∨ − k_d ω.");

  py::class_<dynamics::RigidBody>(m, "RigidBody", "Rigid body: J ω̇ = Jω × ω + τ, Ṙ = R ω̂.")
      .def(py::init([](const Mat3& J) {
             try {
               return dynamics::RigidBody(J);  // the constructor's inertia check (SetupError)
             } catch (const InputError& e) {
               throw InputError(std::string("RigidBody(): J: ") + e.what());
             }
           }),
           py::arg("J"), "J symmetric positive definite, finite, triangle inequality (ValueError).")
      .def_property_readonly("J", &dynamics::RigidBody::inertia)
      .def("angular_acceleration",
           [](const dynamics::RigidBody& b, const Vec3& w, const Vec3& tau) {
             constexpr const char* kLabel = "RigidBody.angular_acceleration()";
             return b.angular_acceleration(scenario::checked_vector3(w, "omega_b", kLabel),
                                           scenario::checked_vector3(tau, "tau_b", kLabel));
           },
           py::arg("omega_b"), py::arg("tau_b"),
           "ω̇ = J⁻¹(Jω × ω + τ) (Euler's equation, [PET-ERG eq. (1)]); finite arguments.")
      .def("kinetic_energy",
           [](const dynamics::RigidBody& b, const Vec3& w) {
             return b.kinetic_energy(scenario::checked_vector3(w, "omega_b", "RigidBody.kinetic_energy()"));
           },
           py::arg("omega_b"), "½ ωᵀJω; omega_b finite.");

  py::class_<GovernorOutput>(m, "GovernorOutput", "Everything the PET-ERG knows at one instant.")
      .def_readonly("tau_b", &GovernorOutput::tau_b)
      .def_readonly("R_g", &GovernorOutput::R_g)
      .def_readonly("xi_g", &GovernorOutput::xi_g)
      .def_readonly("rho", &GovernorOutput::rho)
      .def_readonly("V", &GovernorOutput::V)
      .def_readonly("W", &GovernorOutput::W)
      .def_readonly("gamma_d", &GovernorOutput::gamma_d)
      .def_readonly("gamma_g", &GovernorOutput::gamma_g)
      .def_readonly("gamma", &GovernorOutput::gamma)
      .def_readonly("trigger", &GovernorOutput::trigger)
      .def_readonly("sampled", &GovernorOutput::sampled)
      .def_property_readonly(
          "tie_break", [](const GovernorOutput& o) { return o.tie_break.active; },
          "A saddle tie-break of the navigation field is held (docs/pet-erg.md, section 4).")
      .def_property_readonly(
          "tie_break_cone", [](const GovernorOutput& o) { return o.tie_break.active ? o.tie_break.cone : -1; },
          "The cone the held tie-break goes around, -1 if none (docs/pet-erg.md, section 4).")
      .def_readonly("tie_break_started", &GovernorOutput::tie_break_started,
                    "step() started a saddle tie-break at this call (docs/pet-erg.md, section 4).")
      .def_property_readonly("margins", &margins_of)
      .def_property_readonly("min_margin", &GovernorOutput::min_margin);
}

using GovernorClass = py::class_<PyGovernor>;

/// Governor(...) from plain values by governor::design (docs/pet-erg.md, sections 10-13),
/// Governor.from_scenario, reset and step (PET-ERG paper, Fig. 1).
void def_governor_flight_loop(GovernorClass& cls) {
  cls
      .def(py::init([](const Mat3& J, double kp, double kd, double tau_max,
                       const std::vector<ConeConstraint>& cones, const std::string& mode, double kappa,
                       double c_gamma, double Ts, double epsilon, double epsilon_gamma,
                       double control_period, const std::vector<py::dict>& wheels, const std::string& margins,
                       double disturbance_bound, double attitude_bias_bound, double attitude_noise,
                       double rate_bias_bound, double rate_noise, int delay_periods, double torque_quantum,
                       double robust_reference_step) {
             DesignArgs a;
             a.control_period = control_period;
             a.wheels = wheels;
             a.margins = margins;
             a.bounds = {disturbance_bound, attitude_bias_bound, attitude_noise, rate_bias_bound,
                         rate_noise,        delay_periods,       torque_quantum};
             a.robust_reference_step = robust_reference_step;
             return PyGovernor(J, kp, kd, tau_max, cones, mode, kappa, c_gamma, Ts, epsilon, epsilon_gamma, a);
           }),
           py::arg("J"), py::kw_only(), py::arg("kp"), py::arg("kd"), py::arg("tau_max"),
           py::arg("cones") = std::vector<ConeConstraint>{}, py::arg("mode") = "pet",
           py::arg("kappa") = 1.0, py::arg("c_gamma") = 3.0, py::arg("Ts") = 0.5,
           py::arg("epsilon") = 1e-3, py::arg("epsilon_gamma") = 0.1,
           py::arg("control_period") = 0.0, py::arg("wheels") = std::vector<py::dict>{},
           py::arg("margins") = "nominal", py::arg("disturbance_bound") = 0.0,
           py::arg("attitude_bias_bound") = 0.0, py::arg("attitude_noise") = 0.0,
           py::arg("rate_bias_bound") = 0.0, py::arg("rate_noise") = 0.0, py::arg("delay_periods") = 0,
           py::arg("torque_quantum") = 0.0, py::arg("robust_reference_step") = 0.0,
           "kp, kd, tau_max are required (as in a scenario file); every argument is checked by "
           "the scenario readers (ValueError naming it). The governor is built by governor::design "
           "(docs/pet-erg.md, sections 10-13): control_period > 0 gives the flight loop's bounded "
           "step; wheels (dicts with axis_b, torque_max, momentum_max, momentum, as [[wheels]]) "
           "their polytope's Gamma_d; margins = \"robust\" the robust margin from the bounds "
           "(disturbance_bound, attitude_bias_bound, attitude_noise, rate_bias_bound, rate_noise, "
           "delay_periods, torque_quantum, robust_reference_step; 0: derived) with the reduced "
           "torque limits and tightened cones.")
      .def_static("from_scenario", &PyGovernor::from_scenario, py::arg("path"),
                  "The governor of a pet_erg scenario file exactly as its flight loop builds it "
                  "(wheel polytope, bounded step, robust margins with margins = \"robust\"; "
                  "docs/pet-erg.md, sections 10-13). ValueError naming file, line and key on a "
                  "bad file.")
      .def("reset", &PyGovernor::reset, py::arg("t0"), py::arg("R_g0"),
           "Start at t0 with R_g(t0) = R_g0 [PET-ERG Sec. IV-A].")
      .def("step", &PyGovernor::step, py::arg("t"), py::arg("R"), py::arg("omega_b"),
           py::arg("R_d"),
           "One control step (PET-ERG paper, Fig. 1): returns a GovernorOutput with τ (3). "
           "Refuses a call before reset(), time going backwards, a non-rotation R or R_d and a "
           "non-finite omega_b (ValueError naming the argument).");
}

/// The stateless evaluations of [PET-ERG eqs. (3)-(6)], the robust margin and the design figures, the state.
void def_governor_evaluations(GovernorClass& cls) {
  cls
      .def("evaluate", [](const PyGovernor& g, const Mat3& R, const Vec3& w, const Mat3& R_g,
                          const Mat3& R_d, const py::object& flag_arg) {
             if (!py::isinstance<py::bool_>(flag_arg)) {
               throw py::type_error("Governor.evaluate(): flag: must be True or False, got " +
                                    py::str(py::type::of(flag_arg).attr("__name__")).cast<std::string>());
             }
             const bool flag = flag_arg.cast<bool>();
             const State x = checked_state(R, w, R_g, "Governor.evaluate()");
             return g.governor().evaluate(x.R, x.omega_b, x.R_g,
                                          scenario::checked_rotation_matrix(R_d, "R_d", "Governor.evaluate()"), flag);
           },
           py::arg("R"), py::arg("omega_b"), py::arg("R_g"), py::arg("R_d"), py::arg("flag"),
           "Stateless evaluation of [PET-ERG eqs. (3)-(6)] at one state.")
      .def("lyapunov", [](const PyGovernor& g, const Mat3& R, const Vec3& w, const Mat3& R_g) {
             const State x = checked_state(R, w, R_g, "Governor.lyapunov()");
             return g.governor().lyapunov(x.R, x.omega_b, x.R_g);
           }, py::arg("R"), py::arg("omega_b"), py::arg("R_g"),
           "V(R, ω, R_g) = ½ωᵀJω + k_p φ(RᵀR_g) (Sec. III-A).")
      .def("gamma", [](const PyGovernor& g, const Mat3& R_g) {
             return g.governor().gamma(scenario::checked_rotation_matrix(R_g, "R_g", "Governor.gamma()"));
           },
           py::arg("R_g"), "Γ(R_g) (Sec. III-B.1); Γ_W with robust margins (docs/pet-erg.md, section 13).")
      .def("level", [](const PyGovernor& g, const Mat3& R, const Vec3& w, const Mat3& R_g) {
             const State x = checked_state(R, w, R_g, "Governor.level()");
             return g.governor().level(x.R, x.omega_b, x.R_g);
           }, py::arg("R"), py::arg("omega_b"), py::arg("R_g"),
           "The level compared with Γ: V, or W = V − ε ωᵀJ sk(RᵀR_g)^∨ with robust margins "
           "(docs/pet-erg.md, section 13).")
      .def_property_readonly("robust", [](const PyGovernor& g) -> py::object {
        const auto& r = g.governor().params().robust;
        if (!r) return py::none();
        py::dict d;
        d["epsilon"] = r->epsilon;
        d["delta"] = r->delta;
        d["gamma_min"] = r->gamma_min;
        d["torque_error"] = r->torque_error;
        d["command_error"] = r->command_error;
        d["measurement_margin"] = r->measurement_margin;
        d["max_reference_step"] = r->max_reference_step;
        return d;
      }, "The robust margin (docs/pet-erg.md, section 13) as a dict, or None with the nominal margins.")
      .def("trigger_condition", [](const PyGovernor& g, const Mat3& R, const Vec3& w, const Mat3& R_g) {
             const State x = checked_state(R, w, R_g, "Governor.trigger_condition()");
             return g.governor().trigger_condition(x.R, x.omega_b, x.R_g);
           }, py::arg("R"), py::arg("omega_b"), py::arg("R_g"), "Trigger (5): Γ(R_g) − c_Γ V ≥ 0.")
      .def_property_readonly("design", [](const PyGovernor& g) { return design_dict(g.design()); },
                             "The design figures (docs/pet-erg.md, sections 12-13): wheel_gamma_d, "
                             "wheel_gamma_d_upper, wheel_binding (-1 without wheels), tau_max_reduced "
                             "and wheel_gamma_d_reduced (0 with the nominal margins), bounded_step, and "
                             "the tau_max and polytope_gamma_d the governor runs with.")
      .def_property_readonly("reference", [](const PyGovernor& g) { return g.governor().reference(); })
      .def_property_readonly("trigger_flag", [](const PyGovernor& g) { return g.governor().trigger_flag(); })
      .def_property_readonly("gamma_d", [](const PyGovernor& g) { return g.governor().gamma_d(); })
      .def_property_readonly("cones", [](const PyGovernor& g) {
        return std::vector<ConeConstraint>(g.governor().cones().begin(), g.governor().cones().end());
      });
}

}  // namespace

void bind_governor(py::module_& m) {
  bind_cones(m);
  bind_pd_body_output(m);
  GovernorClass cls(m, "Governor", "PD law [PET-ERG eq. (3)] + [PET-ERG eqs. (5)-(6)] / ERG [PET-ERG eq. (4)].");
  def_governor_flight_loop(cls);
  def_governor_evaluations(cls);
}

}  // namespace attiguard::python
