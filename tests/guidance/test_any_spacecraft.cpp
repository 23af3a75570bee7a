// Issue 13, item 5: the waypoint guidance on any spacecraft (tests/guidance/any_spacecraft.hpp).
// Every random craft is either rejected up front by the feasibility check, with its reason, or
// completes within its accuracy: no NaN, no divergence, no time-out. A few hundred crafts here;
// scripts/waypoint_any_spacecraft.sh runs 10^4 (ATTIGUARD_ANY_SPACECRAFT_RUNS) on two threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <mutex>
#include <thread>
#include <vector>

#include "any_spacecraft.hpp"
#include "sanitizer_build.hpp"

namespace attiguard::test::any_spacecraft {
namespace {

int env_int(const char* name, int fallback) {
  const char* v = std::getenv(name);
  return v != nullptr ? std::max(1, std::atoi(v)) : fallback;
}

double median(std::vector<double> x) {
  if (x.empty()) return 0.0;
  std::sort(x.begin(), x.end());
  const std::size_t n = x.size();
  return n % 2 == 1 ? x[n / 2] : 0.5 * (x[n / 2 - 1] + x[n / 2]);
}

/// The first words of a rejection reason (its key path and cause), for the tally.
std::string reason_class(const std::string& what) {
  const auto key = what.find(": ");
  std::string s = key == std::string::npos ? what : what.substr(key + 2);
  const auto cut = s.find_first_of("0123456789(");
  return s.substr(0, std::min<std::size_t>(cut, 70));
}

TEST(AnySpacecraft, EveryRandomCraftIsRejectedWithAReasonOrCompletes) {
  const int runs = env_int("ATTIGUARD_ANY_SPACECRAFT_RUNS", static_cast<int>(for_this_build(300, 75)));
  const int threads = env_int("ATTIGUARD_ANY_SPACECRAFT_THREADS", 1);
  const unsigned long long seed = 13;
  std::vector<Verdict> verdicts(static_cast<std::size_t>(runs));
  std::vector<std::thread> pool;
  for (int w = 0; w < threads; ++w) {
    pool.emplace_back([&, w] {
      for (int k = w; k < runs; k += threads) verdicts[static_cast<std::size_t>(k)] = judge(make_case(seed, k));
    });
  }
  for (std::thread& t : pool) t.join();

  int rejected = 0, completed = 0, incomplete = 0, failed = 0;
  std::vector<double> dv_ratio, t_ratio;
  std::map<std::string, int> rejections;
  for (int k = 0; k < runs; ++k) {
    const Verdict& v = verdicts[static_cast<std::size_t>(k)];
    switch (v.kind) {
      case Verdict::rejected:
        ++rejected;
        EXPECT_FALSE(v.reason.empty()) << "case " << k;
        ++rejections[reason_class(v.reason)];
        break;
      case Verdict::completed:
        ++completed;
        if (v.delta_v_ratio > 0.0) dv_ratio.push_back(v.delta_v_ratio);
        if (v.time_ratio > 0.0) t_ratio.push_back(v.time_ratio);
        break;
      case Verdict::incomplete:
        ++incomplete;
        ADD_FAILURE() << "case " << k << " incomplete: " << v.reason;
        break;
      case Verdict::failed:
        ++failed;
        ADD_FAILURE() << "case " << k << " failed: " << v.reason;
        break;
    }
  }
  const int accepted = runs - rejected;
  std::printf("[ measured ] %d random crafts (seed %llu): %d rejected up front, %d accepted: %d "
              "completed (%.2f %%), %d incomplete, %d NaN/divergence\n",
              runs, seed, rejected, accepted, completed,
              accepted > 0 ? 100.0 * completed / accepted : 0.0, incomplete, failed);
  std::printf("[ measured ] completed runs: median delta-v / ideal %.3f (p90 %.3f), median time / "
              "ideal %.3f\n",
              median(dv_ratio),
              dv_ratio.empty() ? 0.0 : [&] { auto x = dv_ratio; std::sort(x.begin(), x.end()); return x[x.size() * 9 / 10]; }(),
              median(t_ratio));
  for (const auto& [why, count] : rejections) std::printf("[ rejected ] %5d  %s\n", count, why.c_str());
  EXPECT_GT(accepted, runs / 4);  // the generator is not all infeasible crafts
  EXPECT_EQ(failed, 0);
  EXPECT_EQ(incomplete, 0);
}

}  // namespace
}  // namespace attiguard::test::any_spacecraft
