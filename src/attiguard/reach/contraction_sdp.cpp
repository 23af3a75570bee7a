#include "attiguard/reach/contraction_sdp.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>
#include <sstream>

#include "attiguard/reach/lmi_proof.hpp"
#include "attiguard/reach/metrics.hpp"

namespace attiguard::reach {

namespace {

constexpr int kSym[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}};

Mat3 sym_basis(int k) {
  Mat3 E = Mat3::Zero();
  E(kSym[k][0], kSym[k][1]) = 1.0;
  E(kSym[k][1], kSym[k][0]) = 1.0;
  return E;
}

Mat3 sym_from(const Eigen::VectorXd& y, int offset) {
  Mat3 S = Mat3::Zero();
  for (int k = 0; k < 6; ++k) S += y(offset + k) * sym_basis(k);
  return S;
}

double max_eig(const Eigen::MatrixXd& S) {
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(0.5 * (S + S.transpose()), Eigen::EigenvaluesOnly);
  return es.eigenvalues()(es.eigenvalues().size() - 1);
}

/// Largest generalised eigenvalue of X relative to the SPD matrix Y (λ_max(L⁻¹XL⁻ᵀ), Y = LLᵀ).
double relative_max_eig(const Mat3& X, const Mat3& Y) {
  const Eigen::LLT<Mat3> llt(Y);
  const Mat3 Linv = llt.matrixL().solve(Mat3::Identity());
  return lambda_max(Linv * X * Linv.transpose());
}

/// Certifies (Q, P, μ, c) against the enclosure and the previous metric; see the header.
MetricSolution certify(const LmiEnclosure& enc, const Mat3& Q_prev, const Mat3& P_prev, Mat3 Q,
                       Mat3 P, std::vector<double> mu, double c) {
  MetricSolution sol;
  sol.c_requested = c;
  Q = 0.5 * (Q + Q.transpose());
  P = 0.5 * (P + P.transpose());
  if (!Q.allFinite() || !P.allFinite() || !(lambda_min(Q) > 0.0) || !(lambda_min(P) > 0.0)) {
    sol.message = "metric not positive definite";
    return sol;
  }
  for (int pass = 0; pass < 4; ++pass) {
    const double lq = relative_max_eig(Q, Q_prev);
    const double lp = relative_max_eig(P, P_prev);
    const double l = std::max(lq, lp);
    if (l <= 1.0 && lambda_min(Q_prev - Q) >= 0.0 && lambda_min(P_prev - P) >= 0.0) break;
    const double s = (1.0 - 1e-12 * (1 << (2 * pass))) / std::max(l, 1.0);
    Q *= s;
    P *= s;
    for (double& m : mu) m *= s;
    sol.scaled = true;
  }
  if (lambda_min(Q_prev - Q) < 0.0 || lambda_min(P_prev - P) < 0.0) {
    sol.message = "cannot keep Q <= Q_prev, P <= P_prev";
    return sol;
  }
  double worst = lmi_worst_eigenvalue(enc, Q, P, c, mu);
  if (!std::isfinite(worst)) {
    sol.message = "robust multiplier not positive";
    return sol;
  }
  const double lmin = std::min(lambda_min(Q), lambda_min(P));
  constexpr double kMargin = 1e-12;
  if (worst > -kMargin) {
    c += (worst + 2.0 * kMargin) / (2.0 * lmin);
    worst = lmi_worst_eigenvalue(enc, Q, P, c, mu);
  }
  if (!(worst <= 0.0)) {
    sol.message = "LMI re-check failed";
    return sol;
  }
  // The proof in outward-rounded interval arithmetic (lmi_proof.hpp): Q, P ≻ 0, Q ≺ Q_prev,
  // P ≺ P_prev and the LMI at every vertex. A failed monotonicity proof (Q = Q_prev to rounding)
  // scales (Q, P, μ) down, a failed LMI proof raises c; both keep what was proved before.
  bool proved = false;
  for (int attempt = 0; attempt < 6 && !proved; ++attempt) {
    const bool metric_ok = prove_less(-Q, Mat3::Zero()).proved && prove_less(-P, Mat3::Zero()).proved &&
                           prove_less(Q, Q_prev).proved && prove_less(P, P_prev).proved;
    if (!metric_ok) {
      const double s = 1.0 - 1e-12 * std::ldexp(1.0, 2 * attempt);
      Q *= s;
      P *= s;
      for (double& m : mu) m *= s;
      sol.scaled = true;
      continue;
    }
    const NegativeDefiniteProof lmi = prove_contraction_lmi(enc, Q, P, c, mu);
    if (lmi.proved) {
      proved = true;
      break;
    }
    const double excess = std::isfinite(lmi.margin) ? std::max(lmi.margin, 0.0) : 0.0;
    c += (excess + kMargin * std::ldexp(1.0, 2 * attempt)) / (2.0 * std::min(lambda_min(Q), lambda_min(P)));
  }
  if (!proved) {
    sol.message = "LMI or metric bounds not proved in interval arithmetic";
    return sol;
  }
  worst = lmi_worst_eigenvalue(enc, Q, P, c, mu);
  sol.ok = true;
  sol.c = c;
  sol.Q = Q;
  sol.P = P;
  sol.worst_eigenvalue = worst;
  return sol;
}

}  // namespace

