/// @file output_reader_fuzz.cpp
/// libFuzzer target for the readers of result files (docs/errors.md, "Strict readers"): the
/// trajectory.csv and summary.json readers of `attiguard view` and `export-aem` and the runs.csv
/// reader of `campaign --resume` and the campaign view. The first byte of the input picks the
/// file (its value mod 4), the rest is that file's text:
///   0  DIR/trajectory.csv of a run folder (valid summary.json): view_data and the AEM export
///   1  DIR/summary.json of a run folder (valid trajectory.csv): read_run_summary and view_data
///   2  DIR/runs.csv of a campaign folder (valid campaign.json): read_runs_table and view_data
///   3  DIR/runs.csv under --resume: read_runs with a fixed header
/// Any attiguard::Error is an expected refusal of bad input; anything else (another exception, a
/// crash, a sanitizer report, a NaN or infinity in the view's data) is a bug.
///   build-fuzz/fuzz/output_reader_fuzz -max_total_time=60 build-fuzz/corpus-output tests/data/output_readers

#include <unistd.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "attiguard/app/aem_export.hpp"
#include "attiguard/app/result_summary.hpp"
#include "attiguard/app/view_page.hpp"
#include "attiguard/campaign/runs_file.hpp"
#include "attiguard/core/errors.hpp"

namespace {

namespace fs = std::filesystem;

/// This process's scratch folder (one per fuzzing process).
const fs::path& scratch() {
  static const fs::path dir = [] {
    fs::path d = fs::temp_directory_path() / ("attiguard_output_fuzz_" + std::to_string(::getpid()));
    fs::create_directories(d);
    return d;
  }();
  return dir;
}

void put(const fs::path& path, std::string_view text) {
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(text.data(), static_cast<std::streamsize>(text.size()));
}

/// Aborts (a finding) when `j` holds a number that is not finite.
void require_finite(const nlohmann::json& j) {
  if (j.is_number_float() && !std::isfinite(j.get<double>())) std::abort();
  if (j.is_structured()) {
    for (const auto& v : j) require_finite(v);
  }
}

constexpr std::string_view kSummary = R"({"kind": "pet_erg", "name": "fuzz"})";
constexpr std::string_view kTrajectory = "t,q_w,q_x,q_y,q_z\n0,1,0,0,0\n0.5,1,0,0,0\n";
constexpr std::string_view kRunsHeader = "run,seed,attempts,status,reason,control.kp,outcome,violation,t_conv";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const int mode = data[0] % 4;
  const std::string_view text(reinterpret_cast<const char*>(data) + 1, size - 1);
  const fs::path dir = scratch() / "dir";
  std::error_code ec;
  fs::remove_all(dir, ec);
  fs::create_directories(dir);
  try {
    if (mode == 0 || mode == 1) {
      put(dir / "trajectory.csv", mode == 0 ? text : kTrajectory);
      put(dir / "summary.json", mode == 1 ? text : kSummary);
      if (mode == 1) (void)attiguard::app::read_run_summary(dir / "summary.json");
      require_finite(attiguard::app::view_data(dir));
      if (mode == 0) (void)attiguard::app::export_aem(dir, attiguard::io::AemMetadata{}, dir / "a.aem");
    } else if (mode == 2) {
      put(dir / "campaign.json", R"({"runs_requested": 3})");
      put(dir / "runs.csv", text);
      (void)attiguard::campaign::read_runs_table(dir / "runs.csv");
      require_finite(attiguard::app::view_data(dir));
    } else {
      put(dir / "runs.csv", text);
      (void)attiguard::campaign::read_runs(dir / "runs.csv", std::string(kRunsHeader));
    }
  } catch (const attiguard::Error&) {
    // a refusal with a message naming the file: expected
  }
  return 0;
}
