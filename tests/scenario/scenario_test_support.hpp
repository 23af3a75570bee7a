#pragma once
/// Helpers for the scenario-layer tests: parse inline TOML and capture the InputError message.

#include <gtest/gtest.h>

#include <map>
#include <sstream>
#include <string>
#include <string_view>

#include "attiguard/core/errors.hpp"
#include "attiguard/scenario/document.hpp"

namespace attiguard::scenario::test {

/// The message of the InputError `f()` throws; fails the test when it throws nothing or the
/// message spans more than one line.
template <class F>
std::string input_error(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << "not one line: " << message;
    return message;
  }
  ADD_FAILURE() << "no InputError was thrown";
  return {};
}

/// Success when `message` contains `part`, with both shown otherwise.
inline ::testing::AssertionResult contains(const std::string& message, std::string_view part) {
  if (message.find(part) != std::string::npos) {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure()
         << "\"" << message << "\" does not contain \"" << part << "\"";
}

/// Success when `message` starts with `prefix` (the FILE:LINE:COL: KEY.PATH: part of an error).
inline ::testing::AssertionResult starts_with(const std::string& message, std::string_view prefix) {
  if (message.starts_with(prefix)) {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure()
         << "\"" << message << "\" does not start with \"" << prefix << "\"";
}

/// `text` with the 1-based lines in `replacements` replaced (a replacement may be several lines
/// or empty, which keeps an empty line so that later line numbers do not move).
inline std::string with_lines(std::string_view text,
                              const std::map<int, std::string>& replacements) {
  std::istringstream in{std::string(text)};
  std::string out;
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    const auto it = replacements.find(n);
    out += (it == replacements.end() ? line : it->second) + "\n";
  }
  return out;
}

}  // namespace attiguard::scenario::test
