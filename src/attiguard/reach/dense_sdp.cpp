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
#include <optional>
#include <type_traits>
#include <sstream>
#include <time.h>

namespace attiguard::reach {

namespace {

// The process-wide switch of set_dense_sdp_enabled (tests, benchmarks): off, each call's
// SdpSettings::solver decides (docs/reach.md, "Dense SDP solver").
std::atomic<bool> g_dense_sdp_enabled{false};
std::atomic<long> g_dense_sdp_accepted{0};
std::atomic<long> g_dense_sdp_fallback{0};
std::atomic<long> g_dense_sdp_infeasible{0};
std::atomic<long> g_csdp_solves{0};
std::atomic<long> g_dense_sdp_iterations{0};
std::atomic<long long> g_dense_sdp_nanoseconds{0};
std::atomic<long long> g_csdp_nanoseconds{0};

template <int N>
using BlockMat = Eigen::Matrix<double, N, N>;
template <int N>
using BlockMap = Eigen::Map<BlockMat<N>>;
template <int N>
using ConstBlockMap = Eigen::Map<const BlockMat<N>>;

/// A block's matrix seen with its size fixed at compile time (N = Eigen::Dynamic: as it is).
template <int N>
BlockMap<N> fixed(Eigen::MatrixXd& A) {
  return BlockMap<N>(A.data(), A.rows(), A.cols());
}
template <int N>
ConstBlockMap<N> fixed(const Eigen::MatrixXd& A) {
  return ConstBlockMap<N>(A.data(), A.rows(), A.cols());
}

/// Calls f(std::integral_constant<int, N>{}) with N = s for the block sizes compiled fixed (those
/// of ConReach's LMIs: 3, 6 and 9) and N = Eigen::Dynamic for the others.
template <class F>
decltype(auto) with_block_size(int s, F&& f) {
  switch (s) {
    case 3: return f(std::integral_constant<int, 3>{});
    case 6: return f(std::integral_constant<int, 6>{});
    case 9: return f(std::integral_constant<int, 9>{});
    default: return f(std::integral_constant<int, Eigen::Dynamic>{});
  }
}

/// L with L Lᵀ = A (lower triangular, upper triangle zero); false when A is not positive definite
/// (or not finite). Reads the lower triangle of A.
template <class MatA, class MatL>
bool cholesky_lower(const MatA& A, MatL&& L) {
  const Eigen::Index s = A.rows();
  for (Eigen::Index j = 0; j < s; ++j) {
    double d = A(j, j);
    for (Eigen::Index q = 0; q < j; ++q) d -= L(j, q) * L(j, q);
    if (!(d > 0.0)) return false;
    const double ljj = std::sqrt(d);
    L(j, j) = ljj;
    for (Eigen::Index i = j + 1; i < s; ++i) {
      double v = A(i, j);
      for (Eigen::Index q = 0; q < j; ++q) v -= L(i, q) * L(j, q);
      L(i, j) = v / ljj;
    }
    for (Eigen::Index i = 0; i < j; ++i) L(i, j) = 0.0;
  }
  return true;
}

/// W = L⁻¹ for a lower-triangular L with a positive diagonal (forward substitution).
template <class MatL, class MatW>
void lower_inverse(const MatL& L, MatW&& W) {
  const Eigen::Index s = L.rows();
  W.setZero();
  for (Eigen::Index j = 0; j < s; ++j) {
    W(j, j) = 1.0 / L(j, j);
    for (Eigen::Index i = j + 1; i < s; ++i) {
      double v = 0.0;
      for (Eigen::Index q = j; q < i; ++q) v -= L(i, q) * W(q, j);
      W(i, j) = v / L(i, i);
    }
  }
}

/// ⟨F, V⟩ for a term, entry by entry when it is sparse.
template <int N, class TermT, class V>
double dense_sdp_inner(const TermT& t, const V& v) {
  if (!t.sparse) {
    return fixed<N>(t.F).cwiseProduct(v).sum();
  }
  double s = 0.0;
  for (std::size_t e = 0; e < t.values.size(); ++e) {
    s += t.values[e] * v(t.rows[e], t.cols[e]);
  }
  return s;
}

/// M += a F for a term, entry by entry when it is sparse.
template <int N, class TermT, class Mt>
void dense_sdp_axpy(const TermT& t, double a, Mt&& m) {
  if (!t.sparse) {
    m += a * fixed<N>(t.F);
    return;
  }
  for (std::size_t e = 0; e < t.values.size(); ++e) {
    m(t.rows[e], t.cols[e]) += a * t.values[e];
  }
}

/// λ_min of a symmetric block: Eigen's fixed-size solver where N is fixed (several times faster
/// than the dynamic one on these sizes), the block's preallocated solver otherwise.
template <int N>
double block_min_eigenvalue(const Eigen::MatrixXd& T,
                            Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>& eig) {
  if constexpr (N == Eigen::Dynamic) {
    eig.compute(T, Eigen::EigenvaluesOnly);
    return eig.eigenvalues()(0);
  } else {
    const BlockMat<N> A = fixed<N>(T);
    const Eigen::SelfAdjointEigenSolver<BlockMat<N>> es(A, Eigen::EigenvaluesOnly);
    return es.eigenvalues()(0);
  }
}

/// Symmetrised F of a term and its non-zero entries (both triangles); storage reused.
template <class TermT>
void load_term(TermT& t, const Eigen::MatrixXd& F, int s) {
  t.F = 0.5 * (F + F.transpose());
  t.rows.clear();
  t.cols.clear();
  t.values.clear();
  for (int c = 0; c < s; ++c) {
    for (int r = 0; r < s; ++r) {
      if (t.F(r, c) != 0.0) {
        t.rows.push_back(r);
        t.cols.push_back(c);
        t.values.push_back(t.F(r, c));
      }
    }
  }
  const auto nnz = static_cast<int>(t.values.size());
  t.sparse = 2 * nnz <= s * s;
  t.outer = nnz < 2 * s;
}

}  // namespace

DenseSdpSolver::DenseSdpSolver(const LmiProblem& problem, const DenseSdpSettings& settings)
    : problem_(&problem), settings_(settings) {
  const int m = problem.num_variables();
  y_.setZero(m);
  dy_.setZero(m);
  h_.setZero(m);
  rp_.setZero(m);
  M_.setZero(m, m);
  schur_ = Eigen::LLT<Eigen::MatrixXd>(m);
  gram_eig_ = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(m);
  for (const LmiBlock& lb : problem.blocks()) {
    Block k;
    const int s = lb.size;
    k.size = s;
    n_ += s;
    for (const auto& term : lb.terms) {
      Term t;
      t.var = term.first;
      t.rows.reserve(static_cast<std::size_t>(s) * s);
      t.cols.reserve(static_cast<std::size_t>(s) * s);
      t.values.reserve(static_cast<std::size_t>(s) * s);
      k.terms.push_back(std::move(t));
    }
    for (Eigen::MatrixXd* W : {&k.F0, &k.X, &k.S, &k.Sinv, &k.Rd, &k.dX, &k.dS, &k.dXa, &k.dSa,
                               &k.G, &k.R, &k.T, &k.U, &k.LX, &k.WX, &k.W}) {
      W->setZero(s, s);
    }
    const auto nt = static_cast<Eigen::Index>(k.terms.size());
    k.Gs.setZero(static_cast<Eigen::Index>(s) * s, nt);
    k.eig = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(s);
    blocks_.push_back(std::move(k));
  }
  load(problem);
}

bool DenseSdpSolver::same_shape(const LmiProblem& problem) const noexcept {
  if (problem.num_variables() != y_.size() || problem.blocks().size() != blocks_.size()) {
    return false;
  }
  for (std::size_t i = 0; i < blocks_.size(); ++i) {
    const LmiBlock& lb = problem.blocks()[i];
    const Block& k = blocks_[i];
    if (lb.size != k.size || lb.terms.size() != k.terms.size()) return false;
    for (std::size_t j = 0; j < k.terms.size(); ++j) {
      if (lb.terms[j].first != k.terms[j].var) return false;
    }
  }
  return true;
}

bool DenseSdpSolver::reload(const LmiProblem& problem) {
  if (!same_shape(problem)) return false;
  problem_ = &problem;
  load(problem);
  return true;
}

/// Copies the problem's data into the solver's storage (same shape) and redoes the measures and
/// the independence test.
void DenseSdpSolver::load(const LmiProblem& problem) {
  b_ = problem.objective();
  double f0sq = 0.0;
  for (std::size_t i = 0; i < blocks_.size(); ++i) {
    const LmiBlock& lb = problem.blocks()[i];
    Block& k = blocks_[i];
    k.F0 = 0.5 * (lb.F0 + lb.F0.transpose());
    f0sq += k.F0.squaredNorm();
    for (std::size_t j = 0; j < k.terms.size(); ++j) {
      load_term(k.terms[j], lb.terms[j].second, k.size);
    }
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
        double g = 0.0;
        for (std::size_t e = 0; e < ti.values.size(); ++e) {
          g += ti.values[e] * tj.F(ti.rows[e], ti.cols[e]);
        }
        M_(ti.var, tj.var) += g;
      }
    }
  }
  gram_eig_.compute(M_, Eigen::EigenvaluesOnly);
  const Eigen::VectorXd& ev = gram_eig_.eigenvalues();
  return ev(0) > 1e-12 * ev(ev.size() - 1);
}

