#pragma once
/// @file shortest_number.hpp
/// A value a user gave, echoed in a message (docs/errors.md): the shortest decimal text that
/// reads back as the same double. Derived figures use four_digits.hpp instead.

#include <array>
#include <charconv>
#include <cmath>
#include <string>
#include <system_error>

namespace attiguard {

/// Shortest decimal text that reads back as `x` ("-1", "0.05", "1e-09"), and "nan", "inf",
/// "-inf" for the non-finite values (docs/errors.md, numbers in messages).
[[nodiscard]] inline std::string shortest_number(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  std::array<char, 64> buf{};
  const auto [end, ec] = std::to_chars(buf.data(), buf.data() + buf.size(), x);
  if (ec != std::errc{}) return "?";
  return std::string(buf.data(), end);
}

}  // namespace attiguard
