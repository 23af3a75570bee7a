// A dozen loops of issue 46's corpus (tests/data/reach/corpus, scripts/reach_corpus.py; the
// table of all 40 in docs/reach.md, "Coverage"): with default settings except a smaller work
// budget, each ends with a verdict (exit 0 safe or exit 4 cannot_prove, never exit 3), every
// sampled and adversarial trajectory stays inside its balls and tube, and a loop whose own
// nominal violates its constraint is never `safe`.

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_runner.hpp"
#include "sanitizer_build.hpp"

#ifdef ATTIGUARD_CLI_PATH

struct CorpusLoop {
  const char* file;
  bool nominal_violates;  ///< the generator placed its constraint across the nominal
};

namespace {

/// The loop's file with samples and the splitting budget scaled to this build.
std::filesystem::path corpus_for_this_build(const std::string& file) {
  std::string text = attiguard::test::read_file(std::filesystem::path(ATTIGUARD_SOURCE_DIR) /
                                                "tests/data/reach/corpus" / file);
  const std::string key = "\nsamples = ";
  const std::size_t at = text.find(key, text.find("[soundness]"));
  if (at != std::string::npos) {
    const std::size_t end = text.find_first_not_of("0123456789", at + key.size());
    text.replace(at + key.size(), end - at - key.size(), std::to_string(attiguard::test::for_this_build(100, 20)));
  }
  text += "\n[partition]\nmax_cell_steps = " + std::to_string(attiguard::test::for_this_build(600, 80)) +
          "\nmax_seconds = " + std::to_string(attiguard::test::for_this_build(20, 2)) + "\n";
  const std::filesystem::path copy = attiguard::test::fresh_dir(std::string("corpus_") + file) / file;
  std::ofstream(copy) << text;
  return copy;
}

}  // namespace

class ReachCorpus : public testing::TestWithParam<CorpusLoop> {};

TEST_P(ReachCorpus, EndsWithAVerdictAndNoEscape) {
  const CorpusLoop loop = GetParam();
  const auto scenario = corpus_for_this_build(loop.file);
  const auto out = scenario.parent_path() / "out";
  const auto r = attiguard::test::run_cli("reach '" + scenario.string() + "' --out '" + out.string() + "'");
  ASSERT_TRUE(r.exit_code == 0 || r.exit_code == 4) << r.exit_code << ": " << r.err;
  const auto j = nlohmann::json::parse(attiguard::test::read_file(out / "reach.json"));
  const std::string verdict = j["verdict"].get<std::string>();
  EXPECT_EQ(verdict, r.exit_code == 0 ? "safe" : "cannot_prove");
  EXPECT_EQ(j["soundness"]["inside"].get<long>(), j["soundness"]["samples"].get<long>());
  EXPECT_EQ(j["soundness"]["tube_inside"].get<long>(), j["soundness"]["samples"].get<long>());
  EXPECT_LE(j["adversarial"]["worst_ratio"].get<double>(), 1.0 + 1e-12);
  if (loop.nominal_violates) {
    EXPECT_EQ(verdict, "cannot_prove");
  }
  if (verdict == "cannot_prove") {
    EXPECT_FALSE(j["safety_reason"].get<std::string>().empty());
    EXPECT_GE(j["first_failure_time"].get<double>(), 0.0);
  }
  std::filesystem::remove_all(scenario.parent_path());
}

// Spread over the models, scales, offsets and outcomes of the corpus (docs/reach.md, "Coverage").
INSTANTIATE_TEST_SUITE_P(
    Dozen, ReachCorpus,
    testing::Values(CorpusLoop{"loop_02_pd.toml", false}, CorpusLoop{"loop_04_pd.toml", false},
                    CorpusLoop{"loop_07_pd.toml", true}, CorpusLoop{"loop_12_pd.toml", false},
                    CorpusLoop{"loop_19_pd.toml", false}, CorpusLoop{"loop_28_pd.toml", true},
                    CorpusLoop{"loop_29_free.toml", false}, CorpusLoop{"loop_31_free.toml", false},
                    CorpusLoop{"loop_34_free.toml", false}, CorpusLoop{"loop_35_linear_omega.toml", false},
                    CorpusLoop{"loop_37_linear_omega.toml", false}, CorpusLoop{"loop_40_linear_omega.toml", false}),
    [](const testing::TestParamInfo<CorpusLoop>& info) {
      std::string name = info.param.file;
      return name.substr(0, name.find('.'));
    });

#endif
