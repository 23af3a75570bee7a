// CSDP behind a safe, serialised interface (see sdp_solver.hpp).
//
// CSDP's easy_sdp() obtains its parameters by calling initparams(), which in the library opens
// ./param.csdp in the *current directory* and defaults printlevel to 1 (progress on stdout).
// We define initparams() here, with C linkage: easy_sdp() then calls ours, which hands over the
// parameters of the current solve and printlevel 0 and never touches the file system. The build
// links the static libsdp.a (src/CMakeLists.txt), so this definition is the only one linked;
// with a shared libsdp.so it interposes through the PLT. solve_sdp() checks after every call that
// ours was used and reports a failure otherwise, so a build where the override is not in effect
// cannot go unnoticed.

#include "attiguard/reach/sdp_solver.hpp"

#include <Eigen/Eigenvalues>

#include "attiguard/reach/dense_sdp.hpp"
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <mutex>
#include <new>
#include <sstream>
#include <stdexcept>

extern "C" {
#include <csdp/declarations.h>
}

namespace {

// Guarded by solver_mutex(): the parameters of the solve in progress.
paramstruc g_params{};
bool g_initparams_called = false;

std::mutex& solver_mutex() {
  static std::mutex m;
  return m;
}

std::atomic<long> g_solve_count{0};

}  // namespace

/// Replaces CSDP's initparams (which reads ./param.csdp and defaults to printing): see above.
extern "C" void initparams(struct paramstruc* params, int* printlevel) {
  *params = g_params;
  *printlevel = 0;
  g_initparams_called = true;
}

namespace attiguard::reach {

LmiProblem::LmiProblem(int num_variables) : b_(Eigen::VectorXd::Zero(num_variables)) {
  if (num_variables <= 0) {
    throw std::invalid_argument("LmiProblem: needs at least one variable");
  }
}

int LmiProblem::add_block(int size) {
  if (size <= 0) {
    throw std::invalid_argument("LmiProblem: block size must be positive");
  }
  LmiBlock block;
  block.size = size;
  block.F0 = Eigen::MatrixXd::Zero(size, size);
  blocks_.push_back(std::move(block));
  return static_cast<int>(blocks_.size()) - 1;
}

void LmiProblem::add_constant(int block, const Eigen::MatrixXd& M) {
  LmiBlock& blk = blocks_.at(static_cast<std::size_t>(block));
  if (M.rows() != blk.size || M.cols() != blk.size) {
    throw std::invalid_argument("LmiProblem: constant of the wrong size");
  }
  blk.F0 += M;
}

void LmiProblem::add_term(int block, int var, const Eigen::MatrixXd& M) {
  LmiBlock& blk = blocks_.at(static_cast<std::size_t>(block));
  if (var < 0 || var >= num_variables()) {
    throw std::invalid_argument("LmiProblem: variable index out of range");
  }
  if (M.rows() != blk.size || M.cols() != blk.size) {
    throw std::invalid_argument("LmiProblem: term of the wrong size");
  }
  for (auto& [v, F] : blk.terms) {
    if (v == var) {
      F += M;
      return;
    }
  }
  blk.terms.emplace_back(var, M);
}

void LmiProblem::set_objective(int var, double coef) {
  if (var < 0 || var >= num_variables()) {
    throw std::invalid_argument("LmiProblem: variable index out of range");
  }
  b_(var) = coef;
}

Eigen::MatrixXd LmiProblem::evaluate(int block, const Eigen::VectorXd& y) const {
  const LmiBlock& blk = blocks_.at(static_cast<std::size_t>(block));
  Eigen::MatrixXd S = blk.F0;
  for (const auto& [v, F] : blk.terms) {
    S += y(v) * F;
  }
  return 0.5 * (S + S.transpose());
}

double LmiProblem::min_eigenvalue(const Eigen::VectorXd& y) const {
  double lo = std::numeric_limits<double>::infinity();
  for (int k = 0; k < static_cast<int>(blocks_.size()); ++k) {
    const Eigen::MatrixXd S = evaluate(k, y);
    if (!S.allFinite()) {
      return -std::numeric_limits<double>::infinity();
    }
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(S, Eigen::EigenvaluesOnly);
    lo = std::min(lo, es.eigenvalues()(0));
  }
  return lo;
}

long sdp_solve_count() noexcept { return g_solve_count.load(); }

namespace {

/// Everything handed to CSDP, allocated with malloc (CSDP's convention) and freed here.
class CsdpData {
 public:
  CsdpData() = default;
  CsdpData(const CsdpData&) = delete;
  CsdpData& operator=(const CsdpData&) = delete;
  ~CsdpData() { release(); }

