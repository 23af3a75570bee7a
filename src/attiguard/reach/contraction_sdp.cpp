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

/// The metric variables of the SDP as 6×6 basis matrices: Q's six, P's six, and (coupled) S's
/// nine entries [[0, e_a e_bᵀ], [e_b e_aᵀ, 0]].
std::vector<Mat6> metric_basis(bool coupled) {
  std::vector<Mat6> out;
  for (int part = 0; part < 2; ++part) {
    for (int k = 0; k < 6; ++k) {
      Mat6 E = Mat6::Zero();
      E.block<3, 3>(3 * part, 3 * part) = sym_basis(k);
      out.push_back(E);
    }
  }
  if (coupled) {
    for (int a = 0; a < 3; ++a) {
      for (int b = 0; b < 3; ++b) {
        Mat6 E = Mat6::Zero();
        E(a, 3 + b) = 1.0;
        E(3 + b, a) = 1.0;
        out.push_back(E);
      }
    }
  }
  return out;
}

StateMetric metric_from(const Eigen::VectorXd& y, const std::vector<Mat6>& basis) {
  Mat6 M = Mat6::Zero();
  for (std::size_t k = 0; k < basis.size(); ++k) M += y(static_cast<int>(k)) * basis[k];
  return {M.topLeftCorner<3, 3>(), M.topRightCorner<3, 3>(), M.bottomRightCorner<3, 3>()};
}

double max_eig(const Eigen::MatrixXd& S) {
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(0.5 * (S + S.transpose()), Eigen::EigenvaluesOnly);
  return es.eigenvalues()(es.eigenvalues().size() - 1);
}

double min_eig(const Mat6& S) { return -max_eig(-S); }

/// Largest generalised eigenvalue of X relative to the SPD matrix Y (λ_max(L⁻¹XL⁻ᵀ), Y = LLᵀ).
double relative_max_eig(const Mat6& X, const Mat6& Y) {
  const Eigen::LLT<Mat6> llt(Y);
  const Mat6 Linv = llt.matrixL().solve(Mat6::Identity());
  return max_eig(Linv * X * Linv.transpose());
}

/// Relative eigenvalue of M against M_prev; block by block for two product metrics (the
/// product metric's own formulas, kept bit for bit).
double relative_metric_eig(const StateMetric& m, const StateMetric& prev) {
  if (m.S.isZero(0.0) && prev.S.isZero(0.0)) {
    auto rel3 = [](const Mat3& X, const Mat3& Y) {
      const Eigen::LLT<Mat3> llt(Y);
      const Mat3 Linv = llt.matrixL().solve(Mat3::Identity());
      return lambda_max(Linv * X * Linv.transpose());
    };
    return std::max(rel3(m.Q, prev.Q), rel3(m.P, prev.P));
  }
  return relative_max_eig(metric_matrix(m), metric_matrix(prev));
}

/// λ_min(M_prev − M) (block by block for two product metrics).
double gap_to_prev(const StateMetric& m, const StateMetric& prev) {
  if (m.S.isZero(0.0) && prev.S.isZero(0.0)) {
    return std::min(lambda_min(prev.Q - m.Q), lambda_min(prev.P - m.P));
  }
  return min_eig(metric_matrix(prev) - metric_matrix(m));
}

/// λ_min(M) (min(λ_min Q, λ_min P) for a product metric).
double metric_min_eig(const StateMetric& m) {
  if (m.S.isZero(0.0)) return std::min(lambda_min(m.Q), lambda_min(m.P));
  return min_eig(metric_matrix(m));
}

/// M ≻ 0 and M ≺ M_prev proved in interval arithmetic (3×3 blocks for two product metrics).
bool prove_metric(const StateMetric& m, const StateMetric& prev) {
  if (m.S.isZero(0.0) && prev.S.isZero(0.0)) {
    return prove_less(Mat3(-m.Q), Mat3::Zero()).proved && prove_less(Mat3(-m.P), Mat3::Zero()).proved &&
           prove_less(m.Q, prev.Q).proved && prove_less(m.P, prev.P).proved;
  }
  const Mat6 M = metric_matrix(m);
  return prove_less(Mat6(-M), Mat6::Zero()).proved && prove_less(M, metric_matrix(prev)).proved;
}

