#pragma once
/// @file sdp_solver.hpp
/// A small semidefinite-programming front end over CSDP (libsdp-dev, EPL):
///
///   minimise bᵀy  subject to  F0_k + Σ_i y_i F_ik ⪰ 0  for every block k,
///
/// which is CSDP's dual form (A_i = F_i, C = −F0, a = b). The wrapper
///  - owns every byte handed to CSDP (malloc'd as CSDP's free_prob() expects, freed by RAII);
///  - never reads ./param.csdp and never prints: it supplies CSDP's parameters itself
///    (sdp_solver.cpp defines initparams(), which easy_sdp() calls; see there);
///  - validates the data (finite, symmetric, sizes) before the call, so that CSDP's internal
///    exit() paths for malformed input cannot be reached (only out-of-memory remains);
///  - serialises calls with a process-wide mutex (CSDP keeps global state: not thread-safe);
///  - re-checks the returned y by eigenvalues of every block and reports the smallest one.
/// A solver failure is a status, never an exception or a process exit.

#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

namespace attiguard::reach {

/// One linear matrix inequality F0 + Σ_i y_i F_i ⪰ 0 of a fixed size.
struct LmiBlock {
  int size{0};
  Eigen::MatrixXd F0;                                 ///< constant term (symmetric)
  std::vector<std::pair<int, Eigen::MatrixXd>> terms;  ///< (variable index, F_i), symmetric
};

/// min bᵀy s.t. every block ⪰ 0.
class LmiProblem {
 public:
  explicit LmiProblem(int num_variables);
  /// Adds a block of the given size with F0 = 0; returns its index.
  int add_block(int size);
  /// F0 += M on block k.
  void add_constant(int block, const Eigen::MatrixXd& M);
  /// F_var += M on block k.
  void add_term(int block, int var, const Eigen::MatrixXd& M);
  /// b_var = coef.
  void set_objective(int var, double coef);

  [[nodiscard]] int num_variables() const noexcept { return static_cast<int>(b_.size()); }
  [[nodiscard]] const std::vector<LmiBlock>& blocks() const noexcept { return blocks_; }
  [[nodiscard]] const Eigen::VectorXd& objective() const noexcept { return b_; }
  /// F0 + Σ y_i F_i of block k.
  [[nodiscard]] Eigen::MatrixXd evaluate(int block, const Eigen::VectorXd& y) const;
  /// Smallest eigenvalue over all blocks at y.
  [[nodiscard]] double min_eigenvalue(const Eigen::VectorXd& y) const;

 private:
  Eigen::VectorXd b_;
  std::vector<LmiBlock> blocks_;
};

/// Solver parameters (CSDP's own names; defaults are CSDP's documented defaults except the
/// iteration cap). printlevel is always 0.
struct DenseSdpWorkspace;

/// Which solver solve_sdp uses (issue 48; docs/reach.md, "Dense SDP solver").
enum class SdpSolverKind {
  csdp,   ///< CSDP alone
  dense,  ///< the dense solver of dense_sdp.hpp first, CSDP when it does not solve (the default)
};

struct SdpSettings {
  SdpSolverKind solver{SdpSolverKind::dense};
  /// The dense solver's warm start (dense_sdp.hpp; issue 48, docs/reach.md "Dense SDP solver"):
  /// not owned; when set, the dense solver kept there is reused and warm-started when the
  /// problem has its shape (solve_sdp_dense_warm). nullptr: a new solver, cold start.
  DenseSdpWorkspace* warm_start{nullptr};
  double axtol{1e-8};
  double atytol{1e-8};
  double objtol{1e-8};
  double pinftol{1e8};
  double dinftol{1e8};
  int maxiter{100};
};

enum class SdpStatus {
  solved,      ///< CSDP returned 0 (or 3, partial success) and every block re-checks ⪰ −tol
  infeasible,  ///< CSDP proved the LMIs infeasible (its code 2, "dual infeasible")
  failed,      ///< anything else: numerical trouble, iteration limit, re-check failed, bad data
};

struct SdpResult {
  SdpStatus status{SdpStatus::failed};
  int csdp_code{-1};        ///< easy_sdp's return value (-1: not called)
  Eigen::VectorXd y;        ///< the solution (empty unless solved)
  double objective{0.0};    ///< bᵀy
  double min_eigenvalue{0.0};  ///< smallest eigenvalue over the blocks at y (re-check)
  std::string message;      ///< one line for humans
};

/// Solves the problem with CSDP. Never throws for solver trouble (status failed/infeasible);
/// throws std::invalid_argument only for a malformed problem (programming error), which is
/// detected before CSDP is called. `recheck_tol`: blocks must have λ_min ≥ −recheck_tol.
[[nodiscard]] SdpResult solve_sdp(const LmiProblem& problem, const SdpSettings& settings = {},
                                  double recheck_tol = 1e-9);

/// Number of solve_sdp calls in this process (statistics).
[[nodiscard]] long sdp_solve_count() noexcept;

}  // namespace attiguard::reach
