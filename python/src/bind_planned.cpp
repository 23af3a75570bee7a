/// @file bind_planned.cpp
/// The planned mode's flight-loop object from Python (docs/pet-erg.md, section 16.2;
/// docs/python.md): PlannedGovernor.from_scenario plans the slew of a `governor = "planned"`
/// pet_erg scenario exactly as its run does (sim::planned_setup), then reset(t0) and
/// step(t, R, omega_b) in the user's own loop; the same validation as the CLI.

#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <utility>

#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "attiguard/core/errors.hpp"
#include "attiguard/governor/planned_governor.hpp"
#include "attiguard/scenario/argument_checks.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/read_pet_erg.hpp"
#include "attiguard/sim/planned_run.hpp"
#include "bindings.hpp"

namespace py = pybind11;

namespace attiguard::python {
namespace {

using governor::PlannedGovernor;
using governor::PlannedOutput;
using lie::Mat3;
using lie::Vec3;

/// What one step returns to Python (docs/pet-erg.md, section 16.2).
struct PyPlannedStep {
  Vec3 tau_b;
  double demand_ratio;
  Mat3 R_p;
  double sigma, rate, accel, V;
  bool sampled, admissible;
  std::string rule;
  double torque_bound, gamma_g;
};

constexpr std::array<const char*, 4> kRuleNames{"jump", "accelerate", "coast", "brake"};

/// The planned governor of a scenario (sim::planned_setup) and the flight loop's time checks.
class PyPlannedGovernor {
 public:
  static PyPlannedGovernor from_scenario(const std::string& path) {
    const scenario::Document doc = scenario::load_document(path);
    const sim::PetErgScenario sc = scenario::parse_pet_erg(doc);
    if (sc.params.mode != governor::GovernorMode::planned) {
      scenario::fail_at(doc, "governor", "PlannedGovernor.from_scenario needs governor = \"planned\" "
                                         "(Governor.from_scenario flies the PET-ERG)");
    }
    return PyPlannedGovernor(sim::planned_setup(sc));
  }

  void reset(double t0) {
    if (!std::isfinite(t0)) throw InputError(std::string(kLabelReset) + ": t0: must be finite");
    gov_.reset(t0);
    last_t_ = t0;
    started_ = true;
  }

  PyPlannedStep step(double t, const Mat3& R, const Vec3& omega_b, const std::optional<Vec3>& wheel_momentum_b) {
    check_step_time(kLabelStep, "reset(t0)", started_, t, last_t_);
    const Mat3 R_ok = scenario::checked_rotation_matrix(R, "R", kLabelStep);
    const Vec3 w_ok = scenario::checked_vector3(omega_b, "omega_b", kLabelStep);
    const Vec3 h_ok = wheel_momentum_b ? scenario::checked_vector3(*wheel_momentum_b, "wheel_momentum_b", kLabelStep)
                                       : Vec3::Zero();
    last_t_ = t;
    const PlannedOutput& o = gov_.step(t, R_ok, w_ok, h_ok);
    return PyPlannedStep{o.tau_b, o.demand_ratio, o.reference.R_ib, o.sigma, o.rate, o.accel, o.V,
                         o.sampled, o.choice.admissible,
                         kRuleNames[static_cast<std::size_t>(o.choice.rule)],
                         o.choice.torque_bound, o.choice.gamma_g};
  }

  [[nodiscard]] const sim::PlannedSetup& setup() const noexcept { return setup_; }

 private:
  explicit PyPlannedGovernor(sim::PlannedSetup setup)
      : setup_(std::move(setup)), gov_(setup_.planned.plan, setup_.run.cones, setup_.params) {}

  static constexpr const char* kLabelReset = "PlannedGovernor.reset()";
  static constexpr const char* kLabelStep = "PlannedGovernor.step()";

