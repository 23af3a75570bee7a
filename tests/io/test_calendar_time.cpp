// io/calendar_time: CCSDS calendar time tags, parsed, formatted and shifted.

#include <gtest/gtest.h>

#include "attiguard/io/calendar_time.hpp"

namespace attiguard::io {
namespace {

TEST(CalendarTime, ParsesAndFormatsBackTheSameText) {
  const auto t = parse_calendar_time("2026-03-20T12:34:56.250");
  ASSERT_TRUE(t.has_value());
  EXPECT_EQ(format_calendar_time(*t, 3), "2026-03-20T12:34:56.250");
  EXPECT_DOUBLE_EQ(t->fraction, 0.25);
  const auto unix0 = parse_calendar_time("1970-01-01T00:00:00");
  ASSERT_TRUE(unix0.has_value());
  EXPECT_EQ(unix0->whole_seconds, 0);
  // J2000 epoch: 946728000 s after 1970-01-01 on a uniform scale.
  EXPECT_EQ(parse_calendar_time("2000-01-01T12:00:00")->whole_seconds, 946728000);
}

TEST(CalendarTime, AddingSecondsCrossesDaysMonthsAndLeapDays) {
  const auto t = *parse_calendar_time("2024-02-28T23:59:59.5");
  EXPECT_EQ(format_calendar_time(add_seconds(t, 0.75), 2), "2024-02-29T00:00:00.25");
  EXPECT_EQ(format_calendar_time(add_seconds(t, 86400.5), 1), "2024-03-01T00:00:00.0");
  EXPECT_EQ(format_calendar_time(add_seconds(t, -86400.0), 1), "2024-02-27T23:59:59.5");
  EXPECT_NEAR(seconds_between(t, add_seconds(t, 59.99)), 59.99, 1e-12);
}

TEST(CalendarTime, FractionRoundingCarriesIntoTheSeconds) {
  const CalendarTime t{59, 0.9996};
  EXPECT_EQ(format_calendar_time(t, 3), "1970-01-01T00:01:00.000");
}

TEST(CalendarTime, RejectsMalformedOrImpossibleTimes) {
  for (const char* bad : {"2026-02-30T00:00:00", "2026-13-01T00:00:00", "2026-01-01 00:00:00",
                          "2026-01-01T24:00:00", "2026-01-01T00:60:00", "2026-01-01T00:00:00.",
                          "2026-01-01T00:00:00.12x", "26-01-01T00:00:00", "2025-02-29T00:00:00"}) {
    EXPECT_FALSE(parse_calendar_time(bad).has_value()) << bad;
  }
  EXPECT_TRUE(parse_calendar_time("2024-02-29T00:00:00").has_value());
}

}  // namespace
}  // namespace attiguard::io
