#pragma once
/// @file sanitizer_build.hpp
/// ATTIGUARD_TEST_ASAN is defined when the tests are built with AddressSanitizer (GCC's
/// __SANITIZE_ADDRESS__ or clang's __has_feature): tests that limit the address space skip
/// themselves there, since ASan reserves terabytes of shadow memory (.ci/run).

#if defined(__SANITIZE_ADDRESS__)
#define ATTIGUARD_TEST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define ATTIGUARD_TEST_ASAN 1
#endif
#endif
