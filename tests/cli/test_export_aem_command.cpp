// cli/export_aem_command: `attiguard run --aem` and `attiguard export-aem DIR` on the PET-ERG
// paper scenario; the AEM read back equals trajectory.csv (docs/interop.md).
#ifdef ATTIGUARD_CLI_PATH
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "attiguard/io/aem_reader.hpp"
#include "attiguard/io/csv_reader.hpp"
#include "cli_runner.hpp"

namespace attiguard {
namespace {

namespace fs = std::filesystem;

std::string example(const char* name) {
  return std::string("'") + ATTIGUARD_SOURCE_DIR + "/examples/" + name + "'";
}

/// The largest difference between the AEM samples and the trajectory's t, q (sign of QC ≥ 0)
/// and ω_b (when the AEM has rates).
double worst_difference(const io::AemFile& aem, const io::CsvTable& csv) {
  EXPECT_EQ(aem.samples.size(), csv.rows.size());
  const std::size_t t = *csv.column("t"), qw = *csv.column("q_w"), wx = *csv.column("omega_x");
  double worst = 0.0;
  for (std::size_t i = 0; i < std::min(aem.samples.size(), csv.rows.size()); ++i) {
    const auto& row = csv.rows[i];
    const auto& s = aem.samples[i];
    worst = std::max(worst, std::abs(s.t - row[t]));
    const double sign = row[qw] < 0.0 ? -1.0 : 1.0;
    for (std::size_t k = 0; k < 4; ++k) worst = std::max(worst, std::abs(s.q_ib[k] - sign * row[qw + k]));
    if (aem.metadata.with_rates) {
      for (std::size_t k = 0; k < 3; ++k) worst = std::max(worst, std::abs(s.omega_b[k] - row[wx + k]));
    }
  }
  return worst;
}

TEST(ExportAemCommand, RunWithAemWritesTheTrajectoryAsAnAemThatReadsBackToOneInATrillion) {
  const fs::path dir = test::fresh_dir("aem_run");
  const auto r = test::run_cli("run " + example("pet_erg_paper.toml") + " --out '" + dir.string() + "' --aem");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("attitude.aem"), std::string::npos) << r.out;
  const io::AemFile aem = io::read_aem(dir / "attitude.aem", "2000-01-01T12:00:00");
  EXPECT_EQ(aem.metadata.object_name, "pet_erg_paper");
  EXPECT_EQ(aem.metadata.ref_frame_a, "EME2000");
  EXPECT_EQ(aem.metadata.ref_frame_b, "SC_BODY_1");
  EXPECT_EQ(aem.metadata.time_system, "TT");
  EXPECT_EQ(aem.attitude_dir, "A2B");
  EXPECT_EQ(aem.quaternion_type, "FIRST");
  const io::CsvTable csv = io::read_csv(dir / "trajectory.csv");
  EXPECT_EQ(csv.rows.size(), 6001u);
  EXPECT_LE(worst_difference(aem, csv), 1e-12);

  // export-aem of the same folder, version 2.0 with rates, the scenario's [ephemeris] keys.
  std::ofstream(dir / "scenario.toml")
      << test::read_file(fs::path(ATTIGUARD_SOURCE_DIR) / "examples/pet_erg_paper.toml")
      << "\n[ephemeris]\nepoch = \"2026-03-20T06:30:00.5\"\ntime_system = \"UTC\"\n"
         "object_name = \"DEMOSAT\"\nobject_id = \"2026-042B\"\nref_frame_a = \"ICRF\"\n";
  const auto e = test::run_cli("export-aem '" + dir.string() + "' --scenario '" +
                               (dir / "scenario.toml").string() + "' --aem-version 2.0 --rates --out '" +
                               (dir / "v2.aem").string() + "'");
  ASSERT_EQ(e.exit_code, 0) << e.err;
  const io::AemFile v2 = io::read_aem(dir / "v2.aem", "2026-03-20T06:30:00.5");
  EXPECT_EQ(v2.metadata.version, io::AemVersion::v2);
  EXPECT_TRUE(v2.metadata.with_rates);
  EXPECT_EQ(v2.metadata.object_id, "2026-042B");
  EXPECT_EQ(v2.metadata.ref_frame_a, "ICRF");
  EXPECT_EQ(v2.start_time, "2026-03-20T06:30:00.500000000000");
  EXPECT_EQ(v2.stop_time, "2026-03-20T06:31:00.500000000000");
  EXPECT_LE(worst_difference(v2, csv), 1e-12);
  fs::remove_all(dir);
}

TEST(ExportAemCommand, BadEphemerisKeysAndMissingTrajectoryAreInvalidInput) {
  const fs::path dir = test::fresh_dir("aem_bad");
  std::ofstream(dir / "bad.toml")
      << test::read_file(fs::path(ATTIGUARD_SOURCE_DIR) / "examples/pet_erg_paper.toml")
      << "\n[ephemeris]\nepoch = \"2026-02-30T00:00:00\"\n";
  const auto r = test::run_cli("check '" + (dir / "bad.toml").string() + "'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("ephemeris.epoch"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("bad.toml:"), std::string::npos) << r.err;
  EXPECT_EQ(test::count_lines(r.err), 1);

  const auto m = test::run_cli("export-aem '" + dir.string() + "'");
  EXPECT_EQ(m.exit_code, 2);
  EXPECT_NE(m.err.find("trajectory.csv: not found"), std::string::npos) << m.err;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace attiguard
#endif
