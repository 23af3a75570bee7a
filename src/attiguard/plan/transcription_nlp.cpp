#include "attiguard/plan/transcription_nlp.hpp"

#include <algorithm>
#include <cmath>
#include <mutex>

#include <IpIpoptApplication.hpp>
#include <IpTNLP.hpp>

#include "attiguard/core/errors.hpp"
#include "attiguard/io/interruption.hpp"

namespace attiguard::plan {

namespace {

using Ipopt::Index;
using Ipopt::Number;

constexpr int kPointVars = 10;
constexpr double kInfinity = 1e19;

/// ∂f/∂z's structural nonzeros: q̇ depends on q and ω, ω̇ on ω and u.
constexpr bool in_point_jacobian(int row, int col) noexcept {
  return row < 4 ? col < 7 : col >= 4;
}

/// The transcription as IPOPT's TNLP (docs/slew-planner.md, "Transcription"). Jacobian and
/// Hessian entries are visited in one fixed order, once for the structure and then for the
/// values.
class SlewNlp final : public Ipopt::TNLP {
 public:
  SlewNlp(const TranscriptionSetup& setup, const TranscriptionValues& guess)
      : setup_(setup), guess_(guess), dynamics_(setup.J_scaled),
        points_(transcription_points(setup.transcription, setup.intervals)) {
    const lie::Quat qc = lie::quat_conjugate(setup.q_target);
    terminal_ = lie::quat_product_matrix(qc).bottomRows<3>();
  }

  TranscriptionResult result;

  bool get_nlp_info(Index& n, Index& m, Index& nnz_jac_g, Index& nnz_h_lag,
                    IndexStyleEnum& index_style) override {
    n = variables();
    m = constraints();
    nnz_jac_g = 0;
    const std::vector<double> x(static_cast<std::size_t>(n), 0.0);
    visit_jacobian(x.data(), [&](int, int, double) { ++nnz_jac_g; });
    nnz_h_lag = 41 * points_;
    index_style = TNLP::C_STYLE;
    return true;
  }

  bool get_bounds_info(Index n, Number* x_l, Number* x_u, Index m, Number* g_l,
                       Number* g_u) override {
    for (Index i = 0; i < n; ++i) {
      x_l[i] = -kInfinity;
      x_u[i] = kInfinity;
    }
    for (int p = 0; p < points_; ++p) {
      for (int i = 0; i < 4; ++i) {  // |q_i| ≤ 1.5: a unit quaternion with room for drift
        x_l[var(p) + i] = -1.5;
        x_u[var(p) + i] = 1.5;
      }
      for (int i = 7; i < 10; ++i) {  // |ū_i| ≤ 1 is implied by ‖ū‖ ≤ 1
        x_l[var(p) + i] = -1.0;
        x_u[var(p) + i] = 1.0;
      }
    }
    for (int i = 0; i < 4; ++i) {
      x_l[var(0) + i] = x_u[var(0) + i] = setup_.q_start(i);
    }
    for (int i = 4; i < 7; ++i) {  // at rest at both ends
      x_l[var(0) + i] = x_u[var(0) + i] = 0.0;
      x_l[var(points_ - 1) + i] = x_u[var(points_ - 1) + i] = 0.0;
    }
    x_l[var_T()] = 1e-3;
    x_u[var_T()] = setup_.max_duration;
    for (Index r = 0; r < m; ++r) {
      g_l[r] = 0.0;
      g_u[r] = 0.0;
    }
    int row = defect_rows();
    for (int p = 0; p < points_; ++p) {
      g_l[row] = -kInfinity;  // ‖ū‖² ≤ torque_limit²
      g_u[row] = setup_.torque_limit * setup_.torque_limit;
      ++row;
      for (const TranscribedCone& cone : setup_.cones) {
        if (!imposed(cone, p)) continue;
        g_l[row] = 0.0;  // qᵀ(M − c_p I)q ≥ 0
        g_u[row] = kInfinity;
        ++row;
      }
    }
    return true;
  }

