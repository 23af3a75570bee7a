// app/failure: the exit code and message of an exception that reaches the top of a program.

#include <gtest/gtest.h>

#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include "attiguard/app/failure.hpp"
#include "attiguard/core/errors.hpp"
#include "attiguard/governor/attitude_governor.hpp"
#include "attiguard/parallel/worker_pool.hpp"

namespace attiguard::app {
namespace {

template <class E>
Failure failure_of(const E& e, const std::string& scenario = "s.toml") {
  return describe_failure(std::make_exception_ptr(e), scenario);
}

TEST(Failure, ErrorFamilyKeepsItsCodeAndMessage) {
  EXPECT_EQ(failure_of(InputError("f:1:2: k: bad")).code, ExitCode::invalid_input);
  EXPECT_EQ(failure_of(InputError("f:1:2: k: bad")).message, "f:1:2: k: bad");
  EXPECT_EQ(failure_of(NumericalError("nan")).code, ExitCode::numerical_failure);
  EXPECT_EQ(failure_of(VerificationFailure("unsafe")).code, ExitCode::verification_failed);
}

TEST(Failure, SetupErrorOfALibraryConstructorIsAnInputError) {
  governor::GovernorParams p;
  p.J = lie::Mat3::Identity();
  p.tau_max = -1.0;  // impossible torque limit
  try {
    (void)governor::AttitudeGovernor(p, {});
    FAIL() << "tau_max < 0 was accepted";
  } catch (...) {
    const Failure f = describe_failure(std::current_exception(), "");
    EXPECT_EQ(f.code, ExitCode::invalid_input);
    EXPECT_EQ(f.message.find("internal error"), std::string::npos) << f.message;
  }
}

TEST(Failure, OutOfMemorySaysWhatWasTooLargeAndIsInputError) {
  const Failure f = failure_of(std::bad_alloc());
  EXPECT_EQ(f.code, ExitCode::invalid_input);
  EXPECT_EQ(f.message.rfind("s.toml: out of memory", 0), 0U) << f.message;
  EXPECT_NE(f.message.find("partition cells"), std::string::npos) << f.message;
  EXPECT_EQ(f.message.find('\n'), std::string::npos);
}

TEST(Failure, LengthErrorFromAHugeContainerIsInputError) {
  std::exception_ptr caught;
  try {
    std::vector<double> v;
    v.reserve(v.max_size() + 1);  // throws std::length_error
  } catch (...) {
    caught = std::current_exception();
  }
  ASSERT_TRUE(caught);
  const Failure f = describe_failure(caught, "big.toml");
  EXPECT_EQ(f.code, ExitCode::invalid_input);
  EXPECT_EQ(f.message.rfind("big.toml: a size is too large", 0), 0U) << f.message;
}

TEST(Failure, AThreadTheSystemRefusedIsInputErrorNamingTheSetting) {
  const parallel::ThreadStartError e(2, 8, "Resource temporarily unavailable");
  const Failure f = failure_of(e);
  EXPECT_EQ(f.code, ExitCode::invalid_input);
  EXPECT_EQ(f.message.rfind("s.toml: --threads: cannot start worker thread 3 of 8 (Resource temporarily "
                            "unavailable): the system limits the threads",
                            0),
            0U)
      << f.message;
  EXPECT_NE(f.message.find("use --threads 2 or fewer (the flag takes at most "), std::string::npos) << f.message;
  EXPECT_EQ(thread_start_advice(parallel::ThreadStartError(0, 4, "x"), "threads = ").substr(0, 33),
            "cannot start worker thread 1 of 4");
  EXPECT_NE(thread_start_advice(parallel::ThreadStartError(0, 4, "x"), "threads = ").find("use threads = 1 or fewer"),
            std::string::npos);
}

TEST(Failure, AnythingElseIsAnInternalError) {
  const Failure f = failure_of(std::logic_error("oops"));
  EXPECT_EQ(f.code, ExitCode::numerical_failure);
  EXPECT_EQ(f.message, "internal error: oops");
}

}  // namespace
}  // namespace attiguard::app
