#pragma once
/// @file one_line.hpp
/// An error message as one line of a CSV or JSON field (docs/campaigns.md, runs.csv `reason`).

#include <string>

namespace attiguard {

/// `s` with every line break replaced by a space.
[[nodiscard]] inline std::string one_line(std::string s) {
  for (char& ch : s) {
    if (ch == '\n' || ch == '\r') ch = ' ';
  }
  return s;
}

}  // namespace attiguard
