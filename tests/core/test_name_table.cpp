// core/name_table: one name table per enum, read by the parser, the summaries and the bindings.

#include <gtest/gtest.h>

#include <string_view>

#include "attiguard/core/name_table.hpp"
#include "attiguard/governor/attitude_governor.hpp"
#include "attiguard/integrate/integrator_settings.hpp"

namespace attiguard {
namespace {

enum class Colour { red, green };
constexpr NameTable<Colour, 2> kColours{{{{Colour::red, "red"}, {Colour::green, "green"}}}};

TEST(NameTable, NameFindAndNamesAgree) {
  static_assert(kColours.name(Colour::green) == "green");
  static_assert(*kColours.find("red") == Colour::red);
  EXPECT_FALSE(kColours.find("blue").has_value());
  EXPECT_EQ(kColours.name(static_cast<Colour>(7)), "?");
  const auto names = kColours.names();
  ASSERT_EQ(names.size(), 2U);
  EXPECT_EQ(names[0], "red");
  EXPECT_EQ(names[1], "green");
}

TEST(NameTable, EveryEnumeratorOfTheLibraryTablesRoundTrips) {
  for (const auto& e : governor::kGovernorModeNames.entries) {
    EXPECT_EQ(*governor::kGovernorModeNames.find(e.name), e.value) << e.name;
  }
  for (const auto& e : integrate::kMethodNames.entries) {
    EXPECT_EQ(*integrate::kMethodNames.find(e.name), e.value) << e.name;
  }
  EXPECT_EQ(governor::kGovernorModeNames.name(governor::GovernorMode::pet), "pet");
  EXPECT_EQ(integrate::kMethodNames.name(integrate::Method::rkmk_dp54), "rkmk_dp54");
}

}  // namespace
}  // namespace attiguard
