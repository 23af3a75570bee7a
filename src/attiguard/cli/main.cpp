/// @file main.cpp
/// The `attiguard` program: argument parsing (CLI11) and the mapping of failures to exit codes.
///
/// Exit codes (docs/conventions.md): 0 success; 2 invalid input, including bad command-line
/// arguments, set-up errors of the library and a scenario too large for the memory; 3 numerical
/// failure, and any unexpected internal error; 4 a requested safety verification failed. Every non-zero exit prints exactly one line on stderr:
///   attiguard: error: <message>

#include <algorithm>
#include <exception>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <system_error>
#include <iostream>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "attiguard/cli/campaign_command.hpp"
#include "attiguard/cli/commands.hpp"
#include "attiguard/cli/export_aem_command.hpp"
#include "attiguard/cli/plan_command.hpp"
#include "attiguard/cli/reach_command.hpp"
#include "attiguard/cli/tune_command.hpp"
#include "attiguard/cli/view_command.hpp"
#include "attiguard/core/errors.hpp"
#include "attiguard/core/version.hpp"
#include "attiguard/app/failure.hpp"
#include "attiguard/app/kinds.hpp"
#include "attiguard/io/interruption.hpp"
#include "attiguard/scenario/work_limits.hpp"

namespace {

using attiguard::ExitCode;

/// Prints the one stderr line of a failed run (newlines in the message become "; ") and returns
/// the exit code.
int fail(ExitCode code, std::string message) {
  std::string line;
  line.reserve(message.size());
  for (char c : message) {
    if (c == '\r') continue;
    if (c == '\n') {
      line += "; ";
    } else {
      line += c;
    }
  }
  while (line.ends_with("; ")) line.resize(line.size() - 2);
  std::cout.flush();
  std::cerr << "attiguard: error: " << line << std::endl;
  return static_cast<int>(code);
}

/// The footer of `attiguard --help`: every scenario kind with its description.
std::string kinds_help() {
  std::size_t width = 0;
  for (const auto& k : attiguard::app::kinds()) width = std::max(width, k.name.size());
  std::string text = "Scenario kinds (the top-level `kind` key of the scenario file):\n";
  for (const auto& k : attiguard::app::kinds()) {
    text += "  " + std::string(k.name) + std::string(width - k.name.size() + 2, ' ') +
            std::string(k.description) + "\n";
  }
  text +=
      "\nExit codes: 0 success, 2 invalid input, 3 numerical failure, 4 verification failed.\n"
      "Documentation: docs/conventions.md, docs/scenario-format.md.";
  return text;
}

/// The scenario file named on the command line (the first argument after the subcommand that
/// is an existing file), for messages about failures that carry no location; "" when none.
std::string scenario_argument(int argc, char** argv) noexcept {
  try {
    for (int i = 2; i < argc; ++i) {
      std::error_code ec;
      if (std::filesystem::is_regular_file(argv[i], ec)) return argv[i];
    }
  } catch (...) {
  }
  return {};
}

/// "run, check, reach, campaign": the subcommands' names in declaration order.
std::string subcommand_list(CLI::App& app) {
  std::string names;
  for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
    names += (names.empty() ? "" : ", ") + sub->get_name();
  }
  return names;
}

/// --seed S as an unsigned 64-bit integer: digits only, at most 2^64 − 1 (docs/campaigns.md).
std::uint64_t parse_seed(const std::string& text) {
  std::uint64_t seed = 0;
  const char* end = text.data() + text.size();
  const auto r = std::from_chars(text.data(), end, seed);
  if (text.empty() || text.front() == '-' || text.front() == '+') {
    throw attiguard::InputError("--seed: must be a whole number from 0 to 18446744073709551615, got '" +
                                text + "'");
  }
  if (r.ec == std::errc::result_out_of_range) {
    throw attiguard::InputError("--seed: " + text + " is larger than 2^64 - 1 = 18446744073709551615");
  }
  if (r.ec != std::errc{} || r.ptr != end) {
    throw attiguard::InputError("--seed: must be a whole number from 0 to 18446744073709551615, got '" +
                                text + "'");
  }
  return seed;
}

