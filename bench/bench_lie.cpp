// Benchmarks of the SO(3) core: exp and log (lie/so3.hpp).
#include <benchmark/benchmark.h>

#include <array>

#include "attiguard/lie/so3.hpp"

namespace {

using attiguard::lie::Mat3;
using attiguard::lie::Vec3;

std::array<Vec3, 64> sample_vectors() {
  std::array<Vec3, 64> w;
  for (std::size_t i = 0; i < w.size(); ++i) {
    const double s = 0.05 * static_cast<double>(i);
    w[i] = Vec3(std::sin(1.3 * s + 0.1), std::cos(0.7 * s), std::sin(2.1 * s)) * (0.1 + s);
  }
  return w;
}

void BM_So3Exp(benchmark::State& state) {
  const auto w = sample_vectors();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(attiguard::lie::exp(w[i++ & 63]));
  }
}
BENCHMARK(BM_So3Exp);

void BM_So3Log(benchmark::State& state) {
  const auto w = sample_vectors();
  std::array<Mat3, 64> R;
  for (std::size_t i = 0; i < R.size(); ++i) {
    R[i] = attiguard::lie::exp(w[i]);
  }
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(attiguard::lie::log(R[i++ & 63]));
  }
}
BENCHMARK(BM_So3Log);

}  // namespace