void scale(StateMetric& m, std::vector<double>& mu, double s) {
  m.Q *= s;
  m.S *= s;
  m.P *= s;
  for (double& x : mu) x *= s;
}

/// Margin below 0 that a repaired rate leaves on the LMI's largest eigenvalue.
constexpr double kLmiMargin = 1e-12;

/// Q, P ≻ 0 and M ≻ 0 in double precision, every entry finite.
bool positive_definite(const StateMetric& m) {
  return m.Q.allFinite() && m.P.allFinite() && m.S.allFinite() && lambda_min(m.Q) > 0.0 &&
         lambda_min(m.P) > 0.0 && min_eig(metric_matrix(m)) > 0.0;
}

/// M ⪯ M_prev by scaling (M, μ) down (the LMI is homogeneous in them), at most four passes.
void scale_below_prev(const StateMetric& prev, StateMetric& m, std::vector<double>& mu, MetricSolution& sol) {
  for (int pass = 0; pass < 4; ++pass) {
    const double l = relative_metric_eig(m, prev);
    if (l <= 1.0 && gap_to_prev(m, prev) >= 0.0) break;
    scale(m, mu, (1.0 - 1e-12 * (1 << (2 * pass))) / std::max(l, 1.0));
    sol.scaled = true;
  }
}

/// The proof in outward-rounded interval arithmetic (lmi_proof.hpp): M ≻ 0, M ≺ M_prev and the
/// LMI at every vertex, in at most six attempts. A failed monotonicity proof (M = M_prev to
/// rounding) scales (M, μ) down, a failed LMI proof raises c; both keep what was proved before.
bool prove_in_intervals(const LmiEnclosure& enc, const StateMetric& prev, StateMetric& m,
                        std::vector<double>& mu, double& c, MetricSolution& sol) {
  for (int attempt = 0; attempt < 6; ++attempt) {
    if (!prove_metric(m, prev)) {
      scale(m, mu, 1.0 - 1e-12 * std::ldexp(1.0, 2 * attempt));
      sol.scaled = true;
      continue;
    }
    const NegativeDefiniteProof lmi = prove_contraction_lmi(enc, m, c, mu);
    if (lmi.proved) return true;
    const double excess = std::isfinite(lmi.margin) ? std::max(lmi.margin, 0.0) : 0.0;
    c += (excess + kLmiMargin * std::ldexp(1.0, 2 * attempt)) / (2.0 * metric_min_eig(m));
  }
  return false;
}

/// Certifies (M, μ, c) against the enclosure and the previous metric; see the header.
MetricSolution certify(const LmiEnclosure& enc, const StateMetric& prev, StateMetric m,
                       std::vector<double> mu, double c, bool rigorous) {
  MetricSolution sol;
  sol.c_requested = c;
  m.Q = 0.5 * (m.Q + m.Q.transpose());
  m.P = 0.5 * (m.P + m.P.transpose());
  if (!positive_definite(m)) {
    sol.message = "metric not positive definite";
    return sol;
  }
  scale_below_prev(prev, m, mu, sol);
  if (gap_to_prev(m, prev) < 0.0) {
    sol.message = "cannot keep M <= M_prev";
    return sol;
  }
  double worst = lmi_worst_eigenvalue(enc, m, c, mu);
  if (!std::isfinite(worst)) {
    sol.message = "robust multiplier not positive";
    return sol;
  }
  const double lmin = metric_min_eig(m);
  if (worst > -kLmiMargin) {
    c += (worst + 2.0 * kLmiMargin) / (2.0 * lmin);
    worst = lmi_worst_eigenvalue(enc, m, c, mu);
  }
  if (!(worst <= 0.0)) {
    sol.message = "LMI re-check failed";
    return sol;
  }
  const bool proved = rigorous && prove_in_intervals(enc, prev, m, mu, c, sol);
  if (rigorous && !proved) {
    sol.message = "LMI or metric bounds not proved in interval arithmetic";
    return sol;
  }
  sol.proved = proved;
  worst = lmi_worst_eigenvalue(enc, m, c, mu);
  sol.ok = true;
  sol.c = c;
  sol.Q = m.Q;
  sol.S = m.S;
  sol.P = m.P;
  sol.mu = mu;
  sol.worst_eigenvalue = worst;
  return sol;
}

}  // namespace

