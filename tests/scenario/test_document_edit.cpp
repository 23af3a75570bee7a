// scenario/document_edit: numbers by key path and the document as TOML text.

#include <gtest/gtest.h>

#include "attiguard/core/errors.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/document_edit.hpp"

namespace attiguard::scenario {
namespace {

constexpr const char* kText = R"(kind = "pet_erg"
[control]
kp = 5
kd = 1.5
name = "x"
[[cones]]
half_angle_deg = 20.0
)";

TEST(DocumentEdit, ReadsAndSetsNumbersByKeyPath) {
  Document d = parse_document(kText, "t.toml");
  EXPECT_EQ(number_at(d, "control.kp"), 5.0);  // an integer reads as a number
  EXPECT_EQ(number_at(d, "control.kd"), 1.5);
  EXPECT_EQ(number_at(d, "cones[0].half_angle_deg"), 20.0);
  EXPECT_FALSE(number_at(d, "control.name").has_value());
  EXPECT_FALSE(number_at(d, "control.absent").has_value());
  set_number(d, "control.kp", 2.5);
  set_number(d, "control.control_period", 0.1);  // inserted
  set_number(d, "erg.kappa", 3.0);                // table created
  set_number(d, "cones[0].half_angle_deg", 25.0);
  EXPECT_EQ(number_at(d, "control.kp"), 2.5);
  EXPECT_EQ(number_at(d, "control.control_period"), 0.1);
  EXPECT_EQ(number_at(d, "erg.kappa"), 3.0);
  EXPECT_EQ(number_at(d, "cones[0].half_angle_deg"), 25.0);
  EXPECT_THROW(set_number(d, "control.name", 1.0), InputError);
  EXPECT_THROW(set_number(d, "a.b.c", 1.0), InputError);
}

TEST(DocumentEdit, TomlTextParsesBackToTheSameNumbers) {
  Document d = parse_document(kText, "t.toml");
  set_number(d, "control.kd", 0.1 + 0.2);
  const Document back = parse_document(document_text(d), "back.toml");
  EXPECT_EQ(number_at(back, "control.kd"), 0.1 + 0.2);  // exact round trip
  EXPECT_EQ(number_at(back, "cones[0].half_angle_deg"), 20.0);
  EXPECT_EQ(scenario_kind(back), "pet_erg");
  EXPECT_EQ(scenario_file_name("best"), "best.toml");
}

}  // namespace
}  // namespace attiguard::scenario
