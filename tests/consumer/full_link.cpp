// Links attiguard::attiguard (static) the way a downstream user would, without naming CSDP,
// BLAS/LAPACK, threads or MPI: one SDP through CSDP (min y s.t. y − 1 ⪰ 0, solution y = 1;
// docs/reach.md) and the MPI world (one rank outside an MPI launcher). Exit 0 on the expected
// answers.
#include <cmath>
#include <cstdio>

#include "attiguard/core/version.hpp"
#include "attiguard/parallel/mpi_world.hpp"
#include "attiguard/reach/sdp_solver.hpp"

int main() {
  attiguard::reach::LmiProblem problem(1);
  const int block = problem.add_block(1);
  problem.add_constant(block, Eigen::MatrixXd::Constant(1, 1, -1.0));
  problem.add_term(block, 0, Eigen::MatrixXd::Constant(1, 1, 1.0));
  problem.set_objective(0, 1.0);
  // The optimum lies on the boundary (eigenvalue 0): re-check the blocks to 1e-6.
  const attiguard::reach::SdpResult r = attiguard::reach::solve_sdp(problem, {}, 1e-6);
  const attiguard::parallel::World world = attiguard::parallel::mpi_world();
  const bool solved = r.status == attiguard::reach::SdpStatus::solved &&
                      std::abs(r.y(0) - 1.0) < 1e-6;
  std::printf("attiguard %s: SDP %s (%s), y = %.9f; MPI built: %s, rank %d of %d\n",
              attiguard::version_string, solved ? "solved" : "NOT solved", r.message.c_str(),
              r.y.size() > 0 ? r.y(0) : std::nan(""),
              attiguard::parallel::mpi_built() ? "yes" : "no", world.rank, world.size);
  return solved && world.rank == 0 && world.size == 1 ? 0 : 1;
}
