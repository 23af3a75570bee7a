#include "attiguard/dynamics/rigid_body.hpp"
#include "attiguard/lie/symmetric_eigen.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <sstream>

#include "attiguard/core/errors.hpp"

namespace attiguard::dynamics {

std::optional<std::string> inertia_error(const Mat3& J) {
  if (!J.allFinite()) {
    return "inertia matrix has a non-finite entry";
  }
  const double scale = J.cwiseAbs().maxCoeff();
  if (!(scale > 0.0)) {
    return "inertia matrix is zero";
  }
  if ((J - J.transpose()).cwiseAbs().maxCoeff() > 1e-9 * scale) {
    return "inertia matrix is not symmetric";
  }
  const Vec3 m = lie::symmetric_eigenvalues(J);  // ascending
  if (!(m(0) > 0.0)) {
    std::ostringstream os;
    os << "inertia matrix is not positive definite (smallest principal moment " << m(0) << ")";
    return os.str();
  }
  // Physical bodies satisfy J_1 + J_2 ≥ J_3 for the principal moments (J_3 the largest).
  if (m(0) + m(1) < m(2) * (1.0 - 1e-9)) {
    std::ostringstream os;
    os << "principal moments " << m(0) << ", " << m(1) << ", " << m(2)
       << " violate the triangle inequality J1 + J2 >= J3 (no physical body has them)";
    return os.str();
  }
  return std::nullopt;
}

RigidBody::RigidBody(const Mat3& J) {
  if (auto err = inertia_error(J)) {
    throw SetupError(*err);
  }
  J_ = 0.5 * (J + J.transpose());
  J_inv_ = J_.inverse();
  const Vec3 moments = lie::symmetric_eigenvalues(J_);
  lambda_min_ = moments(0);
  lambda_max_ = moments(2);
  const Mat3 off = Mat3::Ones() - Mat3::Identity();
  diagonal_ = J_.cwiseProduct(off).isZero(0.0) && J_inv_.cwiseProduct(off).isZero(0.0);
}

}  // namespace attiguard::dynamics
