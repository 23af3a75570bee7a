#pragma once
/// @file pet_erg_loop.hpp
/// The parts the `pet_erg` simulators share (sim/pet_erg_run.cpp for the PET-ERG and the plain PD
/// law, sim/planned_run.cpp for the planned mode; docs/pet-erg.md, sections 6, 10-12 and 16.2):
/// the stops of the integrator, the run over them, the figures folded at every step, the end of
/// a run and the flight loop's disturbance on the plant. Simulation code (allocates; not the
/// flight loop).

#include <type_traits>
#include <vector>

#include "attiguard/governor/attitude_governor.hpp"
#include "attiguard/integrate/integrator.hpp"
#include "attiguard/sim/adversarial_disturbance.hpp"
#include "attiguard/sim/held_actuation.hpp"
#include "attiguard/sim/pet_erg_run.hpp"

namespace attiguard::sim::pet_erg_loop {

using governor::GovernorOutput;
using lie::Mat3;

/// A stop of the integrator and what happens there.
struct Stop {
  double t{0.0};
  bool sample{false};   ///< a sampling instant t_k of [PET-ERG eq. (5)] (continuous-time loop)
  bool output{false};   ///< an output row
  bool control{false};  ///< a control instant k·control_period (flight loop)
};

/// Sampling instants k·T_s in (0, duration), output instants, and schedule waypoints in
/// (0, duration), merged (instants closer than 1e-9·min(T_s, output_interval) are one stop).
std::vector<Stop> stop_plan(const PetErgScenario& sc);

/// The times of the stops.
std::vector<double> stop_times(const std::vector<Stop>& plan);

/// The end of a run: distance left, active cones, the eigenaxis bang-bang time of the slew and
/// the outcome (docs/pet-erg.md, "Outcomes"), R_d_end = R_d(duration). r.convergence_time and
/// r.reference_motion are set.
void finish_outcome(const PetErgScenario& sc, const Mat3& R_g_end, const Mat3& R_d_end,
                    PetErgResult& r);

/// The figures known before the run starts, with the governor's design.
PetErgResult initial_result(const PetErgScenario& sc, governor::GovernorDesign design,
                            const governor::AttitudeGovernor& gov);

/// A saddle tie-break started at t around cone `cone` (docs/pet-erg.md, section 4).
void note_tie_break(PetErgResult& r, double t, int cone);

/// Folds one instant into the figures: `out` is the governor's view with the torque applied.
void record(const PetErgScenario& sc, PetErgResult& r, double t, const Mat3& R_d, const Mat3& R_ib,
            const GovernorOutput& out);

/// The end of either loop: final errors, outcome and the integrator's counters.
void finish(const PetErgScenario& sc, const PetErgState& y, const integrate::IntegrationStats& stats,
            PetErgResult& r);

/// The state of either loop at t = 0: (R_0, R_g(0), ω_0) of the scenario's [initial].
PetErgState pet_erg_initial_state(const PetErgScenario& sc);

/// The wheels' figures of a flight-loop run (docs/pet-erg.md, section 12): the demand and
/// momentum ratios, the momenta at the end, and Γ_d's upper bracket of the wheel polytope.
void finish_wheels(const PetErgScenario& sc, const HeldActuation& actuation, PetErgResult& r);

/// monitor(t, s, row) when the monitor takes whether its output goes into a row (it may then
/// leave out what only rows read), monitor(t, s) otherwise.
template <class Monitor>
auto call_monitor(Monitor& monitor, double t, const PetErgState& s, bool row) {
  if constexpr (std::is_invocable_v<Monitor&, double, const PetErgState&, bool>) {
    return monitor(t, s, row);
  } else {
    return monitor(t, s);
  }
}

/// The run from t = 0 over the stop plan of `sc` (both loops): `monitor` at t = 0, at every
/// integrator step and at every stop; at each stop `at_stop(stop, t, state)` first (sampling or
/// the control instant); rows to `on_output` at t = 0 and at the output stops (call_monitor says
/// the monitor which of its calls feed a row).
template <class Field, class Monitor, class AtStop, class Observer>
integrate::IntegrationStats integrate_over_stops(const PetErgScenario& sc, const Field& field, PetErgState& y,
                                                 Monitor& monitor, AtStop& at_stop,
                                                 const Observer& on_output) {
  const bool rows = static_cast<bool>(on_output);
  {
    const auto out0 = call_monitor(monitor, 0.0, y, rows);
    if (on_output) {
      on_output(0.0, y, sc.desired.at(0.0), out0);
    }
  }
  const std::vector<Stop> plan = stop_plan(sc);
  const std::vector<double> times = stop_times(plan);
  std::size_t next = 0;
  auto on_stop = [&](double t, PetErgState& s) {
    const Stop& stop = plan[next++];
    at_stop(stop, t, s);
    const auto out = call_monitor(monitor, t, s, stop.output && rows);
    if (stop.output && on_output) {
      on_output(t, s, sc.desired.at(t), out);
    }
    return true;
  };
  auto on_step = [&](double t, const PetErgState& s) { (void)call_monitor(monitor, t, s, false); };
  return integrate::integrate(field, y, 0.0, times, sc.integrator, on_stop, on_step);
}

/// The disturbance d on the plant of the flight loop (docs/pet-erg.md, section 11): the
/// scenario's d(t), or the adversarial torque from the true state and R_g, held from each control
/// instant or recomputed at every evaluation of the field.
class PetErgPlantDisturbance {
 public:
  explicit PetErgPlantDisturbance(const PetErgScenario& sc)
      : im_(sc.imperfections),
        adversarial_(im_.disturbance.kind == dynamics::DisturbanceKind::adversarial),
        continuous_(adversarial_ && im_.adversary.update == DisturbanceUpdate::continuous),
        adversary_(make_adversary(sc.params.J, sc.cones, im_.disturbance.bound, im_.adversary.weight)) {}

  /// d at time t in the state s (an evaluation of the field).
  lie::Vec3 at(double t, const PetErgState& s) const noexcept {
    if (continuous_) return adversarial_torque(adversary_, s.R[0], s.x, s.R[1]);
    return adversarial_ ? held_ : im_.disturbance.at(t);
  }
  /// At a control instant, once R_g is set: the adversarial torque held over the period.
  void hold(const PetErgState& s) noexcept {
    if (adversarial_) held_ = adversarial_torque(adversary_, s.R[0], s.x, s.R[1]);
  }

 private:
  const PetErgImperfections& im_;
  bool adversarial_;
  bool continuous_;
  AdversaryModel adversary_;
  lie::Vec3 held_{lie::Vec3::Zero()};
};

}  // namespace attiguard::sim::pet_erg_loop
