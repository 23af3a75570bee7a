#pragma once
/// @file aem_export.hpp
/// The CCSDS AEM export of a run's attitude history (docs/interop.md): DIR/trajectory.csv
/// (columns t, q_w, q_x, q_y, q_z and, for the rates, omega_x, omega_y, omega_z) to
/// DIR/attitude.aem through io/aem_writer.

#include <filesystem>
#include <vector>

#include "attiguard/io/aem_message.hpp"
#include "attiguard/io/csv_reader.hpp"

namespace attiguard::app {

/// The attitude samples of a trajectory table; throws InputError naming `source` and the
/// missing column when it has no t, q_w … q_z (or omega_x … omega_z when `with_rates`).
[[nodiscard]] std::vector<io::AttitudeSample> attitude_samples(const io::CsvTable& table,
                                                               const std::filesystem::path& source,
                                                               bool with_rates);

/// Writes `out` (default DIR/attitude.aem) from DIR/trajectory.csv with `meta`; returns the
/// path written. Throws InputError when DIR has no trajectory.csv or it has no attitude.
std::filesystem::path export_aem(const std::filesystem::path& dir, const io::AemMetadata& meta,
                                 std::filesystem::path out = {});

}  // namespace attiguard::app
