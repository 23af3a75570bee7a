/// @file scenario_run_fuzz.cpp
/// libFuzzer target over whole scenarios (docs/errors.md, "Fuzzing"): parse, the kind's check,
/// then a bounded run of every kind `attiguard run` runs (campaign files: the nominal), with the
/// rows into a sink that rejects any non-finite value. Work is bounded by the work limits
/// (scenario/work_limits.hpp, lowered here so that one input runs in well under a second); time
/// and memory by libFuzzer's -timeout and -rss_limit_mb. A finding is: a crash or sanitizer
/// report, a hang (timeout), memory beyond the limit, a NaN or infinity in an output row or in
/// the summary, an exit code other than 0, 2, 3 or 4 (app/failure.hpp), or an "internal error"
/// (an exception outside attiguard's error family, std::bad_alloc and std::length_error).
///   build-fuzz/fuzz/scenario_run_fuzz -timeout=5 -rss_limit_mb=500 -max_len=4096 CORPUS examples tests/data

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "attiguard/app/failure.hpp"
#include "attiguard/app/kinds.hpp"
#include "attiguard/core/errors.hpp"
#include "attiguard/io/row_sink.hpp"
#include "attiguard/scenario/dispersion.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/work_limits.hpp"

namespace {

[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "scenario_run_fuzz: %s\n", what.c_str());
  std::abort();
}

/// Rows that must all be finite.
class FiniteRowSink final : public attiguard::io::RowSink {
 public:
  void begin(const std::vector<std::string>& columns) override { columns_ = columns; }
  void row(std::span<const double> values) override {
    for (std::size_t i = 0; i < values.size(); ++i) {
      if (!std::isfinite(values[i])) {
        finding("non-finite value in output column " +
                (i < columns_.size() ? columns_[i] : std::to_string(i)));
      }
    }
  }

 private:
  std::vector<std::string> columns_;
};

/// Every number of the summary must be finite.
void require_finite(const nlohmann::json& j, const std::string& where) {
  if (j.is_number_float() && !std::isfinite(j.get<double>())) finding("non-finite summary " + where);
  if (j.is_object()) {
    for (const auto& [k, v] : j.items()) require_finite(v, where + "." + k);
  }
  if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i) require_finite(j[i], where + "[" + std::to_string(i) + "]");
  }
}

void run_input(std::string_view text) {
  const attiguard::scenario::Document file = attiguard::scenario::parse_document(text, "fuzz.toml");
  attiguard::scenario::Document doc = file;
  if (file.has_top_level("dispersions")) {
    (void)attiguard::scenario::read_dispersions(file);
    doc = attiguard::scenario::nominal_document(file);
  }
  const attiguard::app::KindHandler& handler = attiguard::app::handler_for(doc);
  handler.check(doc);
  if (handler.name == "reach") return;  // an SDP analysis, not a bounded run: checked only
  FiniteRowSink rows;
  attiguard::app::RunOptions options;
  options.write_files = false;
  options.rows = &rows;
  require_finite(handler.run(doc, options), "summary");
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  attiguard::scenario::WorkLimits limits;
  limits.run_steps = 2e4;     // ~0.1 s of integration at most
  limits.output_rows = 2e3;
  limits.campaign_runs = 1;
  limits.reach_cells = 1;
  attiguard::scenario::set_work_limits(limits);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    run_input(text);
  } catch (...) {
    const attiguard::app::Failure f = attiguard::app::describe_failure(std::current_exception(), "fuzz.toml");
    const int code = static_cast<int>(f.code);
    if (code != 2 && code != 3 && code != 4) finding("exit code " + std::to_string(code) + ": " + f.message);
    if (f.message.starts_with("internal error")) finding(f.message);
  }
  return 0;
}
