#pragma once
/// @file aem_writer.hpp
/// Writes an attitude history as a CCSDS Attitude Ephemeris Message in KVN form (CCSDS
/// 504.0-B-1 section 4, version 1.0 by default; 504.0-B-2 for 2.0). Conventions and keys:
/// docs/interop.md.
///
/// The quaternion written is the "A2B" quaternion of the standard: the coordinate
/// transformation from REF_FRAME_A (inertial, i) to REF_FRAME_B (body, b), v_b = R_ibᵀ v_i.
/// Its components equal those of attiguard's Hamilton quaternion of R_ib (scalar QC = q_w,
/// vector Q1..Q3 = q_x..q_z), with the sign chosen so that QC ≥ 0 (the standard's
/// recommendation). Version 1.0 always writes ATTITUDE_DIR = A2B and QUATERNION_TYPE = FIRST
/// (data lines: epoch QC Q1 Q2 Q3); version 2.0 has neither key (the standard fixes the
/// direction A to B and the order Q1 Q2 Q3 QC) and says so in a COMMENT.

#include <filesystem>
#include <span>
#include <string>

#include "attiguard/io/aem_message.hpp"

namespace attiguard::io {

/// The AEM text of `samples` (t increasing, at least one), with CREATION_DATE `created`.
/// Throws InputError when samples is empty, a time is not increasing or a value is not finite.
[[nodiscard]] std::string aem_text(const AemMetadata& meta, std::span<const AttitudeSample> samples,
                                   const CalendarTime& created);

/// Writes aem_text(meta, samples, now in UTC) to `path` (through PATH.partial); throws
/// InputError when the file cannot be written.
void write_aem(const std::filesystem::path& path, const AemMetadata& meta,
               std::span<const AttitudeSample> samples);

/// Fraction digits of the data lines' time tags (CCSDS allows any number).
inline constexpr int kAemTimeDecimals = 12;

}  // namespace attiguard::io