/// The flags that raise the work limits (scenario/work_limits.hpp, docs/errors.md "Work too
/// large") on subcommand `cmd`: `--max-steps`, `--max-output-rows`, `--max-runs`, `--max-cells`.
void add_limit_flags(CLI::App* cmd, attiguard::scenario::WorkLimits& limits) {
  using attiguard::scenario::WorkLimit;
  using attiguard::scenario::limit_flag;
  const auto add = [&](WorkLimit which, double& value, const char* what) {
    cmd->add_option(std::string(limit_flag(which)), value,
                    std::string("Refuse scenarios needing more ") + what + " (default " +
                        CLI::detail::to_string(value) + ")")
        ->type_name("N")
        ->check(CLI::Validator(
            [](const std::string& text) -> std::string {
              double x = 0.0;
              const auto r = std::from_chars(text.data(), text.data() + text.size(), x);
              const bool ok = r.ec == std::errc{} && r.ptr == text.data() + text.size() &&
                              std::isfinite(x) && x >= 1.0;
              return ok ? std::string() : "must be a number >= 1, got '" + text + "'";
            },
            "N"));
  };
  add(WorkLimit::run_steps, limits.run_steps, "integrator/governor steps per run");
  add(WorkLimit::output_rows, limits.output_rows, "output rows per run");
  add(WorkLimit::campaign_runs, limits.campaign_runs, "campaign runs");
  add(WorkLimit::reach_cells, limits.reach_cells, "reach cells x steps");
}

/// The subcommands, and what their arguments are parsed into (CLI11 keeps references to these
/// members: the object stays where it is while the arguments are parsed).
struct Commands {
  attiguard::cli::RunArguments run;            // cli/run_command.cpp
  std::filesystem::path check;                 // cli/check_command.cpp
  attiguard::cli::ReachArguments reach;        // ConReach: cli/reach_command.cpp
  attiguard::cli::PlanArguments plan;          // slew planner: cli/plan_command.cpp
  attiguard::cli::CampaignArguments campaign;  // Monte Carlo campaigns: cli/campaign_command.cpp
  std::string campaign_seed = "1";  // parsed after: CLI11 would wrap "-1" and clamp 2^64
  attiguard::cli::ExportAemArguments aem;      // CCSDS AEM: cli/export_aem_command.cpp
  attiguard::cli::TuneArguments tune;          // gain search: cli/tune_command.cpp
  long tune_budget = 64;  // flags given override the scenario's [tune] table (tune_command.hpp)
  long tune_batch = 4;
  std::string tune_seed = "1";
  bool tune_no_plot = false;
  std::filesystem::path view;                  // browser viewer: cli/view_command.cpp
  attiguard::scenario::WorkLimits limits = attiguard::scenario::work_limits();
  CLI::App* run_cmd{nullptr};
  CLI::App* check_cmd{nullptr};
  CLI::App* reach_cmd{nullptr};
  CLI::App* plan_cmd{nullptr};
  CLI::App* campaign_cmd{nullptr};
  CLI::App* aem_cmd{nullptr};
  CLI::App* tune_cmd{nullptr};
  CLI::App* view_cmd{nullptr};
};

/// The positional SCENARIO of `cmd` (required).
void add_scenario_argument(CLI::App* cmd, std::filesystem::path& scenario, const std::string& help) {
  cmd->add_option("SCENARIO", scenario, help)->required()->type_name("FILE");
}

/// --out DIR of `cmd` (required).
void add_out_option(CLI::App* cmd, std::filesystem::path& out_dir) {
  cmd->add_option("--out", out_dir, "Output directory (created if missing)")->required()->type_name("DIR");
}

/// `run` and `check`.
void add_run_and_check(CLI::App& app, Commands& c) {
  c.run_cmd = app.add_subcommand(
      "run", "Run a scenario; write trajectory.csv and summary.json (and plots) into DIR");
  add_scenario_argument(c.run_cmd, c.run.scenario, "Scenario file (TOML)");
  add_out_option(c.run_cmd, c.run.out_dir);
  c.run_cmd->add_flag("--plot", c.run.plot, "Also write PNG plots into DIR (needs python3-matplotlib)");
  c.run_cmd->add_flag("--aem", c.run.aem, "Also write DIR/attitude.aem (CCSDS AEM, docs/interop.md)");
  c.run_cmd->add_flag("--view", c.run.view, "Also write DIR/view.html (browser viewer, docs/viewer.md)");

  c.check_cmd = app.add_subcommand("check", "Parse and validate a scenario without running it");
  add_scenario_argument(c.check_cmd, c.check, "Scenario file (TOML)");
}

/// `reach`.
void add_reach(CLI::App& app, Commands& c) {
  c.reach_cmd = app.add_subcommand(
      "reach", "ConReach reachability and safety verification; write reach.json into DIR");
  add_scenario_argument(c.reach_cmd, c.reach.scenario, "Scenario file (TOML, kind = \"reach\")");
  add_out_option(c.reach_cmd, c.reach.out_dir);
  c.reach_cmd->add_flag("--plot", c.reach.plot, "Also write PNG plots into DIR");
  c.reach_cmd->add_flag("--view", c.reach.view, "Also write DIR/view.html (docs/viewer.md)");
}

