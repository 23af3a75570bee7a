// The dense HKM / Mehrotra interior-point solver of dense_sdp.hpp (issue 48; docs/reach.md,
// "Dense SDP solver").
//
// One iteration from (X, y, S), X ≻ 0, S ≻ 0, with rp = b − A(X), Rd = F0 + A*(y) − S, where
// A(X)_i = ⟨F_i, X⟩ and A*(y) = Σ y_i F_i:
//   M_ij = ⟨F_i, X F_j S⁻¹⟩ (the HKM Schur complement, symmetric positive definite);
//   for a target σμ and a second-order term G (0 in the predictor, dXa dSa S⁻¹ in the corrector)
//     R  = σμ S⁻¹ − X Rd S⁻¹ − G,   M dy = −b + A(R),
//     dS = Rd + A*(dy),             dX = sym(σμ S⁻¹ − G − X dS S⁻¹) − X,
// which solves A(dX) = rp, dS − A*(dy) = Rd and the linearised X S = σμ I (HKM: X dS S⁻¹
// symmetrised). With X = L_X L_Xᵀ and S = L_S L_Sᵀ (factored once per iteration), S⁻¹ = Wᵀ W for
// W = L_S⁻¹ and M_ij = ⟨G_i, G_j⟩ with G_i = W F_i L_X: M is the Gram matrix of the G_i.
// Mehrotra: the predictor (σ = 0) gives the affine steps and μ_aff, then
// σ = (μ_aff/μ)^e with SDPT3's e = max(1, 3 min(αp, αd)²), and the corrector reuses the
// factorisation of M. Steps: γ times the distance to the boundary, γ = 0.9 + 0.09 min(αp_aff,
// αd_aff), capped at 1: starting from the cap (1, or 1/γ for the corrector), a block whose
// X + α dX passes a Cholesky test keeps α; only the others compute −1/λ_min(L⁻¹ dX L⁻ᵀ).

#include "attiguard/reach/dense_sdp.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <sstream>

