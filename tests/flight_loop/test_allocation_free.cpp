// The flight-loop promise (docs/pet-erg.md, Sec. 5; docs/waypoint.md, "Guidance"; docs/install.md,
// "Flight-only build"): per step, nothing allocated and nothing thrown. Enforced: 10⁴ calls each
// of AttitudeGovernor::step, WaypointSequencer::step and QuaternionPid::step in closed loop, with
// every global operator new / delete of this executable replaced by counting versions, must not
// reach the heap; and the three steps are declared noexcept (static_assert).
//
// Own executable (tests/CMakeLists.txt, attiguard_allocation_tests): the replaced operators
// would otherwise count for the whole suite. Only the step calls are counted (a flag is raised
// around each call), so GoogleTest and the plant propagation in between may allocate. The
// flight layers use fixed-size Eigen types only, which never call malloc, so counting operator
// new covers every standard container, std::function, std::string and exception object.
// The same replaced operators inject an out-of-memory failure (AllocationFailure.*): the one
// place in the suite where std::bad_alloc can be made to happen at a chosen allocation.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <numbers>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "attiguard/control/quaternion_pid.hpp"
#include "attiguard/control/so3_tracking.hpp"
#include "attiguard/control/torque_quantizer.hpp"
#include "attiguard/dynamics/attitude_sensor.hpp"
#include "attiguard/dynamics/disturbance_torque.hpp"
#include "attiguard/dynamics/reaction_wheel_array.hpp"
#include "attiguard/dynamics/spacecraft_plant.hpp"
#include "attiguard/governor/attitude_governor.hpp"
#include "attiguard/governor/planned_governor.hpp"
#include "attiguard/governor/progress_governor.hpp"
#include "attiguard/guidance/waypoint_sequencer.hpp"
#include "attiguard/lie/axis_angle.hpp"
#include "attiguard/lie/quaternion.hpp"
#include "attiguard/lie/so3.hpp"
#include "attiguard/parallel/worker_pool.hpp"
#include "attiguard/plan/slew_planner.hpp"
#include "attiguard/scenario/dispersion.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/read_mission.hpp"
#include "attiguard/scenario/read_pet_erg.hpp"
#include "attiguard/sim/adversarial_disturbance.hpp"
#include "attiguard/sim/mission_slews.hpp"
#include "attiguard/sim/pet_erg_run.hpp"
#include "attiguard/sim/pet_erg_scenario.hpp"

namespace {

std::atomic<bool> g_counting{false};
std::atomic<long> g_allocations{0};
/// Out-of-memory injection (AllocationFailure.*): when > 0, counts down on every throwing
/// allocation of any thread, and the allocation that brings it to 0 throws std::bad_alloc.
std::atomic<long> g_fail_countdown{0};

void* counted_alloc(std::size_t size, std::size_t align) {
  if (g_counting.load(std::memory_order_relaxed)) {
    g_allocations.fetch_add(1, std::memory_order_relaxed);
  }
  const std::size_t n = size == 0 ? 1 : size;
  void* p = align > alignof(std::max_align_t)
                ? std::aligned_alloc(align, (n + align - 1) / align * align)
                : std::malloc(n);
  return p;
}

void* counted_alloc_or_throw(std::size_t size, std::size_t align) {
  if (g_fail_countdown.load(std::memory_order_relaxed) > 0 &&
      g_fail_countdown.fetch_sub(1, std::memory_order_relaxed) == 1) {
    throw std::bad_alloc();
  }
  void* p = counted_alloc(size, align);
  if (p == nullptr) {
    throw std::bad_alloc();
  }
  return p;
}

}  // namespace

