#pragma once
/// @file ephemeris_check.hpp
/// The validation of the optional `[ephemeris]` table by the kind parsers (docs/interop.md,
/// "Scenario keys"; implemented with parse_ephemeris in ephemeris_table.cpp). Includes the
/// table reader, so only scenario/ uses it.

#include "attiguard/scenario/table_reader.hpp"

namespace attiguard::scenario {

/// Reads and validates `[ephemeris]` of `root` when present (every key checked, unknown keys
/// rejected): the kind parsers call it so that `attiguard check` and `run` report a bad key.
void check_ephemeris_table(const TableReader& root);

/// Rejects, at `ephemeris.epoch`, an epoch whose run of `duration` seconds would end after
/// io::last_calendar_time() (the AEM's time tags have 4-digit years; docs/interop.md,
/// "Scenario keys"). Compared in double before any date is computed. No-op without [ephemeris].
void check_ephemeris_end(const TableReader& root, double duration);

}  // namespace attiguard::scenario
