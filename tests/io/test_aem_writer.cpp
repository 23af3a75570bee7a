// io/aem_writer: the CCSDS AEM text (keys, conventions) and its round trip through io/aem_reader.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "attiguard/core/errors.hpp"
#include "attiguard/io/aem_reader.hpp"
#include "attiguard/io/aem_writer.hpp"

namespace attiguard::io {
namespace {

AemMetadata metadata(AemVersion v, bool rates) {
  AemMetadata m;
  m.version = v;
  m.with_rates = rates;
  m.object_name = "TESTSAT";
  m.object_id = "2026-001A";
  m.epoch = *parse_calendar_time("2026-03-20T12:00:00");
  return m;
}

const CalendarTime kCreated{1'780'000'000, 0.0};

/// The data lines of an AEM text, split into fields.
std::vector<std::vector<std::string>> data_lines(const std::string& text) {
  std::vector<std::vector<std::string>> out;
  std::istringstream in(text);
  std::string line;
  bool data = false;
  while (std::getline(in, line)) {
    if (line == "DATA_START") {
      data = true;
    } else if (line == "DATA_STOP") {
      data = false;
    } else if (data) {
      std::istringstream f(line);
      std::vector<std::string> fields;
      for (std::string w; f >> w;) fields.push_back(w);
      out.push_back(fields);
    }
  }
  return out;
}

/// A value of "KEY = VALUE", "" when the key is absent.
std::string value_of(const std::string& text, const std::string& key) {
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    const auto eq = line.find('=');
    if (eq == std::string::npos) continue;
    std::string k = line.substr(0, eq);
    while (!k.empty() && k.back() == ' ') k.pop_back();
    if (k == key) {
      std::string v = line.substr(eq + 1);
      while (!v.empty() && v.front() == ' ') v.erase(v.begin());
      return v;
    }
  }
  return "";
}

/// The direction cosine matrix of a CCSDS quaternion (Q1, Q2, Q3 vector part, QC scalar), as
/// the attitude standard defines it for the transformation of coordinates from frame A to frame
/// B (504.0-B-1 annex, the rotation of angle φ about the Euler axis e: Q = e sin(φ/2),
/// QC = cos(φ/2)): A(q) = (QC² − |q|²) I + 2 q qᵀ − 2 QC [q×]. Written out here independently
/// of attiguard's lie/ code.
Eigen::Matrix3d ccsds_dcm(double q1, double q2, double q3, double qc) {
  const Eigen::Vector3d q(q1, q2, q3);
  Eigen::Matrix3d cross;
  cross << 0, -q3, q2, q3, 0, -q1, -q2, q1, 0;
  return (qc * qc - q.squaredNorm()) * Eigen::Matrix3d::Identity() + 2.0 * q * q.transpose() -
         2.0 * qc * cross;
}

TEST(AemWriter, NinetyDegreesAboutYTransformsInertialCoordinatesToBodyPerTheStandard) {
  // R_ib = rotation of 90° about y: the body x axis points along inertial −z.
  const double h = std::numbers::pi / 4.0;
  const AttitudeSample s{0.0, {std::cos(h), 0.0, std::sin(h), 0.0}, {0.0, 0.0, 0.0}};
  for (AemVersion v : {AemVersion::v1, AemVersion::v2}) {
    const std::string text = aem_text(metadata(v, false), std::span(&s, 1), kCreated);
    const auto lines = data_lines(text);
    ASSERT_EQ(lines.size(), 1u);
    ASSERT_EQ(lines[0].size(), 5u);
    double q1, q2, q3, qc;
    if (v == AemVersion::v1) {  // QUATERNION_TYPE = FIRST: QC Q1 Q2 Q3
      EXPECT_EQ(value_of(text, "QUATERNION_TYPE"), "FIRST");
      EXPECT_EQ(value_of(text, "ATTITUDE_DIR"), "A2B");
      qc = std::stod(lines[0][1]), q1 = std::stod(lines[0][2]), q2 = std::stod(lines[0][3]),
      q3 = std::stod(lines[0][4]);
    } else {  // 504.0-B-2: Q1 Q2 Q3 QC
      q1 = std::stod(lines[0][1]), q2 = std::stod(lines[0][2]), q3 = std::stod(lines[0][3]),
      qc = std::stod(lines[0][4]);
    }
    const Eigen::Matrix3d A = ccsds_dcm(q1, q2, q3, qc);
    // The body x axis, expressed in inertial coordinates, is body (1, 0, 0).
    const Eigen::Vector3d x_b = A * Eigen::Vector3d(0.0, 0.0, -1.0);
    EXPECT_NEAR((x_b - Eigen::Vector3d::UnitX()).norm(), 0.0, 1e-15);
    // Inertial x is body +z; y is unchanged.
    EXPECT_NEAR((A * Eigen::Vector3d::UnitX() - Eigen::Vector3d::UnitZ()).norm(), 0.0, 1e-15);
    EXPECT_NEAR((A * Eigen::Vector3d::UnitY() - Eigen::Vector3d::UnitY()).norm(), 0.0, 1e-15);
    EXPECT_NEAR(q2, std::sin(h), 1e-16);  // rotation +90° about y: e = y, φ = +90°
  }
}

TEST(AemWriter, WritesEveryObligatoryKeyAndTheDirectionAndScalarPositionInVersion1) {
  const std::vector<AttitudeSample> s{{0.0, {1, 0, 0, 0}, {0, 0, 0}},
                                      {0.5, {1, 0, 0, 0}, {0, 0, 0}}};
  const std::string text = aem_text(metadata(AemVersion::v1, false), s, kCreated);
  for (const char* key : {"CCSDS_AEM_VERS", "CREATION_DATE", "ORIGINATOR", "OBJECT_NAME", "OBJECT_ID",
                          "CENTER_NAME", "REF_FRAME_A", "REF_FRAME_B", "ATTITUDE_DIR",
                          "TIME_SYSTEM", "START_TIME", "STOP_TIME", "ATTITUDE_TYPE",
                          "QUATERNION_TYPE"}) {
    EXPECT_FALSE(value_of(text, key).empty()) << key;
  }
  EXPECT_EQ(value_of(text, "CCSDS_AEM_VERS"), "1.0");
  EXPECT_EQ(value_of(text, "ATTITUDE_TYPE"), "QUATERNION");
  EXPECT_EQ(value_of(text, "START_TIME"), "2026-03-20T12:00:00.000000000000");
  EXPECT_EQ(value_of(text, "STOP_TIME"), "2026-03-20T12:00:00.500000000000");
  EXPECT_EQ(text.rfind("CCSDS_AEM_VERS", 0), 0u);  // the first keyword of the message

  const std::string v2 = aem_text(metadata(AemVersion::v2, true), s, kCreated);
  EXPECT_EQ(value_of(v2, "CCSDS_AEM_VERS"), "2.0");
  EXPECT_EQ(value_of(v2, "ATTITUDE_TYPE"), "QUATERNION/ANGVEL");
  EXPECT_EQ(value_of(v2, "ATTITUDE_DIR"), "");  // removed by 504.0-B-2 (direction fixed A to B)
}

TEST(AemWriter, RoundTripThroughTheReaderToOneInATrillion) {
  // A tumbling trajectory: R(t) = exp(t ω̂) R0, with a negative q_w on some rows.
  std::vector<AttitudeSample> samples;
  const Eigen::Quaterniond q0(Eigen::AngleAxisd(2.0, Eigen::Vector3d(1, -2, 0.5).normalized()));
  for (int k = 0; k < 500; ++k) {
    const double t = 0.013 * k + 1.0 / 3.0;
    const Eigen::Quaterniond q =
        Eigen::Quaterniond(Eigen::AngleAxisd(0.9 * t, Eigen::Vector3d(0.3, 0.4, -0.2).normalized())) * q0;
    const double sign = (k / 50) % 2 == 0 ? 1.0 : -1.0;
    samples.push_back({t, {sign * q.w(), sign * q.x(), sign * q.y(), sign * q.z()},
                       {0.1 * std::sin(t), -0.2, 0.3 * std::cos(t)}});
  }
  for (AemVersion v : {AemVersion::v1, AemVersion::v2}) {
    for (bool rates : {false, true}) {
      const AemMetadata m = metadata(v, rates);
      const AemFile back =
          parse_aem(aem_text(m, samples, kCreated), "test.aem", "2026-03-20T12:00:00");
      EXPECT_EQ(back.metadata.object_name, "TESTSAT");
      EXPECT_EQ(back.metadata.object_id, "2026-001A");
      EXPECT_EQ(back.metadata.version, v);
      EXPECT_EQ(back.metadata.with_rates, rates);
      ASSERT_EQ(back.samples.size(), samples.size());
      double worst = 0.0;
      for (std::size_t i = 0; i < samples.size(); ++i) {
        const auto& a = samples[i];
        const auto& b = back.samples[i];
        worst = std::max(worst, std::abs(a.t - b.t));
        const double sign = a.q_ib[0] < 0.0 ? -1.0 : 1.0;  // written with QC ≥ 0
        for (std::size_t k = 0; k < 4; ++k) worst = std::max(worst, std::abs(sign * a.q_ib[k] - b.q_ib[k]));
        EXPECT_GE(b.q_ib[0], 0.0);
        if (rates) {
          for (std::size_t k = 0; k < 3; ++k) worst = std::max(worst, std::abs(a.omega_b[k] - b.omega_b[k]));
        }
      }
      EXPECT_LE(worst, 1e-12);
    }
  }
}

TEST(AemWriter, RefusesEmptyNonFiniteOrNonIncreasingSamples) {
  const AemMetadata m = metadata(AemVersion::v1, false);
  EXPECT_THROW((void)aem_text(m, std::span<const AttitudeSample>(), kCreated), InputError);
  const std::vector<AttitudeSample> repeated{{1.0, {1, 0, 0, 0}, {}}, {1.0, {1, 0, 0, 0}, {}}};
  EXPECT_THROW((void)aem_text(m, repeated, kCreated), InputError);
  const std::vector<AttitudeSample> nan{{0.0, {std::nan(""), 0, 0, 0}, {}}};
  EXPECT_THROW((void)aem_text(m, nan, kCreated), InputError);
}

TEST(AemReader, NamesTheLineOfAMalformedDataLine) {
  const std::vector<AttitudeSample> s{{0.0, {1, 0, 0, 0}, {}}};
  std::string text = aem_text(metadata(AemVersion::v1, false), s, kCreated);
  text.replace(text.find("DATA_STOP"), 9, "2026-03-20T12:00:01 1 0 0\nDATA_STOP");
  try {
    (void)parse_aem(text, "bad.aem");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.aem:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("expected 5 fields, found 4"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace attiguard::io
