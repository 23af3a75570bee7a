#pragma once
/// @file messages.hpp
/// Internal text helpers of the scenario layer: number and string formatting for one-line error
/// messages, and "did you mean …?" suggestions. Not part of the public interface.

#include <toml++/toml.h>

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace attiguard::scenario::detail {

/// Shortest decimal text that reads back as `x` ("-1", "0.05", "1e-09"), and "nan", "inf",
/// "-inf" for the non-finite values: shortest_number (core/shortest_number.hpp).
[[nodiscard]] std::string format_number(double x);

/// `s` between `quote` characters, with backslash, the quote, and control characters escaped so
/// that the result is always a single line.
[[nodiscard]] std::string quoted(std::string_view s, char quote = '\'');

/// What a TOML value is, for "expected X, got Y": "a string \"5\"", "an integer",
/// "a floating-point number", "an empty array", "a table", …
[[nodiscard]] std::string describe(const toml::node& n);

/// One component of a dotted key path: the key itself when it is a TOML bare key
/// ([A-Za-z0-9_-]+), otherwise the key as a quoted TOML string.
[[nodiscard]] std::string path_component(std::string_view key);

/// Optimal-string-alignment edit distance (insertions, deletions, substitutions and transpositions
/// of adjacent characters each cost 1).
[[nodiscard]] std::size_t edit_distance(std::string_view a, std::string_view b);

/// True when `typed` is plausibly a typo of `intended`: equal ignoring case, one a prefix of the
/// other (both at least 4 characters), or an edit distance of at most max(1, min(3, n / 3)) with
/// n the length of `intended`.
[[nodiscard]] bool is_near_miss(std::string_view typed, std::string_view intended);

/// The candidate `typed` is most plausibly a typo of (smallest edit distance among the near
/// misses, first in order on ties), or nullopt.
[[nodiscard]] std::optional<std::string> closest_match(std::string_view typed,
                                                       std::span<const std::string> candidates);

}  // namespace attiguard::scenario::detail
