#pragma once
/// @file aem_reader.hpp
/// Reads a CCSDS Attitude Ephemeris Message in KVN form as written by aem_writer.hpp (one
/// segment, ATTITUDE_TYPE QUATERNION or QUATERNION/RATE of version 1.0, QUATERNION or
/// QUATERNION/ANGVEL of version 2.0; docs/interop.md). Used by the round-trip tests and by
/// anyone checking an exported file.

#include <filesystem>
#include <string_view>

#include "attiguard/io/aem_message.hpp"

namespace attiguard::io {

/// Parses AEM text. The samples' t are seconds from the time tag `epoch` (when empty, from
/// the first data line's time tag), quaternions returned as Hamilton q_ib (scalar first) and
/// rates in rad/s. Throws InputError "NAME:LINE: what" (NAME = `name`) on any malformed line,
/// a missing obligatory key, an unknown ATTITUDE_TYPE or a data line with the wrong count.
[[nodiscard]] AemFile parse_aem(std::string_view text, std::string_view name,
                                std::string_view epoch = {});

/// parse_aem of the file's content; InputError when it cannot be read.
[[nodiscard]] AemFile read_aem(const std::filesystem::path& path, std::string_view epoch = {});

}  // namespace attiguard::io
