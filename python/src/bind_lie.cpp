/// @file bind_lie.cpp
/// SO(3) and unit-quaternion helpers (docs/conventions.md, "Frames and rotations").

#include <pybind11/eigen.h>

#include "attiguard/lie/quaternion.hpp"
#include "attiguard/lie/so3.hpp"
#include "bindings.hpp"

namespace py = pybind11;

namespace attiguard::python {

void bind_lie(py::module_& m) {
  using lie::Mat3;
  using lie::Quat;
  using lie::Vec3;
  m.def("hat", [](const Vec3& x) { return lie::hat(x); }, py::arg("x"),
        "hat: R^3 -> so(3), hat(x) y = x × y (conventions).");
  m.def("vee", [](const Mat3& X) { return lie::vee(X); }, py::arg("X"), "Inverse of hat.");
  m.def("expm", [](const Vec3& w) { return lie::exp(w); }, py::arg("w"),
        "Exponential map so(3) -> SO(3) of the rotation vector w (Rodrigues).");
  m.def("logm", [](const Mat3& R) { return lie::log(R); }, py::arg("R"),
        "Logarithm SO(3) -> rotation vector, ‖log R‖ ∈ [0, π].");
  m.def("distance", [](const Mat3& A, const Mat3& B) { return lie::distance(A, B); },
        py::arg("R1"), py::arg("R2"), "Bi-invariant distance ‖log(R1ᵀ R2)‖ [rad].");
  m.def("phi", [](const Mat3& R) { return lie::phi(R); }, py::arg("R"),
        "Attitude error function φ(R) = ½ tr(I − R) = 1 − cos θ (PET-ERG paper, Sec. III-A).");
  m.def("project_to_so3", [](const Mat3& M) { return lie::project_to_so3(M); }, py::arg("M"),
        "Closest rotation to M (polar decomposition).");
  m.def("is_rotation", [](const Mat3& M, double tol) { return lie::is_rotation(M, tol); },
        py::arg("M"), py::arg("tol") = 1e-9);
  m.def("quat_to_rotation", [](const Quat& q) { return lie::quat_to_rotation(q); }, py::arg("q"),
        "R(q) = I + 2η S(ε) + 2 S(ε)², q = [η, ε] scalar first (waypoint paper, (1)).");
  m.def("rotation_to_quat", [](const Mat3& R) { return lie::rotation_to_quat(R); }, py::arg("R"),
        "Unit quaternion [η, ε] of R, η ≥ 0.");
  m.def("quat_multiply", [](const Quat& p, const Quat& q) { return lie::quat_multiply(p, q); },
        py::arg("p"), py::arg("q"), "Hamilton product p ⊗ q (waypoint paper, (12)).");
  m.def("quat_conjugate", [](const Quat& q) { return lie::quat_conjugate(q); }, py::arg("q"));
  m.def("quat_from_axis_angle",
        [](const Vec3& axis, double angle) { return lie::quat_from_axis_angle(axis.normalized(), angle); },
        py::arg("axis"), py::arg("angle"), "[cos(θ/2), k sin(θ/2)] for the rotation θ about k.");
}

}  // namespace attiguard::python