/// SDPT3's infeasible start (Toh, Todd and Tütüncü 1999): per block X = ξ I, S = η I, y = 0, with
/// ξ = max(10, √s, s·max_i (1 + |b_i|)/(1 + ‖F_i‖)) and η = max(10, √s, ‖F0‖, max_i ‖F_i‖).
void DenseSdpSolver::initial_point() {
  limiting_ = {0, 0};
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
    k.X = xi * Eigen::MatrixXd::Identity(k.size, k.size);
    k.S = eta * Eigen::MatrixXd::Identity(k.size, k.size);
    scale_ = std::max({scale_, xi, eta});
  }
}

/// Block k's part of factor_and_residuals: L_X, L_X⁻¹, W = L_S⁻¹, S⁻¹ = Wᵀ W, Rd = F0 + A*(y) −
/// S, rp −= A(X) and the sums (false when X or S is not positive definite).
template <int N>
bool DenseSdpSolver::factor_block(Block& k, Sums& sums) {
  const auto X = fixed<N>(k.X);
  const auto S = fixed<N>(k.S);
  auto LS = fixed<N>(k.U);
  if (!cholesky_lower(S, LS) || !cholesky_lower(X, fixed<N>(k.LX))) {
    return false;
  }
  k.wx_ready = false;  // L_X⁻¹ only when a primal step test needs it (block_step)
  lower_inverse(fixed<N>(k.U), fixed<N>(k.W));
  const auto W = fixed<N>(k.W);
  fixed<N>(k.Sinv).noalias() = W.transpose().lazyProduct(W);
  auto Rd = fixed<N>(k.Rd);
  Rd = fixed<N>(k.F0) - S;
  for (const Term& t : k.terms) {
    dense_sdp_axpy<N>(t, y_(t.var), Rd);
    rp_(t.var) -= dense_sdp_inner<N>(t, X);
  }
  sums.xs += X.cwiseProduct(S).sum();
  sums.f0x += fixed<N>(k.F0).cwiseProduct(X).sum();
  sums.rd2 += Rd.squaredNorm();
  return true;
}