// ---- every replaceable global allocation function (C++17 [new.delete]) ----
void* operator new(std::size_t n) { return counted_alloc_or_throw(n, 0); }
void* operator new[](std::size_t n) { return counted_alloc_or_throw(n, 0); }
void* operator new(std::size_t n, std::align_val_t a) {
  return counted_alloc_or_throw(n, static_cast<std::size_t>(a));
}
void* operator new[](std::size_t n, std::align_val_t a) {
  return counted_alloc_or_throw(n, static_cast<std::size_t>(a));
}
void* operator new(std::size_t n, const std::nothrow_t&) noexcept { return counted_alloc(n, 0); }
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept { return counted_alloc(n, 0); }
void* operator new(std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
  return counted_alloc(n, static_cast<std::size_t>(a));
}
void* operator new[](std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
  return counted_alloc(n, static_cast<std::size_t>(a));
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept { std::free(p); }

namespace attiguard {
namespace {

using lie::Mat3;
using lie::Quat;
using lie::Vec3;

// The three flight-loop steps promise not to throw.
static_assert(noexcept(std::declval<governor::AttitudeGovernor&>().step(
    0.0, std::declval<const Mat3&>(), std::declval<const Vec3&>(), std::declval<const Mat3&>())));
static_assert(noexcept(std::declval<guidance::WaypointSequencer&>().step(
    std::declval<const guidance::MissionInputs&>())));
static_assert(noexcept(std::declval<control::QuaternionPid&>().step(
    std::declval<const Quat&>(), std::declval<const Vec3&>(), std::declval<const Quat&>(),
    std::declval<const Vec3&>(), 0.0)));

constexpr int kCalls = 10000;

/// Calls f() with allocation counting on; returns its result.
template <class F>
auto counted(F&& f) {
  g_counting.store(true, std::memory_order_relaxed);
  auto result = f();
  g_counting.store(false, std::memory_order_relaxed);
  return result;
}

/// R ← R exp(h ω̂), ω ← ω + h J⁻¹((Jω) × ω + τ) over `substeps` Lie-Euler sub-steps of dt.
void propagate_attitude(const dynamics::RigidBody& body, const Vec3& tau_b, double dt,
                        Mat3& R_ib, Vec3& omega_b) {
  constexpr int substeps = 10;
  const double h = dt / substeps;
  for (int s = 0; s < substeps; ++s) {
    omega_b += h * body.angular_acceleration(omega_b, tau_b);
    R_ib = R_ib * lie::exp(h * omega_b);
  }
}

TEST(AllocationFree, CountingSeesAnAllocationInsideTheWindow) {
  // The counter itself works: a std::vector built inside the window is seen.
  g_allocations = 0;
  const std::size_t n = counted([] { return std::vector<double>(8, 1.0).size(); });
  EXPECT_EQ(n, 8U);
  EXPECT_GE(g_allocations.load(), 1);
}

TEST(AllocationFree, AttitudeGovernorStepOnThePetErgPaperScenario) {
  // PET-ERG paper, Sec. V (examples/pet_erg_paper.toml), in mode pet and in mode continuous.
  // bounded_step: the reference move of the pet_erg flight loop (docs/pet-erg.md, section 10),
  // with κ = 100 so that the move is bounded and halved on most steps.
  struct Case {
    governor::GovernorMode mode;
    bool bounded_step;
    double kappa;
  };
  for (const Case c : {Case{governor::GovernorMode::pet, false, 1.0},
                       Case{governor::GovernorMode::continuous, false, 1.0},
                       Case{governor::GovernorMode::pet, true, 100.0}}) {
    const governor::GovernorMode mode = c.mode;
    governor::GovernorParams params;
    params.mode = mode;
    params.bounded_step = c.bounded_step;
    params.kappa = c.kappa;
    params.J = Vec3(1.0, 2.0, 3.0).asDiagonal();
    params.tau_max = 2.5;
    const std::array cones{governor::keep_in_cone(Vec3::UnitZ(), Vec3(-0.791, 0.061, -0.609),
                                                  160.0 * std::numbers::pi / 180.0)};
    governor::AttitudeGovernor gov(params, cones);
    const dynamics::RigidBody body(params.J);
    const Mat3 R_d = lie::rotation_from_axis_angle({Vec3::UnitY(), std::numbers::pi / 2.0});
    Mat3 R_ib = Mat3::Identity();
    Vec3 omega_b(0.2, 0.3, 0.4);
    const double dt = 0.005;
    g_allocations = 0;
    int samples = 0;
    for (int k = 0; k < kCalls; ++k) {
      const governor::GovernorOutput out =
          counted([&] { return gov.step(k * dt, R_ib, omega_b, R_d); });
      samples += out.sampled ? 1 : 0;
      propagate_attitude(body, out.tau_b, dt, R_ib, omega_b);
    }
    EXPECT_EQ(g_allocations.load(), 0)
        << "heap allocations in " << kCalls << " calls of AttitudeGovernor::step (mode "
        << (mode == governor::GovernorMode::pet ? "pet" : "continuous")
        << (c.bounded_step ? ", bounded step" : "") << ")";
    EXPECT_LT(lie::distance(R_ib, R_d), 1e-2);  // the loop really flew the manoeuvre
    if (mode == governor::GovernorMode::pet) {
      EXPECT_GE(samples, 90);  // 50 s at T_s = 0.5 s: the trigger (5) was evaluated
    }
  }
}

TEST(AllocationFree, AttitudeGovernorStepThroughASaddleTieBreak) {
  // examples/pet_erg_symmetric_sun.toml at 10 Hz with the bounded step (docs/pet-erg.md, section
  // 4, "Saddles: the tie-break"): the Sun exactly on the slew path, the tie-break starts, holds the
  // detour and is released inside the counted calls.
  governor::GovernorParams params;
  params.bounded_step = true;
  params.J = Vec3(1.0, 2.0, 3.0).asDiagonal();
  params.tau_max = 2.5;
  const double sixty = std::numbers::pi / 3.0;
  const std::array cones{governor::keep_out_cone(Vec3::UnitX(), Vec3(std::cos(sixty), std::sin(sixty), 0.0),
                                                 20.0 * std::numbers::pi / 180.0)};
  governor::AttitudeGovernor gov(params, cones);
  const dynamics::RigidBody body(params.J);
  const Mat3 R_d = lie::exp(2.0 * sixty * Vec3::UnitZ());
  Mat3 R_ib = Mat3::Identity();
  Vec3 omega_b = Vec3::Zero();
  const double dt = 0.01;
  g_allocations = 0;
  int started = 0;
  int held = 0;
  for (int k = 0; k < kCalls; ++k) {
    const governor::GovernorOutput out = counted([&] { return gov.step(k * dt, R_ib, omega_b, R_d); });
    started += out.tie_break_started ? 1 : 0;
    held += out.tie_break.active ? 1 : 0;
    propagate_attitude(body, out.tau_b, dt, R_ib, omega_b);
  }
  EXPECT_EQ(g_allocations.load(), 0) << "heap allocations in " << kCalls
                                     << " calls of AttitudeGovernor::step through a saddle tie-break";
  EXPECT_EQ(started, 1);
  EXPECT_GT(held, 0);
  EXPECT_FALSE(gov.tie_break().active);       // released
  EXPECT_LT(lie::distance(R_ib, R_d), 1e-2);  // around the Sun to R_d
}

// The pet_erg flight loop's on-board pieces besides the governor (docs/pet-erg.md, sections
// 11-12): sensor model, quantiser, wheel allocation, disturbance; a 10 Hz loop of 4 wheels.
static_assert(noexcept(std::declval<const dynamics::AttitudeSensor&>().measure(
    std::declval<const Mat3&>(), std::declval<const Vec3&>(), 0)));
static_assert(noexcept(control::quantize_torque(std::declval<const Vec3&>(), 0.0)));
static_assert(noexcept(std::declval<const dynamics::ReactionWheelArray&>().allocate(
    std::declval<const Vec3&>())));
static_assert(noexcept(std::declval<const dynamics::DisturbanceTorque&>().at(0.0)));

TEST(AllocationFree, WheelFlightLoopWithImperfections) {
  governor::GovernorParams params;
  params.J = Vec3(1.0, 2.0, 3.0).asDiagonal();
  params.tau_max = 2.5;
  params.bounded_step = true;
  params.polytope_gamma_d = 0.36;
  const std::array cones{governor::keep_in_cone(Vec3::UnitZ(), Vec3(-0.791, 0.061, -0.609),
                                                160.0 * std::numbers::pi / 180.0)};
  governor::AttitudeGovernor gov(params, cones);
  const auto wheels = dynamics::pyramid_wheels(35.26 * std::numbers::pi / 180.0, 1.5, 2.0);
  const dynamics::ReactionWheelArray array(wheels);
  dynamics::AttitudeSensor sensor;
  sensor.attitude_bias_b = Vec3(0.001, -0.002, 0.001);
  sensor.attitude_noise = 0.001;
  sensor.rate_noise = 0.001;
  dynamics::DisturbanceTorque disturbance;
  disturbance.kind = dynamics::DisturbanceKind::random;
  disturbance.bound = 0.02;
  disturbance.hold = 0.1;
  const dynamics::RigidBody body(params.J);
  const Mat3 R_d = lie::rotation_from_axis_angle({Vec3::UnitY(), std::numbers::pi / 2.0});
  Mat3 R_ib = Mat3::Identity();
  Vec3 omega_b(0.2, 0.3, 0.4);
  const double dt = 0.1;
  g_allocations = 0;
  for (int k = 0; k < 600; ++k) {
    const Vec3 tau = counted([&] {
      const dynamics::Measurement m = sensor.measure(R_ib, omega_b, static_cast<std::uint64_t>(k));
      const governor::GovernorOutput& out = gov.step(k * dt, m.R_ib, m.omega_b, R_d);
      const dynamics::WheelVector u = array.allocate(control::quantize_torque(out.tau_b, 0.01));
      return Vec3(array.body_torque(u) + disturbance.at(k * dt));
    });
    propagate_attitude(body, tau, dt, R_ib, omega_b);
  }
  EXPECT_EQ(g_allocations.load(), 0) << "heap allocations in the wheel flight loop";
  EXPECT_LT(lie::distance(R_ib, R_d), 0.05);  // the loop really flew the manoeuvre
}

// The adversarial disturbance (docs/pet-erg.md, section 11), header-only on the flight layers:
// evaluated like the flight loop's vector field, at every sub-step of the plant, next to the
// governor's step.
static_assert(noexcept(sim::adversarial_torque(std::declval<const sim::AdversaryModel&>(),
                                               std::declval<const Mat3&>(),
                                               std::declval<const Vec3&>(),
                                               std::declval<const Mat3&>())));

TEST(AllocationFree, AdversarialDisturbanceInAFlightLoop) {
  governor::GovernorParams params;
  params.J = Vec3(1.0, 2.0, 3.0).asDiagonal();
  params.tau_max = 2.5;
  params.bounded_step = true;
  const std::array cones{governor::keep_in_cone(Vec3::UnitZ(), Vec3(-0.791, 0.061, -0.609),
                                                160.0 * std::numbers::pi / 180.0)};
  governor::AttitudeGovernor gov(params, cones);
  const sim::AdversaryModel adversary = sim::make_adversary(params.J, cones, 0.05, 0.5);
  const dynamics::RigidBody body(params.J);
  const Mat3 R_d = lie::rotation_from_axis_angle({Vec3::UnitY(), std::numbers::pi / 2.0});
  Mat3 R_ib = Mat3::Identity();
  Vec3 omega_b(0.2, 0.3, 0.4);
  const double dt = 0.1;
  constexpr int substeps = 10;
  const double h = dt / substeps;
  double largest = 0.0;
  g_allocations = 0;
  for (int k = 0; k < 600; ++k) {
    const Vec3 tau = counted([&] { return Vec3(gov.step(k * dt, R_ib, omega_b, R_d).tau_b); });
    for (int s = 0; s < substeps; ++s) {
      const Vec3 d = counted(
          [&] { return sim::adversarial_torque(adversary, R_ib, omega_b, gov.reference()); });
      largest = std::max(largest, d.norm());
      omega_b += h * body.angular_acceleration(omega_b, tau + d);
      R_ib = R_ib * lie::exp(h * omega_b);
    }
  }
  EXPECT_EQ(g_allocations.load(), 0) << "heap allocations with the adversarial disturbance";
  EXPECT_NEAR(largest, 0.05, 1e-12);  // the adversary really acted, at its bound
}

// One control instant of the pet_erg flight loop with robust margins and 4 wheels
// (sim/pet_erg_run.cpp, simulate_flight_loop's `control`; docs/pet-erg.md, sections 11-13):
// sensor draw, R_d(t), governor step, quantisation, allocation. Declared noexcept throughout.
static_assert(noexcept(std::declval<const dynamics::ReactionWheelArray&>().allocate(control::quantize_torque(
    std::declval<governor::AttitudeGovernor&>()
        .step(0.0, std::declval<const dynamics::AttitudeSensor&>().measure(
                       std::declval<const Mat3&>(), std::declval<const Vec3&>(), 0).R_ib,
              std::declval<const Vec3&>(), std::declval<const governor::ReferenceSchedule&>().at(0.0))
        .tau_b,
    0.0))));

TEST(AllocationFree, RobustWheelFlightLoopOfTheRobustCampaignExample) {
  // examples/pet_erg_robust_campaign.toml without its [dispersions] (robust margins, 4-wheel
  // pyramid, 10 Hz loop, sensor bias and noise, quantisation, adversarial disturbance) and its
  // nominal twin. The true states of every control instant come from the scenario's own flight
  // loop (simulate_pet_erg, one row per control period, rows after the control instant); the
  // counted calls replay that loop's control instants and must move R_g exactly as it did.
  for (const char* name : {"pet_erg_robust_campaign.toml", "pet_erg_robust_campaign_nominal.toml"}) {
    const scenario::Document doc =
        scenario::load_document(std::string(ATTIGUARD_SOURCE_DIR) + "/examples/" + name);
    sim::PetErgScenario sc = scenario::parse_pet_erg(scenario::nominal_document(doc));
    const bool robust = std::string(name) == "pet_erg_robust_campaign.toml";
    ASSERT_EQ(sc.margins == governor::Margins::robust, robust) << name;
    ASSERT_EQ(sc.wheels.size(), 4U) << name;
    ASSERT_GT(sc.control_period, 0.0) << name;
    sc.output_interval = sc.control_period;
    struct Row {
      double t;
      Mat3 R_ib;
      Vec3 omega_b;
      Mat3 R_g;
    };
    std::vector<Row> rows;
    (void)sim::simulate_pet_erg(sc, [&](double t, const sim::PetErgState& y, const Mat3&,
                                        const governor::GovernorOutput&) {
      rows.push_back({t, y.R[0], y.x, y.R[1]});
    });
    ASSERT_GT(rows.size(), 10000U) << name;

    const governor::GovernorDesign design = sim::design_governor(sc);
    governor::AttitudeGovernor gov(design.params, design.cones);
    const dynamics::ReactionWheelArray array(sc.wheels);
    const dynamics::AttitudeSensor& sensor = sc.imperfections.sensor;
    const double quantum = sc.imperfections.torque_quantum;
    gov.reset(0.0, sc.R_g0);
    g_allocations = 0;
    double largest_departure = 0.0;
    double largest_wheel_torque = 0.0;
    for (std::size_t k = 0; k < rows.size(); ++k) {
      const Row& row = rows[k];
      const dynamics::WheelVector u = counted([&] {
        const dynamics::Measurement m = sensor.measure(row.R_ib, row.omega_b, static_cast<std::uint64_t>(k));
        const governor::GovernorOutput& out = gov.step(row.t, m.R_ib, m.omega_b, sc.desired.at(row.t));
        return array.allocate(control::quantize_torque(out.tau_b, quantum));
      });
      largest_departure = std::max(largest_departure, lie::distance(gov.reference(), row.R_g));
      for (int i = 0; i < array.count(); ++i) {
        largest_wheel_torque = std::max(largest_wheel_torque, std::abs(u[static_cast<std::size_t>(i)]));
      }
    }
    EXPECT_EQ(g_allocations.load(), 0) << "heap allocations in " << rows.size()
                                       << " control instants of " << name;
    // The counted calls are the flight loop's: the same reference at every instant ...
    EXPECT_LT(largest_departure, 1e-9) << name;
    // ... which really moved R_g (the robust run to the end of the 120° slew; the nominal run
    // stops short of it), with torque on the wheels.
    EXPECT_GT(lie::distance(gov.reference(), sc.R_g0), 0.5) << name;
    if (robust) {
      EXPECT_LT(lie::distance(gov.reference(), sc.desired.at(sc.duration)), 1e-2) << name;
    }
    EXPECT_GT(largest_wheel_torque, 1e-3) << name;
  }
}

TEST(AllocationFree, QuaternionPidStepTrackingATurn) {
  const control::QuaternionPidGains gains{20.0, 2.0, 20.0, 0.05};
  control::QuaternionPid pid(gains);
  const dynamics::RigidBody body(Vec3(100.0, 120.0, 80.0).asDiagonal());
  Mat3 R_ib = Mat3::Identity();
  Vec3 omega_b = Vec3::Zero();
  const double dt = 0.01;
  g_allocations = 0;
  for (int k = 0; k < kCalls; ++k) {
    // A desired attitude turning slowly about a tilted axis, with its feed-forward rate.
    const Vec3 omega_d_d = 0.02 * Vec3(1.0, 1.0, 0.5).normalized();
    const Quat q_id = lie::quat_from_rotation_vector((k * dt) * omega_d_d);
    const Quat q_ib = lie::rotation_to_quat(R_ib);
    const control::QuaternionPidOutput out =
        counted([&] { return pid.step(q_ib, omega_b, q_id, omega_d_d, dt); });
    propagate_attitude(body, out.tau_b, dt, R_ib, omega_b);
  }
  EXPECT_EQ(g_allocations.load(), 0) << "heap allocations in " << kCalls
                                     << " calls of QuaternionPid::step";
}

/// A 120 deg slew with a 25 deg keep-out cone on body +z centred on its path.
plan::SlewProblem slew_around_a_cone() {
  plan::SlewProblem p;
  p.J_b = Vec3(2.4, 3.1, 3.9).asDiagonal();
  p.tau_max = 1.0;
  p.torque_headroom = 0.1;
  p.cone_margin = 4.0 * std::numbers::pi / 180.0;
  p.R_target = lie::exp(Vec3(0.0, 1.0, 0.0) * (120.0 * std::numbers::pi / 180.0));
  const Vec3 sun = lie::exp(Vec3(0.0, 1.0, 0.0) * (60.0 * std::numbers::pi / 180.0)) * Vec3::UnitZ();
  p.cones.push_back(governor::keep_out_cone(Vec3::UnitZ(), sun, 25.0 * std::numbers::pi / 180.0));
  return p;
}

// The planned slew's flight-loop parts (docs/pet-erg.md, section 16): the progress governor's
// rate at each sampling instant and the tracking law at each control step, flying a plan of a
// 120 deg slew around a keep-out cone with the plan's clock governed. Set-up (the plan, the
// governor's tables) is outside the counted window.
TEST(AllocationFree, TrackingLawAndProgressGovernorFlyingAPlan) {
  const plan::SlewProblem p = slew_around_a_cone();
  const plan::PlannedSlew planned = plan::plan_slew(p);
  const control::TrackingGains gains{0.5, 1.5};
  const double dt = 0.01;
  const int per_sample = 10;
  const governor::ProgressGovernor progress(planned.plan, p.cones, p.tau_max, gains, per_sample * dt, 0.05);
  const dynamics::RigidBody body(p.J_b);
  Mat3 R_ib = Mat3::Identity();
  Vec3 omega_b = Vec3::Zero();
  double sigma = 0.0, rate = 0.0;
  g_allocations = 0;
  for (int k = 0; k < kCalls; ++k) {
    if (k % per_sample == 0) rate = counted([&] { return progress.choose_rate(sigma, R_ib, omega_b); });
    const Vec3 tau_b = counted([&] {
      return control::tracking_torque(p.J_b, R_ib, omega_b, progress.reference(sigma, rate), gains);
    });
    propagate_attitude(body, tau_b, dt, R_ib, omega_b);
    sigma = std::min(planned.plan.duration(), sigma + rate * dt);
  }
  EXPECT_EQ(g_allocations.load(), 0) << "heap allocations in " << kCalls
                                     << " steps of the tracking law and the progress governor";
  EXPECT_GT(sigma, 0.0);  // the clock moved
}

// The planned mode's flight-loop object (docs/pet-erg.md, section 16.2): PlannedGovernor::step
// at 10 Hz with one period of delay (the prediction, the choice of ṡ at every step, the tracking
// law with the hold's feedforward, the saturation), flying the same plan as above from a start
// off the plan by 2 deg. Set-up outside the
// counted window; also throw-free (noexcept).
TEST(AllocationFree, PlannedGovernorStepFlyingAPlanWithDelay) {
  const plan::SlewProblem p = slew_around_a_cone();
  const plan::PlannedSlew planned = plan::plan_slew(p);
  const double h = 0.1;
  governor::PlannedGovernor gov(planned.plan, p.cones,
                                governor::PlannedGovernorParams{{2.0, 4.0}, p.tau_max, h, 0.05, h, 1, std::nullopt});
  const dynamics::RigidBody body(p.J_b);
  Mat3 R_ib = lie::exp(Vec3(2.0 * std::numbers::pi / 180.0, 0.0, 0.0));
  Vec3 omega_b = Vec3::Zero();
  static_assert(noexcept(gov.step(0.0, R_ib, omega_b)));
  Vec3 acting_b = Vec3::Zero();
  gov.reset(0.0);
  g_allocations = 0;
  double sigma = 0.0;
  for (int k = 0; k < kCalls; ++k) {
    const governor::PlannedOutput out = counted([&] { return gov.step(k * h, R_ib, omega_b); });
    propagate_attitude(body, acting_b, h, R_ib, omega_b);  // one period of delay
    acting_b = out.tau_b;
    sigma = out.sigma;
  }
  EXPECT_EQ(g_allocations.load(), 0) << "heap allocations in " << kCalls << " PlannedGovernor steps";
  EXPECT_GT(sigma, 0.0);  // the clock moved
}

// docs/mission.md, "Planned slews": a planned mission's attitude loop allocates only at a slew's
// start (planning is set-up code); the steps that fly the plan and those that track R_d between
// slews reach no heap.
TEST(AllocationFree, PlannedMissionStepsAfterTheSlewStart) {
  const sim::MissionScenario sc = scenario::parse_mission(scenario::load_document(
      std::string(ATTIGUARD_SOURCE_DIR) + "/examples/mission_sun_constrained_planned.toml"));
  sim::MissionSlews slews(sc);
  const dynamics::RigidBody body(sc.waypoint.J);
  const double h = sc.waypoint.control_period;
  dynamics::SpacecraftState y;
  y.R[0] = sc.waypoint.R0_ib;
  y.x.setZero();
  guidance::MissionCommand cmd;
  cmd.q_id = lie::rotation_to_quat(sc.waypoint.R0_ib * lie::exp(Vec3(0.0, 0.0, 0.5 * std::numbers::pi)));
  (void)slews.step(0.0, y, cmd);  // the slew's start: planned here
  ASSERT_EQ(slews.state().slew, 0);
  Mat3 R_ib = y.R[0];
  Vec3 omega_b = Vec3::Zero();
  g_allocations = 0;
  for (int k = 1; k < kCalls / 10; ++k) {
    const Vec3 tau_b = counted([&] { return slews.step(k * h, y, cmd).tau_b; });
    propagate_attitude(body, tau_b, h, R_ib, omega_b);
    y.R[0] = R_ib;
    y.x.segment<3>(0) = omega_b;
  }
  EXPECT_EQ(g_allocations.load(), 0) << "heap allocations in " << kCalls / 10 << " planned mission steps";
  EXPECT_EQ(slews.state().slew, -1);  // the plan was flown, then R_d tracked
}

// Issue 49, item 7: a worker thread whose state cannot be allocated (std::bad_alloc inside
// std::thread's constructor, as under `ulimit -v`) is the same ThreadStartError as a thread the
// system refuses — threads already made are released without work and joined — never a
// std::bad_alloc escaping as exit 3. The third allocation of run_workers (after the pool and the
// first thread's state) fails here.
TEST(AllocationFailure, AWorkerThreadThatCannotBeAllocatedIsAThreadStartError) {
  std::atomic<int> bodies{0};
  g_fail_countdown = 3;
  try {
    parallel::run_workers(4, [&](long) { ++bodies; });
    g_fail_countdown = 0;
    FAIL() << "no ThreadStartError";
  } catch (const parallel::ThreadStartError& e) {
    g_fail_countdown = 0;
    EXPECT_EQ(e.started(), 1);
    EXPECT_EQ(e.wanted(), 4);
    EXPECT_NE(std::string(e.what()).find("out of memory"), std::string::npos) << e.what();
  } catch (const std::bad_alloc&) {
    g_fail_countdown = 0;
    FAIL() << "std::bad_alloc escaped run_workers";
  }
  EXPECT_EQ(bodies.load(), 0);  // released without work
}

/// Plant (2)-(5) of the waypoint paper over one control period dt, Lie-Euler in 10 substeps,
/// the commands held (outside the counted window).
void fly(const dynamics::SpacecraftPlant& plant, const guidance::MissionCommand& cmd,
         guidance::MissionInputs& in) {
  constexpr int substeps = 10;
  const double h = in.dt / substeps;
  for (int s = 0; s < substeps; ++s) {
    const Vec3 a_i = plant.acceleration_i(in.R_ib, cmd.inputs);
    in.omega_b += h * plant.body().angular_acceleration(in.omega_b, plant.applied_torque(cmd.inputs.tau_b));
    in.R_ib = in.R_ib * lie::exp(h * in.omega_b);
    in.p_i += h * in.v_i;
    in.v_i += h * a_i;
  }
}

TEST(AllocationFree, MissionStepOverTwoWaypoints) {
  // Table I of the waypoint paper with the improved choices of examples/waypoint_fine.toml.
  guidance::MissionParams p;
  p.mass = 100.0;
  p.T_max = 20.0;
  p.f_max = 0.5;
  p.pointing_tolerance = 1e-5;
  p.pointing_thrust_axis = true;
  p.arrival_radius = 0.005;
  p.position_accuracy = 0.2;
  p.speed_accuracy = 0.005;
  p.braking_margin = 0.95;
  p.flip_timing = guidance::FlipTiming::braking_point;
  p.flip_lead_time = 60.0;
  p.rct = {0.02, 0.5};
  p.brake_speed = guidance::default_brake_speed(p);
  const control::QuaternionPidGains gains{20.0, 2.0, 20.0, 0.05};
  const std::array waypoints_i{Vec3(200.0, 0.0, 0.0), Vec3(200.0, 200.0, 0.0)};
  guidance::WaypointSequencer mission(p, gains, waypoints_i);
  const dynamics::SpacecraftPlant plant(p.mass, 20.0 * Mat3::Identity());

  guidance::MissionInputs in;
  in.dt = 0.1;
  std::set<guidance::Mode> modes;
  g_allocations = 0;
  for (int k = 0; k < kCalls; ++k) {
    const guidance::MissionCommand cmd = counted([&] { return mission.step(in); });
    modes.insert(cmd.mode);
    fly(plant, cmd, in);
  }
  EXPECT_EQ(g_allocations.load(), 0) << "heap allocations in " << kCalls
                                     << " calls of WaypointSequencer::step";
  std::string visited;
  for (const guidance::Mode m : modes) {
    visited += std::string(" ") + guidance::mode_name(m);
  }
  // The loop went through the guided modes and finished both waypoints.
  EXPECT_GE(modes.size(), 7U) << "modes visited:" << visited;
  EXPECT_TRUE(modes.count(guidance::Mode::fine) == 1 && mission.done()) << "modes visited:" << visited;
  std::printf("Mission modes visited:%s\n", visited.c_str());
}

TEST(AllocationFree, MissionStepBrakingALateralAndRecedingStartWithShapedGains) {
  // The paths beyond the paper's geometry: a start moving away from the first waypoint and across
  // its line of sight (lateral-speed brake, closest approach, re-plan), with the shaped PID of profile
  // "craft" (S = J/J_max, ω × Jω) on unequal principal moments.
  guidance::MissionParams p;
  p.mass = 100.0;
  p.T_max = 20.0;
  p.f_max = 0.5;
  p.pointing_tolerance = 1e-3;
  p.cruise_speed = 2.0;  // the 5 m/s lateral start is above max(brake_speed, V_d/4)
  p.pointing_thrust_axis = true;
  p.arrival_radius = 0.005;
  p.position_accuracy = 0.2;
  p.speed_accuracy = 0.005;
  p.braking_margin = 0.95;
  p.flip_timing = guidance::FlipTiming::braking_point;
  p.flip_lead_time = 60.0;
  p.rct = {0.02, 0.5};
  p.brake_speed = guidance::default_brake_speed(p);
  const Mat3 J = Vec3(5.0, 20.0, 24.0).asDiagonal();
  control::QuaternionPidGains gains{2.0 * 0.09 * 24.0, 0.0, 4.0 * 0.3 * 24.0, 0.0};
  gains.shaped = true;
  gains.shaping = J / 24.0;
  gains.shaping_scale = 24.0;
  const std::array waypoints_i{Vec3(200.0, 0.0, 0.0), Vec3(200.0, 200.0, 0.0)};
  guidance::WaypointSequencer mission(p, gains, waypoints_i);
  const dynamics::SpacecraftPlant plant(p.mass, J);

  guidance::MissionInputs in;
  in.dt = 0.1;
  in.v_i = Vec3(-2.0, 5.0, 0.0);  // receding from the first waypoint and 5 m/s across its line
  std::set<guidance::Mode> modes;
  std::set<guidance::TransitionReason> reasons;
  g_allocations = 0;
  for (int k = 0; k < kCalls; ++k) {
    const guidance::MissionCommand cmd = counted([&] { return mission.step(in); });
    modes.insert(cmd.mode);
    if (cmd.transition) reasons.insert(cmd.reason);
    fly(plant, cmd, in);
  }
  EXPECT_EQ(g_allocations.load(), 0) << "heap allocations in " << kCalls
                                     << " calls of WaypointSequencer::step";
  std::string visited;
  for (const guidance::TransitionReason r : reasons) visited += std::string(" ") + guidance::reason_name(r);
  EXPECT_EQ(modes.count(guidance::Mode::brake), 1U) << "reasons:" << visited;
  EXPECT_EQ(reasons.count(guidance::TransitionReason::lateral_speed), 1U) << "reasons:" << visited;
  EXPECT_EQ(reasons.count(guidance::TransitionReason::replan), 1U) << "reasons:" << visited;
  std::printf("Mission transition reasons:%s\n", visited.c_str());
}

TEST(AllocationFree, MissionStepFlyingRctOnlyLegsInTheRctTransfer) {
  // Two legs inside half the re-plan distance: the RCT fly them in mode rct_transfer and fine
  // control takes over near each waypoint (docs/waypoint.md, "The RCT-only legs").
  guidance::MissionParams p;
  p.mass = 100.0;
  p.T_max = 20.0;
  p.f_max = 0.5;
  p.cruise_speed = 2.0;
  p.arrival_radius = 0.01;
  p.position_accuracy = 0.2;
  p.speed_accuracy = 0.005;
  p.replan_distance = 100.0;
  p.rct = {0.02, 0.5};
  p.rct.braking_acceleration = 0.5 * p.f_max / p.mass;
  p.brake_speed = guidance::default_brake_speed(p);
  p.rct_transfer = true;
  const control::QuaternionPidGains gains{20.0, 2.0, 20.0, 0.05};
  const std::array waypoints_i{Vec3(20.0, 10.0, 0.0), Vec3(20.0, -20.0, 5.0)};
  guidance::WaypointSequencer mission(p, gains, waypoints_i);
  const dynamics::SpacecraftPlant plant(p.mass, 20.0 * Mat3::Identity());

  guidance::MissionInputs in;
  in.dt = 0.1;
  std::set<guidance::Mode> modes;
  g_allocations = 0;
  for (int k = 0; k < kCalls && !mission.done(); ++k) {
    const guidance::MissionCommand cmd = counted([&] { return mission.step(in); });
    modes.insert(cmd.mode);
    fly(plant, cmd, in);
  }
  EXPECT_EQ(g_allocations.load(), 0) << "heap allocations in WaypointSequencer::step (rct_transfer)";
  EXPECT_EQ(modes.count(guidance::Mode::rct_transfer), 1U);
  EXPECT_EQ(modes.count(guidance::Mode::align), 0U);
  EXPECT_TRUE(mission.done());
}

}  // namespace
}  // namespace attiguard
