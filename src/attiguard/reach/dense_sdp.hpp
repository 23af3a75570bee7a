#pragma once
/// @file dense_sdp.hpp
/// A dense primal-dual interior-point solver for ConReach's small SDPs (issue 48; docs/reach.md,
/// "Dense SDP solver"): 12–30 variables, a few 3×3–9×9 blocks. solve_sdp() (sdp_solver.hpp)
/// tries it first when set_dense_sdp_enabled(true) and falls back to CSDP, which stays the
/// reference and decides infeasibility.
///
/// Sign conventions (those of sdp_solver.hpp, CSDP's dual form with A_i = F_i, C = −F0, a = b):
///
///   dual   (y, S):  minimise bᵀy      s.t.  S = F0 + Σ_i y_i F_i ⪰ 0
///   primal (X):     maximise −⟨F0, X⟩  s.t.  ⟨F_i, X⟩ = b_i,  X ⪰ 0
///
/// with X and S block-diagonal (one dense matrix per LmiBlock) and ⟨·,·⟩ the trace inner product
/// summed over the blocks; bᵀy + ⟨F0, X⟩ = ⟨X, S⟩ ≥ 0 on feasible pairs.
///
/// Method: infeasible-start path following with the HKM search direction (Helmberg, Rendl,
/// Vanderbei and Wolkowicz 1996; Kojima, Shindoh and Hara 1997; Monteiro 1997) and Mehrotra's
/// predictor–corrector, step lengths to the boundary (a Cholesky test per block, eigenvalues only
/// for the blocks that fail it) and the adaptive centring exponent of SDPT3 (Todd, Toh and Tütüncü
/// 1998; Toh, Todd and Tütüncü 1999). The m×m Schur complement M_ij = ⟨F_i, X F_j S⁻¹⟩ is formed
/// as the Gram matrix of G_i = L_S⁻¹ F_i L_X (X = L_X L_Xᵀ, S = L_S L_Sᵀ; sparse F_i entry by
/// entry) and factored by Eigen's LLT. Every matrix of the iteration lives in the solver object:
/// the loop allocates nothing.

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <array>
#include <optional>
#include <vector>

#include "attiguard/reach/sdp_solver.hpp"

namespace attiguard::reach {

/// Stopping rules of the dense solver (issue 48; docs/reach.md, "Dense SDP solver").
struct DenseSdpSettings {
  double tolerance{1e-9};        ///< relative gap, primal and dual infeasibility: solved
  double loose_tolerance{1e-8};  ///< accepted when the iteration stalls (CSDP's objtol)
  int max_iterations{60};
  double divergence{1e12};  ///< max |X|, |y| beyond this: failed (likely infeasible; CSDP decides)
  /// An iterate X ⪰ 0 with −⟨F0, X⟩ ≥ ratio·max{1, ‖y‖}·‖A(X)‖ ends the solve as `infeasible`:
  /// every feasible y then has ‖y‖ ≥ −⟨F0, X⟩/‖A(X)‖ (docs/reach.md, "Dense SDP solver").
  /// 10² since stop 61 (10⁴ before): infeasible metric SDPs cross 10² at about iteration 20 and
  /// 10⁴ at about 28, while every solved one of the examples had a bound of 0 at every iteration.
  double infeasibility_ratio{1e2};
};

/// What the last solve did.
struct DenseSdpInfo {
  int iterations{0};
  double relative_gap{0.0};           ///< max(⟨X,S⟩, |bᵀy + ⟨F0,X⟩|) / (1 + |bᵀy| + |⟨F0,X⟩|)
  double primal_infeasibility{0.0};   ///< ‖b − A(X)‖ / (1 + ‖b‖)
  double dual_infeasibility{0.0};     ///< ‖F0 + A*(y) − S‖_F / (1 + ‖F0‖_F)
  /// tr X at the end: bᵀy' ≥ p* − ε tr X* for any y' with λ_min(F0 + A*(y')) ≥ −ε, so a solution
  /// infeasible by ε (CSDP's, about 1e-8) may lie that far below the optimum.
  double primal_trace{0.0};
  /// −⟨F0, X⟩/‖A(X)‖ of the last iterate (0 when ⟨F0, X⟩ ≥ 0): a lower bound on ‖y‖ over the
  /// feasible set of the LMIs (X ⪰ 0 makes ⟨F0 + A*(y), X⟩ ≥ 0 for every feasible y).
  double feasible_y_norm_bound{0.0};
  bool infeasible{false};  ///< the bound exceeded infeasibility_ratio·max{1, ‖y‖}
};

/// The HKM / Mehrotra solver of dense_sdp.hpp for one LmiProblem; reusable (solve() restarts from
/// the default infeasible start every time). The problem must outlive the solver and pass
/// solve_sdp's validation (finite, symmetric, every variable used). Linearly dependent F_i are
/// not solved (status failed: CSDP's business).
class DenseSdpSolver {
 public:
  /// Copies the problem's blocks and allocates all the workspace (issue 48, docs/reach.md).
  explicit DenseSdpSolver(const LmiProblem& problem, const DenseSdpSettings& settings = {});

