#include "attiguard/lie/symmetric_eigen.hpp"

#include <Eigen/Eigenvalues>

namespace attiguard::lie {

Vec3 symmetric_eigenvalues(const Mat3& M) {
  const Mat3 S = 0.5 * (M + M.transpose());
  return Eigen::SelfAdjointEigenSolver<Mat3>(S, Eigen::EigenvaluesOnly).eigenvalues();
}

double lambda_min(const Mat3& M) { return symmetric_eigenvalues(M)(0); }

double lambda_max(const Mat3& M) { return symmetric_eigenvalues(M)(2); }

}  // namespace attiguard::lie
