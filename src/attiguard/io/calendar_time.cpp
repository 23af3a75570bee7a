#include "attiguard/io/calendar_time.hpp"

#include <cmath>
#include <cstdio>

namespace attiguard::io {
namespace {

/// Days since 1970-01-01 of a proleptic Gregorian date (the civil-from-days inverse below).
std::int64_t days_from_civil(std::int64_t y, int m, int d) {
  y -= m <= 2 ? 1 : 0;
  const std::int64_t era = (y >= 0 ? y : y - 399) / 400;
  const std::int64_t yoe = y - era * 400;
  const std::int64_t doy = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + d - 1;
  const std::int64_t doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  return era * 146097 + doe - 719468;
}

struct Civil {
  std::int64_t year;
  int month;
  int day;
};

Civil civil_from_days(std::int64_t z) {
  z += 719468;
  const std::int64_t era = (z >= 0 ? z : z - 146096) / 146097;
  const std::int64_t doe = z - era * 146097;
  const std::int64_t yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
  const std::int64_t doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
  const std::int64_t mp = (5 * doy + 2) / 153;
  const int d = static_cast<int>(doy - (153 * mp + 2) / 5 + 1);
  const int m = static_cast<int>(mp < 10 ? mp + 3 : mp - 9);
  return {yoe + era * 400 + (m <= 2 ? 1 : 0), m, d};
}

bool is_leap(std::int64_t y) { return (y % 4 == 0 && y % 100 != 0) || y % 400 == 0; }

int days_in_month(std::int64_t y, int m) {
  static constexpr int kDays[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  return m == 2 && is_leap(y) ? 29 : kDays[m - 1];
}

/// The digits text[pos, pos + n) as a number; -1 when any is not a digit.
long digits(std::string_view text, std::size_t pos, std::size_t n) {
  if (pos + n > text.size()) return -1;
  long v = 0;
  for (std::size_t i = pos; i < pos + n; ++i) {
    if (text[i] < '0' || text[i] > '9') return -1;
    v = v * 10 + (text[i] - '0');
  }
  return v;
}

}  // namespace

std::optional<CalendarTime> parse_calendar_time(std::string_view text) {
  // YYYY-MM-DDThh:mm:ss : 19 characters, then optionally '.' and 1-15 digits.
  if (text.size() < 19 || text[4] != '-' || text[7] != '-' || text[10] != 'T' ||
      text[13] != ':' || text[16] != ':') {
    return std::nullopt;
  }
  const long y = digits(text, 0, 4), mo = digits(text, 5, 2), d = digits(text, 8, 2);
  const long h = digits(text, 11, 2), mi = digits(text, 14, 2), s = digits(text, 17, 2);
  if (y < 1000 || mo < 1 || mo > 12 || d < 1 || h < 0 || h > 23 || mi < 0 || mi > 59 || s < 0 ||
      s > 59) {
    return std::nullopt;
  }
  if (d > days_in_month(y, static_cast<int>(mo))) return std::nullopt;
  double fraction = 0.0;
  if (text.size() > 19) {
    const std::size_t n = text.size() - 20;
    if (text[19] != '.' || n == 0 || n > 15 || digits(text, 20, n) < 0) return std::nullopt;
    double scale = 0.1;
    for (std::size_t i = 20; i < text.size(); ++i, scale /= 10.0) fraction += (text[i] - '0') * scale;
  }
  CalendarTime t;
  t.whole_seconds = days_from_civil(y, static_cast<int>(mo), static_cast<int>(d)) * 86400 +
                    h * 3600 + mi * 60 + s;
  t.fraction = fraction;
  return t;
}

std::string format_calendar_time(const CalendarTime& time, int decimals) {
  if (decimals < 0) decimals = 0;
  if (decimals > 15) decimals = 15;
  const double scale = std::pow(10.0, decimals);
  auto units = static_cast<std::int64_t>(std::llround(time.fraction * scale));
  std::int64_t whole = time.whole_seconds;
  const auto full = static_cast<std::int64_t>(std::llround(scale));
  if (units >= full) {  // the fraction rounded up to a whole second
    units -= full;
    whole += 1;
  }
  std::int64_t days = whole >= 0 ? whole / 86400 : (whole - 86399) / 86400;
  const std::int64_t sod = whole - days * 86400;
  const Civil c = civil_from_days(days);
  char buf[64];
  std::snprintf(buf, sizeof buf, "%04lld-%02d-%02dT%02lld:%02lld:%02lld",
                static_cast<long long>(c.year), c.month, c.day,
                static_cast<long long>(sod / 3600), static_cast<long long>(sod / 60 % 60),
                static_cast<long long>(sod % 60));
  std::string out = buf;
  if (decimals > 0) {
    std::snprintf(buf, sizeof buf, ".%0*lld", decimals, static_cast<long long>(units));
    out += buf;
  }
  return out;
}

CalendarTime add_seconds(const CalendarTime& time, double seconds) {
  const double whole = std::floor(seconds);
  double fraction = time.fraction + (seconds - whole);
  std::int64_t carry = static_cast<std::int64_t>(whole);
  if (fraction >= 1.0) {
    fraction -= 1.0;
    carry += 1;
  }
  return {time.whole_seconds + carry, fraction};
}

CalendarTime last_calendar_time() {
  return {days_from_civil(9999, 12, 31) * 86400 + 86399, 0.0};
}

double seconds_between(const CalendarTime& a, const CalendarTime& b) {
  return static_cast<double>(b.whole_seconds - a.whole_seconds) + (b.fraction - a.fraction);
}

}  // namespace attiguard::io