Mat6 contraction_lmi(const Mat6& M, const Mat3& A, const Mat3& B, const Vec3& omega, double c) {
  Mat6 F = Mat6::Zero();
  F.topLeftCorner<3, 3>() = -lie::hat(omega);
  F.topRightCorner<3, 3>() = Mat3::Identity();
  F.bottomLeftCorner<3, 3>() = A;
  F.bottomRightCorner<3, 3>() = B;
  return M * F + F.transpose() * M - 2.0 * c * M;
}

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

double lmi_worst_eigenvalue(const LmiEnclosure& enc, const StateMetric& m, double c,
                            const std::vector<double>& mu) {
  double worst = -std::numeric_limits<double>::infinity();
  const Mat6 M = metric_matrix(m);
  const Eigen::Matrix<double, 6, 3> U = M.rightCols<3>();
  const bool product = m.S.isZero(0.0);
  for (std::size_t v = 0; v < enc.vertices.size(); ++v) {
    const LmiVertex& vx = enc.vertices[v];
    Mat6 S = product ? contraction_lmi(m.Q, m.P, vx.A, vx.B, vx.omega, c)
                     : contraction_lmi(M, vx.A, vx.B, vx.omega, c);
    if (enc.rho > 0.0) {
      const double mv = v < mu.size() ? mu[v] : 0.0;
      if (!(mv > 0.0)) return std::numeric_limits<double>::infinity();
      S += mv * enc.rho * enc.rho * Mat6::Identity() + (U * U.transpose()) / mv;
    }
    worst = std::max(worst, max_eig(S));
  }
  return worst;
}

double lmi_worst_eigenvalue(const LmiEnclosure& enc, const Mat3& Q, const Mat3& P, double c,
                            const std::vector<double>& mu) {
  return lmi_worst_eigenvalue(enc, StateMetric{Q, Mat3::Zero(), P}, c, mu);
}

double identity_metric_rate(const LmiEnclosure& enc) {
  double c = -std::numeric_limits<double>::infinity();
  for (const LmiVertex& vx : enc.vertices) {
    const Mat6 M0 = contraction_lmi(Mat3::Identity(), Mat3::Identity(), vx.A, vx.B, vx.omega, 0.0);
    c = std::max(c, 0.5 * max_eig(M0) + enc.rho);
  }
  return c;
}

MetricSolution fallback_metric(const LmiEnclosure& enc, const StateMetric& prev, bool rigorous) {
  const double s = metric_min_eig(prev) * (1.0 - 1e-12);
  const std::vector<double> mu(enc.vertices.size(), enc.rho > 0.0 ? s / enc.rho : 0.0);
  MetricSolution sol = certify(enc, prev, {s * Mat3::Identity(), Mat3::Zero(), s * Mat3::Identity()},
                               mu, identity_metric_rate(enc), rigorous);
  sol.status = SdpStatus::failed;
  sol.message = sol.ok ? "fallback Q = P = s I at the identity-metric rate"
                       : "fallback Q = P = s I at the identity-metric rate: " + sol.message;
  return sol;
}

MetricSolution fallback_metric(const LmiEnclosure& enc, const Mat3& Q_prev, const Mat3& P_prev) {
  return fallback_metric(enc, StateMetric{Q_prev, Mat3::Zero(), P_prev}, true);
}

MetricSolution solve_metric(const LmiEnclosure& enc, const Mat3& Q_prev, const Mat3& P_prev,
                            double c, MetricObjective objective, const MetricSdpSettings& settings) {
  MetricSdpSettings product = settings;
  product.coupled = false;
  return solve_metric(enc, StateMetric{Q_prev, Mat3::Zero(), P_prev}, c, objective, product);
}