  bool get_starting_point(Index n, bool init_x, Number* x, bool init_z, Number* z_L, Number* z_U,
                          Index m, bool init_lambda, Number* lambda) override {
    if (!init_x) return false;
    if (init_z || init_lambda) {  // a warm start: the guess's multipliers (warm_startable)
      if (guess_.z_lower.size() != static_cast<std::size_t>(n) ||
          guess_.lambda.size() != static_cast<std::size_t>(m)) {
        return false;
      }
      if (init_z) {
        std::copy(guess_.z_lower.begin(), guess_.z_lower.end(), z_L);
        std::copy(guess_.z_upper.begin(), guess_.z_upper.end(), z_U);
      }
      if (init_lambda) std::copy(guess_.lambda.begin(), guess_.lambda.end(), lambda);
    }
    for (int p = 0; p < points_; ++p) {
      for (int i = 0; i < kPointVars; ++i) x[var(p) + i] = guess_.points[static_cast<std::size_t>(p)](i);
    }
    x[var_T()] = guess_.duration;
    return true;
  }

  bool eval_f(Index, const Number* x, bool, Number& obj) override {
    obj = x[var_T()];
    return true;
  }

  bool eval_grad_f(Index n, const Number*, bool, Number* grad) override {
    for (Index i = 0; i < n; ++i) grad[i] = 0.0;
    grad[var_T()] = 1.0;
    return true;
  }

  bool eval_g(Index, const Number* x, bool, Index m, Number* g) override {
    for (Index r = 0; r < m; ++r) g[r] = 0.0;
    const double T = x[var_T()];
    const int N = setup_.intervals;
    for (int k = 0; k < N; ++k) {
      const Interval iv = interval(k);
      const StateVector fa = dynamics_.f(point(x, iv.a));
      const StateVector fb = dynamics_.f(point(x, iv.b));
      const StateVector xa = point(x, iv.a).head<7>();
      const StateVector xb = point(x, iv.b).head<7>();
      if (hermite_simpson()) {
        const StateVector fm = dynamics_.f(point(x, iv.m));
        const StateVector xm = point(x, iv.m).head<7>();
        const StateVector d1 = xm - 0.5 * (xa + xb) - c1() * T * (fa - fb);
        const StateVector d2 = xb - xa - c2() * T * (fa + 4.0 * fm + fb);
        for (int i = 0; i < 7; ++i) {
          g[14 * k + i] = d1(i);
          g[14 * k + 7 + i] = d2(i);
        }
      } else {
        const StateVector d = xb - xa - ct() * T * (fa + fb);
        for (int i = 0; i < 7; ++i) g[7 * k + i] = d(i);
      }
    }
    int row = defect_rows();
    for (int p = 0; p < points_; ++p) {
      const PointVector z = point(x, p);
      g[row++] = z.segment<3>(7).squaredNorm();
      const Eigen::Vector4d q = z.head<4>();
      for (const TranscribedCone& cone : setup_.cones) {
        if (!imposed(cone, p)) continue;
        g[row++] = q.dot(cone.form * q) - cone.cosine_at_point[static_cast<std::size_t>(p)] * q.squaredNorm();
      }
    }
    const Eigen::Vector3d terminal = terminal_ * point(x, points_ - 1).head<4>();
    for (int i = 0; i < 3; ++i) g[row++] = terminal(i);
    return true;
  }

  bool eval_jac_g(Index, const Number* x, bool, Index, Index, Index* iRow, Index* jCol,
                  Number* values) override {
    Index e = 0;
    if (values == nullptr) {
      const std::vector<double> zero(static_cast<std::size_t>(variables()), 0.0);
      visit_jacobian(zero.data(), [&](int r, int c, double) {
        iRow[e] = r;
        jCol[e] = c;
        ++e;
      });
    } else {
      visit_jacobian(x, [&](int, int, double v) { values[e++] = v; });
    }
    return true;
  }