Mat6 contraction_lmi(const Mat3& Q, const Mat3& P, const Mat3& A, const Mat3& B, const Vec3& omega,
                     double c) {
  const Mat3 W = lie::hat(omega);
  Mat6 M;
  M.topLeftCorner<3, 3>() = W * Q - Q * W - 2.0 * c * Q;
  M.topRightCorner<3, 3>() = Q + A.transpose() * P;
  M.bottomLeftCorner<3, 3>() = Q + P * A;
  M.bottomRightCorner<3, 3>() = B.transpose() * P + P * B - 2.0 * c * P;
  return M;
}

double lmi_worst_eigenvalue(const LmiEnclosure& enc, const Mat3& Q, const Mat3& P, double c,
                            const std::vector<double>& mu) {
  double worst = -std::numeric_limits<double>::infinity();
  Eigen::Matrix<double, 6, 3> U = Eigen::Matrix<double, 6, 3>::Zero();
  U.bottomRows<3>() = P;
  for (std::size_t v = 0; v < enc.vertices.size(); ++v) {
    const LmiVertex& vx = enc.vertices[v];
    Mat6 S = contraction_lmi(Q, P, vx.A, vx.B, vx.omega, c);
    if (enc.rho > 0.0) {
      const double m = v < mu.size() ? mu[v] : 0.0;
      if (!(m > 0.0)) return std::numeric_limits<double>::infinity();
      S += m * enc.rho * enc.rho * Mat6::Identity() + (U * U.transpose()) / m;
    }
    worst = std::max(worst, max_eig(S));
  }
  return worst;
}

double identity_metric_rate(const LmiEnclosure& enc) {
  double c = -std::numeric_limits<double>::infinity();
  for (const LmiVertex& vx : enc.vertices) {
    const Mat6 M0 = contraction_lmi(Mat3::Identity(), Mat3::Identity(), vx.A, vx.B, vx.omega, 0.0);
    c = std::max(c, 0.5 * max_eig(M0) + enc.rho);
  }
  return c;
}

MetricSolution fallback_metric(const LmiEnclosure& enc, const Mat3& Q_prev, const Mat3& P_prev) {
  const double s = std::min(lambda_min(Q_prev), lambda_min(P_prev)) * (1.0 - 1e-12);
  const std::vector<double> mu(enc.vertices.size(), enc.rho > 0.0 ? s / enc.rho : 0.0);
  MetricSolution sol = certify(enc, Q_prev, P_prev, s * Mat3::Identity(), s * Mat3::Identity(), mu,
                               identity_metric_rate(enc));
  sol.status = SdpStatus::failed;
  sol.message = "fallback Q = P = s I at the identity-metric rate";
  return sol;
}

