#pragma once
/// @file calendar_time.hpp
/// Calendar time tags of CCSDS messages (docs/interop.md, "Time tags"): the form
/// YYYY-MM-DDThh:mm:ss[.d…] of CCSDS 502.0/504.0 (calendar date, 24-hour clock), held as whole
/// seconds since 1970-01-01T00:00:00 of a uniform time scale (no leap seconds are inserted: a
/// run spanning a UTC leap second is tagged as if the scale were uniform) plus a fraction.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace attiguard::io {

/// An instant as whole seconds since 1970-01-01T00:00:00 plus a fraction in [0, 1).
struct CalendarTime {
  std::int64_t whole_seconds{0};
  double fraction{0.0};
};

/// Parses YYYY-MM-DDThh:mm:ss[.d…] (year 1000-9999, a valid day of the month, hh < 24,
/// mm < 60, ss < 60, at most 15 fraction digits); nullopt when the text is not of that form.
[[nodiscard]] std::optional<CalendarTime> parse_calendar_time(std::string_view text);

/// `time` as YYYY-MM-DDThh:mm:ss.d… with `decimals` (0-15) fraction digits (rounded; a
/// fraction that rounds to 1 carries into the seconds).
[[nodiscard]] std::string format_calendar_time(const CalendarTime& time, int decimals);

/// `time` + `seconds` (seconds ≥ 0 or < 0), the fraction kept in [0, 1).
[[nodiscard]] CalendarTime add_seconds(const CalendarTime& time, double seconds);

/// 9999-12-31T23:59:59, the last whole second of the 4-digit years that CCSDS time tags can
/// hold (docs/interop.md, "Time tags"): a message must end by it.
[[nodiscard]] CalendarTime last_calendar_time();

/// b − a in seconds.
[[nodiscard]] double seconds_between(const CalendarTime& a, const CalendarTime& b);

}  // namespace attiguard::io
