/// @file bind_lie.cpp
/// SO(3) and unit-quaternion helpers (docs/conventions.md, "Frames and rotations"). Every
/// argument is checked before the call by the scenario readers' rules
/// (scenario/argument_checks.hpp; docs/python.md, "Validation"): finite numbers, rotations
/// orthonormal to 1e-9 with det +1, unit quaternions to 1e-9, a non-zero axis. ValueError names
/// the argument.

#include <algorithm>
#include <cmath>
#include <string>

#include <pybind11/eigen.h>

#include "attiguard/core/errors.hpp"
#include "attiguard/lie/quaternion.hpp"
#include "attiguard/lie/so3.hpp"
#include "attiguard/scenario/argument_checks.hpp"
#include "bindings.hpp"

namespace py = pybind11;

namespace attiguard::python {
namespace {

using lie::Mat3;
using lie::Quat;
using lie::Vec3;
using scenario::checked_matrix3;
using scenario::checked_rotation_matrix;
using scenario::checked_unit_quaternion;
using scenario::checked_vector3;

/// Tolerance of vee()'s skew-symmetry check: ‖X + Xᵀ‖_F <= 1e-9 · max(1, ‖X‖_F), the
/// rotation tolerance of the readers scaled to the matrix.
constexpr double kSkewTolerance = 1e-9;

Mat3 checked_skew(const Mat3& X, const char* label) {
  const Mat3 ok = checked_matrix3(X, "X", label);
  const double asym = (ok + ok.transpose()).norm();
  if (!(asym <= kSkewTolerance * std::max(1.0, ok.norm()))) {
    throw InputError(std::string(label) + ": X: not skew-symmetric: ||X + X^T||_F = " +
                     std::to_string(asym) + " exceeds 1e-9 * max(1, ||X||_F)");
  }
  return ok;
}

}  // namespace

void bind_lie(py::module_& m) {
  m.def("hat", [](const Vec3& x) { return lie::hat(checked_vector3(x, "x", "hat()")); }, py::arg("x"),
        "hat: R^3 -> so(3), hat(x) y = x × y (conventions). x finite.");
  m.def("vee", [](const Mat3& X) { return lie::vee(checked_skew(X, "vee()")); }, py::arg("X"),
        "Inverse of hat; X finite and skew-symmetric to 1e-9 (relative).");
  m.def("expm",
        [](const Vec3& w) { return lie::exp(scenario::checked_rotation_vector(w, "w", "expm()")); },
        py::arg("w"),
        "Exponential map so(3) -> SO(3) of the rotation vector w (Rodrigues); w finite, "
        "‖w‖ <= 1e6 rad.");
  m.def("logm", [](const Mat3& R) { return lie::log(checked_rotation_matrix(R, "R", "logm()")); },
        py::arg("R"), "Logarithm SO(3) -> rotation vector, ‖log R‖ ∈ [0, π]; R a rotation.");
  m.def("distance",
        [](const Mat3& A, const Mat3& B) {
          return lie::distance(checked_rotation_matrix(A, "R1", "distance()"),
                               checked_rotation_matrix(B, "R2", "distance()"));
        },
        py::arg("R1"), py::arg("R2"), "Bi-invariant distance ‖log(R1ᵀ R2)‖ [rad].");
  m.def("phi", [](const Mat3& R) { return lie::phi(checked_rotation_matrix(R, "R", "phi()")); },
        py::arg("R"),
        "Attitude error function φ(R) = ½ tr(I − R) = 1 − cos θ [PET-ERG Sec. III-A].");
  m.def("project_to_so3",
        [](const Mat3& M) {
          const Mat3 ok = checked_matrix3(M, "M", "project_to_so3()");
          // The polar factor is unique only for an invertible M.
          const double scale = std::max(1.0, ok.norm());
          if (!(std::abs(ok.determinant()) > 1e-12 * scale * scale * scale)) {
            throw InputError("project_to_so3(): M: singular (det = " +
                             std::to_string(ok.determinant()) +
                             "): the closest rotation is not unique");
          }
          return lie::project_to_so3(ok);
        },
        py::arg("M"), "Closest rotation to M (polar decomposition); M finite and invertible.");
  m.def("is_rotation",
        [](const Mat3& M, double tol) {
          const Mat3 ok = checked_matrix3(M, "M", "is_rotation()");
          return lie::is_rotation(ok, scenario::checked_number(tol, "tol", false, "is_rotation()"));
        },
        py::arg("M"), py::arg("tol") = 1e-9, "‖MᵀM − I‖_F <= tol and det M > 0; M finite, tol >= 0.");
  m.def("quat_to_rotation",
        [](const Quat& q) { return lie::quat_to_rotation(checked_unit_quaternion(q, "q", "quat_to_rotation()")); },
        py::arg("q"),
        "R(q) = I + 2η S(ε) + 2 S(ε)², q = [η, ε] scalar first, unit to 1e-9 [Waypoint eq. (1)].");
  m.def("rotation_to_quat",
        [](const Mat3& R) { return lie::rotation_to_quat(checked_rotation_matrix(R, "R", "rotation_to_quat()")); },
        py::arg("R"), "Unit quaternion [η, ε] of R, η ≥ 0.");
  m.def("quat_multiply",
        [](const Quat& p, const Quat& q) {
          return lie::quat_multiply(checked_unit_quaternion(p, "p", "quat_multiply()"),
                                    checked_unit_quaternion(q, "q", "quat_multiply()"));
        },
        py::arg("p"), py::arg("q"), "Hamilton product p ⊗ q of unit quaternions [Waypoint eq. (12)].");
  m.def("quat_conjugate",
        [](const Quat& q) { return lie::quat_conjugate(checked_unit_quaternion(q, "q", "quat_conjugate()")); },
        py::arg("q"), "Conjugate [η, −ε] of a unit quaternion.");
  m.def("quat_from_axis_angle",
        [](const Vec3& axis, double angle) {
          return lie::quat_from_axis_angle(
              scenario::checked_axis_angle(axis, angle, "axis", "angle", "quat_from_axis_angle()"), angle);
        },
        py::arg("axis"), py::arg("angle"),
        "[cos(θ/2), k sin(θ/2)] for the rotation θ about k = axis/‖axis‖; axis finite, non-zero; "
        "angle finite, |angle| <= 1e6 rad.");
}

}  // namespace attiguard::python
