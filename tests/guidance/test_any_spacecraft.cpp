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
#include "craft_classes.hpp"
#include "sanitizer_build.hpp"

namespace attiguard::test::any_spacecraft {
namespace {

int env_int(const char* name, int fallback) {
  const char* v = std::getenv(name);
  return v != nullptr ? std::max(1, std::atoi(v)) : fallback;
}

/// The q-quantile of x (the element at floor(q n)), 0 when empty.
double quantile(std::vector<double> x, double q) {
  if (x.empty()) return 0.0;
  std::sort(x.begin(), x.end());
  return x[std::min(x.size() - 1, static_cast<std::size_t>(q * static_cast<double>(x.size())))];
}

double median(std::vector<double> x) {
  if (x.empty()) return 0.0;
  std::sort(x.begin(), x.end());
  const std::size_t n = x.size();
  return n % 2 == 1 ? x[n / 2] : 0.5 * (x[n / 2 - 1] + x[n / 2]);
}

/// ATTIGUARD_CRAFT_CLASS_DUMP=FILE appends one line per case (class, index, verdict, mission
/// time, RCT-only legs' time and count, actual/predicted), to pair runs with and without the RCT
/// transfer (ATTIGUARD_RCT_TRANSFER=0) craft by craft (docs/waypoint.md, "The RCT-only legs").
void dump_verdicts(const char* cls, const std::vector<Verdict>& verdicts) {
  const char* path = std::getenv("ATTIGUARD_CRAFT_CLASS_DUMP");
  if (path == nullptr) return;
  std::FILE* f = std::fopen(path, "a");
  if (f == nullptr) return;
  for (std::size_t k = 0; k < verdicts.size(); ++k) {
    const Verdict& v = verdicts[k];
    std::fprintf(f, "%s %zu %d %.3f %.3f %d %.4f %.4f %.4f\n", cls, k, static_cast<int>(v.kind), v.total_time,
                 v.rct_leg_time, v.rct_legs, v.predicted_ratio, v.fine_fraction, v.transfer_fraction);
  }
  std::fclose(f);
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
  dump_verdicts("generator", verdicts);

  int rejected = 0, completed = 0, incomplete = 0, failed = 0;
  std::vector<double> dv_ratio, t_ratio, p_ratio;
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
        if (v.predicted_ratio > 0.0) p_ratio.push_back(v.predicted_ratio);
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
  std::printf("[ measured ] completed runs: time / predicted (docs/waypoint.md, \"Prediction\") "
              "median %.3f, p5 %.3f, p95 %.3f\n",
              median(p_ratio), quantile(p_ratio, 0.05), quantile(p_ratio, 0.95));
  for (const auto& [why, count] : rejections) std::printf("[ rejected ] %5d  %s\n", count, why.c_str());
  EXPECT_GT(accepted, runs / 4);  // the generator is not all infeasible crafts
  EXPECT_EQ(failed, 0);
  EXPECT_EQ(incomplete, 0);
}

/// Issue 25: the three craft classes (craft_classes.hpp), each craft given 1.5 × the tool's own
/// predicted mission time. Every run ends completed or refused up front with its reason, or (the
/// rest, reported) incomplete with its reason; none in NaN or divergence. The figures of the
/// acceptance are printed per class (docs/waypoint.md, "Craft classes").
TEST(AnySpacecraft, CraftClassesCompleteWithinOneAndAHalfTimesThePrediction) {
  const int runs = env_int("ATTIGUARD_CRAFT_CLASS_RUNS", static_cast<int>(for_this_build(60, 6)));
  const int threads = env_int("ATTIGUARD_ANY_SPACECRAFT_THREADS", 1);
  const unsigned long long seed = 25;
  for (int ci = 0; ci < kCraftClassCount; ++ci) {
    const auto cls = static_cast<CraftClass>(ci);
    std::vector<Verdict> verdicts(static_cast<std::size_t>(runs));
    std::vector<std::thread> pool;
    for (int w = 0; w < threads; ++w) {
      pool.emplace_back([&, w] {
        for (int k = w; k < runs; k += threads) {
          verdicts[static_cast<std::size_t>(k)] = judge(make_class_case(cls, seed, k));
        }
      });
    }
    for (std::thread& t : pool) t.join();
    int rejected = 0, completed = 0, incomplete = 0, failed = 0;
    std::vector<double> p_ratio, user_ratio, fine, handover_fine, transfer, mission_time, rct_leg_time;
    std::map<std::string, int> reasons;
    int rct_legs = 0;
    std::map<std::string, double> fine_by_entry;
    double completed_time = 0.0;
    for (int k = 0; k < runs; ++k) {
      const Verdict& v = verdicts[static_cast<std::size_t>(k)];
      if (v.kind == Verdict::rejected) {
        ++rejected;
        EXPECT_FALSE(v.reason.empty()) << class_name(cls) << " " << k;
        ++reasons["refused: " + v.reason.substr(v.reason.find(": ") + 2, 150)];
      } else if (v.kind == Verdict::completed) {
        ++completed;
        p_ratio.push_back(v.predicted_ratio);
        user_ratio.push_back(v.time_ratio);
        fine.push_back(v.fine_fraction);
        handover_fine.push_back(v.fine_fraction - v.rct_leg_fraction);
        transfer.push_back(v.transfer_fraction);
        mission_time.push_back(v.total_time);
        if (v.rct_legs > 0) rct_leg_time.push_back(v.rct_leg_time / v.rct_legs);
        rct_legs += v.rct_legs;
        completed_time += v.total_time;
        for (const auto& [entry, t] : v.fine_time_by_entry) fine_by_entry[entry] += t;
      } else if (v.kind == Verdict::incomplete) {
        ++incomplete;
        EXPECT_FALSE(v.reason.empty()) << class_name(cls) << " " << k;
        ++reasons["incomplete: " + v.reason.substr(v.reason.find(':') + 1, 60)];
      } else {
        ++failed;
        ADD_FAILURE() << class_name(cls) << " case " << k << " failed: " << v.reason;
      }
    }
    const int accepted = runs - rejected;
    std::printf("[ measured ] %-14s %d crafts (seed %llu): %d refused, %d completed (%.1f %% of accepted), "
                "%d incomplete, %d NaN/divergence; time/predicted median %.3f p95 %.3f; time/user's "
                "estimate median %.3f; fine-control share median %.3f (%.3f without the RCT-only legs)\n",
                class_name(cls), runs, seed, rejected, completed,
                accepted > 0 ? 100.0 * completed / accepted : 0.0, incomplete, failed, median(p_ratio),
                quantile(p_ratio, 0.95), median(user_ratio), median(fine), median(handover_fine));
    std::printf("[ measured ] %-14s rct_transfer share median %.3f; mission time median %.1f s; %d RCT-only "
                "legs, mean leg time per mission median %.1f s\n",
                class_name(cls), median(transfer), median(mission_time), rct_legs, median(rct_leg_time));
    dump_verdicts(class_name(cls), verdicts);
    for (const auto& [why, count] : reasons) std::printf("[  reason  ] %5d  %s\n", count, why.c_str());
    // Where the fine phase's time goes: its share of all completed missions' time by how fine
    // control was entered (docs/waypoint.md, "Craft classes").
    for (const auto& [entry, t] : fine_by_entry) {
      std::printf("[  fine    ] %-45s %5.1f %% of the completed missions' time\n", entry.c_str(),
                  completed_time > 0.0 ? 100.0 * t / completed_time : 0.0);
    }
    EXPECT_EQ(failed, 0) << class_name(cls);
    EXPECT_GE(completed, accepted * 49 / 50) << class_name(cls);  // see docs/waypoint.md for the measured rate
    EXPECT_LE(rejected, runs / 4) << class_name(cls);
  }
}

/// Issue 42: the large chemical craft spend much of their missions in legs the RCT fly alone
/// (legs within half the derived re-plan distance, docs/waypoint.md, "Craft classes"). That is
/// the faster choice: the same crafts with those legs given to the main engine (the re-plan
/// distance cut to max(30 δ_p, 20 δ)) take longer, or do not finish within 6× the prediction,
/// because each main-engine leg costs two slow turns of a heavy craft on small wheels.
TEST(AnySpacecraft, LargeChemicalCraftsFlyTheirShortLegsFasterWithTheRctAlone) {
  const int runs = env_int("ATTIGUARD_RCT_LEG_RUNS", static_cast<int>(for_this_build(40, 4)));
  int compared = 0, rct_faster = 0;
  for (int k = 0; k < runs; ++k) {
    const Case c = make_class_case(CraftClass::large_chemical, 25, k, 6.0);
    sim::WaypointScenario sc = scenario::parse_waypoint(scenario::parse_document(c.toml, "large_chemical.toml"));
    const sim::WaypointSimResult with_rct_legs = sim::simulate_waypoint(sc);
    ASSERT_TRUE(with_rct_legs.finite) << k;
    const bool rct_leg = mode_times(with_rct_legs).rct_legs > 0;
    if (!with_rct_legs.completed || !rct_leg) continue;
    sc.mission.replan_distance = std::max(30.0 * sc.mission.position_accuracy, 20.0 * sc.mission.arrival_radius);
    const sim::WaypointSimResult main_engine = sim::simulate_waypoint(sc);
    ASSERT_TRUE(main_engine.finite) << k;
    ++compared;
    if (!main_engine.completed || main_engine.total_time > with_rct_legs.total_time) ++rct_faster;
  }
  std::printf("[ measured ] large_chemical, %d crafts with RCT-only legs: faster with them in %d\n", compared,
              rct_faster);
  EXPECT_GT(compared, runs / 2);
  EXPECT_GE(rct_faster, compared * 9 / 10);
}

}  // namespace
}  // namespace attiguard::test::any_spacecraft