  bool eval_h(Index, const Number* x, bool, Number, Index, const Number* lambda, bool, Index,
              Index* iRow, Index* jCol, Number* values) override {
    if (values == nullptr) {
      Index e = 0;
      for (int p = 0; p < points_; ++p) {
        const int o = var(p);
        for (int i = 0; i < 4; ++i) {
          for (int j = 0; j <= i; ++j) { iRow[e] = o + i; jCol[e] = o + j; ++e; }
        }
        for (int i = 4; i < 7; ++i) {
          for (int j = 0; j < 4; ++j) { iRow[e] = o + i; jCol[e] = o + j; ++e; }
        }
        for (int i = 4; i < 7; ++i) {
          for (int j = 4; j <= i; ++j) { iRow[e] = o + i; jCol[e] = o + j; ++e; }
        }
        for (int i = 7; i < 10; ++i) { iRow[e] = o + i; jCol[e] = o + i; ++e; }
        for (int j = 0; j < kPointVars; ++j) { iRow[e] = var_T(); jCol[e] = o + j; ++e; }
      }
      return true;
    }
    const double T = x[var_T()];
    // μ_p: the multiplier of f(z_p) in the Lagrangian, divided by T.
    std::vector<StateVector> mu(static_cast<std::size_t>(points_), StateVector::Zero());
    for (int k = 0; k < setup_.intervals; ++k) {
      const Interval iv = interval(k);
      if (hermite_simpson()) {
        StateVector l1, l2;
        for (int i = 0; i < 7; ++i) {
          l1(i) = lambda[14 * k + i];
          l2(i) = lambda[14 * k + 7 + i];
        }
        mu[static_cast<std::size_t>(iv.a)] += -c1() * l1 - c2() * l2;
        mu[static_cast<std::size_t>(iv.b)] += c1() * l1 - c2() * l2;
        mu[static_cast<std::size_t>(iv.m)] += -4.0 * c2() * l2;
      } else {
        StateVector l;
        for (int i = 0; i < 7; ++i) l(i) = lambda[7 * k + i];
        mu[static_cast<std::size_t>(iv.a)] += -ct() * l;
        mu[static_cast<std::size_t>(iv.b)] += -ct() * l;
      }
    }
    Index e = 0;
    int row = defect_rows();
    for (int p = 0; p < points_; ++p) {
      const PointVector z = point(x, p);
      const StateVector& m_p = mu[static_cast<std::size_t>(p)];
      PointHessian H = T * dynamics_.hessian(m_p);
      H.block<3, 3>(7, 7) += 2.0 * lambda[row++] * lie::Mat3::Identity();
      for (const TranscribedCone& cone : setup_.cones) {
        if (!imposed(cone, p)) continue;
        const double c = cone.cosine_at_point[static_cast<std::size_t>(p)];
        H.block<4, 4>(0, 0) += 2.0 * lambda[row++] * (cone.form - c * Eigen::Matrix4d::Identity());
      }
      const Eigen::Matrix<double, 1, 10> t_row = m_p.transpose() * dynamics_.jacobian(z);
      for (int i = 0; i < 4; ++i) {
        for (int j = 0; j <= i; ++j) values[e++] = H(i, j);
      }
      for (int i = 4; i < 7; ++i) {
        for (int j = 0; j < 4; ++j) values[e++] = H(i, j);
      }
      for (int i = 4; i < 7; ++i) {
        for (int j = 4; j <= i; ++j) values[e++] = H(i, j);
      }
      for (int i = 7; i < 10; ++i) values[e++] = H(i, i);
      for (int j = 0; j < kPointVars; ++j) values[e++] = t_row(j);
    }
    return true;
  }

  bool intermediate_callback(Ipopt::AlgorithmMode, Index iter, Number, Number, Number, Number,
                             Number, Number, Number, Number, Index, const Ipopt::IpoptData*,
                             Ipopt::IpoptCalculatedQuantities*) override {
    result.iterations = iter;
    return !io::interrupted();
  }

