#include "attiguard/scenario/ephemeris_table.hpp"

#include <array>
#include <string_view>

#include "attiguard/io/calendar_time.hpp"
#include "attiguard/scenario/ephemeris_check.hpp"
#include "attiguard/scenario/messages.hpp"
#include "attiguard/scenario/table_reader.hpp"

namespace attiguard::scenario {
namespace {

/// TIME_SYSTEM values of CCSDS 504.0-B-1 annex A used for spacecraft attitude.
constexpr std::array<std::string_view, 9> kTimeSystems{"UTC", "TAI", "TT", "GPS", "TDB",
                                                       "TCB", "TCG", "UT1", "MET"};
constexpr std::array<std::string_view, 2> kVersions{"1.0", "2.0"};

/// A KVN value: non-empty, printable, no '=' (it would be read back as a key separator).
std::string kvn_value(const TableReader& t, std::string_view key, std::string_view fallback) {
  std::string v = t.string_or(key, fallback);
  if (v.empty()) t.fail(key, "must not be empty");
  for (char c : v) {
    if (c == '=' || static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) > 0x7e) {
      t.fail(key, "must be printable ASCII without '=' (it is written as a CCSDS KVN value)");
    }
  }
  return v;
}

constexpr std::string_view kDefaultEpoch = "2000-01-01T12:00:00";

/// Fills `m` from the table `e`; keys left out keep the values of `m`.
void read_table(const TableReader& e, io::AemMetadata& m) {
  const std::string epoch = e.string_or("epoch", kDefaultEpoch);
  const auto t0 = io::parse_calendar_time(epoch);
  if (!t0 && epoch.size() >= 19 && epoch.substr(17, 2) == "60" &&
      io::parse_calendar_time(epoch.substr(0, 17) + "59" + epoch.substr(19))) {
    e.fail("epoch", "'" + epoch + "' is a UTC leap second, which the epoch cannot be: the AEM's "
                    "time tags count a uniform scale without leap seconds (docs/interop.md, "
                    "\"Time tags\"); give the following second (the next day's 00:00:00) instead");
  }
  if (!t0) {
    e.fail("epoch", "'" + epoch + "' is not a time YYYY-MM-DDThh:mm:ss[.d...] (e.g. "
                    "\"2026-03-20T12:00:00.000\")");
  }
  m.epoch = *t0;
  m.time_system = e.string_or("time_system", m.time_system, kTimeSystems);
  m.object_name = kvn_value(e, "object_name", m.object_name);
  m.object_id = kvn_value(e, "object_id", m.object_id);
  m.center_name = kvn_value(e, "center_name", m.center_name);
  m.ref_frame_a = kvn_value(e, "ref_frame_a", m.ref_frame_a);
  m.ref_frame_b = kvn_value(e, "ref_frame_b", m.ref_frame_b);
  m.originator = kvn_value(e, "originator", m.originator);
  const std::string_view version = m.version == io::AemVersion::v1 ? "1.0" : "2.0";
  m.version = e.string_or("aem_version", version, kVersions) == "1.0" ? io::AemVersion::v1
                                                                      : io::AemVersion::v2;
  m.with_rates = e.boolean_or("rates", m.with_rates);
}

}  // namespace

io::AemMetadata default_ephemeris(const std::string& name) {
  io::AemMetadata m;
  m.epoch = *io::parse_calendar_time(kDefaultEpoch);
  m.time_system = "TT";
  m.object_name = name;
  return m;
}

void check_ephemeris_table(const TableReader& root) {
  if (const auto e = root.optional_table("ephemeris")) {
    io::AemMetadata m = default_ephemeris("scenario");
    read_table(*e, m);
    e->finish();
  }
}

void check_ephemeris_end(const TableReader& root, double duration) {
  const auto e = root.optional_table("ephemeris");
  if (!e || !e->has("epoch")) return;  // the default epoch (2000) + any countable duration fits
  io::AemMetadata m = default_ephemeris("scenario");
  read_table(*e, m);
  const io::CalendarTime last = io::last_calendar_time();
  if (const double room = io::seconds_between(m.epoch, last); !(duration <= room)) {
    e->fail("epoch", "the run of " + detail::format_number(duration) + " s from this epoch ends after " +
                         io::format_calendar_time(last, 0) + " (" +
                         detail::format_number(room) + " s after the epoch), the last time an "
                         "AEM can tag with its 4-digit years; use an earlier epoch");
  }
}

io::AemMetadata parse_ephemeris(const Document& doc) {
  const TableReader root(doc);
  const std::string name = root.string_or("name", "SPACECRAFT");
  io::AemMetadata m = default_ephemeris(name);
  m.comments.push_back("attiguard scenario " + name);
  if (const auto e = root.optional_table("ephemeris")) {
    read_table(*e, m);
    e->finish();
  }
  return m;
}

}  // namespace attiguard::scenario
