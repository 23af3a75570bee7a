// Every ω face of every U_i and every state-tube segment contains the exact tube, computed from
// the closed-form flow of linear ω-dynamics (no sampled initial states): for ω̇ = Mω and the
// initial ball B(ω0, b), the reach set at t is e^{Mt}B(ω0, b), whose extent along ±e_k is
// ±(e^{Mt}ω0)_k + b‖e_kᵀe^{Mt}‖. The extreme over [t0, t1] is found on a 64-point grid refined by
// golden-section search. Cases: the paper's example, its coarse-step variant (one sub-step,
// integrator step 0.1 s) and a body spinning at 20 rad/s — each missed the exact tube while the
// nominal's error was covered by a fixed 1e-9 (docs/reach.md, "Nominal error bound").

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

#include <unsupported/Eigen/MatrixFunctions>

#include "attiguard/reach/conreach.hpp"

namespace ar = attiguard::reach;

namespace {

struct LinearCase {
  std::string name;
  ar::Mat3 M;
  ar::InitialSet initial;
  ar::ConReachSettings settings;
};

/// max over t ∈ [t0, t1] of g(t) (grid, then golden-section around the best grid point).
double max_over(const std::function<double(double)>& g, double t0, double t1) {
  const int n = 64;
  double best = -INFINITY;
  int arg = 0;
  for (int j = 0; j <= n; ++j) {
    const double v = g(t0 + (t1 - t0) * j / n);
    if (v > best) {
      best = v;
      arg = j;
    }
  }
  double a = t0 + (t1 - t0) * std::max(0, arg - 1) / n;
  double b = t0 + (t1 - t0) * std::min(n, arg + 1) / n;
  const double phi = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int it = 0; it < 60; ++it) {
    const double c = b - phi * (b - a);
    const double d = a + phi * (b - a);
    if (g(c) > g(d)) b = d; else a = c;
    best = std::max({best, g(c), g(d)});
  }
  return best;
}

/// Extent of the exact ω reach set along +e_k (sign +1) or −e_k (sign −1) over [t0, t1].
double exact_extent(const LinearCase& c, int k, double sign, double t0, double t1) {
  return max_over([&](double t) {
    const ar::Mat3 F = (c.M * t).exp();
    return sign * (F * c.initial.omega0)(k) + c.initial.omega_radius * F.row(k).norm();
  }, t0, t1);
}

/// Counts the faces of `box` over [t0, t1] that miss the exact tube (by more than 1e-15
/// relative, the rounding of the closed form itself).
int missed_faces(const LinearCase& c, const ar::Box3& box, double t0, double t1, std::string& first) {
  int missed = 0;
  for (int k = 0; k < 3; ++k) {
    const double hi = exact_extent(c, k, +1.0, t0, t1);
    const double lo = -exact_extent(c, k, -1.0, t0, t1);
    const double tol = 1e-15 * (1.0 + std::abs(hi) + std::abs(lo));
    if (box.hi(k) < hi - tol || box.lo(k) > lo + tol) {
      if (missed++ == 0 && first.empty()) {
        first = "[" + std::to_string(t0) + ", " + std::to_string(t1) + "] axis " + std::to_string(k) +
                ": box [" + std::to_string(box.lo(k)) + ", " + std::to_string(box.hi(k)) + "]";
      }
    }
  }
  return missed;
}

LinearCase paper_case() {
  LinearCase c;
  c.name = "paper";
  c.M = ar::Vec3(-2, -1, -3).asDiagonal();
  c.initial = {ar::Mat3::Identity(), 0.1, ar::Vec3(0.65, 0.54, 0.61), 0.1};
  return c;
}

class ReachTubeExact : public ::testing::TestWithParam<LinearCase> {};

TEST_P(ReachTubeExact, EveryOmegaFaceOfEveryBoxAndSegmentContainsTheClosedFormTube) {
  const LinearCase& c = GetParam();
  const ar::LinearOmegaLoop loop(c.M);
  const ar::ReachResult res = ar::run_conreach(loop, c.initial, c.settings);
  int boxes = 0, segments = 0, missed_boxes = 0, missed_segments = 0;
  std::string first_box, first_segment;
  for (const ar::ReachStep& st : res.steps) {
    ++boxes;
    missed_boxes += missed_faces(c, st.omega_box, st.t0, st.t1, first_box) > 0;
    for (const ar::TubeSegment& seg : st.state_tube) {
      ++segments;
      missed_segments += missed_faces(c, seg.omega, seg.t0, seg.t1, first_segment) > 0;
    }
  }
  EXPECT_EQ(missed_boxes, 0) << c.name << ": " << missed_boxes << " of " << boxes << " U_i, first " << first_box;
  EXPECT_EQ(missed_segments, 0) << c.name << ": " << missed_segments << " of " << segments
                                << " segments, first " << first_segment;
}

std::vector<LinearCase> cases() {
  std::vector<LinearCase> out;
  out.push_back(paper_case());
  LinearCase coarse = paper_case();
  coarse.name = "paper_coarse_step";
  coarse.settings.substeps = 1;
  coarse.settings.integrator_step = 0.1;
  out.push_back(coarse);
  LinearCase spin;
  spin.name = "spin_20_rad_s";
  spin.M << 0, -20, 0, 20, 0, 0, 0, 0, 0;
  spin.initial = {ar::Mat3::Identity(), 0.05, ar::Vec3(1, 0, 0), 0.05};
  spin.settings.horizon = 2.0;
  out.push_back(spin);
  LinearCase growth;
  growth.name = "growth20";
  growth.M = ar::Vec3(20, -1, -1).asDiagonal();
  growth.initial = {ar::Mat3::Identity(), 0.02, ar::Vec3(0.65, 0.54, 0.61), 0.05};
  growth.settings.horizon = 0.1;
  growth.settings.steps = 10;
  out.push_back(growth);
  return out;
}

INSTANTIATE_TEST_SUITE_P(LinearCases, ReachTubeExact, ::testing::ValuesIn(cases()),
                         [](const auto& info) { return info.param.name; });

}  // namespace
