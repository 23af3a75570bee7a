/// @file reach_command.cpp
/// `attiguard reach SCENARIO --out DIR [--plot]` (docs/reach.md).

#include "attiguard/cli/reach_command.hpp"

#include <exception>
#include <fstream>
#include <new>
#include <iostream>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "attiguard/cli/commands.hpp"
#include "attiguard/cli/view_command.hpp"
#include "attiguard/core/errors.hpp"
#include "attiguard/parallel/mpi_world.hpp"
#include "attiguard/app/outcome_line.hpp"
#include "attiguard/app/output_folder.hpp"
#include "attiguard/app/failure.hpp"
#include "attiguard/app/reach_run.hpp"
#include "attiguard/io/json_file.hpp"
#include "attiguard/io/output_records.hpp"
#include "attiguard/scenario/resolved_scenario.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/read_reach.hpp"

namespace attiguard::cli {
namespace {

/// reach.json as run_reach wrote it before reporting an unproved verdict.
nlohmann::json read_reach_json(const std::filesystem::path& path) {
  std::ifstream f(path, std::ios::binary);
  nlohmann::json j = nlohmann::json::parse(f, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded()) throw std::runtime_error(path.string() + ": cannot read the reach.json just written");
  return j;
}

}  // namespace

namespace {

void reach_into(const ReachArguments& args, const parallel::World& world, app::OutputFolder& folder) {
  const scenario::Document doc = scenario::load_document(args.scenario);
  const reach::ReachScenario sc = scenario::parse_reach(doc);
  folder.set_subject("reach", args.scenario.string());
  if (args.out_dir.empty()) throw InputError("--out: the output directory must not be empty");

  // Under mpirun the partition cells are split over the ranks (docs/scaling.md); rank 0 prints
  // and writes. Outputs are written even when the verification fails; plots are made before
  // rethrowing.
  nlohmann::json summary;
  if (world.root()) {
    io::ensure_directory(args.out_dir);
    io::write_text(args.out_dir, scenario::kResolvedScenarioFile,
                   scenario::resolve_scenario(doc, [](const scenario::Document& d) { (void)scenario::parse_reach(d); }));
  }
  // A safety verification that fails (exit 4) still has its reach.json, its outcome line, its
  // plots and view; the failure is rethrown after them. Any other failure leaves
  // reach.json.partial saying why (app/output_folder.hpp).
  std::exception_ptr unproved;
  try {
    try {
      summary = app::run_reach(sc, args.out_dir, world);
    } catch (const parallel::ThreadStartError& e) {  // located at the key that asked for them
      scenario::fail_in_table(doc, "partition", "threads", app::thread_start_advice(e, "threads = "));
    } catch (const std::bad_alloc&) {  // the cells' analyses on those threads ran out of memory
      if (sc.threads <= 1) throw;
      scenario::fail_in_table(doc, "partition", "threads",
                              "out of memory with threads = " + std::to_string(sc.threads) +
                                  " (each thread analyses one cell at a time, with its own memory): "
                                  "the system limits the memory of this process (ulimit -v); use "
                                  "fewer threads");
    }
  } catch (const VerificationFailure&) {
    if (!world.root()) throw;
    unproved = std::current_exception();
    summary = read_reach_json(args.out_dir / "reach.json");
  }
  if (!world.root()) return;
  // The one-line outcome (docs/conventions.md, "Outcome line"), then the paths written.
  std::cout << app::reach_outcome_line(summary) << '\n';
  std::cout << "Wrote:\n  " << (args.out_dir / "reach.json").string() << "\n  "
            << (args.out_dir / scenario::kResolvedScenarioFile).string() << '\n';
  if (args.plot) {
    const PlotOutcome plots = plot_results("reach", args.out_dir);
    io::record_plots(args.out_dir, plots.written);
    for (const auto& p : plots.written) std::cout << "  " << p.string() << '\n';
    if (plots.skipped_because) std::cerr << "attiguard: warning: no plots: " << *plots.skipped_because << '\n';
  }
  if (args.view) std::cout << "  " << write_run_view(args.out_dir).string() << '\n';
  std::cout.flush();
  folder.finish();
  if (unproved) std::rethrow_exception(unproved);
}

}  // namespace

void reach_command(const ReachArguments& args) {
  // The folder's earlier outputs go first, even when the scenario is then refused; a failure
  // other than an unproved verdict leaves .partial files and reach.json.partial
  // (docs/conventions.md, "Outputs").
  const parallel::World world = parallel::mpi_world();
  app::OutputFolder folder(args.out_dir, app::OutputCommand::reach, world.root(), {args.scenario});
  app::run_in_folder(folder, "reach", args.scenario, [&] { reach_into(args, world, folder); });
}

}  // namespace attiguard::cli