  /// Runs the HKM predictor–corrector iteration of dense_sdp.hpp (Helmberg–Rendl–Vanderbei–
  /// Wolkowicz 1996 direction, Mehrotra centring); status solved when the stopping rules hold
  /// and y re-checks by eigenvalues (LmiProblem::min_eigenvalue ≥ −recheck_tol), as solve_sdp.
  /// Never reports infeasible: a problem it cannot solve is `failed` (CSDP decides).
  [[nodiscard]] SdpResult solve(double recheck_tol = 1e-9);

  /// Loads another problem of this solver's shape (the same blocks, sizes and term variables,
  /// in order) into its storage, keeping the last iterate for solve_warm(); false, and nothing
  /// changed, when the shapes differ. The problem must outlive the next solve.
  bool reload(const LmiProblem& problem);
  /// solve() started from the last solve's final iterate, X and S shifted by `shift` times their
  /// mean eigenvalue (at least `shift`) per block, when that solve returned `solved`; a cold
  /// solve() otherwise (docs/reach.md, "Dense SDP solver").
  [[nodiscard]] SdpResult solve_warm(double shift, double recheck_tol = 1e-9);

  /// Iterations and final residuals of the last solve() (docs/reach.md, "Dense SDP solver").
  [[nodiscard]] const DenseSdpInfo& info() const noexcept { return info_; }

 private:
  struct Term {
    int var{0};
    Eigen::MatrixXd F;                 ///< symmetrised F_i of the block
    std::vector<int> rows, cols;       ///< the non-zero entries (both triangles)
    std::vector<double> values;
    bool sparse{false};  ///< at most half the entries non-zero: inner products entry by entry
    bool outer{false};   ///< fewer than 2s entries: X F S⁻¹ by outer products (schur_block)
  };
  struct Block {
    int size{0};
    Eigen::MatrixXd F0;
    std::vector<Term> terms;
    Eigen::MatrixXd X, S, Sinv, Rd, dX, dS, dXa, dSa, G, R, T, U;
    Eigen::MatrixXd LX;  ///< the Cholesky factor L_X, upper triangle zero
    Eigen::MatrixXd WX;  ///< L_X⁻¹ (lower triangular), valid when wx_ready
    bool wx_ready{false};
    Eigen::MatrixXd W;   ///< L_S⁻¹ (S⁻¹ = Wᵀ W)
    Eigen::MatrixXd Gs;  ///< column j: P_j = X F_j S⁻¹, s² × terms
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig;  ///< blocks of a size not compiled fixed
  };
  /// Block sums of factor_and_residuals: ⟨X,S⟩, ⟨F0,X⟩, ‖Rd‖².
  struct Sums {
    double xs{0.0}, f0x{0.0}, rd2{0.0};
  };

  SdpResult iterate(double recheck_tol);
  [[nodiscard]] bool same_shape(const LmiProblem& problem) const noexcept;
  void load(const LmiProblem& problem);
  bool constraints_independent();
  void initial_point();
  bool factor_and_residuals();
  [[nodiscard]] bool converged(double tol) const noexcept;
  bool form_schur();
  void direction(double target, bool corrector);
  double max_step(bool primal, double cap);
  double affine_mu(double ap, double ad) const;
  void update(double ap, double ad);
  SdpResult finish(bool ok, double recheck_tol);

  // Kernels on one block, templated on its size (3, 6, 9 fixed; Eigen::Dynamic otherwise).
  template <int N>
  bool factor_block(Block& k, Sums& sums);
  template <int N>
  void schur_block(Block& k);
  template <int N>
  void residual_block(Block& k, double target, bool corrector);
  template <int N>
  void step_block(Block& k, double target, bool corrector);
  template <int N>
  static double block_step(Block& k, bool primal, double cap);
  template <int N>
  static double affine_block(const Block& k, double ap, double ad);
  template <int N>
  static void update_block(Block& k, double ap, double ad);

