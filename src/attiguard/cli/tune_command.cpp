/// @file tune_command.cpp
/// `attiguard tune`: the fastest guaranteed manoeuvre of a pet_erg scenario over its gains, on
/// threads and MPI ranks (docs/pet-erg.md, section "Tuning").

#include "attiguard/cli/tune_command.hpp"

#include <chrono>
#include <iostream>

#include "attiguard/app/tune_batch.hpp"
#include "attiguard/app/outcome_line.hpp"
#include "attiguard/app/output_folder.hpp"
#include "attiguard/app/tune_search.hpp"
#include "attiguard/io/interruption.hpp"
#include "attiguard/io/json_file.hpp"
#include "attiguard/io/output_records.hpp"
#include "attiguard/cli/commands.hpp"
#include "attiguard/cli/output_dir.hpp"
#include "attiguard/core/errors.hpp"
#include "attiguard/parallel/mpi_world.hpp"
#include "attiguard/parallel/thread_limit.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/dispersion.hpp"
#include "attiguard/scenario/document_edit.hpp"
#include "attiguard/scenario/tune_table.hpp"

namespace attiguard::cli {

namespace {

/// The most runs `--budget` / `[tune] budget` ask for (docs/errors.md, "No abort"): every run is
/// a full simulation kept in memory and listed in tune.json; 10⁵ runs take hours already.
constexpr long kTuneBudgetLimit = 100000;

/// InputError naming the flag or the `[tune] budget` key when the budget is beyond the limit.
void check_budget(const TuneArguments& args, const scenario::TuneTable& table,
                  const scenario::Document& loaded) {
  const auto beyond = [](long budget) {
    return std::to_string(budget) + " runs are more than the limit " +
           std::to_string(kTuneBudgetLimit) +
           " (each is a full simulation, kept in memory and listed in tune.json): use a smaller budget";
  };
  if (args.budget) {
    if (*args.budget > kTuneBudgetLimit) throw InputError("--budget: " + beyond(*args.budget));
  } else if (table.budget && *table.budget > kTuneBudgetLimit) {
    scenario::fail_in_table(loaded, "tune", "budget", beyond(*table.budget));
  }
}

/// The search settings: each flag given, else its `[tune]` key, else the default.
app::TuneSettings tune_settings(const TuneArguments& args, const scenario::TuneTable& table,
                                const scenario::Document& nominal) {
  app::TuneSettings s;
  for (const std::string& r : args.ranges) s.parameters.push_back(app::parse_tune_range(r));
  if (s.parameters.empty()) {
    s.parameters = table.ranges;
  }
  if (s.parameters.empty()) s.parameters = app::default_tune_parameters(nominal);
  s.budget = args.budget.value_or(table.budget.value_or(64));
  s.seed = args.seed.value_or(table.seed.value_or(1));
  s.batch = args.batch.value_or(table.batch.value_or(4));
  s.threads = args.threads;
  return s;
}

/// Writes the best scenario (DIR/best, scenario::scenario_file_name) and prints the paths written.
void write_best(const TuneArguments& args, const scenario::Document& nominal,
                const app::TuneSettings& s, const app::TuneResult& r,
                const std::filesystem::path& tune_path) {
  const app::TunePoint& b = r.points[*r.best];
  const auto best_path = args.out_dir / scenario::scenario_file_name("best");
  {
    const scenario::Document best = app::tune_candidate(nominal, s.parameters, b.values);
    io::write_text(args.out_dir, best_path.filename().string(),
                   "# Written by attiguard tune from " + args.scenario.filename().string() +
                       " (docs/pet-erg.md, section \"Tuning\")\n" + scenario::document_text(best));
  }
  std::cout << "Wrote:\n  " << tune_path.string() << "\n  " << best_path.string() << '\n';
}

}  // namespace

namespace {

void tune_into(const TuneArguments& args, const parallel::World& world, app::OutputFolder& folder) {
  scenario::TuneTable table;
  scenario::Document nominal;
  app::TuneSettings s;
  // The set-up fails on every rank or on none (rank 0 alone makes DIR: the others write nothing).
  app::run_on_every_rank([&] {
    const scenario::Document loaded = scenario::load_document(args.scenario);
    table = scenario::read_tune_table(loaded);
    parallel::check_thread_count(args.threads);  // 1 to 4 per hardware thread (thread_limit.hpp)
    check_budget(args, table, loaded);
    // A campaign scenario is tuned at its nominal values.
    nominal = loaded.has_top_level("dispersions") ? scenario::nominal_document(loaded) : loaded;
    s = tune_settings(args, table, nominal);
    if (world.root()) make_output_dir(args.out_dir);
  }, world);
  folder.set_subject("pet_erg", args.scenario.string());
  s.world = world;
  s.scratch = args.out_dir / ".scratch";
  s.stop = &io::interruption_flag();  // a signal ends the search at the next evaluation
  if (world.root()) {
    std::cout << "Tuning " << args.scenario.string() << ": " << s.budget << " runs on "
              << world.size << " rank(s) x " << s.threads << " thread(s), seed " << s.seed << '\n';
    for (const auto& p : s.parameters) {
      std::cout << "  " << p.key << " in [" << p.min << ", " << p.max << "] (log-uniform)\n";
    }
    std::cout << std::flush;
  }
  const auto start = std::chrono::steady_clock::now();
  const app::TuneResult r = app::tune_search(nominal, s);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::error_code ec;
  std::filesystem::remove_all(s.scratch / ("rank" + std::to_string(world.rank)), ec);
  nlohmann::json j = app::tune_json(s, r);
  const auto tune_path = args.out_dir / "tune.json";
  if (world.root()) {
    std::filesystem::remove(s.scratch, ec);  // empty unless another rank is still removing its own
    j["ranks"] = world.size;
    j["threads"] = s.threads;
    j["wall_time_s"] = wall;
    io::write_json(tune_path, j);
    // The one-line outcome (docs/conventions.md, "Outcome line"), then the paths written.
    std::cout << app::tune_outcome_line(j) << '\n';
  }
  if (!r.best) {
    folder.finish();
    if (world.root()) std::cout << "Wrote:\n  " << tune_path.string() << '\n' << std::flush;
    throw VerificationFailure(args.scenario.string() + ": attiguard tune: " +
                              j["outcome_reason"].get<std::string>() + " (see " +
                              tune_path.string() + ")");
  }
  if (!world.root()) return;
  folder.finish();
  write_best(args, nominal, s, r, tune_path);
  if (args.plot.value_or(table.plot.value_or(true))) print_plots("tune", args.out_dir);
  folder.finish();
}

}  // namespace

void tune_command(const TuneArguments& args) {
  // The folder's earlier outputs go first, even when the scenario is then refused; a failure
  // other than "none converged" (exit 4, tune.json is its result) leaves .partial files and
  // tune.json.partial (docs/conventions.md, "Outputs").
  const parallel::World world = parallel::mpi_world();
  app::OutputFolder folder(args.out_dir, app::OutputCommand::tune, world.root(), {args.scenario});
  app::run_in_folder(folder, "pet_erg", args.scenario, [&] { tune_into(args, world, folder); });
}

}  // namespace attiguard::cli