  blockmatrix C{0, nullptr};
  double* a{nullptr};
  constraintmatrix* constraints{nullptr};
  int num_constraints{0};
  blockmatrix X{0, nullptr};
  double* y{nullptr};
  blockmatrix Z{0, nullptr};
  bool have_solution{false};

  template <class T>
  static T* alloc(std::size_t count) {
    void* p = std::calloc(count, sizeof(T));
    if (p == nullptr) {
      throw std::bad_alloc();
    }
    return static_cast<T*>(p);
  }

 private:
  static void free_blockmatrix(blockmatrix& M) {
    if (M.blocks == nullptr) {
      return;
    }
    for (int k = 1; k <= M.nblocks; ++k) {
      std::free(M.blocks[k].data.mat);  // union: vec or mat
    }
    std::free(M.blocks);
    M.blocks = nullptr;
  }

  void release() {
    free_blockmatrix(C);
    std::free(a);
    if (constraints != nullptr) {
      for (int i = 1; i <= num_constraints; ++i) {
        sparseblock* p = constraints[i].blocks;
        while (p != nullptr) {
          sparseblock* next = p->next;
          std::free(p->entries);
          std::free(p->iindices);
          std::free(p->jindices);
          std::free(p);
          p = next;
        }
      }
      std::free(constraints);
    }
    if (have_solution) {
      free_blockmatrix(X);
      std::free(y);
      free_blockmatrix(Z);
    }
  }
};

/// 0-based offset of the 1-based entry (i, j) of a column-major n×n block (CSDP's ijtok).
constexpr int ij_to_k(int i, int j, int n) { return (j - 1) * n + i - 1; }

void validate(const LmiProblem& problem) {
  if (problem.blocks().empty()) {
    throw std::invalid_argument("LmiProblem: no blocks");
  }
  if (!problem.objective().allFinite()) {
    throw std::invalid_argument("LmiProblem: non-finite objective");
  }
  std::vector<bool> used(static_cast<std::size_t>(problem.num_variables()), false);
  auto check = [](const Eigen::MatrixXd& M) {
    if (!M.allFinite()) {
      throw std::invalid_argument("LmiProblem: non-finite matrix entry");
    }
    const double scale = 1.0 + M.cwiseAbs().maxCoeff();
    if ((M - M.transpose()).cwiseAbs().maxCoeff() > 1e-12 * scale) {
      throw std::invalid_argument("LmiProblem: non-symmetric matrix");
    }
  };
  for (const LmiBlock& blk : problem.blocks()) {
    check(blk.F0);
    for (const auto& [v, F] : blk.terms) {
      check(F);
      if (F.cwiseAbs().maxCoeff() > 0.0) {
        used[static_cast<std::size_t>(v)] = true;
      }
    }
  }
  for (bool u : used) {
    if (!u) {
      throw std::invalid_argument("LmiProblem: a variable appears in no block");
    }
  }
}

/// C = −F0 block by block (CSDP's C of the dual form, sdp_solver.hpp); returns n, the sum of
/// the block sizes. A 1×1 block is CSDP's DIAG category, a larger one a dense MATRIX.
int fill_constant_blocks(const LmiProblem& problem, CsdpData& data) {
  const int K = static_cast<int>(problem.blocks().size());
  int n = 0;
  data.C.nblocks = K;
  data.C.blocks = CsdpData::alloc<blockrec>(static_cast<std::size_t>(K) + 1);
  for (int k = 1; k <= K; ++k) {
    const LmiBlock& blk = problem.blocks()[static_cast<std::size_t>(k - 1)];
    const int s = blk.size;
    n += s;
    blockrec& rec = data.C.blocks[k];
    rec.blocksize = s;
    if (s == 1) {
      rec.blockcategory = DIAG;
      rec.data.vec = CsdpData::alloc<double>(2);
      rec.data.vec[1] = -blk.F0(0, 0);
    } else {
      rec.blockcategory = MATRIX;
      rec.data.mat = CsdpData::alloc<double>(static_cast<std::size_t>(s) * s);
      for (int i = 1; i <= s; ++i) {
        for (int j = 1; j <= s; ++j) {
          rec.data.mat[ij_to_k(i, j, s)] = -0.5 * (blk.F0(i - 1, j - 1) + blk.F0(j - 1, i - 1));
        }
      }
    }
  }
  return n;
}

/// a = b (1-based, CSDP's convention).
void fill_objective(const LmiProblem& problem, CsdpData& data) {
  const int m = problem.num_variables();
  data.a = CsdpData::alloc<double>(static_cast<std::size_t>(m) + 1);
  for (int i = 1; i <= m; ++i) {
    data.a[i] = problem.objective()(i - 1);
  }
}

/// F_var of the block (the last term naming it), nullptr when the block has none.
const Eigen::MatrixXd* term_of(const LmiBlock& blk, int var) {
  const Eigen::MatrixXd* F = nullptr;
  for (const auto& [v, M] : blk.terms) {
    if (v == var) {
      F = &M;
    }
  }
  return F;
}

/// Number of non-zero entries of the upper triangle of the s×s matrix F.
int upper_nonzeros(const Eigen::MatrixXd& F, int s) {
  int nnz = 0;
  for (int r = 0; r < s; ++r) {
    for (int c = r; c < s; ++c) {
      nnz += F(r, c) != 0.0 ? 1 : 0;
    }
  }
  return nnz;
}

/// Pushes block k of constraint i — the nnz non-zero upper-triangle entries of F, symmetrised —
/// onto the front of the constraint's block list (linked first, so that release() frees it).
void push_sparse_block(CsdpData& data, int i, int k, int s, int nnz, const Eigen::MatrixXd& F) {
  auto* sb = CsdpData::alloc<sparseblock>(1);
  sb->next = data.constraints[i].blocks;
  data.constraints[i].blocks = sb;
  sb->nextbyblock = nullptr;
  sb->blocknum = k;
  sb->blocksize = s;
  sb->constraintnum = i;
  sb->issparse = 1;
  sb->numentries = nnz;
  sb->entries = CsdpData::alloc<double>(static_cast<std::size_t>(nnz) + 1);
  sb->iindices = CsdpData::alloc<int>(static_cast<std::size_t>(nnz) + 1);
  sb->jindices = CsdpData::alloc<int>(static_cast<std::size_t>(nnz) + 1);
  int e = 1;
  for (int r = 0; r < s; ++r) {
    for (int c = r; c < s; ++c) {
      const double v = 0.5 * (F(r, c) + F(c, r));
      if (F(r, c) != 0.0) {
        sb->entries[e] = v;
        sb->iindices[e] = r + 1;
        sb->jindices[e] = c + 1;
        ++e;
      }
    }
  }
}

/// A_i = F_i for every variable i, as CSDP's sparse constraint matrices.
void fill_constraints(const LmiProblem& problem, CsdpData& data) {
  const int m = problem.num_variables();
  const int K = static_cast<int>(problem.blocks().size());
  data.constraints = CsdpData::alloc<constraintmatrix>(static_cast<std::size_t>(m) + 1);
  data.num_constraints = m;
  for (int i = 1; i <= m; ++i) {
    data.constraints[i].blocks = nullptr;
    // Push blocks in decreasing order so that the list ends up in increasing block order.
    for (int k = K; k >= 1; --k) {
      const LmiBlock& blk = problem.blocks()[static_cast<std::size_t>(k - 1)];
      const Eigen::MatrixXd* F = term_of(blk, i - 1);
      if (F == nullptr) {
        continue;
      }
      const int nnz = upper_nonzeros(*F, blk.size);
      if (nnz == 0) {
        continue;
      }
      push_sparse_block(data, i, k, blk.size, nnz, *F);
    }
  }
}

/// The parameters initparams() hands to CSDP (caller holds solver_mutex()).
void set_parameters(const SdpSettings& settings) {
  g_params.axtol = settings.axtol;
  g_params.atytol = settings.atytol;
  g_params.objtol = settings.objtol;
  g_params.pinftol = settings.pinftol;
  g_params.dinftol = settings.dinftol;
  g_params.maxiter = settings.maxiter;
  g_params.minstepfrac = 0.90;
  g_params.maxstepfrac = 0.97;
  g_params.minstepp = 1e-8;
  g_params.minstepd = 1e-8;
  g_params.usexzgap = 1;
  g_params.tweakgap = 0;
  g_params.affine = 0;
  g_params.perturbobj = 1.0;
  g_params.fastmode = 0;
}

/// easy_sdp under the process-wide lock, its return value into `code`; false when CSDP did not
/// call our initparams().
bool run_csdp(int n, int m, CsdpData& data, const SdpSettings& settings, int& code) {
  double pobj = 0.0;
  double dobj = 0.0;
  std::lock_guard<std::mutex> lock(solver_mutex());
  set_parameters(settings);
  g_initparams_called = false;
  initsoln(n, m, data.C, data.a, data.constraints, &data.X, &data.y, &data.Z);
  data.have_solution = true;
  code = easy_sdp(n, m, data.C, data.a, data.constraints, 0.0, &data.X, &data.y, &data.Z,
                  &pobj, &dobj);
  return g_initparams_called;
}

/// The result of CSDP's code and y: infeasible (code 2), failed (other codes, a non-finite y,
/// or a y whose blocks fail the eigenvalue re-check), or solved.
void read_solution(const LmiProblem& problem, const CsdpData& data, int code, double recheck_tol,
               SdpResult& result) {
  const int m = problem.num_variables();
  Eigen::VectorXd y(m);
  for (int i = 1; i <= m; ++i) {
    y(i - 1) = data.y[i];
  }
  std::ostringstream os;
  if (code == 2) {
    result.status = SdpStatus::infeasible;
    os << "CSDP: the LMIs are infeasible (code 2)";
    result.message = os.str();
    return;
  }
  if (code != 0 && code != 3) {
    os << "CSDP failed (code " << code << ")";
    result.message = os.str();
    return;
  }
  if (!y.allFinite()) {
    result.message = "CSDP returned a non-finite solution";
    return;
  }
  result.min_eigenvalue = problem.min_eigenvalue(y);
  result.objective = problem.objective().dot(y);
  if (!(result.min_eigenvalue >= -recheck_tol)) {
    os << "CSDP solution fails the eigenvalue re-check (min eigenvalue " << result.min_eigenvalue
       << ", code " << code << ")";
    result.message = os.str();
    return;
  }
  result.status = SdpStatus::solved;
  result.y = y;
  os << "solved (code " << code << ", objective " << result.objective << ")";
  result.message = os.str();
}

/// Adds the thread CPU time since its construction to the CSDP time of dense_sdp_counts() when it
/// goes out of scope.
class ScopedCsdpTimer {
 public:
  ScopedCsdpTimer() : start_(thread_cpu_nanoseconds()) {}
  ~ScopedCsdpTimer() { record_csdp_time(thread_cpu_nanoseconds() - start_); }
  ScopedCsdpTimer(const ScopedCsdpTimer&) = delete;
  ScopedCsdpTimer& operator=(const ScopedCsdpTimer&) = delete;

