#pragma once
/// @file shortest_number.hpp
/// The shortest decimal text that reads back as the same double: a value a user gave, echoed in
/// a message (docs/errors.md; derived figures use four_digits.hpp instead), and the numbers of
/// the CSV outputs (io/csv_writer.hpp).

#include <array>
#include <charconv>
#include <cmath>
#include <string>
#include <system_error>

namespace attiguard {

/// Appends the shortest decimal text that reads back as `x` (std::to_chars: "-1", "0.05",
/// "1e-09", "inf", "-inf", "nan" or "-nan"): the number form of the CSV outputs
/// (docs/conventions.md, "Outputs") and of shortest_number.
inline void append_shortest(std::string& out, double x) {
  std::array<char, 32> buf{};  // the longest double, "-2.2250738585072014e-308", is 24 chars
  const auto [end, ec] = std::to_chars(buf.data(), buf.data() + buf.size(), x);
  out.append(buf.data(), ec == std::errc{} ? end : buf.data());
}

/// Shortest decimal text that reads back as `x` ("-1", "0.05", "1e-09"), and "nan", "inf",
/// "-inf" for the non-finite values (docs/errors.md, numbers in messages).
[[nodiscard]] inline std::string shortest_number(double x) {
  if (std::isnan(x)) return "nan";
  std::string s;
  append_shortest(s, x);
  return s;
}

}  // namespace attiguard
