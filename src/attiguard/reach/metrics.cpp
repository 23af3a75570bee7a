#include "attiguard/reach/metrics.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <cmath>

#include "attiguard/core/errors.hpp"

namespace attiguard::reach {


bool is_spd(const Mat3& M) {
  if (!M.allFinite()) return false;
  const double scale = M.cwiseAbs().maxCoeff();
  if ((M - M.transpose()).cwiseAbs().maxCoeff() > 1e-12 * std::max(1.0, scale)) return false;
  return lambda_min(M) > 0.0;
}

void require_spd(const Mat3& M, const std::string& what) {
  if (!M.allFinite()) {
    throw InputError(what + ": non-finite entry (must be a symmetric positive definite matrix)");
  }
  if (!is_spd(M)) {
    const bool symmetric = (M - M.transpose()).cwiseAbs().maxCoeff() <=
                           1e-12 * std::max(1.0, M.cwiseAbs().maxCoeff());
    throw InputError(what + (symmetric ? ": not positive definite (smallest eigenvalue " +
                                             std::to_string(lambda_min(M)) + ")"
                                       : ": not symmetric") +
                     " (must be symmetric positive definite)");
  }
}

double p_distance(const Mat3& P, const Vec3& x1, const Vec3& x2) {
  const Vec3 d = x1 - x2;
  return std::sqrt(std::max(0.0, d.dot(P * d)));
}

double dq_upper(const Mat3& Q, const Mat3& R1, const Mat3& R2) {
  const Vec3 w = lie::log(R1.transpose() * R2);
  return std::sqrt(std::max(0.0, w.dot(Q * w)));
}

double dq_lower(const Mat3& Q, const Mat3& R1, const Mat3& R2) {
  return std::sqrt(std::max(0.0, lambda_min(Q))) * lie::distance(R1, R2);
}

double product_distance_upper(const ProductMetric& m, const Mat3& R1, const Vec3& w1,
                              const Mat3& R2, const Vec3& w2) {
  const double a = dq_upper(m.Q, R1, R2);
  const double b = p_distance(m.P, w1, w2);
  return std::sqrt(a * a + b * b);
}

double product_distance_lower(const ProductMetric& m, const Mat3& R1, const Vec3& w1,
                              const Mat3& R2, const Vec3& w2) {
  const double a = dq_lower(m.Q, R1, R2);
  const double b = p_distance(m.P, w1, w2);
  return std::sqrt(a * a + b * b);
}

Mat6 metric_matrix(const StateMetric& m) {
  Mat6 M;
  M << m.Q, m.S, m.S.transpose(), m.P;
  return M;
}

Mat3 attitude_schur(const StateMetric& m) {
  if (m.S.isZero(0.0)) return m.Q;
  const Mat3 X = m.Q - m.S * m.P.llt().solve(m.S.transpose());
  return 0.5 * (X + X.transpose());
}

Mat3 omega_schur(const StateMetric& m) {
  if (m.S.isZero(0.0)) return m.P;
  const Mat3 X = m.P - m.S.transpose() * m.Q.llt().solve(m.S);
  return 0.5 * (X + X.transpose());
}

double metric_distance_upper(const StateMetric& m, const Mat3& R1, const Vec3& w1, const Mat3& R2,
                             const Vec3& w2) {
  const Vec3 a = lie::log(R1.transpose() * R2);
  const Vec3 b = w2 - w1;
  const double q = a.dot(m.Q * a) + 2.0 * a.dot(m.S * b) + b.dot(m.P * b);
  return std::sqrt(std::max(0.0, q));
}

double metric_cover_radius(const StateMetric& m, double a, double b) {
  const Eigen::JacobiSVD<Mat3> svd(m.S);
  const double s = svd.singularValues()(0);
  double sq = lambda_max(m.Q) * a * a + 2.0 * s * a * b + lambda_max(m.P) * b * b;
  if (s > 0.0 && a > 0.0 && b > 0.0) {
    // The set lies in the ellipsoid ‖w‖²θ/a² + ‖v‖²(1 − θ)/b² ≤ 1 for every θ ∈ (0, 1), i.e.
    // z = D_θ u with ‖u‖ ≤ 1, D_θ = diag(a/√θ I, b/√(1 − θ) I): sup zᵀMz ≤ λ_max(D_θ M D_θ).
    const Mat6 M = metric_matrix(m);
    for (int k = 1; k < 40; ++k) {
      const double th = k / 40.0;
      Eigen::Matrix<double, 6, 1> d;
      d << Vec3::Constant(a / std::sqrt(th)), Vec3::Constant(b / std::sqrt(1.0 - th));
      const Mat6 X = d.asDiagonal() * M * d.asDiagonal();
      const Eigen::SelfAdjointEigenSolver<Mat6> es(0.5 * (X + X.transpose()), Eigen::EigenvaluesOnly);
      sq = std::min(sq, es.eigenvalues()(5));
    }
  }
  return std::sqrt(sq);
}

double attitude_enclosure_radius(const Mat3& Q, double r) { return r / std::sqrt(lambda_min(Q)); }

Vec3 p_ball_half_widths(const Mat3& P, double r) {
  const Mat3 Pinv = P.inverse();
  return r * Pinv.diagonal().cwiseMax(0.0).cwiseSqrt();
}

}  // namespace attiguard::reach