/// Cholesky of every X and S (false when one is not positive definite), L_X, W = L_S⁻¹,
/// S⁻¹ = Wᵀ W, Rd, rp and the measures.
bool DenseSdpSolver::factor_and_residuals() {
  rp_ = b_;
  Sums sums;
  for (Block& k : blocks_) {
    if (!with_block_size(k.size, [&](auto n) { return factor_block<decltype(n)::value>(k, sums); })) {
      return false;
    }
  }
  const double dobj = b_.dot(y_);
  const double denom = 1.0 + std::abs(dobj) + std::abs(sums.f0x);
  info_.relative_gap = std::max(sums.xs, std::abs(dobj + sums.f0x)) / denom;
  info_.primal_infeasibility = rp_.norm() / (1.0 + norm_b_);
  info_.dual_infeasibility = std::sqrt(sums.rd2) / (1.0 + norm_f0_);
  info_.primal_trace = 0.0;
  for (const Block& k : blocks_) {
    info_.primal_trace += k.X.trace();
  }
  const double ax = (b_ - rp_).norm();  // ‖A(X)‖
  info_.feasible_y_norm_bound = sums.f0x < 0.0 ? -sums.f0x / ax : 0.0;
  info_.infeasible = info_.feasible_y_norm_bound >=
                     settings_.infeasibility_ratio * std::max(1.0, y_.norm());
  return std::isfinite(info_.relative_gap) && std::isfinite(info_.primal_infeasibility) &&
         std::isfinite(info_.dual_infeasibility);
}

