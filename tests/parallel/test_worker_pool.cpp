// parallel/worker_pool and parallel/thread_limit: worker threads that never end in
// std::terminate, and the bound of --threads (docs/errors.md, "No abort").

#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <fstream>
#include <stdexcept>
#include <string>

#include "attiguard/core/errors.hpp"
#include "attiguard/parallel/parallel_for.hpp"
#include "attiguard/parallel/thread_limit.hpp"
#include "attiguard/parallel/worker_pool.hpp"
#include "sanitizer_build.hpp"


namespace attiguard::parallel {
namespace {

TEST(WorkerPool, RunsEveryWorkerOnceAndRethrowsTheFirstExceptionAfterAllJoined) {
  std::atomic<long> mask{0};
  run_workers(5, [&](long w) { mask |= 1L << w; });
  EXPECT_EQ(mask.load(), 0b11111);
  std::atomic<int> finished{0};
  EXPECT_THROW(run_workers(4, [&](long w) {
                 if (w == 2) throw std::runtime_error("worker 2");
                 ++finished;
               }),
               std::runtime_error);
  EXPECT_EQ(finished.load(), 3);  // the others ran to their end before the rethrow
  EXPECT_THROW(parallel_for(100, 3, [](long i) {
                 if (i == 50) throw InputError("item 50");
               }),
               InputError);
}

/// In a child process whose address space leaves room for a few 8 MiB thread stacks only:
/// 0 when run_workers(64) throws ThreadStartError without running any body, else 1.
[[maybe_unused]] int child_with_few_threads() {  // unused under ASan
  long pages = 0;
  std::ifstream("/proc/self/statm") >> pages;
  const rlim_t now = static_cast<rlim_t>(pages) * static_cast<rlim_t>(::sysconf(_SC_PAGESIZE));
  const rlimit limit{now + (48u << 20), now + (48u << 20)};
  if (::setrlimit(RLIMIT_AS, &limit) != 0) return 2;
  std::atomic<int> ran{0};
  try {
    run_workers(64, [&](long) { ++ran; });
  } catch (const ThreadStartError& e) {
    return e.started() < 64 && e.wanted() == 64 && ran.load() == 0 ? 0 : 1;
  } catch (...) {
    return 1;
  }
  return 1;
}

TEST(WorkerPool, AThreadTheSystemRefusesIsAThreadStartErrorNotTerminate) {
#ifdef ATTIGUARD_TEST_ASAN
  GTEST_SKIP() << "ASan reserves its shadow memory: an address-space limit is not a thread limit";
#else
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) ::_exit(child_with_few_threads());
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status)) << "the child ended by signal " << WTERMSIG(status) << " (abort?)";
  EXPECT_EQ(WEXITSTATUS(status), 0);
#endif
}

TEST(ThreadLimit, IsFourPerHardwareThreadBetweenTheFloorAndTheCap) {
  EXPECT_GE(thread_limit(), kMinThreadLimit);
  EXPECT_LE(thread_limit(), kThreadCap);
  EXPECT_EQ(thread_limit(),
            std::clamp(kThreadsPerCore * hardware_threads(), kMinThreadLimit, kThreadCap));
  EXPECT_NO_THROW(check_thread_count(1));
  EXPECT_NO_THROW(check_thread_count(thread_limit()));
  try {
    check_thread_count(thread_limit() + 1);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind("--threads: " + std::to_string(thread_limit() + 1) + " is more than the limit " +
                          std::to_string(thread_limit()),
                      0),
              0u)
        << m;
    EXPECT_NE(m.find("use --threads " + std::to_string(thread_limit()) + " or fewer"), std::string::npos) << m;
  }
  EXPECT_THROW(check_thread_count(0), InputError);
  EXPECT_THROW(check_thread_count(-3), InputError);
}

}  // namespace
}  // namespace attiguard::parallel
