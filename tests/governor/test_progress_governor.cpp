// The governed progress's thresholds and rate (governor/progress_governor.hpp; docs/pet-erg.md,
// section 16.1): Γ_d is the edge of the torque bound; every state of the level set
// {V ≤ min(Γ_g, Γ_d(ṡ))} against any reference of the period's window keeps every cone and
// ‖τ‖ ≤ τ_max under the tracking law (sampled, on a CubeSat and a station); the rate is 1 on
// the plan and 0 far from it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include <Eigen/Eigenvalues>

#include "attiguard/governor/cone_constraint.hpp"
#include "attiguard/governor/progress_governor.hpp"
#include "attiguard/lie/so3.hpp"
#include "attiguard/plan/slew_planner.hpp"

namespace attiguard::governor::progress_governor_test {
namespace {

using lie::Mat3;
using lie::Vec3;

constexpr double kDeg = std::numbers::pi / 180.0;

struct Craft {
  const char* name;
  plan::SlewProblem problem;
  plan::PlannedSlew planned;
  control::TrackingGains gains;
};

/// A slew of 120 deg with a keep-out cone of 25 deg on body +z centred on the eigenaxis path,
/// planned with a 4 deg cone margin and 10 % torque headroom. Stiff gains (a bandwidth 5× the
/// slew's, damping 0.8 or 0.05: the torque threshold binds, on the rate error or on the attitude
/// error) or soft ones (k_R = τ_max / 2: the cone threshold binds).
enum class Gains { stiff, stiff_light_damping, soft };
Craft make_craft(const char* name, double scale, double tau_max, Gains gains) {
  Craft c{name, {}, {}, {}};
  Mat3 J;
  J << 2.4, 0.12, -0.08,  //
      0.12, 3.1, 0.05,    //
      -0.08, 0.05, 3.9;
  c.problem.J_b = scale * J;
  c.problem.tau_max = tau_max;
  c.problem.torque_headroom = 0.1;
  c.problem.cone_margin = 4.0 * kDeg;
  c.problem.R_target = lie::exp(Vec3(0.0, 1.0, 0.0) * 120.0 * kDeg);
  const Vec3 sun = lie::exp(Vec3(0.0, 1.0, 0.0) * 60.0 * kDeg) * Vec3::UnitZ();
  c.problem.cones.push_back(keep_out_cone(Vec3::UnitZ(), sun, 25.0 * kDeg));
  c.planned = plan::plan_slew(c.problem);
  const double omega_n = 10.0 * std::numbers::pi / c.planned.plan.duration();
  const double J_max = Eigen::SelfAdjointEigenSolver<Mat3>(c.problem.J_b).eigenvalues().maxCoeff();
  c.gains = control::TrackingGains{J_max * omega_n * omega_n, 2.0 * 0.8 * J_max * omega_n};
  if (gains == Gains::stiff_light_damping) c.gains.k_Omega = 2.0 * 0.05 * J_max * omega_n;
  if (gains == Gains::soft) {
    const double k_R = 0.5 * tau_max;
    c.gains = control::TrackingGains{k_R, 2.0 * 0.7 * std::sqrt(k_R * J_max)};
  }
  return c;
}

std::vector<Craft> crafts() {
  return {make_craft("CubeSat, stiff gains", 0.0175, 1e-3, Gains::stiff),
          make_craft("CubeSat, stiff gains, light damping", 0.0175, 1e-3, Gains::stiff_light_damping),
          make_craft("CubeSat, soft gains", 0.0175, 1e-3, Gains::soft),
          make_craft("station, stiff gains", 1.5e6, 50.0, Gains::stiff),
          make_craft("station, soft gains", 1.5e6, 50.0, Gains::soft)};
}

ProgressGovernor governor_of(const Craft& c, double sample_period) {
  return ProgressGovernor(c.planned.plan, c.problem.cones, c.problem.tau_max, c.gains,
                          sample_period, 0.05);
}

TEST(ProgressGovernor, TheTorqueThresholdIsTheEdgeOfTheBoundAndFallsWithTheRate) {
  for (const Craft& c : crafts()) {
    const ProgressGovernor g = governor_of(c, 0.01 * c.planned.plan.duration());
    const PlanWindow w = g.window(0.3 * c.planned.plan.duration(), 0.35 * c.planned.plan.duration());
    double previous = std::numeric_limits<double>::infinity();
    for (const double rate : {0.0, 0.25, 0.5, 0.75, 1.0}) {
      const double gamma = g.torque_threshold(rate, w);
      ASSERT_GT(gamma, 0.0) << c.name << " rate " << rate;  // the plan leaves 10 % headroom
      EXPECT_NEAR(g.torque_bound(gamma, rate, w), c.problem.tau_max, 1e-9 * c.problem.tau_max)
          << c.name << " rate " << rate;
      EXPECT_LT(gamma, previous) << c.name << " rate " << rate;
      previous = gamma;
    }
  }
}

// The guarantee, sampled: states of the level set V = f Γ (f up to 1, split at random between
// the attitude and the rate error, random directions), against references anywhere in the
// period's window at the rate ṡ: the law's torque is within τ_max and the body keeps the cone.
TEST(ProgressGovernor, EveryStateOfTheLevelSetKeepsTheConeAndTheTorqueBound) {
  std::mt19937_64 rng(20261206);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  std::normal_distribution<double> n01(0.0, 1.0);
  for (const Craft& c : crafts()) {
    const double T = c.planned.plan.duration();
    const double Ts = 0.02 * T;
    const ProgressGovernor g = governor_of(c, Ts);
    int checked = 0;
    for (int trial = 0; trial < 4000; ++trial) {
      const double sigma = u01(rng) * T;
      const double rate = u01(rng);
      const PlanWindow w = g.window(sigma, sigma + rate * Ts);
      const double gamma = std::min(g.cone_threshold(w), g.torque_threshold(rate, w));
      if (!(gamma > 0.0)) continue;
      const control::TrackingReference ref = g.reference(sigma + u01(rng) * rate * Ts, rate);
      const double level = std::sqrt(u01(rng)) * gamma;  // more samples near the edge
      const double f = u01(rng);
      const double theta = std::acos(std::max(-1.0, 1.0 - f * level / c.gains.k_R));
      const Vec3 axis = Vec3(n01(rng), n01(rng), n01(rng)).normalized();
      const Mat3 R = ref.R_ib * lie::exp(theta * axis);
      const Vec3 d = Vec3(n01(rng), n01(rng), n01(rng)).normalized();
      const Vec3 e_Omega = d * std::sqrt(2.0 * (1.0 - f) * level / d.dot(c.problem.J_b * d));
      const Vec3 w_b = e_Omega + R.transpose() * ref.R_ib * ref.omega_b;
      ASSERT_LE(control::tracking_lyapunov(c.problem.J_b, R, w_b, ref, c.gains), gamma * (1.0 + 1e-9));
      const Vec3 tau = control::tracking_torque(c.problem.J_b, R, w_b, ref, c.gains);
      ASSERT_LE(tau.norm(), c.problem.tau_max * (1.0 + 1e-12)) << c.name << " trial " << trial;
      const ConeConstraint& cone = c.problem.cones.front();
      ASSERT_GE(cone.direction_i.dot(R * cone.axis_b), cone.cos_theta_c - 1e-12)
          << c.name << " trial " << trial;
      ++checked;
    }
    EXPECT_GT(checked, 2000) << c.name;
  }
}

// The feedforward's error at no attitude error (R = R_d): the law's gyroscopic and transport
// terms beyond the reference's, B(e, v) + e × J e, against the bound ½(λ_max − λ_min)E² +
// (2λ_max − λ_min) E ṡ‖ω_p‖ (docs/pet-erg.md, section 16.1, "Torque"). Sampled over the
// crafts' inertias: never above it, and within 45 % of it at the worst sample (the former bound
// 3λ_max E ṡ‖ω_p‖ + λ_max E², twice as loose, fails the second check).
TEST(ProgressGovernor, TheFeedforwardErrorBoundsTheGyroscopicTermsTightly) {
  std::mt19937_64 rng(20261207);
  std::normal_distribution<double> n01(0.0, 1.0);
  for (const Craft& c : crafts()) {
    const ProgressGovernor g = governor_of(c, 0.1);
    const Mat3& J = c.problem.J_b;
    double worst = 0.0;
    for (int trial = 0; trial < 20000; ++trial) {
      const Vec3 v = Vec3(n01(rng), n01(rng), n01(rng)) * 0.05;
      const Vec3 e = Vec3(n01(rng), n01(rng), n01(rng)) * 0.05 * std::exp(n01(rng));
      const control::TrackingReference ref{Mat3::Identity(), v, Vec3::Zero()};
      const Vec3 law = control::tracking_torque(J, Mat3::Identity(), v + e, ref, {0.0, 0.0});
      const Vec3 error = law - v.cross(J * v);
      const PlanWindow w{v.norm(), 0.0, 0.0, 0.0};
      const double bound = g.feedforward_error(0.0, e.norm(), 1.0, w);
      ASSERT_LE(error.norm(), bound * (1.0 + 1e-12)) << c.name << " trial " << trial;
      worst = std::max(worst, error.norm() / bound);
    }
    EXPECT_GT(worst, 0.55) << c.name;
  }
}

/// The body at attitude error θ about `axis` and rate error e_Ω from the reference.
struct Offset {
  Mat3 R;
  Vec3 w_b;
};
Offset offset(const control::TrackingReference& ref, double theta, const Vec3& axis,
              const Vec3& e_Omega) {
  const Mat3 R = ref.R_ib * lie::exp(theta * axis);
  return Offset{R, e_Omega + R.transpose() * ref.R_ib * ref.omega_b};
}

// The guarantee at its edges: states built to be the worst of the level set {V = Γ} — the
// attitude error turning the cone's body axis straight at the cone's boundary, and attitude
// and rate errors aligned with the feedforward torque (every split of V between them) — over
// references across the period's window. A cone threshold at 1.5× the margin, or a torque
// bound missing 30 % of its attitude or its rate term, fails here.
TEST(ProgressGovernor, TheWorstStatesOfTheLevelSetKeepTheConeAndTheTorqueBound) {
  for (const Craft& c : crafts()) {
    const double T = c.planned.plan.duration();
    const double Ts = 0.02 * T;
    const ProgressGovernor g = governor_of(c, Ts);
    const ConeConstraint& cone = c.problem.cones.front();
    double closest_cone = std::numeric_limits<double>::infinity();
    double largest_torque = 0.0;
    for (int i = 0; i < 400; ++i) {
      const double sigma = T * i / 400.0;
      for (const double rate : {0.25, 0.5, 1.0}) {
        const PlanWindow w = g.window(sigma, sigma + rate * Ts);
        const double gamma_g = g.cone_threshold(w);
        const double gamma = std::min(gamma_g, g.torque_threshold(rate, w));
        if (!(gamma > 0.0)) continue;
        for (int j = 0; j <= 8; ++j) {
          const control::TrackingReference ref = g.reference(sigma + rate * Ts * j / 8.0, rate);
          // Cone: all of V in the attitude error, the body axis turned away from a_c.
          const double theta = std::acos(std::max(-1.0, 1.0 - gamma / c.gains.k_R));
          const Vec3 away_b = ref.R_ib.transpose() * (-cone.direction_i);
          const Vec3 axis = cone.axis_b.cross(away_b);
          if (axis.norm() > 1e-9) {
            const Offset o = offset(ref, theta, axis.normalized(), Vec3::Zero());
            const double m = cone.direction_i.dot(o.R * cone.axis_b) - cone.cos_theta_c;
            closest_cone = std::min(closest_cone, m);
            ASSERT_GE(m, -1e-12) << c.name << " sigma " << sigma << " rate " << rate;
          }
          // Torque: errors aligned with the feedforward, each split of V.
          const Vec3 ff = control::tracking_torque(c.problem.J_b, ref.R_ib, ref.omega_b, ref, c.gains);
          const Vec3 dir = ff.norm() > 0.0 ? Vec3(ff.normalized()) : Vec3::UnitX();
          for (int split = 0; split <= 32; ++split) {
            const double f = split / 32.0;
            const double th = std::acos(std::max(-1.0, 1.0 - f * gamma / c.gains.k_R));
            const Vec3 e = -dir * std::sqrt(2.0 * (1.0 - f) * gamma / dir.dot(c.problem.J_b * dir));
            const Offset o = offset(ref, th, -dir, e);
            const Vec3 tau = control::tracking_torque(c.problem.J_b, o.R, o.w_b, ref, c.gains);
            largest_torque = std::max(largest_torque, tau.norm() / c.problem.tau_max);
            ASSERT_LE(tau.norm(), c.problem.tau_max * (1.0 + 1e-12))
                << c.name << " sigma " << sigma << " rate " << rate << " f " << f;
          }
        }
      }
    }
    // The edges are reached: the worst states come close to the bound that binds.
    EXPECT_TRUE(closest_cone < 1e-3 || largest_torque > 0.97)
        << c.name << ": closest to the cone " << closest_cone << ", largest |tau|/tau_max "
        << largest_torque;
  }
}

TEST(ProgressGovernor, TheRateIsOneOnThePlanAndZeroFarFromIt) {
  for (const Craft& c : crafts()) {
    const double T = c.planned.plan.duration();
    const ProgressGovernor g = governor_of(c, 0.01 * T);
    for (const double frac : {0.1, 0.5, 0.9}) {
      const governor::SlewPlanSample s = c.planned.plan.evaluate(frac * T);
      EXPECT_EQ(g.choose_rate(frac * T, s.R_ib, s.omega_b), 1.0) << c.name << " at " << frac;
      // 30 deg off and turning away at the plan's top rate: the clock stops.
      const Mat3 R_off = s.R_ib * lie::exp(Vec3(1.0, 0.0, 0.0) * 30.0 * kDeg);
      EXPECT_EQ(g.choose_rate(frac * T, R_off, -s.omega_b), 0.0) << c.name << " at " << frac;
    }
  }
}

/// What a governed flight of the plan did (continuous loop, the rate sampled every T_s).
struct Flight {
  double largest_torque_ratio{0.0};
  double smallest_cone_margin{1.0};  ///< a_cᵀ R a_b − cos θ_c
  double converged_at{-1.0};         ///< when σ = T_p and the attitude is within 1e-3 rad
  double time_held{0.0};             ///< time with ṡ = 0
};

/// Flies the plan from R_0 = R_p(0) exp(θ_0 e_x) at rest under the tracking law, the rate chosen
/// by `g` (or forced to 1), RK4 steps of T_p/2000 with the attitude by exp (second order).
Flight fly(const Craft& c, const ProgressGovernor& g, double Ts, double theta0, bool forced) {
  const double T = c.planned.plan.duration();
  const double h = T / 2000.0;
  const int per_sample = std::max(1, static_cast<int>(std::lround(Ts / h)));
  const Mat3& J = c.problem.J_b;
  Mat3 R = lie::exp(Vec3(theta0, 0.0, 0.0));
  Vec3 w = Vec3::Zero();
  double sigma = 0.0, rate = 0.0;
  Flight out;
  const ConeConstraint& cone = c.problem.cones.front();
  for (int k = 0; k < 20000; ++k) {
    if (k % per_sample == 0) rate = forced ? 1.0 : g.choose_rate(sigma, R, w);
    const control::TrackingReference ref = g.reference(sigma, rate);
    const Vec3 tau = control::tracking_torque(J, R, w, ref, c.gains);
    out.largest_torque_ratio = std::max(out.largest_torque_ratio, tau.norm() / c.problem.tau_max);
    out.smallest_cone_margin =
        std::min(out.smallest_cone_margin, cone.direction_i.dot(R * cone.axis_b) - cone.cos_theta_c);
    if (rate == 0.0) out.time_held += h;
    // The torque held over the step (a zero-order hold at h = T_p/2000).
    const Vec3 a1 = J.ldlt().solve((J * w).cross(w) + tau);
    const Vec3 w_mid = w + 0.5 * h * a1;
    const Vec3 a2 = J.ldlt().solve((J * w_mid).cross(w_mid) + tau);
    R = R * lie::exp(h * w_mid);
    w = w + h * a2;
    sigma = std::min(T, sigma + rate * h);
    if (sigma >= T && lie::distance(R, c.problem.R_target) < 1e-3 && out.converged_at < 0.0) {
      out.converged_at = (k + 1) * h;
      break;
    }
  }
  return out;
}

// Started off the plan at rest, as far as the governor's set allows at the start (90 % of
// min{Γ_g, Γ_d(0)} in the attitude error, at most 20 deg): the governor holds the clock until
// the tracking error fits the thresholds of a moving clock, then flies the plan, keeping every
// constraint, and converges (the same ratio to the plan on the CubeSat and the station). The
// same starts with the clock forced to ṡ = 1 ask for more than τ_max on the lightly damped craft
// (the test fails if the governor is replaced by ṡ = 1).
TEST(ProgressGovernor, AGovernedFlightFromOffThePlanKeepsEveryConstraintAndConverges) {
  int forced_violations = 0;
  for (const Craft& c : crafts()) {
    const double T = c.planned.plan.duration();
    const double Ts = 0.02 * T;
    const ProgressGovernor g = governor_of(c, Ts);
    const PlanWindow w0 = g.window(0.0, 0.0);
    const double gamma0 = std::min(g.cone_threshold(w0), g.torque_threshold(0.0, w0));
    const double theta0 =
        std::min(20.0 * kDeg, std::acos(std::max(-1.0, 1.0 - 0.9 * gamma0 / c.gains.k_R)));
    const Flight governed = fly(c, g, Ts, theta0, false);
    EXPECT_LE(governed.largest_torque_ratio, 1.0) << c.name;
    EXPECT_GE(governed.smallest_cone_margin, 0.0) << c.name;
    EXPECT_GT(governed.converged_at, 0.0) << c.name << ": not converged";
    const Flight forced = fly(c, g, Ts, theta0, true);
    if (forced.largest_torque_ratio > 1.0 || forced.smallest_cone_margin < 0.0) ++forced_violations;
    std::printf("%s: start %.3g deg off; governed %s %.4g s = %.3g x the plan (%.4g s), held "
                "%.3g s, max |tau|/tau_max %.4f, min cone margin %.4g; forced to 1: max "
                "|tau|/tau_max %.3f, min cone margin %.4g\n",
                c.name, theta0 / kDeg, governed.converged_at > 0.0 ? "converged at" : "not converged by",
                governed.converged_at > 0.0 ? governed.converged_at : 10.0 * T,
                (governed.converged_at > 0.0 ? governed.converged_at : 10.0 * T) / T, T,
                governed.time_held, governed.largest_torque_ratio, governed.smallest_cone_margin,
                forced.largest_torque_ratio, forced.smallest_cone_margin);
  }
  // Flown at ṡ = 1 from the same starts, some craft leaves the bounds the governor kept.
  EXPECT_GE(forced_violations, 1);
}

}  // namespace
}  // namespace attiguard::governor::progress_governor_test