  void finalize_solution(Ipopt::SolverReturn, Index n, const Number* x, const Number* z_L,
                         const Number* z_U, Index m, const Number*, const Number* lambda, Number,
                         const Ipopt::IpoptData*, Ipopt::IpoptCalculatedQuantities*) override {
    result.values.points.resize(static_cast<std::size_t>(points_));
    for (int p = 0; p < points_; ++p) result.values.points[static_cast<std::size_t>(p)] = point(x, p);
    result.values.duration = x[var_T()];
    result.values.z_lower.assign(z_L, z_L + n);
    result.values.z_upper.assign(z_U, z_U + n);
    result.values.lambda.assign(lambda, lambda + m);
  }

  /// The program's sizes (n variables, m constraints).
  [[nodiscard]] int variable_count() const noexcept { return variables(); }
  [[nodiscard]] int constraint_count() const noexcept { return constraints(); }

 private:
  struct Interval {
    int a, m, b;  ///< the interval's points: start, midpoint (Hermite–Simpson), end
  };

  [[nodiscard]] bool hermite_simpson() const noexcept {
    return setup_.transcription == Transcription::hermite_simpson;
  }
  [[nodiscard]] Interval interval(int k) const noexcept {
    return hermite_simpson() ? Interval{2 * k, 2 * k + 1, 2 * k + 2} : Interval{k, -1, k + 1};
  }
  [[nodiscard]] double c1() const noexcept { return 1.0 / (8.0 * setup_.intervals); }
  [[nodiscard]] double c2() const noexcept { return 1.0 / (6.0 * setup_.intervals); }
  [[nodiscard]] double ct() const noexcept { return 1.0 / (2.0 * setup_.intervals); }
  [[nodiscard]] static int var(int p) noexcept { return kPointVars * p; }
  [[nodiscard]] int var_T() const noexcept { return kPointVars * points_; }
  [[nodiscard]] int variables() const noexcept { return var_T() + 1; }
  [[nodiscard]] int defect_rows() const noexcept {
    return (hermite_simpson() ? 14 : 7) * setup_.intervals;
  }
  /// A cone is imposed at every point but the two fixed ends (checked before the solve) where
  /// its cosine is finite: −∞ leaves the point free of it (TranscribedCone).
  [[nodiscard]] bool imposed(const TranscribedCone& cone, int p) const noexcept {
    return p > 0 && p < points_ - 1 && std::isfinite(cone.cosine_at_point[static_cast<std::size_t>(p)]);
  }
  [[nodiscard]] int constraints() const noexcept {
    int cone_rows = 0;
    for (const TranscribedCone& cone : setup_.cones) {
      for (int p = 0; p < points_; ++p) cone_rows += imposed(cone, p) ? 1 : 0;
    }
    return defect_rows() + points_ + cone_rows + 3;
  }
  [[nodiscard]] static PointVector point(const Number* x, int p) noexcept {
    return Eigen::Map<const PointVector>(x + var(p));
  }

