#pragma once
/// @file finite.hpp
/// The sign-and-finiteness tests of set-up arguments (docs/errors.md): NaN and ±inf fail both.

#include <cmath>

namespace attiguard {

/// x is finite and > 0.
[[nodiscard]] inline bool positive_finite(double x) noexcept { return std::isfinite(x) && x > 0.0; }

/// x is finite and ≥ 0.
[[nodiscard]] inline bool non_negative_finite(double x) noexcept {
  return std::isfinite(x) && x >= 0.0;
}

}  // namespace attiguard
