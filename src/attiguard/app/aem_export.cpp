#include "attiguard/app/aem_export.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <system_error>

#include "attiguard/core/errors.hpp"
#include "attiguard/io/aem_writer.hpp"

namespace attiguard::app {

namespace {

/// The largest |‖q‖ − 1| of a trajectory.csv quaternion the AEM export takes (docs/interop.md):
/// a run writes unit quaternions to 17 digits; anything farther is not an attitude.
constexpr double kUnitQuaternionTolerance = 1e-6;

/// x with 9 significant digits, for an error message.
std::string shown(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", x);
  return text;
}

/// InputError naming the file, the row and its time when the quaternion of `s` is not a unit
/// quaternion (docs/interop.md): an AEM of it would claim an attitude it does not hold.
void check_unit_quaternion(const io::AttitudeSample& s, const std::filesystem::path& source,
                           std::size_t row) {
  const double norm = std::sqrt(s.q_ib[0] * s.q_ib[0] + s.q_ib[1] * s.q_ib[1] +
                                s.q_ib[2] * s.q_ib[2] + s.q_ib[3] * s.q_ib[3]);
  if (std::abs(norm - 1.0) <= kUnitQuaternionTolerance) return;
  throw InputError(source.string() + ": data row " + std::to_string(row + 1) + " (t = " +
                   shown(s.t) + " s): the quaternion q_w, q_x, q_y, q_z has norm " +
                   shown(norm) + ", not 1 (within 1e-06): not an attitude of a run");
}

}  // namespace

std::vector<io::AttitudeSample> attitude_samples(const io::CsvTable& table,
                                                 const std::filesystem::path& source,
                                                 bool with_rates) {
  auto need = [&](const char* name) {
    const auto i = table.column(name);
    if (!i) {
      throw InputError(source.string() + ": no column '" + name +
                       "' (the AEM export needs t, q_w, q_x, q_y, q_z" +
                       (with_rates ? ", omega_x, omega_y, omega_z)" : ")"));
    }
    return *i;
  };
  const std::size_t t = need("t");
  const std::array<std::size_t, 4> q{need("q_w"), need("q_x"), need("q_y"), need("q_z")};
  std::array<std::size_t, 3> w{};
  if (with_rates) w = {need("omega_x"), need("omega_y"), need("omega_z")};
  std::vector<io::AttitudeSample> samples;
  samples.reserve(table.rows.size());
  for (const auto& row : table.rows) {
    io::AttitudeSample s;
    s.t = row[t];
    for (std::size_t k = 0; k < 4; ++k) s.q_ib[k] = row[q[k]];
    check_unit_quaternion(s, source, samples.size());
    if (with_rates) {
      for (std::size_t k = 0; k < 3; ++k) s.omega_b[k] = row[w[k]];
    }
    samples.push_back(s);
  }
  return samples;
}

std::filesystem::path export_aem(const std::filesystem::path& dir, const io::AemMetadata& meta,
                                 std::filesystem::path out) {
  const auto csv = dir / "trajectory.csv";
  std::error_code ec;
  if (!std::filesystem::is_regular_file(csv, ec)) {
    throw InputError(csv.string() + ": not found (export-aem reads the trajectory of `attiguard "
                                    "run SCENARIO --out DIR` or `campaign --replay K`)");
  }
  const io::CsvTable table = io::read_csv(csv);
  const auto samples = attitude_samples(table, csv, meta.with_rates);
  if (out.empty()) out = dir / "attitude.aem";
  io::write_aem(out, meta, samples);
  return out;
}

}  // namespace attiguard::app
