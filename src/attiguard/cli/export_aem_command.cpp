/// @file export_aem_command.cpp
/// `attiguard export-aem DIR` and the `--aem` step of `attiguard run` (docs/interop.md).

#include "attiguard/cli/export_aem_command.hpp"

#include <fstream>
#include <iostream>
#include <system_error>

#include <nlohmann/json.hpp>

#include "attiguard/app/aem_export.hpp"
#include "attiguard/app/output_folder.hpp"
#include "attiguard/io/interruption.hpp"
#include "attiguard/io/partial_file.hpp"
#include "attiguard/app/result_summary.hpp"
#include "attiguard/core/errors.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/ephemeris_table.hpp"

namespace attiguard::cli {
namespace {

/// The scenario name of DIR/summary.json, read by the reader of `attiguard view`
/// (app/result_summary.hpp); "SPACECRAFT" when there is no summary.json or it has no name.
std::string summary_name(const std::filesystem::path& dir) {
  std::error_code ec;
  if (!std::filesystem::exists(dir / "summary.json", ec)) return "SPACECRAFT";
  const nlohmann::json j = app::read_run_summary(dir / "summary.json");
  return j.contains("name") ? j["name"].get<std::string>() : "SPACECRAFT";
}

/// DIR as the folder of a run (docs/interop.md): a reach folder (its trajectory.csv is
/// the analysis' nominal, not a flown attitude) is refused.
void check_run_folder(const std::filesystem::path& dir) {
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) {
    throw InputError(dir.string() + ": not a directory (expected the --out DIR of a run)");
  }
  if (std::filesystem::exists(dir / "reach.json", ec) && !std::filesystem::exists(dir / "summary.json", ec)) {
    throw InputError(dir.string() + ": the folder of `attiguard reach` (reach.json), not of a run: its "
                     "trajectory.csv is the nominal of the analysis; export-aem exports the trajectory "
                     "of `attiguard run SCENARIO --out DIR` or `campaign --replay K`");
  }
}

/// The AEM metadata of --scenario, which must be the scenario of the run in DIR
/// (docs/interop.md): a scenario of another kind than DIR/summary.json's (a reach scenario for a
/// pet_erg run) is refused at its `kind`.
io::AemMetadata scenario_ephemeris(const std::filesystem::path& scenario_path, const std::filesystem::path& dir) {
  const scenario::Document doc = scenario::load_document(scenario_path);
  const std::string kind = scenario::scenario_kind(doc);
  std::error_code ec;
  const std::string run_kind = std::filesystem::exists(dir / "summary.json", ec)
                                   ? app::read_run_summary(dir / "summary.json")["kind"].get<std::string>()
                                   : std::string();
  if (kind == "reach" || (!run_kind.empty() && kind != run_kind)) {
    scenario::fail_at(doc, "kind",
                      "--scenario: a scenario of kind '" + kind + "' is not the scenario of the run in " +
                          dir.string() + (run_kind.empty() ? std::string() : " (kind '" + run_kind + "')") +
                          ": give the scenario the run was made of");
  }
  return scenario::parse_ephemeris(doc);
}

}  // namespace

namespace {

void export_aem_into(const ExportAemArguments& args) {
  check_run_folder(args.dir);
  io::AemMetadata meta;
  if (!args.scenario.empty()) {
    meta = scenario_ephemeris(args.scenario, args.dir);
  } else {
    meta = scenario::default_ephemeris(summary_name(args.dir));
    meta.comments.push_back("attiguard run " + meta.object_name +
                            "; no --scenario: default ephemeris keys (docs/interop.md)");
  }
  if (!args.version.empty()) {
    if (args.version == "1.0") {
      meta.version = io::AemVersion::v1;
    } else if (args.version == "2.0") {
      meta.version = io::AemVersion::v2;
    } else {
      throw InputError("--aem-version: must be 1.0 or 2.0, got '" + args.version + "'");
    }
  }
  if (args.rates) meta.with_rates = true;
  const auto path = app::export_aem(args.dir, meta, args.out);
  io::throw_if_interrupted();
  std::cout << "Wrote:\n  " << path.string() << '\n';
}

}  // namespace

void export_aem_command(const ExportAemArguments& args) {
  // DIR holds the run the AEM is made of: only DIR/attitude.aem (or --out FILE) is this
  // command's, and an earlier one goes before anything is read (app/output_folder.hpp).
  // An --out FILE named *.aem is removed first as well; any other name (a mistyped input file)
  // is only ever replaced by a complete AEM.
  const bool own_file = !args.out.empty();
  app::OutputFolder folder(args.dir, app::OutputCommand::export_aem, true, {args.scenario});
  if (own_file && args.out.extension() == ".aem") {
    std::error_code ec;
    std::filesystem::remove(args.out, ec);
    std::filesystem::remove(io::partial_path(args.out), ec);
  } else {
    folder.claim();
  }
  try {
    export_aem_into(args);
  } catch (...) {
    if (own_file) {
      std::error_code ec;
      if (std::filesystem::is_regular_file(args.out, ec)) {
        std::filesystem::rename(args.out, io::partial_path(args.out), ec);
      }
      if (io::interrupted()) {
        throw io::Interrupted("interrupted by " + io::interruption_signal_name() + ": no " +
                              args.out.string() + " written");
      }
      throw;
    }
    folder.fail(std::current_exception());
  }
}

std::filesystem::path write_run_aem(const std::filesystem::path& scenario,
                                    const std::filesystem::path& dir) {
  return app::export_aem(dir, scenario::parse_ephemeris(scenario::load_document(scenario)));
}

}  // namespace attiguard::cli