/// `plan`.
void add_plan(CLI::App& app, Commands& c) {
  c.plan_cmd = app.add_subcommand(
      "plan", "Plan a near time-optimal slew that keeps every cone; write plan.csv and plan.json "
              "into DIR (docs/slew-planner.md)");
  add_scenario_argument(c.plan_cmd, c.plan.scenario, "Scenario file (TOML, kind = \"pet_erg\")");
  c.plan_cmd->add_option("--out", c.plan.out_dir,
                         "Output directory (created if missing; default out/<scenario>_plan)")
      ->type_name("DIR");
  c.plan_cmd->add_flag("--plot", c.plan.plot, "Also write PNG plots into DIR");
  c.plan_cmd->add_flag("--view", c.plan.view, "Also write DIR/view.html (browser viewer, docs/viewer.md)");
}

/// `campaign`.
void add_campaign(CLI::App& app, Commands& c) {
  attiguard::cli::CampaignArguments& a = c.campaign;
  CLI::App* cmd = c.campaign_cmd = app.add_subcommand(
      "campaign",
      "Monte Carlo campaign over the scenario's [dispersions]; write runs.csv and campaign.json "
      "into DIR (under mpirun: runs split over the ranks)");
  add_scenario_argument(cmd, a.scenario, "Scenario file with [dispersions]");
  cmd->add_option("--runs", a.runs, "Number of runs N (runs 0..N-1)")->type_name("N");
  cmd->add_option("--seed", c.campaign_seed, "Campaign seed S, 0 to 2^64 - 1 (default 1)")->type_name("S");
  add_out_option(cmd, a.out_dir);
  cmd->add_option("--threads", a.threads, "Worker threads per process")->type_name("T");
  cmd->add_option("--replay", a.replay, "Re-run run K alone with its full trajectory into DIR/run_K")
      ->type_name("K");
  cmd->add_flag("--resume", a.resume, "Keep the runs already in DIR/runs.csv and run the others");
  cmd->add_flag("--plot", a.plot, "Also write histograms and scatter plots");
  cmd->add_flag("--view", a.view, "With --replay: also DIR/run_K/view.html");
  cmd->add_flag("--aem", a.aem, "With --replay: also DIR/run_K/attitude.aem");
}

/// `export-aem`.
void add_export_aem(CLI::App& app, Commands& c) {
  attiguard::cli::ExportAemArguments& a = c.aem;
  CLI::App* cmd = c.aem_cmd = app.add_subcommand(
      "export-aem", "Write the attitude history of a run's DIR as a CCSDS AEM (docs/interop.md)");
  cmd->add_option("DIR", a.dir, "Output folder of a run")->required()->type_name("DIR");
  cmd->add_option("--scenario", a.scenario, "Scenario file with the [ephemeris] keys")->type_name("FILE");
  cmd->add_option("--aem-version", a.version, "1.0 (default) or 2.0")->type_name("V");
  cmd->add_flag("--rates", a.rates, "Angular rates as well (QUATERNION/RATE)");
  cmd->add_option("--out", a.out, "Output file (default DIR/attitude.aem)")->type_name("FILE");
}

/// `tune`.
void add_tune(CLI::App& app, Commands& c) {
  CLI::App* cmd = c.tune_cmd = app.add_subcommand(
      "tune", "Search k_p, k_d, kappa, T_s, c_Gamma of a pet_erg scenario for the fastest converged manoeuvre "
              "with every constraint kept; write tune.json and the best scenario into DIR (docs/pet-erg.md)");
  add_scenario_argument(cmd, c.tune.scenario, "pet_erg scenario file");
  add_out_option(cmd, c.tune.out_dir);
  cmd->add_option("--threads", c.tune.threads, "Worker threads per process")->type_name("T");
  cmd->add_option("--budget", c.tune_budget, "Runs in all (default: [tune] budget, else 64)")->type_name("RUNS");
  cmd->add_option("--batch", c.tune_batch,
                  "Points per refinement batch (default: [tune] batch, else 4); the search "
                  "depends on it, not on the ranks and threads")
      ->type_name("B");
  cmd->add_option("--seed", c.tune_seed, "Search seed S, 0 to 2^64 - 1 (default: [tune] seed, else 1)")
      ->type_name("S");
  cmd->add_option("--range", c.tune.ranges,
                  "KEY=MIN:MAX, searched log-uniformly; repeat per key (replaces [tune.ranges] and the "
                  "default control.kp, control.kd, erg.kappa, erg.sampling_period, erg.c_gamma ranges)")
      ->type_name("KEY=MIN:MAX");
  cmd->add_flag("--no-plot", c.tune_no_plot, "Do not write DIR/tune_tradeoff.png (also [tune] plot = false)");
}