bool DenseSdpSolver::converged(double tol) const noexcept {
  return info_.relative_gap <= tol && info_.primal_infeasibility <= tol &&
         info_.dual_infeasibility <= tol;
}

/// Adds block k's part of M_ij = ⟨F_i, X F_j S⁻¹⟩ (header comment) to the lower triangle of M:
/// P_j = X F_j S⁻¹ for every term (by outer products X e_r · e_cᵀ S⁻¹ of its entries when they
/// are few, else by two products), then ⟨F_i, P_j⟩ for i ≥ j (entry by entry when F_i is sparse).
template <int N>
void DenseSdpSolver::schur_block(Block& k) {
  const int s = k.size;
  const int nt = static_cast<int>(k.terms.size());
  const auto X = fixed<N>(k.X);
  const auto Sinv = fixed<N>(k.Sinv);
  for (int j = 0; j < nt; ++j) {
    const Term& t = k.terms[static_cast<std::size_t>(j)];
    BlockMap<N> P(k.Gs.col(j).data(), s, s);
    if (t.outer) {
      P.setZero();
      for (std::size_t e = 0; e < t.values.size(); ++e) {
        P.noalias() += (t.values[e] * X.col(t.rows[e])) * Sinv.row(t.cols[e]);
      }
    } else {
      auto U = fixed<N>(k.U);
      U.noalias() = fixed<N>(t.F).lazyProduct(Sinv);
      P.noalias() = X.lazyProduct(U);
    }
  }
  for (int j = 0; j < nt; ++j) {
    const ConstBlockMap<N> P(k.Gs.col(j).data(), s, s);
    const int vj = k.terms[static_cast<std::size_t>(j)].var;
    for (int i = j; i < nt; ++i) {
      const Term& ti = k.terms[static_cast<std::size_t>(i)];
      // the lower triangle of M; the upper one is its mirror
      M_(std::max(ti.var, vj), std::min(ti.var, vj)) +=
          dense_sdp_inner<N>(ti, P) * (ti.var == vj && i != j ? 2.0 : 1.0);
    }
  }
}