namespace {

/// The variables of the SDP [ConReach eq. (20)]: the metric's entries (metric_basis), then one multiplier μ_v
/// per vertex when the enclosure is robust (ρ > 0), then t for the max_min_eigenvalue objective.
struct SdpLayout {
  std::vector<Mat6> basis;
  int nm{0};         ///< metric variables
  int nv{0};         ///< vertices of the enclosure
  bool robust{false};
  bool enclosure{false};  ///< MetricObjective::max_min_eigenvalue
  int mu0{0};        ///< index of μ_0
  int t_var{0};      ///< index of t
  int nvar{0};
};

SdpLayout sdp_layout(const LmiEnclosure& enc, MetricObjective objective, bool coupled) {
  SdpLayout l;
  l.basis = metric_basis(coupled);
  l.nm = static_cast<int>(l.basis.size());
  l.nv = static_cast<int>(enc.vertices.size());
  l.robust = enc.rho > 0.0;
  l.enclosure = objective == MetricObjective::max_min_eigenvalue;
  l.mu0 = l.nm;
  l.t_var = l.mu0 + (l.robust ? l.nv : 0);
  l.nvar = l.t_var + (l.enclosure ? 1 : 0);
  return l;
}

/// Product metric: Q_floor I ⪯ Q ⪯ Q_prev, P_floor I ⪯ P ⪯ P_prev (and tI ⪯ Q, tI ⪯ P).
void add_product_bounds(LmiProblem& prob, const StateMetric& prev, const MetricSdpSettings& settings,
                        const SdpLayout& l) {
  for (int part = 0; part < 2; ++part) {
    const int off = part == 0 ? 0 : 6;
    const double floor = part == 0 ? settings.q_floor : settings.p_floor;
    const Mat3& pm = part == 0 ? prev.Q : prev.P;
    const int lo = prob.add_block(3);
    const int hi = prob.add_block(3);
    prob.add_constant(lo, -floor * Eigen::MatrixXd::Identity(3, 3));
    prob.add_constant(hi, pm);
    for (int k = 0; k < 6; ++k) {
      prob.add_term(lo, off + k, sym_basis(k));
      prob.add_term(hi, off + k, -sym_basis(k));
    }
    if (l.enclosure) {
      const int tb = prob.add_block(3);
      for (int k = 0; k < 6; ++k) prob.add_term(tb, off + k, sym_basis(k));
      prob.add_term(tb, l.t_var, -Eigen::MatrixXd::Identity(3, 3));
    }
  }
}

/// Coupled metric: diag(Q_floor I, P_floor I) ⪯ M ⪯ M_prev; tI ⪯ Q − SP⁻¹Sᵀ ⟺ M − diag(tI, 0) ⪰ 0,
/// and tI ⪯ P − SᵀQ⁻¹S ⟺ M − diag(0, tI) ⪰ 0 (Schur complements, P ≻ 0 and Q ≻ 0).
void add_coupled_bounds(LmiProblem& prob, const StateMetric& prev, const MetricSdpSettings& settings,
                        const SdpLayout& l) {
  Mat6 floor = Mat6::Zero();
  floor.topLeftCorner<3, 3>() = settings.q_floor * Mat3::Identity();
  floor.bottomRightCorner<3, 3>() = settings.p_floor * Mat3::Identity();
  const int lo = prob.add_block(6);
  const int hi = prob.add_block(6);
  prob.add_constant(lo, -floor);
  prob.add_constant(hi, metric_matrix(prev));
  for (int k = 0; k < l.nm; ++k) {
    prob.add_term(lo, k, l.basis[static_cast<std::size_t>(k)]);
    prob.add_term(hi, k, -l.basis[static_cast<std::size_t>(k)]);
  }
  if (l.enclosure) {
    for (int part = 0; part < 2; ++part) {
      const int tb = prob.add_block(6);
      for (int k = 0; k < l.nm; ++k) prob.add_term(tb, k, l.basis[static_cast<std::size_t>(k)]);
      Eigen::MatrixXd T = Eigen::MatrixXd::Zero(6, 6);
      T.block(3 * part, 3 * part, 3, 3) = -Eigen::MatrixXd::Identity(3, 3);
      prob.add_term(tb, l.t_var, T);
    }
  }
}

/// The contraction LMI at every vertex, ⪯ −strictness·I; robustly (the 9×9 Schur form of
/// contraction_sdp.hpp, multiplier μ_v) when ρ > 0.
void add_contraction_lmis(LmiProblem& prob, const LmiEnclosure& enc, double c,
                          const MetricSdpSettings& settings, const SdpLayout& l) {
  const int n = l.robust ? 9 : 6;
  for (int v = 0; v < l.nv; ++v) {
    const LmiVertex& vx = enc.vertices[static_cast<std::size_t>(v)];
    const int b = prob.add_block(n);
    prob.add_constant(b, -settings.strictness * Eigen::MatrixXd::Identity(n, n));
    for (int k = 0; k < l.nm; ++k) {
      const Mat6& E = l.basis[static_cast<std::size_t>(k)];
      Eigen::MatrixXd Fk = Eigen::MatrixXd::Zero(n, n);
      Fk.topLeftCorner(6, 6) = -contraction_lmi(E, vx.A, vx.B, vx.omega, c);
      if (l.robust) {
        Fk.block(0, 6, 6, 3) = -E.rightCols<3>();
        Fk.block(6, 0, 3, 6) = -E.rightCols<3>().transpose();
      }
      prob.add_term(b, k, Fk);
    }
    if (l.robust) {
      Eigen::MatrixXd Fm = Eigen::MatrixXd::Zero(n, n);
      Fm.topLeftCorner(6, 6) = -enc.rho * enc.rho * Eigen::MatrixXd::Identity(6, 6);
      Fm.bottomRightCorner(3, 3) = Eigen::MatrixXd::Identity(3, 3);
      prob.add_term(b, l.mu0 + v, Fm);
    }
  }
}

/// max_min_eigenvalue: minimise −t − 10⁻³(tr Q + tr P); max_trace_q: minimise −tr(Q) (the
/// paper's (20)).
void set_sdp_objective(LmiProblem& prob, const SdpLayout& l) {
  if (l.enclosure) {
    prob.set_objective(l.t_var, -1.0);
    for (int k = 0; k < 3; ++k) {
      prob.set_objective(k, -1e-3);
      prob.set_objective(6 + k, -1e-3);
    }
  } else {
    for (int k = 0; k < 3; ++k) prob.set_objective(k, -1.0);
  }
}

/// metric_problem on the layout `l` (= sdp_layout(enc, objective, settings.coupled)).
LmiProblem metric_problem_on(const LmiEnclosure& enc, const StateMetric& prev, double c,
                             const MetricSdpSettings& settings, const SdpLayout& l) {
  LmiProblem prob(l.nvar);
  if (!settings.coupled) {
    add_product_bounds(prob, prev, settings, l);
  } else {
    add_coupled_bounds(prob, prev, settings, l);
  }
  add_contraction_lmis(prob, enc, c, settings, l);
  set_sdp_objective(prob, l);
  return prob;
}

}  // namespace

