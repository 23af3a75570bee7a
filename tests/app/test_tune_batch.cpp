// app/tune_batch: a batch of tune candidates over ranks and threads, and its exact exchange
// encoding (docs/pet-erg.md, section 15). The split over two MPI ranks is the ctest
// TuneMpi.OneRankAndTwoRanksGiveTheSameSearch (tests/cli/tune_mpi_equal.cmake).

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <unistd.h>

#include "attiguard/app/tune_batch.hpp"
#include "attiguard/core/errors.hpp"
#include "attiguard/scenario/document.hpp"

namespace attiguard::app {
namespace {

std::filesystem::path batch_scratch(const std::string& name) {
  return std::filesystem::temp_directory_path() /
         ("attiguard_tune_batch_" + name + "_" + std::to_string(::getpid()));
}

scenario::Document paper() {
  return scenario::load_document(std::string(ATTIGUARD_SOURCE_DIR) + "/examples/pet_erg_paper.toml");
}

TEST(TuneBatch, ShareRoundTripsEveryDoubleBitForBit) {
  TuneBatchShare s;
  TunePoint a;
  a.values = {0.1, 1.0 / 3.0, std::nextafter(2.0, 3.0), 5e-324, 1.7976931348623157e308};
  a.status = "ok";
  a.outcome = "converged";
  a.reason = "why \"quoted\"";
  a.violations = 2;
  a.convergence_time = 30.549999999999997;
  a.ratio = std::nextafter(1.0, 0.0);
  TunePoint b;  // rejected: no outcome, no times
  b.values = {4.0};
  b.status = "rejected";
  b.reason = "t.toml:1:1: control.kp: too large";
  s.positions = {3, 0};
  s.failures = {"", "3 numerical trouble"};
  s.points = {a, b};
  const TuneBatchShare back = decode_tune_share(encode_tune_share(s));
  ASSERT_EQ(back.positions, s.positions);
  EXPECT_EQ(back.failures, s.failures);
  ASSERT_EQ(back.points.size(), 2u);
  ASSERT_EQ(back.points[0].values.size(), a.values.size());
  for (std::size_t i = 0; i < a.values.size(); ++i) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(back.points[0].values[i]), std::bit_cast<std::uint64_t>(a.values[i]));
  }
  EXPECT_EQ(back.points[0].status, "ok");
  EXPECT_EQ(back.points[0].outcome, "converged");
  EXPECT_EQ(back.points[0].reason, a.reason);
  EXPECT_EQ(back.points[0].violations, 2);
  EXPECT_EQ(std::bit_cast<std::uint64_t>(*back.points[0].convergence_time),
            std::bit_cast<std::uint64_t>(*a.convergence_time));
  EXPECT_EQ(std::bit_cast<std::uint64_t>(*back.points[0].ratio), std::bit_cast<std::uint64_t>(*a.ratio));
  EXPECT_FALSE(back.points[0].bang_bang_time.has_value());
  EXPECT_EQ(back.points[1].status, "rejected");
  EXPECT_FALSE(back.points[1].convergence_time.has_value());
  EXPECT_THROW((void)decode_tune_share("not cbor"), NumericalError);
}

// Every candidate's point, in candidate order, equal to evaluating it alone, whatever the threads.
TEST(TuneBatch, PointsComeBackInCandidateOrderWhateverTheThreads) {
  const scenario::Document doc = paper();
  const std::vector<TuneParameter> p{{"control.kp", 1.0, 10.0}, {"erg.kappa", 0.5, 5.0}};
  const std::vector<std::vector<double>> c{{5.0, 1.0}, {2.0, 0.5}, {1e300, 1.0}, {8.0, 3.0}, {3.0, 2.0}};
  const auto one = evaluate_tune_batch(doc, p, c, 1, batch_scratch("one"), {});
  const auto three = evaluate_tune_batch(doc, p, c, 3, batch_scratch("three"), {});
  ASSERT_EQ(one.size(), c.size());
  ASSERT_EQ(three.size(), c.size());
  for (std::size_t i = 0; i < c.size(); ++i) {
    const TunePoint alone = evaluate_candidate(doc, p, c[i], batch_scratch("alone"));
    for (const auto* q : {&one[i], &three[i]}) {
      EXPECT_EQ(q->values, c[i]);
      EXPECT_EQ(q->status, alone.status);
      EXPECT_EQ(q->outcome, alone.outcome);
      EXPECT_EQ(q->convergence_time, alone.convergence_time);
    }
  }
  EXPECT_EQ(one[0].outcome, "converged");  // the paper's gains
  EXPECT_EQ(one[2].status, "rejected");    // k_p = 1e300: Gamma_d underflows
}

// A candidate whose evaluation throws (here: a scenario of no known kind) is not raised at once
// (under MPI the other ranks would wait in the exchange): after it, as its own error family.
TEST(TuneBatch, AnEvaluationThatThrowsIsRaisedAfterTheBatch) {
  const scenario::Document bad = scenario::parse_document("kind = \"no_such_kind\"\n", "bad.toml");
  try {
    (void)evaluate_tune_batch(bad, {}, {{}, {}}, 2, batch_scratch("bad"), {});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no_such_kind"), std::string::npos) << e.what();
  }
}

// The set-up step of the command: its error family and message come through (one rank here; two
// ranks, with a failure on rank 0 alone: tests/cli/tune_mpi_equal.cmake).
TEST(TuneBatch, RunOnEveryRankRaisesTheStepsError) {
  int calls = 0;
  run_on_every_rank([&] { ++calls; }, {});
  EXPECT_EQ(calls, 1);
  EXPECT_THROW(run_on_every_rank([] { throw VerificationFailure("x"); }, {}), VerificationFailure);
  try {
    run_on_every_rank([] { throw InputError("dir: cannot create output directory"); }, {});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "dir: cannot create output directory");
  }
}

}  // namespace
}  // namespace attiguard::app
