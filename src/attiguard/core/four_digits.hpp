#pragma once
/// @file four_digits.hpp
/// A derived figure in a message (docs/errors.md): 4 significant digits, "%.4g". Values a user
/// wrote are echoed with scenario::detail::format_number instead (shortest round trip).

#include <cstdio>
#include <string>

namespace attiguard {

/// x with 4 significant digits, for the numbers a message derives (docs/errors.md).
[[nodiscard]] inline std::string four_digits(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", x);
  return buf;
}

}  // namespace attiguard
