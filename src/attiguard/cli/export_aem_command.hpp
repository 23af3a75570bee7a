#pragma once
/// @file export_aem_command.hpp
/// `attiguard export-aem DIR [--scenario FILE] [--aem-version V] [--rates] [--out FILE]`: the
/// attitude history of DIR/trajectory.csv as a CCSDS AEM (docs/interop.md).

#include <filesystem>
#include <string>

namespace attiguard::cli {

/// Arguments of `attiguard export-aem`.
struct ExportAemArguments {
  std::filesystem::path dir;       ///< DIR: the output folder of a run
  std::filesystem::path scenario;  ///< --scenario FILE: its [ephemeris] keys (empty: defaults)
  std::string version;             ///< --aem-version 1.0 | 2.0 (empty: the scenario's)
  bool rates{false};               ///< --rates: QUATERNION/RATE (2.0: QUATERNION/ANGVEL)
  std::filesystem::path out;       ///< --out FILE (empty: DIR/attitude.aem)
};

/// Writes the AEM and prints its path. Throws InputError on bad arguments or input files.
void export_aem_command(const ExportAemArguments& args);

/// The `--aem` step of `attiguard run` / `campaign --replay`: DIR/attitude.aem from the
/// scenario's [ephemeris] keys; returns its path.
std::filesystem::path write_run_aem(const std::filesystem::path& scenario,
                                    const std::filesystem::path& dir);

}  // namespace attiguard::cli
