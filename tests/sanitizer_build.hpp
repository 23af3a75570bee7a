#pragma once
/// @file sanitizer_build.hpp
/// ATTIGUARD_TEST_ASAN is defined when the tests are built with AddressSanitizer (GCC's
/// __SANITIZE_ADDRESS__ or clang's __has_feature): tests that limit the address space skip
/// themselves there, since ASan reserves terabytes of shadow memory (.ci/run).
///
/// The long tests scale their work with `for_this_build`: the sanitized build runs the numerics
/// 15–20× slower than Release (the soundness sampling of a reach 18×, docs/performance.md,
/// "Build: the CI's sanitizer build"), so there they repeat the same code paths fewer times, in
/// about the Release run's time, while the Release suite keeps the full sizes.

#if defined(__SANITIZE_ADDRESS__)
#define ATTIGUARD_TEST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define ATTIGUARD_TEST_ASAN 1
#endif
#endif

namespace attiguard::test {

/// How many times fewer repetitions a long test does in the sanitized build (1 in Release).
#ifdef ATTIGUARD_TEST_ASAN
inline constexpr long kSanitizedWorkDivisor = 16;
#else
inline constexpr long kSanitizedWorkDivisor = 1;
#endif

/// The work size `n` (samples, draws, runs) of a long test in this build: n in Release,
/// n / kSanitizedWorkDivisor in the sanitized build, never below `at_least` nor above n.
constexpr long for_this_build(long n, long at_least = 1) {
  const long scaled = n / kSanitizedWorkDivisor;
  if (scaled >= at_least) return scaled;
  return at_least < n ? at_least : n;
}

}  // namespace attiguard::test