LmiProblem metric_problem(const LmiEnclosure& enc, const StateMetric& prev, double c,
                          MetricObjective objective, const MetricSdpSettings& settings) {
  return metric_problem_on(enc, prev, c, settings, sdp_layout(enc, objective, settings.coupled));
}

MetricSolution solve_metric(const LmiEnclosure& enc, const StateMetric& prev, double c,
                            MetricObjective objective, const MetricSdpSettings& settings) {
  const SdpLayout l = sdp_layout(enc, objective, settings.coupled);
  const LmiProblem prob = metric_problem_on(enc, prev, c, settings, l);

  const SdpResult res = solve_sdp(prob, settings.sdp, 1e-7);
  if (res.status != SdpStatus::solved) {
    MetricSolution sol;
    sol.c_requested = c;
    sol.status = res.status;
    sol.message = res.message;
    return sol;
  }
  std::vector<double> mu;
  if (l.robust) {
    for (int v = 0; v < l.nv; ++v) mu.push_back(res.y(l.mu0 + v));
  }
  MetricSolution sol = certify(enc, prev, metric_from(res.y, l.basis), mu, c, settings.rigorous);
  sol.status = sol.ok ? SdpStatus::solved : SdpStatus::failed;
  if (sol.ok) sol.message = res.message;
  return sol;
}

}  // namespace attiguard::reach
