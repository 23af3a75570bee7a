#pragma once
/// @file argument_checks.hpp
/// Validation of library arguments (the Python API, docs/python.md) by the scenario readers
/// themselves: the same checks and messages as a scenario file, not a copy. Each function puts
/// `args` (a JSON object with the keys of the scenario schema, docs/scenario-format.md) into a
/// small scenario document labelled `label` (e.g. "keep_out_cone()"), reads it with the readers
/// and throws InputError "LABEL: KEY: …" naming the offending key.

#include <string>

#include <nlohmann/json.hpp>

#include "attiguard/governor/attitude_governor.hpp"
#include "attiguard/lie/quaternion.hpp"
#include "attiguard/lie/so3.hpp"

namespace attiguard::scenario {

/// One cone table of [[cones]] (keys type, axis_b, direction_i, half_angle or half_angle_deg,
/// delta_offset, zeta_offset, repulsive_gain), read by parse_cone.
[[nodiscard]] governor::ConeConstraint checked_cone(const nlohmann::json& cone, const std::string& label);

/// The governor block of a pet_erg scenario (keys governor, control{kp, kd, tau_max},
/// erg{kappa, c_gamma, sampling_period, epsilon, epsilon_gamma}) and an `inertia` (body.inertia's
/// rules: symmetric positive definite, triangle inequality, usable range), read by
/// parse_governor_block and TableReader::inertia.
[[nodiscard]] governor::GovernorParams checked_governor_params(const nlohmann::json& args,
                                                               const std::string& label);

/// The governor of `params` and `cones`, its constructor's errors (Γ_d, cones) labelled.
[[nodiscard]] governor::AttitudeGovernor checked_governor(const governor::GovernorParams& params,
                                                          const std::vector<governor::ConeConstraint>& cones,
                                                          const std::string& label);

/// A rotation matrix `key` (the file reader's rotation check: orthonormal to 1e-9, det +1).
[[nodiscard]] lie::Mat3 checked_rotation_matrix(const lie::Mat3& R, const std::string& key,
                                                const std::string& label);

/// A unit quaternion `key` [w, x, y, z] (the file reader's { quaternion = … } check: 4 finite
/// numbers, norm 1 to within 1e-9; docs/scenario-format.md, "Rotations").
[[nodiscard]] lie::Quat checked_unit_quaternion(const lie::Quat& q, const std::string& key,
                                                const std::string& label);

/// A rotation vector `key` (the file reader's { rotation_vector = … } check: finite, norm
/// <= 1e6 rad; docs/scenario-format.md, "Rotations").
[[nodiscard]] lie::Vec3 checked_rotation_vector(const lie::Vec3& w, const std::string& key,
                                                const std::string& label);

/// An axis and an angle (the file reader's { axis = …, angle = … } check: a finite non-zero
/// axis, a finite angle with |angle| <= 1e6 rad), errors naming `axis_key` / `angle_key`;
/// returns the unit axis.
[[nodiscard]] lie::Vec3 checked_axis_angle(const lie::Vec3& axis, double angle, const std::string& axis_key,
                                           const std::string& angle_key, const std::string& label);

/// A finite 3×3 matrix `key`.
[[nodiscard]] lie::Mat3 checked_matrix3(const lie::Mat3& M, const std::string& key,
                                        const std::string& label);

/// A finite 3-vector `key`.
[[nodiscard]] lie::Vec3 checked_vector3(const lie::Vec3& v, const std::string& key,
                                        const std::string& label);

/// A finite number `key` > 0 (`positive`) or >= 0.
[[nodiscard]] double checked_number(double x, const std::string& key, bool positive,
                                    const std::string& label);

}  // namespace attiguard::scenario
