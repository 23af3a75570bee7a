/// @file reach_command.cpp
/// `attiguard reach SCENARIO --out DIR [--plot]` (docs/reach.md).

#include "attiguard/cli/reach_command.hpp"

#include <cstdio>
#include <iostream>
#include <string>

#include <nlohmann/json.hpp>

#include "attiguard/cli/commands.hpp"
#include "attiguard/cli/view_command.hpp"
#include "attiguard/core/errors.hpp"
#include "attiguard/parallel/mpi_world.hpp"
#include "attiguard/app/reach_run.hpp"
#include "attiguard/io/json_file.hpp"
#include "attiguard/io/output_records.hpp"
#include "attiguard/scenario/resolved_scenario.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/reach_scenario.hpp"

namespace attiguard::cli {

void reach_command(const ReachArguments& args) {
  const scenario::Document doc = scenario::load_document(args.scenario);
  const reach::ReachScenario sc = scenario::parse_reach(doc);
  if (args.out_dir.empty()) throw InputError("--out: the output directory must not be empty");

  // Under mpirun the partition cells are split over the ranks (docs/scaling.md); rank 0 prints
  // and writes. Outputs are written even when the verification fails; plots are made before
  // rethrowing.
  const parallel::World world = parallel::mpi_world();
  nlohmann::json summary;
  if (world.root()) {
    io::remove_recorded_plots(args.out_dir);
    io::ensure_directory(args.out_dir);
    io::write_text(args.out_dir, scenario::kResolvedScenarioFile,
                   scenario::resolve_scenario(doc, [](const scenario::Document& d) { (void)scenario::parse_reach(d); }));
  }
  try {
    summary = app::run_reach(sc, args.out_dir, world);
  } catch (const VerificationFailure&) {
    if (args.plot && world.root()) io::record_plots(args.out_dir, plot_results("reach", args.out_dir).written);
    if (args.view && world.root()) (void)write_run_view(args.out_dir);
    throw;
  } catch (const Error& e) {  // no reach.json: reach.json.partial says why
    if (world.root()) {
      io::write_failure_status(args.out_dir, "reach.json", "reach", args.scenario.string(),
                               static_cast<int>(e.code()), e.what());
    }
    throw;
  }
  if (!world.root()) return;
  const auto& steps = summary["steps"];
  const auto& last = steps.back();
  char buf[256];
  std::cout << "Reach " << sc.name << " (" << sc.model << ", " << summary["rate_mode"].get<std::string>()
            << ", " << summary["cells"].get<long>() << " cell(s) on " << world.size << " rank(s)) in "
            << summary["wall_time_s"].get<double>() << " s\n";
  std::snprintf(buf, sizeof buf, "  final ball: r = %.6g, attitude within %.6g rad, c_N = %.4g\n",
                last["r"].get<double>(), last["attitude_radius"].get<double>(), last["c"].get<double>());
  std::cout << buf;
  std::cout << "  sdp_solves: " << summary["sdp_solves"].get<long>() << '\n';
  std::cout << "  soundness: " << summary["soundness"]["inside"].get<long>() << "/"
            << summary["soundness"]["samples"].get<long>() << " sampled trajectories inside\n";
  std::cout << "  verdict: " << summary["verdict"].get<std::string>() << '\n';
  std::cout << "Wrote:\n  " << (args.out_dir / "reach.json").string() << "\n  "
            << (args.out_dir / scenario::kResolvedScenarioFile).string() << '\n';
  if (args.plot) {
    const PlotOutcome plots = plot_results("reach", args.out_dir);
    io::record_plots(args.out_dir, plots.written);
    for (const auto& p : plots.written) std::cout << "  " << p.string() << '\n';
    if (plots.skipped_because) std::cerr << "attiguard: warning: no plots: " << *plots.skipped_because << '\n';
  }
  if (args.view) std::cout << "  " << write_run_view(args.out_dir).string() << '\n';
}

}  // namespace attiguard::cli