namespace attiguard::reach {

namespace {

// Off by default: with it on, ConReach's figures move by ~1e-6 relative (another point of the
// optimal face, and CSDP's 1e-8 infeasibility), beyond ExampleFigures' 1e-12; switching it on is
// issue 48's decision together with recapturing the figures (docs/reach.md, "Dense SDP solver").
std::atomic<bool> g_dense_sdp_enabled{false};
std::atomic<long> g_dense_sdp_accepted{0};
std::atomic<long> g_dense_sdp_fallback{0};

/// A term with at most this many non-zero entries (both triangles) is used entry by entry.
constexpr int kDenseSdpSparseEntries = 4;

/// ⟨F, V⟩ for a term, entry by entry when it is sparse.
template <class TermT>
double dense_sdp_inner(const TermT& t, const Eigen::MatrixXd& V) {
  if (!t.sparse) {
    return t.F.cwiseProduct(V).sum();
  }
  double s = 0.0;
  for (std::size_t e = 0; e < t.values.size(); ++e) {
    s += t.values[e] * V(t.rows[e], t.cols[e]);
  }
  return s;
}

/// M += a F for a term, entry by entry when it is sparse.
template <class TermT>
void dense_sdp_axpy(const TermT& t, double a, Eigen::MatrixXd& M) {
  if (!t.sparse) {
    M += a * t.F;
    return;
  }
  for (std::size_t e = 0; e < t.values.size(); ++e) {
    M(t.rows[e], t.cols[e]) += a * t.values[e];
  }
}

/// λ_min of the symmetric N×N matrix T, by Eigen's fixed-size solver (several times faster than
/// the dynamic one on these sizes).
template <int N>
double dense_sdp_min_eigenvalue(const Eigen::MatrixXd& T) {
  const Eigen::Matrix<double, N, N> A = T;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, N, N>> es(A, Eigen::EigenvaluesOnly);
  return es.eigenvalues()(0);
}

}  // namespace

DenseSdpSolver::DenseSdpSolver(const LmiProblem& problem, const DenseSdpSettings& settings)
    : problem_(&problem), settings_(settings) {
  const int m = problem.num_variables();
  b_ = problem.objective();
  y_.setZero(m);
  dy_.setZero(m);
  h_.setZero(m);
  rp_.setZero(m);
  M_.setZero(m, m);
  schur_ = Eigen::LLT<Eigen::MatrixXd>(m);
  double f0sq = 0.0;
  for (const LmiBlock& lb : problem.blocks()) {
    Block k;
    const int s = lb.size;
    k.size = s;
    n_ += s;
    k.F0 = 0.5 * (lb.F0 + lb.F0.transpose());
    f0sq += k.F0.squaredNorm();
    for (const auto& [v, F] : lb.terms) {
      Term t;
      t.var = v;
      t.F = 0.5 * (F + F.transpose());
      for (int c = 0; c < s; ++c) {
        for (int r = 0; r < s; ++r) {
          if (t.F(r, c) != 0.0) {
            t.rows.push_back(r);
            t.cols.push_back(c);
            t.values.push_back(t.F(r, c));
          }
        }
      }
      t.sparse = static_cast<int>(t.values.size()) <= kDenseSdpSparseEntries;
      k.terms.push_back(std::move(t));
    }
    for (Eigen::MatrixXd* W : {&k.X, &k.S, &k.Sinv, &k.Rd, &k.dX, &k.dS, &k.dXa, &k.dSa, &k.G,
                               &k.R, &k.T, &k.U, &k.LX, &k.W}) {
      W->setZero(s, s);
    }
    const auto nt = static_cast<Eigen::Index>(k.terms.size());
    k.Gs.setZero(static_cast<Eigen::Index>(s) * s, nt);
    k.Mb.setZero(nt, nt);
    k.I.setIdentity(s, s);
    for (Eigen::LLT<Eigen::MatrixXd>* f : {&k.lx, &k.ls, &k.chol}) {
      *f = Eigen::LLT<Eigen::MatrixXd>(s);
    }
    k.eig = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(s);
    blocks_.push_back(std::move(k));
  }
  norm_b_ = b_.norm();
  norm_f0_ = std::sqrt(f0sq);
  independent_ = constraints_independent();
}

/// Whether the F_i are linearly independent: the Gram matrix ⟨F_i, F_j⟩ (summed over the blocks)
/// has λ_min > 1e-12 λ_max. Dependent F_i make the Schur complement singular in exact arithmetic;
/// such problems are left to CSDP.
bool DenseSdpSolver::constraints_independent() {
  M_.setZero();
  for (const Block& k : blocks_) {
    for (const Term& ti : k.terms) {
      for (const Term& tj : k.terms) {
        M_(ti.var, tj.var) += ti.F.cwiseProduct(tj.F).sum();
      }
    }
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(M_, Eigen::EigenvaluesOnly);
  const Eigen::VectorXd& ev = es.eigenvalues();
  return ev(0) > 1e-12 * ev(ev.size() - 1);
}

/// SDPT3's infeasible start (Toh, Todd and Tütüncü 1999): per block X = ξ I, S = η I, y = 0, with
/// ξ = max(10, √s, s·max_i (1 + |b_i|)/(1 + ‖F_i‖)) and η = max(10, √s, ‖F0‖, max_i ‖F_i‖).
void DenseSdpSolver::initial_point() {
  y_.setZero();
  scale_ = 1.0;
  for (Block& k : blocks_) {
    const double s = k.size;
    double cx = 1.0;
    double cz = std::max(1.0, k.F0.norm());
    for (const Term& t : k.terms) {
      const double nf = t.F.norm();
      cx = std::max(cx, (1.0 + std::abs(b_(t.var))) / (1.0 + nf));
      cz = std::max(cz, nf);
    }
    const double xi = std::max({10.0, std::sqrt(s), s * cx});
    const double eta = std::max({10.0, std::sqrt(s), cz});
    k.X = xi * k.I;
    k.S = eta * k.I;
    scale_ = std::max({scale_, xi, eta});
  }
}

/// Cholesky of every X and S (false when one is not positive definite), L_X, W = L_S⁻¹,
/// S⁻¹ = Wᵀ W, Rd, rp and the measures.
bool DenseSdpSolver::factor_and_residuals() {
  rp_ = b_;
  double xs = 0.0;
  double f0x = 0.0;
  double rd2 = 0.0;
  for (Block& k : blocks_) {
    k.ls.compute(k.S);
    k.lx.compute(k.X);
    if (k.ls.info() != Eigen::Success || k.lx.info() != Eigen::Success) {
      return false;
    }
    k.LX = k.lx.matrixL();
    k.W = k.I;
    k.ls.matrixL().solveInPlace(k.W);
    k.Sinv.noalias() = k.W.transpose().lazyProduct(k.W);
    k.Rd = k.F0 - k.S;
    for (const Term& t : k.terms) {
      dense_sdp_axpy(t, y_(t.var), k.Rd);
      rp_(t.var) -= dense_sdp_inner(t, k.X);
    }
    xs += k.X.cwiseProduct(k.S).sum();
    f0x += k.F0.cwiseProduct(k.X).sum();
    rd2 += k.Rd.squaredNorm();
  }
  const double dobj = b_.dot(y_);
  const double denom = 1.0 + std::abs(dobj) + std::abs(f0x);
  info_.relative_gap = std::max(xs, std::abs(dobj + f0x)) / denom;
  info_.primal_infeasibility = rp_.norm() / (1.0 + norm_b_);
  info_.dual_infeasibility = std::sqrt(rd2) / (1.0 + norm_f0_);
  info_.primal_trace = 0.0;
  for (const Block& k : blocks_) {
    info_.primal_trace += k.X.trace();
  }
  return std::isfinite(info_.relative_gap) && std::isfinite(info_.primal_infeasibility) &&
         std::isfinite(info_.dual_infeasibility);
}

bool DenseSdpSolver::converged(double tol) const noexcept {
  return info_.relative_gap <= tol && info_.primal_infeasibility <= tol &&
         info_.dual_infeasibility <= tol;
}

/// Adds block k's part of M_ij = ⟨F_i, X F_j S⁻¹⟩ = ⟨G_i, G_j⟩, G_i = W F_i L_X (header
/// comment), to the lower triangle of M.
void DenseSdpSolver::schur_block(Block& k) {
  const int s = k.size;
  const int nt = static_cast<int>(k.terms.size());
  for (int i = 0; i < nt; ++i) {
    const Term& t = k.terms[static_cast<std::size_t>(i)];
    Eigen::Map<Eigen::MatrixXd> G(k.Gs.col(i).data(), s, s);
    if (t.sparse) {  // W F L_X = Σ f (W e_r)(e_cᵀ L_X), W and L_X lower triangular
      G.setZero();
      for (std::size_t e = 0; e < t.values.size(); ++e) {
        const int r = t.rows[e];
        const int c = t.cols[e];
        for (int q = 0; q <= c; ++q) {
          const double f = t.values[e] * k.LX(c, q);
          for (int p = r; p < s; ++p) {
            G(p, q) += f * k.W(p, r);
          }
        }
      }
    } else {
      k.U.noalias() = t.F.lazyProduct(k.LX);
      G.noalias() = k.W.lazyProduct(k.U);
    }
  }
  k.Mb.triangularView<Eigen::Lower>() = k.Gs.transpose().lazyProduct(k.Gs);
  for (int j = 0; j < nt; ++j) {
    const int vj = k.terms[static_cast<std::size_t>(j)].var;
    for (int i = 0; i < nt; ++i) {
      const int vi = k.terms[static_cast<std::size_t>(i)].var;
      if (vi >= vj) {  // the upper triangle is the lower one's mirror
        M_(vi, vj) += k.Mb(std::max(i, j), std::min(i, j));
      }
    }
  }
}

/// The Schur complement and its Cholesky factorisation (false when not positive definite).
bool DenseSdpSolver::form_schur() {
  M_.setZero();
  for (Block& k : blocks_) {
    schur_block(k);
  }
  schur_.compute(M_);  // reads the lower triangle
  // Linearly dependent F_i make M singular: a relative diagonal shift of 1e-12, then 1e-9
  // (dy is then one solution of the consistent singular system, to that accuracy).
  const double d = M_.diagonal().cwiseAbs().maxCoeff();
  for (double shift : {1e-12, 1e-9}) {
    if (schur_.info() == Eigen::Success) break;
    M_.diagonal().array() += shift * d;
    schur_.compute(M_);
  }
  return schur_.info() == Eigen::Success;
}

/// The search direction (header comment) for the target σμ; the corrector adds G = dXa dSa S⁻¹.
void DenseSdpSolver::direction(double target, bool corrector) {
  h_ = -b_;
  for (Block& k : blocks_) {
    k.U.noalias() = k.X.lazyProduct(k.Rd);
    if (corrector) {
      k.T.noalias() = k.dXa.lazyProduct(k.dSa);
      k.G.noalias() = k.T.lazyProduct(k.Sinv);
    }
    k.R.noalias() = k.U.lazyProduct(k.Sinv);
    k.R = target * k.Sinv - k.R;
    if (corrector) {
      k.R -= k.G;
    }
    for (const Term& t : k.terms) {
      h_(t.var) += dense_sdp_inner(t, k.R);
    }
  }
  dy_ = h_;
  schur_.solveInPlace(dy_);
  for (Block& k : blocks_) {
    k.dS = k.Rd;
    for (const Term& t : k.terms) {
      dense_sdp_axpy(t, dy_(t.var), k.dS);
    }
    k.U.noalias() = k.X.lazyProduct(k.dS);
    k.T.noalias() = k.U.lazyProduct(k.Sinv);
    k.T = target * k.Sinv - k.T;
    if (corrector) {
      k.T -= k.G;
    }
    k.dX = 0.5 * (k.T + k.T.transpose());
    k.dX -= k.X;
  }
}

/// Largest α with V + α D ⪰ 0 (infinity when D ⪰ 0): −1/λ_min(L⁻¹ D L⁻ᵀ), f the Cholesky
/// factorisation V = L Lᵀ of the iteration.
double DenseSdpSolver::block_step(Block& k, const Eigen::LLT<Eigen::MatrixXd>& f,
                                  const Eigen::MatrixXd& D) {
  k.U = D;
  f.matrixL().solveInPlace(k.U);
  k.T = k.U.transpose();
  f.matrixL().solveInPlace(k.T);
  double lmin = 0.0;
  switch (k.size) {
    case 3: lmin = dense_sdp_min_eigenvalue<3>(k.T); break;
    case 6: lmin = dense_sdp_min_eigenvalue<6>(k.T); break;
    case 9: lmin = dense_sdp_min_eigenvalue<9>(k.T); break;
    default:
      k.eig.compute(k.T, Eigen::EigenvaluesOnly);
      lmin = k.eig.eigenvalues()(0);
  }
  return lmin < 0.0 ? -1.0 / lmin : std::numeric_limits<double>::infinity();
}

/// min(cap, largest α with X + α dX ⪰ 0) (primal) or the same for S + α dS: a block whose
/// V + α D passes a Cholesky test at the current α keeps it; only the others need λ_min.
double DenseSdpSolver::max_step(bool primal, double cap) {
  double a = cap;
  for (Block& k : blocks_) {
    const Eigen::MatrixXd& V = primal ? k.X : k.S;
    const Eigen::MatrixXd& D = primal ? k.dX : k.dS;
    k.T = V;
    k.T += a * D;
    k.chol.compute(k.T);
    if (k.chol.info() == Eigen::Success) {
      continue;
    }
    a = std::min(a, block_step(k, primal ? k.lx : k.ls, D));
  }
  return a;
}

/// ⟨X + αp dX, S + αd dS⟩ / n.
double DenseSdpSolver::affine_mu(double ap, double ad) const {
  double s = 0.0;
  for (const Block& k : blocks_) {
    s += (k.X + ap * k.dX).cwiseProduct(k.S + ad * k.dS).sum();
  }
  return s / n_;
}

void DenseSdpSolver::update(double ap, double ad) {
  y_ += ad * dy_;
  for (Block& k : blocks_) {
    k.X += ap * k.dX;
    k.S += ad * k.dS;
    k.T = 0.5 * (k.X + k.X.transpose());
    k.X = k.T;
    k.T = 0.5 * (k.S + k.S.transpose());
    k.S = k.T;
  }
}

SdpResult DenseSdpSolver::solve(double recheck_tol) {
  initial_point();
  info_ = DenseSdpInfo{};
  if (!independent_) {
    SdpResult result;
    result.message = "dense SDP: the F_i are linearly dependent (left to CSDP)";
    return result;
  }
  bool ok = false;
  for (int it = 0;; ++it) {
    info_.iterations = it;
    if (!factor_and_residuals()) break;
    if (converged(settings_.tolerance)) {
      ok = true;
      break;
    }
    const double big = settings_.divergence * scale_;
    if (it == settings_.max_iterations || y_.cwiseAbs().maxCoeff() > big) break;
    double xs = 0.0;
    double xmax = 0.0;
    for (const Block& k : blocks_) {
      xs += k.X.cwiseProduct(k.S).sum();
      xmax = std::max(xmax, k.X.cwiseAbs().maxCoeff());
    }
    if (xmax > big || !form_schur()) break;
    const double mu = xs / n_;
    direction(0.0, false);
    const double ap_aff = max_step(true, 1.0);
    const double ad_aff = max_step(false, 1.0);
    const double mu_aff = affine_mu(ap_aff, ad_aff);
    const double expo = std::max(1.0, 3.0 * std::pow(std::min(ap_aff, ad_aff), 2));
    const double sigma = std::clamp(std::pow(std::max(mu_aff, 0.0) / mu, expo), 0.0, 1.0);
    for (Block& k : blocks_) {
      k.dXa = k.dX;
      k.dSa = k.dS;
    }
    direction(sigma * mu, true);
    const double gamma = 0.9 + 0.09 * std::min(ap_aff, ad_aff);
    const double ap = std::min(1.0, gamma * max_step(true, 1.0 / gamma));
    const double ad = std::min(1.0, gamma * max_step(false, 1.0 / gamma));
    if (!(ap > 1e-10) && !(ad > 1e-10)) break;
    update(ap, ad);
  }
  if (!ok) {
    ok = converged(settings_.loose_tolerance);
  }
  return finish(ok, recheck_tol);
}

/// The result as solve_sdp builds it: y, bᵀy and the eigenvalue re-check of sdp_solver.hpp.
SdpResult DenseSdpSolver::finish(bool ok, double recheck_tol) const {
  SdpResult result;
  std::ostringstream os;
  if (!ok || !y_.allFinite()) {
    os << "dense SDP: not solved in " << info_.iterations << " iterations (gap "
       << info_.relative_gap << ", infeasibility " << info_.primal_infeasibility << " / "
       << info_.dual_infeasibility << ")";
    result.message = os.str();
    return result;
  }
  result.min_eigenvalue = problem_->min_eigenvalue(y_);
  result.objective = b_.dot(y_);
  if (!(result.min_eigenvalue >= -recheck_tol)) {
    os << "dense SDP solution fails the eigenvalue re-check (min eigenvalue "
       << result.min_eigenvalue << ")";
    result.message = os.str();
    return result;
  }
  result.status = SdpStatus::solved;
  result.y = y_;
  os << "solved (dense, " << info_.iterations << " iterations, objective " << result.objective
     << ")";
  result.message = os.str();
  return result;
}

SdpResult solve_sdp_dense(const LmiProblem& problem, const DenseSdpSettings& settings,
                          double recheck_tol) {
  DenseSdpSolver solver(problem, settings);
  return solver.solve(recheck_tol);
}

void set_dense_sdp_enabled(bool enabled) noexcept { g_dense_sdp_enabled.store(enabled); }

bool dense_sdp_enabled() noexcept { return g_dense_sdp_enabled.load(); }

DenseSdpCounts dense_sdp_counts() noexcept {
  return DenseSdpCounts{g_dense_sdp_accepted.load(), g_dense_sdp_fallback.load()};
}

void record_dense_sdp_outcome(bool accepted) noexcept {
  if (accepted) {
    ++g_dense_sdp_accepted;
  } else {
    ++g_dense_sdp_fallback;
  }
}

}  // namespace attiguard::reach