  sim::PlannedSetup setup_;
  PlannedGovernor gov_;
  bool started_{false};
  double last_t_{0.0};
};

}  // namespace

void bind_planned(py::module_& m) {
  py::class_<PyPlannedStep>(m, "PlannedStep",
                            "One step of the planned governor (docs/pet-erg.md, section 16.2).")
      .def_readonly("tau_b", &PyPlannedStep::tau_b, "torque to command [N m] (saturated at tau_max)")
      .def_readonly("demand_ratio", &PyPlannedStep::demand_ratio, "|tau| the law asked for / tau_max")
      .def_readonly("R_p", &PyPlannedStep::R_p, "the plan's attitude at the clock (R_d at the end)")
      .def_readonly("sigma", &PyPlannedStep::sigma, "the plan's clock [s]")
      .def_readonly("rate", &PyPlannedStep::rate, "the clock's rate s_dot")
      .def_readonly("accel", &PyPlannedStep::accel, "the clock's acceleration [1/s]")
      .def_readonly("V", &PyPlannedStep::V, "the tracking law's Lyapunov function [J]")
      .def_readonly("sampled", &PyPlannedStep::sampled, "this step chose the rate")
      .def_readonly("admissible", &PyPlannedStep::admissible, "the last choice met its thresholds")
      .def_readonly("rule", &PyPlannedStep::rule, "jump, accelerate, coast or brake")
      .def_readonly("torque_bound", &PyPlannedStep::torque_bound, "bound on |tau| of the level set [N m]")
      .def_readonly("gamma_g", &PyPlannedStep::gamma_g, "cone threshold over the plan ahead [J]");
  py::class_<PyPlannedGovernor>(m, "PlannedGovernor",
                                "The planned mode in a user's flight loop (docs/pet-erg.md, section 16.2).")
      .def_static("from_scenario", &PyPlannedGovernor::from_scenario, py::arg("path"),
                  "Plans the slew of a pet_erg scenario file with governor = \"planned\" exactly as "
                  "its run does (gains, headroom, margin, sampling derived as there). InputError "
                  "naming file, line and key on a bad file.")
      .def("reset", &PyPlannedGovernor::reset, py::arg("t0"), "Start the plan's clock at t0 (sigma = 0).")
      .def("step", &PyPlannedGovernor::step, py::arg("t"), py::arg("R"), py::arg("omega_b"),
           py::arg("wheel_momentum_b") = py::none(),
           "One control step at time t (non-decreasing) with the measured R (body to inertial) "
           "and omega_b [rad/s]: the torque to command and the clock. wheel_momentum_b = A h, the "
           "wheels' momentum in the body frame [N m s], when known: the law then cancels the whole "
           "gyroscopic torque (what the CLI's robust planned runs do, docs/pet-erg.md, section 16.3).")
      .def_property_readonly("robust", [](const PyPlannedGovernor& g) { return g.setup().params.robust.has_value(); },
                             "True with margins = \"robust\" (docs/pet-erg.md, section 16.3)")
      .def_property_readonly("robust_rate",
                             [](const PyPlannedGovernor& g) {
                               return g.setup().params.robust ? g.setup().params.robust->rate : 1.0;
                             },
                             "the clock rate the robust design flies the plan at (1 without robust margins)")
      .def_property_readonly("plan_duration",
                             [](const PyPlannedGovernor& g) { return g.setup().planned.plan.duration(); })
      .def_property_readonly("k_R", [](const PyPlannedGovernor& g) { return g.setup().params.gains.k_R; })
      .def_property_readonly("k_Omega",
                             [](const PyPlannedGovernor& g) { return g.setup().params.gains.k_Omega; })
      .def_property_readonly("tau_max", [](const PyPlannedGovernor& g) { return g.setup().params.tau_max; })
      .def_property_readonly("sampling_period",
                             [](const PyPlannedGovernor& g) { return g.setup().params.sample_period; })
      .def_property_readonly("control_period",
                             [](const PyPlannedGovernor& g) { return g.setup().params.control_period; });
}

}  // namespace attiguard::python
