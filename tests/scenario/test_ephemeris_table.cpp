// scenario/ephemeris_table: the [ephemeris] keys of the AEM export (docs/interop.md,
// "Scenario keys").

#include <gtest/gtest.h>

#include <string>

#include "attiguard/io/calendar_time.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/ephemeris_table.hpp"
#include "scenario_test_support.hpp"

namespace attiguard::scenario {
namespace {

TEST(EphemerisTable, DefaultsWithoutTheTableAndTheScenarioNameAsObjectName) {
  const io::AemMetadata m = parse_ephemeris(parse_document("kind = \"pet_erg\"\nname = \"sat\"\n", "a.toml"));
  EXPECT_EQ(m.object_name, "sat");
  EXPECT_EQ(m.object_id, "UNKNOWN");
  EXPECT_EQ(m.time_system, "TT");
  EXPECT_EQ(m.ref_frame_a, "EME2000");
  EXPECT_EQ(m.ref_frame_b, "SC_BODY_1");
  EXPECT_EQ(m.version, io::AemVersion::v1);
  EXPECT_FALSE(m.with_rates);
  EXPECT_EQ(io::format_calendar_time(m.epoch, 0), "2000-01-01T12:00:00");
}

TEST(EphemerisTable, ReadsEveryKey) {
  const io::AemMetadata m = parse_ephemeris(parse_document(
      "kind = \"pet_erg\"\n[ephemeris]\nepoch = \"2026-03-20T06:30:00.25\"\ntime_system = \"UTC\"\n"
      "object_name = \"DEMOSAT\"\nobject_id = \"2026-042B\"\ncenter_name = \"MOON\"\n"
      "ref_frame_a = \"ICRF\"\nref_frame_b = \"SC_BODY_2\"\noriginator = \"ME\"\n"
      "aem_version = \"2.0\"\nrates = true\n",
      "a.toml"));
  EXPECT_EQ(io::format_calendar_time(m.epoch, 2), "2026-03-20T06:30:00.25");
  EXPECT_EQ(m.time_system, "UTC");
  EXPECT_EQ(m.object_name, "DEMOSAT");
  EXPECT_EQ(m.object_id, "2026-042B");
  EXPECT_EQ(m.center_name, "MOON");
  EXPECT_EQ(m.ref_frame_a, "ICRF");
  EXPECT_EQ(m.ref_frame_b, "SC_BODY_2");
  EXPECT_EQ(m.originator, "ME");
  EXPECT_EQ(m.version, io::AemVersion::v2);
  EXPECT_TRUE(m.with_rates);
}

TEST(EphemerisTable, BadValuesAreLocatedAtTheirKey) {
  auto error_of = [](const std::string& body) {
    return test::input_error([&] {
      (void)parse_ephemeris(parse_document("kind = \"pet_erg\"\n[ephemeris]\n" + body, "e.toml"));
    });
  };
  EXPECT_TRUE(test::starts_with(error_of("time_system = \"GMT\"\n"), "e.toml:3:15: ephemeris.time_system:"));
  EXPECT_TRUE(test::contains(error_of("object_id = \"A = B\"\n"), "without '='"));
  EXPECT_TRUE(test::contains(error_of("object_name = \"\"\n"), "must not be empty"));
  EXPECT_TRUE(test::contains(error_of("epoch = \"2026-13-01T00:00:00\"\n"), "is not a time"));
  EXPECT_TRUE(test::contains(error_of("aem_version = \"3.0\"\n"), "ephemeris.aem_version"));
  EXPECT_TRUE(test::contains(error_of("frame = \"X\"\n"), "unknown key 'frame'"));
}

}  // namespace
}  // namespace attiguard::scenario