 private:
  long long start_;
};

}  // namespace

SdpResult solve_sdp(const LmiProblem& problem, const SdpSettings& settings, double recheck_tol) {
  validate(problem);
  ++g_solve_count;
  // Issue 48 (docs/reach.md, "Dense SDP solver"): the dense HKM solver of dense_sdp.hpp first,
  // outside CSDP's lock; CSDP, the reference, when it does not solve and re-check.
  if (settings.solver == SdpSolverKind::dense || dense_sdp_enabled()) {
    const long long t0 = thread_cpu_nanoseconds();
    int iterations = 0;
    SdpResult dense = solve_sdp_dense_warm(problem, settings.warm_start, recheck_tol, &iterations);
    record_dense_sdp_outcome(dense.status, iterations, thread_cpu_nanoseconds() - t0);
    if (dense.status != SdpStatus::failed) {
      return dense;  // solved and re-checked, or infeasible by the bound of DenseSdpInfo
    }
  }
  const ScopedCsdpTimer csdp_timer;
  SdpResult result;
  CsdpData data;
  const int n = fill_constant_blocks(problem, data);
  fill_objective(problem, data);
  fill_constraints(problem, data);
  int code = -1;
  if (!run_csdp(n, problem.num_variables(), data, settings, code)) {
    result.csdp_code = code;
    result.message = "CSDP did not use attiguard's parameters (initparams override not linked)";
    return result;
  }
  result.csdp_code = code;
  read_solution(problem, data, code, recheck_tol, result);
  return result;
}

}  // namespace attiguard::reach