/// The Schur complement and its Cholesky factorisation (false when not positive definite).
bool DenseSdpSolver::form_schur() {
  M_.setZero();
  for (Block& k : blocks_) {
    with_block_size(k.size, [&](auto n) { schur_block<decltype(n)::value>(k); });
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

/// Block k's R = σμ S⁻¹ − X Rd S⁻¹ − G (G = dXa dSa S⁻¹ in the corrector) and h += A(R).
template <int N>
void DenseSdpSolver::residual_block(Block& k, double target, bool corrector) {
  const auto Sinv = fixed<N>(k.Sinv);
  auto U = fixed<N>(k.U);
  auto R = fixed<N>(k.R);
  U.noalias() = fixed<N>(k.X).lazyProduct(fixed<N>(k.Rd));
  if (corrector) {
    auto T = fixed<N>(k.T);
    T.noalias() = fixed<N>(k.dXa).lazyProduct(fixed<N>(k.dSa));
    fixed<N>(k.G).noalias() = T.lazyProduct(Sinv);
  }
  R.noalias() = U.lazyProduct(Sinv);
  R = target * Sinv - R;
  if (corrector) {
    R -= fixed<N>(k.G);
  }
  for (const Term& t : k.terms) {
    h_(t.var) += dense_sdp_inner<N>(t, R);
  }
}

/// Block k's dS = Rd + A*(dy) and dX = sym(σμ S⁻¹ − G − X dS S⁻¹) − X.
template <int N>
void DenseSdpSolver::step_block(Block& k, double target, bool corrector) {
  const auto Sinv = fixed<N>(k.Sinv);
  const auto X = fixed<N>(k.X);
  auto dS = fixed<N>(k.dS);
  auto U = fixed<N>(k.U);
  auto T = fixed<N>(k.T);
  dS = fixed<N>(k.Rd);
  for (const Term& t : k.terms) {
    dense_sdp_axpy<N>(t, dy_(t.var), dS);
  }
  U.noalias() = X.lazyProduct(dS);
  T.noalias() = U.lazyProduct(Sinv);
  T = target * Sinv - T;
  if (corrector) {
    T -= fixed<N>(k.G);
  }
  fixed<N>(k.dX) = 0.5 * (T + T.transpose()) - X;
}

/// The search direction (header comment) for the target σμ; the corrector adds G = dXa dSa S⁻¹.
void DenseSdpSolver::direction(double target, bool corrector) {
  h_ = -b_;
  for (Block& k : blocks_) {
    with_block_size(k.size,
                    [&](auto n) { residual_block<decltype(n)::value>(k, target, corrector); });
  }
  dy_ = h_;
  schur_.solveInPlace(dy_);
  for (Block& k : blocks_) {
    with_block_size(k.size, [&](auto n) { step_block<decltype(n)::value>(k, target, corrector); });
  }
}

/// min(cap, largest α with V + α D ⪰ 0) for block k (V, D = X, dX when primal, else S, dS): when
/// V + cap D passes a Cholesky test, cap; otherwise −1/λ_min(L⁻¹ D L⁻ᵀ), V = L Lᵀ.
template <int N>
double DenseSdpSolver::block_step(Block& k, bool primal, double cap) {
  const auto V = fixed<N>(primal ? k.X : k.S);
  const auto D = fixed<N>(primal ? k.dX : k.dS);
  auto T = fixed<N>(k.T);
  auto U = fixed<N>(k.U);
  T = V + cap * D;
  if (cholesky_lower(T, U)) {
    return cap;
  }
  if (primal && !k.wx_ready) {
    lower_inverse(fixed<N>(k.LX), fixed<N>(k.WX));
    k.wx_ready = true;
  }
  const auto Winv = fixed<N>(primal ? k.WX : k.W);  // L⁻¹
  U.noalias() = Winv.lazyProduct(D);
  T.noalias() = U.lazyProduct(Winv.transpose());
  const double lmin = block_min_eigenvalue<N>(k.T, k.eig);
  return lmin < 0.0 ? std::min(cap, -1.0 / lmin) : cap;
}

/// min(cap, largest α with X + α dX ⪰ 0) (primal) or the same for S + α dS: a block whose
/// V + α D passes a Cholesky test at the current α keeps it; only the others need λ_min. The
/// block that limited the last step of the same kind goes first (it usually limits again, and
/// the others then pass their test at its α).
double DenseSdpSolver::max_step(bool primal, double cap) {
  double a = cap;
  const std::size_t nb = blocks_.size();
  std::size_t& first = limiting_[primal ? 0 : 1];
  std::size_t limiting = first;
  for (std::size_t j = 0; j < nb; ++j) {
    const std::size_t i = (first + j) % nb;
    Block& k = blocks_[i];
    const double ak = with_block_size(
        k.size, [&](auto n) { return block_step<decltype(n)::value>(k, primal, a); });
    if (ak < a) {
      a = ak;
      limiting = i;
    }
  }
  first = limiting;
  return a;
}

template <int N>
double DenseSdpSolver::affine_block(const Block& k, double ap, double ad) {
  return (fixed<N>(k.X) + ap * fixed<N>(k.dX)).cwiseProduct(fixed<N>(k.S) + ad * fixed<N>(k.dS))
      .sum();
}

/// ⟨X + αp dX, S + αd dS⟩ / n.
double DenseSdpSolver::affine_mu(double ap, double ad) const {
  double s = 0.0;
  for (const Block& k : blocks_) {
    s += with_block_size(k.size,
                         [&](auto n) { return affine_block<decltype(n)::value>(k, ap, ad); });
  }
  return s / n_;
}

template <int N>
void DenseSdpSolver::update_block(Block& k, double ap, double ad) {
  auto X = fixed<N>(k.X);
  auto S = fixed<N>(k.S);
  auto T = fixed<N>(k.T);
  X += ap * fixed<N>(k.dX);
  S += ad * fixed<N>(k.dS);
  T = 0.5 * (X + X.transpose());
  X = T;
  T = 0.5 * (S + S.transpose());
  S = T;
}

void DenseSdpSolver::update(double ap, double ad) {
  y_ += ad * dy_;
  for (Block& k : blocks_) {
    with_block_size(k.size, [&](auto n) { update_block<decltype(n)::value>(k, ap, ad); });
  }
}

SdpResult DenseSdpSolver::solve(double recheck_tol) {
  initial_point();
  return iterate(recheck_tol);
}

SdpResult DenseSdpSolver::solve_warm(double shift, double recheck_tol) {
  if (!has_solution_) {
    return solve(recheck_tol);
  }
  for (Block& k : blocks_) {
    const double tx = shift * std::max(1.0, k.X.trace() / k.size);
    const double ts = shift * std::max(1.0, k.S.trace() / k.size);
    k.X.diagonal().array() += tx;
    k.S.diagonal().array() += ts;
  }
  return iterate(recheck_tol);
}

SdpResult DenseSdpSolver::iterate(double recheck_tol) {
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
    if (info_.infeasible) break;
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
  if (!ok && !info_.infeasible) {
    ok = converged(settings_.loose_tolerance);
  }
  return finish(ok, recheck_tol);
}

/// The result as solve_sdp builds it: y, bᵀy and the eigenvalue re-check of sdp_solver.hpp.
SdpResult DenseSdpSolver::finish(bool ok, double recheck_tol) {
  has_solution_ = false;
  SdpResult result;
  std::ostringstream os;
  if (!ok && info_.infeasible) {
    result.status = SdpStatus::infeasible;
    os << "dense SDP: the LMIs are infeasible (after " << info_.iterations
       << " iterations an X ⪰ 0 shows that every feasible y has ‖y‖ ≥ "
       << info_.feasible_y_norm_bound << ")";
    result.message = os.str();
    return result;
  }
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
  has_solution_ = true;
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
  DenseSdpCounts c;
  c.dense = g_dense_sdp_accepted.load();
  c.fallback = g_dense_sdp_fallback.load();
  c.infeasible = g_dense_sdp_infeasible.load();
  c.csdp = g_csdp_solves.load();
  c.dense_iterations = g_dense_sdp_iterations.load();
  c.dense_seconds = static_cast<double>(g_dense_sdp_nanoseconds.load()) * 1e-9;
  c.csdp_seconds = static_cast<double>(g_csdp_nanoseconds.load()) * 1e-9;
  return c;
}

long long thread_cpu_nanoseconds() noexcept {
  timespec ts{};
  if (clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts) != 0) return 0;
  return static_cast<long long>(ts.tv_sec) * 1000000000LL + ts.tv_nsec;
}

void record_dense_sdp_outcome(SdpStatus status, int iterations, long long nanoseconds) noexcept {
  if (status == SdpStatus::solved) {
    ++g_dense_sdp_accepted;
    g_dense_sdp_iterations += iterations;
  } else if (status == SdpStatus::infeasible) {
    ++g_dense_sdp_infeasible;
  } else {
    ++g_dense_sdp_fallback;
  }
  g_dense_sdp_nanoseconds += nanoseconds;
}

void record_csdp_time(long long nanoseconds) noexcept {
  ++g_csdp_solves;
  g_csdp_nanoseconds += nanoseconds;
}

SdpResult solve_sdp_dense_warm(const LmiProblem& problem, DenseSdpWorkspace* workspace,
                               double recheck_tol, int* iterations) {
  std::optional<DenseSdpSolver> local;
  std::optional<DenseSdpSolver>& slot = workspace != nullptr ? workspace->solver : local;
  SdpResult result;
  if (slot && slot->reload(problem)) {
    result = slot->solve_warm(kDenseSdpWarmShift, recheck_tol);
    if (result.status == SdpStatus::failed) {
      result = slot->solve(recheck_tol);
    }
  } else {
    slot.emplace(problem);
    result = slot->solve(recheck_tol);
  }
  if (iterations != nullptr) *iterations = slot->info().iterations;
  return result;
}

}  // namespace attiguard::reach