  /// Visits the Jacobian's entries (row, column, value) in their fixed order.
  template <class Emit>
  void visit_jacobian(const Number* x, Emit&& emit) const {
    const double T = x[var_T()];
    const int N = setup_.intervals;
    // Emits the 7 rows from `row` of  base·[I 0] + scale·∂f/∂z  at point p.
    auto emit_block = [&](int row, int p, double base, double scale, const PointJacobian& F) {
      for (int i = 0; i < 7; ++i) {
        for (int j = 0; j < kPointVars; ++j) {
          if (!in_point_jacobian(i, j)) continue;
          emit(row + i, var(p) + j, (i == j ? base : 0.0) + scale * F(i, j));
        }
      }
    };
    for (int k = 0; k < N; ++k) {
      const Interval iv = interval(k);
      const PointJacobian Fa = dynamics_.jacobian(point(x, iv.a));
      const PointJacobian Fb = dynamics_.jacobian(point(x, iv.b));
      const StateVector fa = dynamics_.f(point(x, iv.a));
      const StateVector fb = dynamics_.f(point(x, iv.b));
      if (hermite_simpson()) {
        const PointJacobian Fm = dynamics_.jacobian(point(x, iv.m));
        const StateVector fm = dynamics_.f(point(x, iv.m));
        const int r1 = 14 * k;
        const int r2 = 14 * k + 7;
        emit_block(r1, iv.a, -0.5, -c1() * T, Fa);
        for (int i = 0; i < 7; ++i) emit(r1 + i, var(iv.m) + i, 1.0);
        emit_block(r1, iv.b, -0.5, c1() * T, Fb);
        for (int i = 0; i < 7; ++i) emit(r1 + i, var_T(), -c1() * (fa(i) - fb(i)));
        emit_block(r2, iv.a, -1.0, -c2() * T, Fa);
        emit_block(r2, iv.m, 0.0, -4.0 * c2() * T, Fm);
        emit_block(r2, iv.b, 1.0, -c2() * T, Fb);
        for (int i = 0; i < 7; ++i) emit(r2 + i, var_T(), -c2() * (fa(i) + 4.0 * fm(i) + fb(i)));
      } else {
        const int r = 7 * k;
        emit_block(r, iv.a, -1.0, -ct() * T, Fa);
        emit_block(r, iv.b, 1.0, -ct() * T, Fb);
        for (int i = 0; i < 7; ++i) emit(r + i, var_T(), -ct() * (fa(i) + fb(i)));
      }
    }
    int row = defect_rows();
    for (int p = 0; p < points_; ++p) {
      const PointVector z = point(x, p);
      for (int i = 7; i < 10; ++i) emit(row, var(p) + i, 2.0 * z(i));
      ++row;
      const Eigen::Vector4d q = z.head<4>();
      for (const TranscribedCone& cone : setup_.cones) {
        if (!imposed(cone, p)) continue;
        const double c = cone.cosine_at_point[static_cast<std::size_t>(p)];
        const Eigen::Vector4d grad = 2.0 * (cone.form * q - c * q);
        for (int i = 0; i < 4; ++i) emit(row, var(p) + i, grad(i));
        ++row;
      }
    }
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 4; ++j) emit(row + i, var(points_ - 1) + j, terminal_(i, j));
    }
  }

  const TranscriptionSetup& setup_;
  const TranscriptionValues& guess_;
  PointDynamics dynamics_;
  int points_;
  Eigen::Matrix<double, 3, 4> terminal_;
};

/// The barrier parameter and the push from the bounds of a warm start.
constexpr double kWarmMuInit = 1e-8;
constexpr double kWarmPush = 1e-9;

/// Whether `guess` carries multipliers of `nlp`'s sizes (a warm start).
bool warm_startable(const TranscriptionValues& guess, const SlewNlp& nlp) {
  const auto n = static_cast<std::size_t>(nlp.variable_count());
  return guess.z_lower.size() == n && guess.z_upper.size() == n &&
         guess.lambda.size() == static_cast<std::size_t>(nlp.constraint_count());
}

/// IPOPT is not thread-safe: one solve at a time in the process.
std::mutex& ipopt_mutex() {
  static std::mutex m;
  return m;
}

const char* status_name(Ipopt::ApplicationReturnStatus status) noexcept {
  switch (status) {
    case Ipopt::Solve_Succeeded: return "Solve_Succeeded";
    case Ipopt::Solved_To_Acceptable_Level: return "Solved_To_Acceptable_Level";
    case Ipopt::Infeasible_Problem_Detected: return "Infeasible_Problem_Detected";
    case Ipopt::Search_Direction_Becomes_Too_Small: return "Search_Direction_Becomes_Too_Small";
    case Ipopt::Diverging_Iterates: return "Diverging_Iterates";
    case Ipopt::User_Requested_Stop: return "User_Requested_Stop";
    case Ipopt::Feasible_Point_Found: return "Feasible_Point_Found";
    case Ipopt::Maximum_Iterations_Exceeded: return "Maximum_Iterations_Exceeded";
    case Ipopt::Restoration_Failed: return "Restoration_Failed";
    case Ipopt::Error_In_Step_Computation: return "Error_In_Step_Computation";
    case Ipopt::Maximum_CpuTime_Exceeded: return "Maximum_CpuTime_Exceeded";
    case Ipopt::Not_Enough_Degrees_Of_Freedom: return "Not_Enough_Degrees_Of_Freedom";
    case Ipopt::Invalid_Problem_Definition: return "Invalid_Problem_Definition";
    case Ipopt::Invalid_Option: return "Invalid_Option";
    case Ipopt::Invalid_Number_Detected: return "Invalid_Number_Detected";
    case Ipopt::Unrecoverable_Exception: return "Unrecoverable_Exception";
    case Ipopt::NonIpopt_Exception_Thrown: return "NonIpopt_Exception_Thrown";
    case Ipopt::Insufficient_Memory: return "Insufficient_Memory";
    case Ipopt::Internal_Error: return "Internal_Error";
  }
  return "unknown status";
}

}  // namespace

