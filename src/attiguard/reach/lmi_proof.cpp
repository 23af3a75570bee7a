#include "attiguard/reach/lmi_proof.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>

#include "attiguard/reach/interval_matrix.hpp"
#include "attiguard/reach/metrics.hpp"
#include "attiguard/reach/scalar_interval.hpp"

namespace attiguard::reach {

namespace {

/// The Gershgorin-after-congruence proof of the file comment for an interval matrix whose
/// members are symmetric (S need not be stored symmetric: both triangles are enclosed).
template <int N>
NegativeDefiniteProof prove_negative_definite(const IMat<N>& S) {
  using MatN = Eigen::Matrix<double, N, N>;
  NegativeDefiniteProof out;
  MatN mid;
  for (int i = 0; i < N; ++i) {
    for (int j = 0; j < N; ++j) {
      const Interval& x = S[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
      if (!x.finite()) return out;
      mid(i, j) = 0.5 * (x.lo + x.hi);
    }
  }
  const Eigen::SelfAdjointEigenSolver<MatN> es(0.5 * (mid + mid.transpose()));
  if (es.info() != Eigen::Success) return out;
  const IMat<N> V = point<N>(es.eigenvectors());
  const IMat<N> Vt = transposed<N>(V);
  const IMat<N> D = product<N>(product<N>(Vt, S), V);
  const IMat<N> G = product<N>(Vt, V);
  double margin = -HUGE_VAL;
  for (std::size_t i = 0; i < N; ++i) {
    Interval row = D[i][i];
    Interval off(0.0);
    for (std::size_t j = 0; j < N; ++j) {
      if (j == i) continue;
      row += Interval(0.0, D[i][j].mag());
      off += Interval(0.0, G[i][j].mag());
    }
    if (!(G[i][i].lo > off.hi)) return out;  // VᵀV not provably nonsingular
    margin = std::max(margin, row.hi);
  }
  out.margin = margin;
  out.proved = margin < 0.0;
  return out;
}

IMat<3> imat(const Mat3& M) { return point<3>(M); }

/// F = [[−ω̂, I], [A, B]] over the vertex's data, A and B widened by their radii.
IMat<6> vertex_matrix(const LmiVertex& vx) {
  // rounding site: vertex-data
  Mat6 Fd = Mat6::Zero();
  Fd.topLeftCorner<3, 3>() = -lie::hat(vx.omega);
  Fd.topRightCorner<3, 3>() = Mat3::Identity();
  Fd.bottomLeftCorner<3, 3>() = vx.A;
  Fd.bottomRightCorner<3, 3>() = vx.B;
  IMat<6> F = point<6>(Fd);
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < 3; ++j) {
      const double ra = vx.A_rad(static_cast<int>(i), static_cast<int>(j));
      const double rb = vx.B_rad(static_cast<int>(i), static_cast<int>(j));
      F[i + 3][j] = F[i + 3][j] + Interval(-ra, ra);
      F[i + 3][j + 3] = F[i + 3][j + 3] + Interval(-rb, rb);
    }
  }
  return F;
}

}  // namespace

NegativeDefiniteProof prove_contraction_lmi(const LmiEnclosure& enc, const StateMetric& metric,
                                            double c, const std::vector<double>& mu) {
  NegativeDefiniteProof worst{true, -HUGE_VAL};
  const IMat<6> M = point<6>(metric_matrix(metric));
  const IMat<6> Mt = transposed<6>(M);
  const Interval two_c = Interval(2.0) * Interval(c);
  for (std::size_t v = 0; v < enc.vertices.size(); ++v) {
    const LmiVertex& vx = enc.vertices[v];
    // L = MF + FᵀM − 2cM with F = [[−ω̂, I], [A, B]] (contraction_sdp.hpp). L is affine in F,
    // so the interval F of the vertex's data [A_v ± A_rad], [B_v ± B_rad] encloses L for every
    // (A, B) the vertex stands for.
    const IMat<6> F = vertex_matrix(vx);
    const IMat<6> MF = product<6>(M, F);
    const IMat<6> FtM = product<6>(transposed<6>(F), Mt);
    IMat<6> S;
    for (std::size_t i = 0; i < 6; ++i) {
      for (std::size_t j = 0; j < 6; ++j) S[i][j] = MF[i][j] + FtM[i][j] - two_c * M[i][j];
    }
    if (enc.rho > 0.0) {
      // + μρ²I + UUᵀ/μ, U = M[0; I] (the last three columns of M).
      const double m = v < mu.size() ? mu[v] : 0.0;
      if (!(m > 0.0) || !std::isfinite(m)) return {false, HUGE_VAL};
      const Interval shift = Interval(m) * Interval(enc.rho) * Interval(enc.rho);
      for (std::size_t i = 0; i < 6; ++i) {
        for (std::size_t j = 0; j < 6; ++j) {
          Interval uu(0.0);
          for (std::size_t k = 3; k < 6; ++k) uu += M[i][k] * M[j][k];
          S[i][j] += uu / m;
        }
        S[i][i] += shift;
      }
    }
    const NegativeDefiniteProof p = prove_negative_definite<6>(S);
    worst.proved = worst.proved && p.proved;
    worst.margin = std::max(worst.margin, p.proved ? p.margin : HUGE_VAL);
  }
  return worst;
}

NegativeDefiniteProof prove_contraction_lmi(const LmiEnclosure& enc, const Mat3& Q, const Mat3& P,
                                            double c, const std::vector<double>& mu) {
  return prove_contraction_lmi(enc, StateMetric{Q, Mat3::Zero(), P}, c, mu);
}

NegativeDefiniteProof prove_less(const Mat6& A, const Mat6& B) {
  IMat<6> D;
  const IMat<6> Ai = point<6>(A);
  const IMat<6> Bi = point<6>(B);
  for (std::size_t i = 0; i < 6; ++i) {
    for (std::size_t j = 0; j < 6; ++j) D[i][j] = Ai[i][j] - Bi[i][j];
  }
  return prove_negative_definite<6>(D);
}

NegativeDefiniteProof prove_less(const Mat3& A, const Mat3& B) {
  return prove_negative_definite<3>(add<3>(imat(A), imat(B), -1.0));
}

}  // namespace attiguard::reach
