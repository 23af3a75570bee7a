#pragma once
/// @file name_table.hpp
/// One name table per enum (docs/architecture.md, "Where the configuration structs live"): the
/// text of each enumerator as it appears in scenario files, summaries and the Python bindings.
/// The table is defined once, next to the enum; the parser, the summary writers and the bindings
/// all read it.

#include <array>
#include <cstddef>
#include <optional>
#include <string_view>

namespace attiguard {

/// One enumerator and its text.
template <class Enum>
struct EnumName {
  Enum value;
  std::string_view name;
};

/// The names of an enum's N enumerators, in the order they are listed in messages.
template <class Enum, std::size_t N>
struct NameTable {
  std::array<EnumName<Enum>, N> entries;

  /// The text of `value` ("?" for a value not in the table).
  [[nodiscard]] constexpr std::string_view name(Enum value) const noexcept {
    for (const EnumName<Enum>& e : entries) {
      if (e.value == value) return e.name;
    }
    return "?";
  }
  /// The enumerator named `text`, or nullopt.
  [[nodiscard]] constexpr std::optional<Enum> find(std::string_view text) const noexcept {
    for (const EnumName<Enum>& e : entries) {
      if (e.name == text) return e.value;
    }
    return std::nullopt;
  }
  /// Every name, in table order (the allowed values of a scenario key).
  [[nodiscard]] constexpr std::array<std::string_view, N> names() const noexcept {
    std::array<std::string_view, N> out{};
    for (std::size_t i = 0; i < N; ++i) out[i] = entries[i].name;
    return out;
  }
};

/// Deduction guide: NameTable{{{E::a, "a"}, {E::b, "b"}}}.
template <class Enum, std::size_t N>
NameTable(std::array<EnumName<Enum>, N>) -> NameTable<Enum, N>;

}  // namespace attiguard
