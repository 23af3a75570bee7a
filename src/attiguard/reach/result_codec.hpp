#pragma once
/// @file result_codec.hpp
/// Exact binary round trip of ConReach results (CBOR through nlohmann-json: doubles keep every
/// bit), so that partition cells computed on other MPI ranks reach every rank unchanged and the
/// distributed analysis writes the same files as the serial one (docs/scaling.md).

#include <string>

#include "attiguard/reach/conreach.hpp"

namespace attiguard::reach {

/// The result as CBOR bytes.
[[nodiscard]] std::string encode_result(const ReachResult& result);

/// The result encoded by encode_result. Throws NumericalError on malformed bytes.
[[nodiscard]] ReachResult decode_result(const std::string& bytes);

}  // namespace attiguard::reach
