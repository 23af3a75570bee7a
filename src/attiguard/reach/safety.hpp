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
  std::vector<bool> step_safe;      ///< per ConReach step (all cells)
};

/// Checks the state tubes of every result.
[[nodiscard]] SafetyVerdict verify_safety(const SafetySpec& spec, const std::vector<ReachResult>& results);

}  // namespace attiguard::reach
