#include "attiguard/reach/lmi_proof.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>

#include "attiguard/reach/scalar_interval.hpp"

namespace attiguard::reach {

namespace {

template <int N>
using IMat = std::array<std::array<Interval, N>, N>;

template <int N>
IMat<N> point(const Eigen::Matrix<double, N, N>& M) {
  IMat<N> out;
  for (int i = 0; i < N; ++i) {
    for (int j = 0; j < N; ++j) out[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = M(i, j);
  }
  return out;
}

template <int N>
IMat<N> product(const IMat<N>& A, const IMat<N>& B) {
  IMat<N> out;
  for (std::size_t i = 0; i < N; ++i) {
    for (std::size_t j = 0; j < N; ++j) {
      Interval s(0.0);
      for (std::size_t k = 0; k < N; ++k) s += A[i][k] * B[k][j];
      out[i][j] = s;
    }
  }
  return out;
}

template <int N>
IMat<N> transposed(const IMat<N>& A) {
  IMat<N> out;
  for (std::size_t i = 0; i < N; ++i) {
    for (std::size_t j = 0; j < N; ++j) out[i][j] = A[j][i];
  }
  return out;
}

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

IMat<3> add(const IMat<3>& A, const IMat<3>& B, double sign = 1.0) {
  IMat<3> out;
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < 3; ++j) out[i][j] = sign > 0 ? A[i][j] + B[i][j] : A[i][j] - B[i][j];
  }
  return out;
}

IMat<3> scaled(const IMat<3>& A, const Interval& s) {
  IMat<3> out;
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < 3; ++j) out[i][j] = s * A[i][j];
  }
  return out;
}

}  // namespace

NegativeDefiniteProof prove_contraction_lmi(const LmiEnclosure& enc, const Mat3& Q, const Mat3& P,
                                            double c, const std::vector<double>& mu) {
  NegativeDefiniteProof worst{true, -HUGE_VAL};
  const IMat<3> Qi = imat(Q);
  const IMat<3> Pi = imat(P);
  const IMat<3> Qt = transposed<3>(Qi);
  const IMat<3> Pt = transposed<3>(Pi);
  const Interval two_c = Interval(2.0) * Interval(c);
  for (std::size_t v = 0; v < enc.vertices.size(); ++v) {
    const LmiVertex& vx = enc.vertices[v];
    const IMat<3> W = imat(lie::hat(vx.omega));
    const IMat<3> A = imat(vx.A);
    const IMat<3> B = imat(vx.B);
    // M = [[ω̂Q − Qω̂ − 2cQ, Q + AᵀP], [Q + PA, BᵀP + PB − 2cP]] (contraction_sdp.hpp).
    const IMat<3> m11 = add(add(product<3>(W, Qi), product<3>(Qi, W), -1.0), scaled(Qi, two_c), -1.0);
    const IMat<3> m12 = add(Qi, product<3>(transposed<3>(A), Pi));
    const IMat<3> m21 = add(Qt, product<3>(Pt, A));
    IMat<3> m22 = add(add(product<3>(transposed<3>(B), Pi), product<3>(Pt, B)), scaled(Pi, two_c), -1.0);
    IMat<6> S;
    Interval shift(0.0);
    if (enc.rho > 0.0) {
      const double m = v < mu.size() ? mu[v] : 0.0;
      if (!(m > 0.0) || !std::isfinite(m)) return {false, HUGE_VAL};
      shift = Interval(m) * Interval(enc.rho) * Interval(enc.rho);
      const IMat<3> PPt = product<3>(Pi, Pt);
      for (std::size_t i = 0; i < 3; ++i) {
        for (std::size_t j = 0; j < 3; ++j) m22[i][j] += PPt[i][j] / m;
      }
    }
    for (std::size_t i = 0; i < 3; ++i) {
      for (std::size_t j = 0; j < 3; ++j) {
        S[i][j] = m11[i][j];
        S[i][j + 3] = m12[i][j];
        S[i + 3][j] = m21[i][j];
        S[i + 3][j + 3] = m22[i][j];
      }
    }
    for (std::size_t i = 0; i < 6; ++i) S[i][i] += shift;
    const NegativeDefiniteProof p = prove_negative_definite<6>(S);
    worst.proved = worst.proved && p.proved;
    worst.margin = std::max(worst.margin, p.proved ? p.margin : HUGE_VAL);
  }
  return worst;
}

NegativeDefiniteProof prove_less(const Mat3& A, const Mat3& B) {
  return prove_negative_definite<3>(add(imat(A), imat(B), -1.0));
}

}  // namespace attiguard::reach