MetricSolution solve_metric(const LmiEnclosure& enc, const Mat3& Q_prev, const Mat3& P_prev,
                            double c, MetricObjective objective, const MetricSdpSettings& settings) {
  const int nv = static_cast<int>(enc.vertices.size());
  const bool robust = enc.rho > 0.0;
  const bool enclosure = objective == MetricObjective::max_min_eigenvalue;
  const int mu0 = 12;
  const int t_var = mu0 + (robust ? nv : 0);
  const int nvar = t_var + (enclosure ? 1 : 0);
  LmiProblem prob(nvar);

  // Q_floor I ⪯ Q ⪯ Q_prev, P_floor I ⪯ P ⪯ P_prev (and tI ⪯ Q, tI ⪯ P).
  for (int part = 0; part < 2; ++part) {
    const int off = part == 0 ? 0 : 6;
    const double floor = part == 0 ? settings.q_floor : settings.p_floor;
    const Mat3& prev = part == 0 ? Q_prev : P_prev;
    const int lo = prob.add_block(3);
    const int hi = prob.add_block(3);
    prob.add_constant(lo, -floor * Eigen::MatrixXd::Identity(3, 3));
    prob.add_constant(hi, prev);
    for (int k = 0; k < 6; ++k) {
      prob.add_term(lo, off + k, sym_basis(k));
      prob.add_term(hi, off + k, -sym_basis(k));
    }
    if (enclosure) {
      const int tb = prob.add_block(3);
      for (int k = 0; k < 6; ++k) prob.add_term(tb, off + k, sym_basis(k));
      prob.add_term(tb, t_var, -Eigen::MatrixXd::Identity(3, 3));
    }
  }
  // The contraction LMI at every vertex.
  const int n = robust ? 9 : 6;
  for (int v = 0; v < nv; ++v) {
    const LmiVertex& vx = enc.vertices[static_cast<std::size_t>(v)];
    const int b = prob.add_block(n);
    prob.add_constant(b, -settings.strictness * Eigen::MatrixXd::Identity(n, n));
    for (int k = 0; k < 6; ++k) {
      Eigen::MatrixXd Fq = Eigen::MatrixXd::Zero(n, n);
      Fq.topLeftCorner(6, 6) = -contraction_lmi(sym_basis(k), Mat3::Zero(), vx.A, vx.B, vx.omega, c);
      prob.add_term(b, k, Fq);
      Eigen::MatrixXd Fp = Eigen::MatrixXd::Zero(n, n);
      Fp.topLeftCorner(6, 6) = -contraction_lmi(Mat3::Zero(), sym_basis(k), vx.A, vx.B, vx.omega, c);
      if (robust) {
        Fp.block(3, 6, 3, 3) = -sym_basis(k);
        Fp.block(6, 3, 3, 3) = -sym_basis(k);
      }
      prob.add_term(b, 6 + k, Fp);
    }
    if (robust) {
      Eigen::MatrixXd Fm = Eigen::MatrixXd::Zero(n, n);
      Fm.topLeftCorner(6, 6) = -enc.rho * enc.rho * Eigen::MatrixXd::Identity(6, 6);
      Fm.bottomRightCorner(3, 3) = Eigen::MatrixXd::Identity(3, 3);
      prob.add_term(b, mu0 + v, Fm);
    }
  }
  if (enclosure) {
    prob.set_objective(t_var, -1.0);
    for (int k = 0; k < 3; ++k) {
      prob.set_objective(k, -1e-3);
      prob.set_objective(6 + k, -1e-3);
    }
  } else {
    for (int k = 0; k < 3; ++k) prob.set_objective(k, -1.0);
  }

  const SdpResult res = solve_sdp(prob, settings.sdp, 1e-7);
  if (res.status != SdpStatus::solved) {
    MetricSolution sol;
    sol.c_requested = c;
    sol.status = res.status;
    sol.message = res.message;
    return sol;
  }
  std::vector<double> mu;
  if (robust) {
    for (int v = 0; v < nv; ++v) mu.push_back(res.y(mu0 + v));
  }
  MetricSolution sol = certify(enc, Q_prev, P_prev, sym_from(res.y, 0), sym_from(res.y, 6), mu, c);
  sol.status = sol.ok ? SdpStatus::solved : SdpStatus::failed;
  if (sol.ok) sol.message = res.message;
  return sol;
}

}  // namespace attiguard::reach
