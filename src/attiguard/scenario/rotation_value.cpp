// TableReader::rotation: a rotation given as an inline table in one of four forms
// (docs/scenario-format.md, "Rotations").

#include <Eigen/LU>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "attiguard/lie/quaternion.hpp"
#include "attiguard/lie/so3.hpp"
#include "attiguard/scenario/messages.hpp"
#include "attiguard/scenario/table_reader.hpp"

namespace attiguard::scenario {

namespace {

/// Tolerance on ‖RᵀR − I‖_F of a matrix and on |‖q‖ − 1| of a quaternion.
constexpr double kRotationTolerance = 1e-9;
/// Rotation angles beyond ±10⁶ rad (≈ 1.6·10⁵ turns) are refused: reduced modulo 2π they keep
/// almost no significant digit (10⁶ rad carries an absolute rounding error of ~10⁻¹⁰ rad, 10³⁰⁰
/// none at all), so such a value is a mistake, not an attitude.
constexpr double kMaxRotationAngle = 1e6;
constexpr const char* kMaxAngleText =
    "the usable range |angle| <= 1e6 rad (5.7e7 deg): give the attitude's angle, e.g. in [-pi, pi]";

constexpr std::string_view kForms =
    "exactly one of: matrix = [[...], [...], [...]], quaternion = [w, x, y, z], "
    "axis = [x, y, z] with angle (rad) or angle_deg, rotation_vector = [x, y, z] (rad)";

/// Which of the rotation forms a rotation table holds (docs/scenario-format.md, "Rotations").
struct RotationForms {
  bool matrix = false;
  bool quaternion = false;
  bool axis = false;
  bool angle = false;
  bool angle_deg = false;
  bool rotation_vector = false;
};

/// Fails unless exactly one form is given (the axis form counts axis, angle and angle_deg).
void require_one_rotation_form(const TableReader& rot, const RotationForms& has) {
  std::vector<std::string> forms;
  if (has.matrix) forms.emplace_back("matrix");
  if (has.quaternion) forms.emplace_back("quaternion");
  if (has.axis || has.angle || has.angle_deg) forms.emplace_back("axis");
  if (has.rotation_vector) forms.emplace_back("rotation_vector");
  if (forms.empty()) {
    rot.fail_here("no rotation given: expected " + std::string(kForms));
  }
  if (forms.size() > 1) {
    std::string given;
    for (const std::string& f : forms) {
      given += (given.empty() ? "" : " and ") + f;
    }
    rot.fail_here(std::to_string(forms.size()) + " rotation forms given (" + given +
                  "): expected " + std::string(kForms));
  }
}

/// The form `matrix`: orthonormal to 1e-9 with det = +1 (docs/scenario-format.md, "Rotations").
Eigen::Matrix3d rotation_from_matrix(const TableReader& rot) {
  const Eigen::Matrix3d M = rot.matrix3("matrix");
  const double err = lie::orthonormality_error(M);
  if (!(err <= kRotationTolerance)) {
    rot.fail("matrix", "not a rotation matrix: ||R^T R - I||_F = " + detail::format_number(err) +
                           " exceeds 1e-9 (det = " + detail::format_number(M.determinant()) +
                           ")");
  }
  const double det = M.determinant();
  if (!(det > 0.0) || !lie::is_rotation(M, kRotationTolerance)) {
    rot.fail("matrix", "not a rotation matrix: det = " + detail::format_number(det) +
                           " (a reflection; a rotation has det = +1)");
  }
  return M;
}

/// The form `quaternion`: [w, x, y, z] scalar first, unit to 1e-9 (docs/conventions.md).
Eigen::Matrix3d rotation_from_quaternion(const TableReader& rot) {
  const Eigen::VectorXd q = rot.vector("quaternion");
  if (q.size() != 4) {
    rot.fail("quaternion", "expected an array of 4 numbers [w, x, y, z] (scalar first), got " +
                               std::to_string(q.size()) +
                               (q.size() == 1 ? " element" : " elements"));
  }
  const double norm = q.norm();
  if (!(std::abs(norm - 1.0) <= kRotationTolerance)) {
    rot.fail("quaternion", "not a unit quaternion: norm = " + detail::format_number(norm) +
                               " (must be 1 to within 1e-9)");
  }
  return lie::quat_to_rotation(lie::Quat(q(0), q(1), q(2), q(3)));
}

/// The form `rotation_vector`: θ k in rad, exp of its hat (docs/conventions.md).
Eigen::Matrix3d rotation_from_rotation_vector(const TableReader& rot) {
  const Eigen::Vector3d v = rot.vector3("rotation_vector");
  if (!(v.norm() <= kMaxRotationAngle)) {
    rot.fail("rotation_vector", "norm " + detail::format_number(v.norm()) + " rad is beyond " +
                                    kMaxAngleText);
  }
  return lie::exp(v);
}

/// The axis-angle form: a non-zero axis with exactly one of angle (rad) and angle_deg (deg).
Eigen::Matrix3d rotation_from_axis_and_angle(const TableReader& rot, const RotationForms& has) {
  if (!has.axis) {
    rot.fail(has.angle ? "angle" : "angle_deg",
             "an angle needs an axis: { axis = [x, y, z], angle = θ } (rad) or angle_deg (deg)");
  }
  if (has.angle && has.angle_deg) {
    rot.fail("angle_deg", "give either angle (rad) or angle_deg (deg), not both");
  }
  if (!has.angle && !has.angle_deg) {
    rot.fail_here("axis needs an angle: add angle (rad) or angle_deg (deg)");
  }
  const Eigen::Vector3d axis = rot.direction("axis");
  const double angle =
      has.angle ? rot.number("angle") : rot.number("angle_deg") * std::numbers::pi / 180.0;
  if (!(std::abs(angle) <= kMaxRotationAngle)) {
    rot.fail(has.angle ? "angle" : "angle_deg",
             detail::format_number(has.angle ? rot.number("angle") : rot.number("angle_deg")) +
                 (has.angle ? " rad" : " deg") + " is beyond " + kMaxAngleText);
  }
  return lie::exp(angle * axis);
}

}  // namespace

Eigen::Matrix3d TableReader::rotation(std::string_view key) const {
  const toml::node* n = take(key);
  if (n == nullptr) {
    missing(key, "a rotation table with " + std::string(kForms));
  }
  const toml::table* t = n->as_table();
  if (t == nullptr) {
    fail(key, "expected a rotation table { ... } with " + std::string(kForms) + "; got " +
                  detail::describe(*n));
  }
  // Not registered for finish(): the forms are every key a rotation table may hold, and the
  // unknown keys are rejected right here, before the forms are counted.
  const TableReader rot(shared_, t, key_path(key));
  RotationForms has;
  has.matrix = rot.has("matrix");
  has.quaternion = rot.has("quaternion");
  has.axis = rot.has("axis");
  has.angle = rot.has("angle");
  has.angle_deg = rot.has("angle_deg");
  has.rotation_vector = rot.has("rotation_vector");
  rot.finish();
  require_one_rotation_form(rot, has);

  if (has.matrix) return rotation_from_matrix(rot);
  if (has.quaternion) return rotation_from_quaternion(rot);
  if (has.rotation_vector) return rotation_from_rotation_vector(rot);
  return rotation_from_axis_and_angle(rot, has);
}

}  // namespace attiguard::scenario
