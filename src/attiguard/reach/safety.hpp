#pragma once
/// @file safety.hpp
/// Safety verification (7) from ConReach results: the unsafe set is a union of pointing-cone
/// violations (a body axis entering a keep-out cone or leaving a keep-in cone) and ω bounds.
/// The decision is sound over continuous time: every state on [t_i, t_{i+1}] lies in the state
/// tube (conreach.hpp) — bi-invariant attitude balls B(R_c, ρ) and ω boxes — and for R in
/// B(R_c, ρ) the axis R a_b is within the angle ρ of R_c a_b (a rotation by θ moves a unit vector
/// by at most θ). A step is "safe" when every segment is proved, otherwise "cannot prove".

#include <optional>
#include <string>
#include <vector>

#include "attiguard/reach/conreach.hpp"

namespace attiguard::reach {

struct PointingCone {
  std::string name;
  Vec3 axis_b{0, 0, 1};       ///< unit body axis
  Vec3 direction_i{0, 0, 1};  ///< unit inertial direction
  double half_angle{0.0};     ///< [rad]
  bool keep_out{true};        ///< keep_out: angle(R a_b, d) ≥ α; keep_in: angle ≤ α
};

struct SafetySpec {
  std::vector<PointingCone> cones;
  std::optional<Vec3> omega_abs_max;    ///< |ω_k| ≤ bound_k
  std::optional<double> omega_norm_max; ///< ‖ω‖ ≤ bound
  [[nodiscard]] bool requested() const { return !cones.empty() || omega_abs_max || omega_norm_max; }
};

struct SafetyVerdict {
  bool requested{false};
  bool proved{false};
  double first_failure_time{-1.0};  ///< start of the first segment not proved (-1: none)
  std::string reason;               ///< which constraint could not be proved first
  std::vector<bool> step_safe;      ///< per ConReach step of the first cell
  bool complete{true};              ///< every analysis reached the horizon
};

/// Empty when the single state (R, ω) meets the specification, else the first constraint it
/// violates (a cone's name, omega_abs_max or omega_norm_max).
[[nodiscard]] std::string violated_by_state(const SafetySpec& spec, const Mat3& R, const Vec3& omega);

/// Empty when every state of the tube segment is proved to meet the specification, else the
/// first constraint that cannot be proved (a cone's name, omega_abs_max or omega_norm_max). The
/// cone angles and the ω-norm are compared with outward rounding, the ball read as centred on the
/// polar factor of the floating-point centre (docs/reach.md, "Rounding sites").
[[nodiscard]] std::string violated_by_segment(const SafetySpec& spec, const TubeSegment& seg);

/// Checks the state tubes of every result. An analysis that stopped before the horizon
/// (ReachResult::complete false) is a failure at its stop time, whether or not safety was
/// requested: `proved` then is false and `complete` too.
[[nodiscard]] SafetyVerdict verify_safety(const SafetySpec& spec, const std::vector<ReachResult>& results);

}  // namespace attiguard::reach
