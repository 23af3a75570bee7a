#pragma once
/// @file csv_format.hpp
/// Deterministic CSV text of campaign results: exact numbers and quoted fields.

#include <string>
#include <string_view>
#include <vector>

namespace attiguard::campaign {

/// %.17g (round-trips exactly; "nan"/"inf" never occur in ok rows).
[[nodiscard]] std::string format_number(double x);
/// The field quoted when it contains a comma, a quote or a newline (RFC 4180).
[[nodiscard]] std::string csv_quote(std::string_view field);
/// Splits one CSV line into fields (RFC 4180 quoting).
[[nodiscard]] std::vector<std::string> csv_split(std::string_view line);

}  // namespace attiguard::campaign
