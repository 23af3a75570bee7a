#pragma once
/// @file ephemeris_table.hpp
/// The optional `[ephemeris]` table of a flight scenario (kinds rigid_body, pet_erg, waypoint,
/// mission): the metadata of the CCSDS AEM export (docs/interop.md, "Scenario keys"): the epoch
/// of t = 0, the time system, the frame names of R_ib and the object's name and id.

#include <string>

#include "attiguard/io/aem_message.hpp"
#include "attiguard/scenario/document.hpp"

namespace attiguard::scenario {

/// The metadata of a scenario without `[ephemeris]`, OBJECT_NAME `name` (docs/interop.md,
/// "Scenario keys": epoch 2000-01-01T12:00:00 TT, EME2000 to SC_BODY_1, version 1.0).
[[nodiscard]] io::AemMetadata default_ephemeris(const std::string& name);

/// The AEM metadata of the document: `[ephemeris]` keys, defaults (docs/interop.md) for the
/// keys left out, OBJECT_NAME defaulting to the scenario's `name`. Throws InputError located at
/// the offending key.
[[nodiscard]] io::AemMetadata parse_ephemeris(const Document& doc);

}  // namespace attiguard::scenario