  const LmiProblem* problem_;
  DenseSdpSettings settings_;
  DenseSdpInfo info_;
  std::vector<Block> blocks_;
  int n_{0};  ///< Σ block sizes
  Eigen::VectorXd b_, y_, dy_, h_, rp_;
  Eigen::MatrixXd M_;
  Eigen::LLT<Eigen::MatrixXd> schur_;
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> gram_eig_;  ///< the independence test
  bool has_solution_{false};
  std::array<std::size_t, 2> limiting_{0, 0};  ///< block that limited the last primal / dual step  ///< the last solve returned solved: X, S, y are its final iterate
  double norm_b_{0.0}, norm_f0_{0.0}, scale_{1.0};
  bool independent_{true};
};

/// One dense solve (DenseSdpSolver of dense_sdp.hpp; issue 48, docs/reach.md "Dense SDP solver").
[[nodiscard]] SdpResult solve_sdp_dense(const LmiProblem& problem,
                                        const DenseSdpSettings& settings = {},
                                        double recheck_tol = 1e-9);

/// Whether solve_sdp tries the dense solver before CSDP whatever SdpSettings::solver says
/// (process-wide, atomic; for tests and benchmarks). Default off: each call's
/// SdpSettings::solver decides (ConReach: dense; docs/reach.md, "Dense SDP solver").
void set_dense_sdp_enabled(bool enabled) noexcept;
/// See set_dense_sdp_enabled (issue 48, docs/reach.md "Dense SDP solver").
[[nodiscard]] bool dense_sdp_enabled() noexcept;

/// solve_sdp's outcomes since the start of the process (issue 48, docs/reach.md): solves
/// accepted from the dense solver, solves that fell back to CSDP, and the CPU time of the calling
/// thread spent in each solver (the dense time includes the attempts that fell back).
struct DenseSdpCounts {
  long dense{0};
  long fallback{0};             ///< dense solves neither solved nor infeasible: CSDP called
  long infeasible{0};           ///< dense solves that ended with the infeasibility bound
  long csdp{0};                ///< CSDP solves (fallbacks and solves with the dense path off)
  long dense_iterations{0};    ///< iterations of the accepted dense solves
  double dense_seconds{0.0};
  double csdp_seconds{0.0};
};

/// CPU time of the calling thread (CLOCK_THREAD_CPUTIME_ID), in nanoseconds: what the counters
/// of dense_sdp_counts() add up (issue 48, docs/reach.md "Dense SDP solver").
[[nodiscard]] long long thread_cpu_nanoseconds() noexcept;
/// The counts of solve_sdp's dense and CSDP solves (issue 48, docs/reach.md "Dense SDP solver").
[[nodiscard]] DenseSdpCounts dense_sdp_counts() noexcept;
/// Called by solve_sdp once per solve with the dense path enabled (issue 48, docs/reach.md).
/// `nanoseconds` of thread CPU time, `iterations` of the solver.
void record_dense_sdp_outcome(SdpStatus status, int iterations, long long nanoseconds) noexcept;
/// Called by solve_sdp once per CSDP solve (issue 48, docs/reach.md "Dense SDP solver").
void record_csdp_time(long long nanoseconds) noexcept;

/// Relative shift of a warm start (DenseSdpSolver::solve_warm): X and S of the previous solve
/// plus 0.1 times their mean eigenvalue (at least 0.1). Measured on the paper's step-0 SDP
/// against the same SDP at other rates and enclosures: 7–10 iterations instead of 10–17; smaller
/// shifts start too close to the boundary (docs/reach.md, "Dense SDP solver").
inline constexpr double kDenseSdpWarmShift = 0.1;

/// A dense solver kept from solve to solve (SdpSettings::warm_start): its storage is reused for
/// problems of the same shape and its last solution starts the next solve (issue 48,
/// docs/reach.md "Dense SDP solver"). Not thread-safe: one per run.
struct DenseSdpWorkspace {
  std::optional<DenseSdpSolver> solver;
};

/// One dense solve. With a workspace whose solver has the problem's shape: reload, warm start
/// (kDenseSdpWarmShift), and a cold start when that does not solve; otherwise a new solver
/// (kept in the workspace) and a cold start. `iterations` (if not null) receives the iterations
/// of the returned solve. Issue 48, docs/reach.md "Dense SDP solver".
[[nodiscard]] SdpResult solve_sdp_dense_warm(const LmiProblem& problem,
                                             DenseSdpWorkspace* workspace, double recheck_tol,
                                             int* iterations = nullptr);

}  // namespace attiguard::reach