/// `view`.
void add_view(CLI::App& app, Commands& c) {
  c.view_cmd = app.add_subcommand(
      "view", "Write DIR/view.html: a self-contained 3-D browser view of a result folder (docs/viewer.md)");
  c.view_cmd->add_option("DIR", c.view, "Output folder of run, reach, plan or campaign")
      ->required()
      ->type_name("DIR");
}

/// Parses the command line into `c`; the exit code when the program ends there (--help,
/// --version, a parse error), nothing when a command is to run.
std::optional<int> parse_arguments(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --version
    return app.exit(e);
  } catch (const CLI::ExtrasError& e) {
    // A first argument that is no subcommand: say so and list them.
    if (argc > 1 && argv[1][0] != '-') {
      bool known = false;
      for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) known = known || sub->get_name() == argv[1];
      if (!known) {
        return fail(ExitCode::invalid_input, std::string("unknown subcommand '") + argv[1] +
                                                 "' (subcommands: " + subcommand_list(app) +
                                                 "; see attiguard --help)");
      }
    }
    return fail(ExitCode::invalid_input, std::string(e.what()) + " (see attiguard --help)");
  } catch (const CLI::ParseError& e) {
    return fail(ExitCode::invalid_input, std::string(e.what()) + " (see attiguard --help)");
  }
  return std::nullopt;
}

/// The arguments CLI11 leaves as text or defaults (the seeds, the tune flags given), and the
/// work limits the flags raised (scenario/work_limits.hpp).
void finish_arguments(Commands& c) {
  if (c.campaign_cmd->parsed()) c.campaign.seed = parse_seed(c.campaign_seed);
  if (c.tune_cmd->parsed()) {
    if (c.tune_cmd->count("--seed") > 0) c.tune.seed = parse_seed(c.tune_seed);
    if (c.tune_cmd->count("--budget") > 0) c.tune.budget = c.tune_budget;
    if (c.tune_cmd->count("--batch") > 0) c.tune.batch = c.tune_batch;
    if (c.tune_no_plot) c.tune.plot = false;
  }
  attiguard::scenario::set_work_limits(c.limits);
}

/// Runs the subcommand parsed; the exit code.
int dispatch(const Commands& c) {
  if (c.run_cmd->parsed()) {
    attiguard::cli::run_command(c.run);
  } else if (c.check_cmd->parsed()) {
    attiguard::cli::check_command(c.check);
  } else if (c.reach_cmd->parsed()) {
    attiguard::cli::reach_command(c.reach);
  } else if (c.plan_cmd->parsed()) {
    attiguard::cli::plan_command(c.plan);
  } else if (c.campaign_cmd->parsed()) {
    attiguard::cli::campaign_command(c.campaign);
  } else if (c.tune_cmd->parsed()) {
    attiguard::cli::tune_command(c.tune);
  } else if (c.view_cmd->parsed()) {
    attiguard::cli::view_command(c.view);
  } else if (c.aem_cmd->parsed()) {
    attiguard::cli::export_aem_command(c.aem);
  } else {
    return fail(ExitCode::invalid_input,
                "a subcommand is required: run, check, reach, plan or campaign (see attiguard --help)");
  }
  attiguard::io::throw_if_interrupted();  // a command that ended without looking (check, MPI ranks)
  return static_cast<int>(ExitCode::ok);
}

int run(int argc, char** argv) {
  // SIGINT and SIGTERM end every command through its failure path: exit 3, one error line, only
  // .partial files and a status in its folder (io/interruption.hpp, app/output_folder.hpp).
  attiguard::io::install_interruption_handlers();
  CLI::App app{"attiguard: spacecraft attitude guidance and control with safety guarantees",
               "attiguard"};
  app.set_version_flag("--version", std::string("attiguard ") + attiguard::version_string);
  app.footer(kinds_help());
  // The subcommand requirement is checked after parsing, so that an unknown option is reported
  // as such rather than as a missing subcommand.
  app.require_subcommand(0, 1);
  Commands c;
  add_run_and_check(app, c);
  add_reach(app, c);
  add_plan(app, c);
  add_campaign(app, c);
  add_export_aem(app, c);
  add_tune(app, c);
  add_view(app, c);
  for (CLI::App* cmd : {c.run_cmd, c.check_cmd, c.reach_cmd, c.campaign_cmd}) add_limit_flags(cmd, c.limits);
  if (const std::optional<int> code = parse_arguments(app, argc, argv)) return *code;
  finish_arguments(c);
  return dispatch(c);
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (...) {
    // The error family → its exit code; std::bad_alloc / std::length_error → 2 with what was
    // too large; anything else → 3 "internal error" (app/failure.hpp).
    const attiguard::app::Failure f =
        attiguard::app::describe_failure(std::current_exception(), scenario_argument(argc, argv));
    return fail(f.code, f.message.empty() ? "out of memory" : f.message);
  }
}
