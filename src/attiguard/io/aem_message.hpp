#pragma once
/// @file aem_message.hpp
/// The content of a CCSDS Attitude Ephemeris Message (AEM, CCSDS 504.0-B-1 "Attitude Data
/// Messages", section 4; version 2.0: 504.0-B-2), shared by its writer (aem_writer.hpp) and its
/// reader (aem_reader.hpp). Conventions in docs/interop.md.

#include <array>
#include <string>
#include <vector>

#include "attiguard/io/calendar_time.hpp"

namespace attiguard::io {

/// CCSDS_AEM_VERS: 1.0 (504.0-B-1) or 2.0 (504.0-B-2).
enum class AemVersion { v1, v2 };

/// Header and metadata keys of one AEM segment (docs/interop.md, "Keys").
struct AemMetadata {
  AemVersion version{AemVersion::v1};
  std::string originator{"attiguard"};
  std::string object_name{"SPACECRAFT"};
  std::string object_id{"UNKNOWN"};
  std::string center_name{"EARTH"};
  std::string ref_frame_a{"EME2000"};  ///< the inertial frame i of R_ib
  std::string ref_frame_b{"SC_BODY_1"};  ///< the body frame b of R_ib
  std::string time_system{"UTC"};
  CalendarTime epoch{};  ///< the instant of t = 0 of the trajectory
  /// QUATERNION/RATE (1.0) or QUATERNION/ANGVEL (2.0): ω_b as well, in deg/s.
  bool with_rates{false};
  std::vector<std::string> comments;  ///< COMMENT lines of the metadata block
};

/// One data line: t [s] from the epoch, the Hamilton scalar-first quaternion of R_ib
/// (docs/conventions.md) and ω_b [rad/s].
struct AttitudeSample {
  double t{0.0};
  std::array<double, 4> q_ib{1.0, 0.0, 0.0, 0.0};
  std::array<double, 3> omega_b{0.0, 0.0, 0.0};
};

/// A parsed AEM: its metadata, creation date and samples (t from the metadata's epoch argument
/// of read_aem).
struct AemFile {
  AemMetadata metadata;
  std::string creation_date;
  std::string attitude_dir;     ///< A2B (1.0); empty in 2.0
  std::string quaternion_type;  ///< FIRST (1.0); empty in 2.0
  std::string start_time, stop_time;
  std::vector<AttitudeSample> samples;
};

}  // namespace attiguard::io