int transcription_points(Transcription transcription, int intervals) noexcept {
  return transcription == Transcription::hermite_simpson ? 2 * intervals + 1 : intervals + 1;
}

TranscriptionResult solve_transcription(const TranscriptionSetup& setup,
                                        const TranscriptionValues& guess) {
  const int points = transcription_points(setup.transcription, setup.intervals);
  if (static_cast<int>(guess.points.size()) != points) {
    throw std::logic_error("solve_transcription: the guess has the wrong number of points");
  }
  for (const TranscribedCone& cone : setup.cones) {
    if (static_cast<int>(cone.cosine_at_point.size()) != points) {
      throw std::logic_error("solve_transcription: a cone has the wrong number of points");
    }
  }
  const std::lock_guard<std::mutex> lock(ipopt_mutex());
  Ipopt::SmartPtr<SlewNlp> nlp = new SlewNlp(setup, guess);
  Ipopt::SmartPtr<Ipopt::IpoptApplication> app = IpoptApplicationFactory();
  app->Options()->SetIntegerValue("print_level", 0);
  app->Options()->SetStringValue("sb", "yes");
  app->Options()->SetIntegerValue("max_iter", setup.max_iterations);
  app->Options()->SetNumericValue("max_cpu_time", setup.max_seconds);
  app->Options()->SetNumericValue("tol", setup.tolerance);
  app->Options()->SetNumericValue("acceptable_tol", 1000.0 * setup.tolerance);
  app->Options()->SetNumericValue("constr_viol_tol", setup.tolerance);
  app->Options()->SetNumericValue("acceptable_constr_viol_tol", 100.0 * setup.tolerance);
  if (warm_startable(guess, *nlp)) {
    // From a solution of a program of the same structure (docs/slew-planner.md, "Speed"): its
    // multipliers, a small barrier parameter, the point hardly pushed from its bounds.
    app->Options()->SetStringValue("warm_start_init_point", "yes");
    app->Options()->SetStringValue("mu_strategy", "monotone");
    app->Options()->SetNumericValue("mu_init", kWarmMuInit);
    for (const char* o : {"warm_start_bound_push", "warm_start_bound_frac",
                          "warm_start_slack_bound_push", "warm_start_slack_bound_frac",
                          "warm_start_mult_bound_push"}) {
      app->Options()->SetNumericValue(o, kWarmPush);
    }
  } else {
    app->Options()->SetStringValue("mu_strategy", "adaptive");
  }
  if (app->Initialize() != Ipopt::Solve_Succeeded) {
    throw NumericalError("plan: IPOPT could not be initialised");
  }
  const Ipopt::ApplicationReturnStatus status = app->OptimizeTNLP(Ipopt::GetRawPtr(nlp));
  TranscriptionResult result = nlp->result;
  result.status = status_name(status);
  result.solved = status == Ipopt::Solve_Succeeded || status == Ipopt::Solved_To_Acceptable_Level;
  if (status == Ipopt::User_Requested_Stop) io::throw_if_interrupted(" while planning the slew");
  if (result.values.points.empty()) result.values = guess;
  return result;
}

}  // namespace attiguard::plan
