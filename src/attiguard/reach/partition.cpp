#include "attiguard/reach/partition.hpp"

#include <cmath>

#include "attiguard/core/errors.hpp"
#include "attiguard/reach/parallel.hpp"

namespace attiguard::reach {

namespace {
/// Grid points of the cover of the ball of radius a in R³ and the cell radius.
std::vector<Vec3> grid(double a, int n, double& cell_radius) {
  if (n <= 1) {
    cell_radius = a;
    return {Vec3::Zero()};
  }
  const double h = 2.0 * a / n;
  cell_radius = h * std::sqrt(3.0) / 2.0;
  std::vector<Vec3> pts;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      for (int k = 0; k < n; ++k) {
        const Vec3 p(-a + h * (i + 0.5), -a + h * (j + 0.5), -a + h * (k + 0.5));
        if (p.norm() <= a + cell_radius) pts.push_back(p);
      }
    }
  }
  return pts;
}
}  // namespace

std::vector<InitialSet> partition_initial_set(const InitialSet& whole, int n_att, int n_omega) {
  if (n_att < 1 || n_omega < 1 || n_att > 50 || n_omega > 50) {
    throw InputError("partition: cells per axis must be in [1, 50]");
  }
  double ra = 0.0;
  double rw = 0.0;
  const std::vector<Vec3> att = grid(whole.attitude_radius, n_att, ra);
  const std::vector<Vec3> om = grid(whole.omega_radius, n_omega, rw);
  std::vector<InitialSet> cells;
  for (const Vec3& eta : att) {
    for (const Vec3& v : om) {
      InitialSet c;
      c.R0 = whole.R0 * lie::exp(eta);
      c.attitude_radius = ra;
      c.omega0 = whole.omega0 + v;
      c.omega_radius = rw;
      c.P0 = whole.P0;
      cells.push_back(c);
    }
  }
  return cells;
}

std::vector<ReachResult> run_partitioned(const ClosedLoop& loop, const std::vector<InitialSet>& cells,
                                         const ConReachSettings& settings, int threads) {
  std::vector<ReachResult> out(cells.size());
  parallel_for(static_cast<long>(cells.size()), threads, [&](long i) {
    out[static_cast<std::size_t>(i)] = run_conreach(loop, cells[static_cast<std::size_t>(i)], settings);
  });
  return out;
}

}  // namespace attiguard::reach
