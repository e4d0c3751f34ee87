#pragma once
// What `hertzdash continue RIG` and Python's hertzdash.continuation() print
// (simulation/rigs/rig_continuation.hpp, docs/orbits.md): the branches as JSON, text and CSV.
#include "hertzdash/io/csv_writer.hpp"
#include "hertzdash/simulation/rigs/rig_continuation.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace hertzdash {

/// "schema_version", "rig", "method", "parameter", "start" {period, section_phase, guess},
/// "failure" (only where no branch was followed), "branch" (one object per point: branch, period,
/// the parameter under its column name with its unit (force_amplitude_N), position_m, velocity_mps, multipliers [[re, im], ...],
/// multiplier_moduli, stable, impacts_per_period, min_impact_speed_mps, min_flight_gap_m),
/// "events" ({type, parameter, branch, period}), "ends" (per branch, why it ended), "inputs",
/// "git_revision". An infinite closeness (no impact, no interior minimum) is null.
nlohmann::ordered_json to_json(const Rig& rig, const ContinuationResult& result);

/// "hertzdash continue RIG: heading", the start, the events and each branch's end.
std::string continuation_text(const Rig& rig, const ContinuationResult& result);

/// The points as CSV (the JSON's per-point keys as columns, each multiplier as _re and _im) below
/// the provenance, the events and the branches' ends as comments.
CsvWriter continuation_csv(const Rig& rig, const ContinuationResult& result);

}  // namespace hertzdash
