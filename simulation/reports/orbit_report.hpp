#pragma once
// What the analyses of a rig's impact sequence print (docs/orbits.md), `hertzdash COMMAND RIG`
// and Python's hertzdash.FUNCTION(): `orbit` (simulation/rigs/rig_orbit.hpp), `continue`
// (rig_continuation.hpp), `lyapunov` (rig_lyapunov.hpp) and `basins` (rig_basins.hpp), each as
// JSON and text, the branches of `continue` and the grid of `basins` as CSV too (orbit_report.cpp).
#include "hertzdash/io/csv_writer.hpp"
#include "hertzdash/simulation/rigs/rig_basins.hpp"
#include "hertzdash/simulation/rigs/rig_continuation.hpp"
#include "hertzdash/simulation/rigs/rig_lyapunov.hpp"
#include "hertzdash/simulation/rigs/rig_orbit.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace hertzdash {

/// "schema_version", "rig", "method", "converged" (and "failure" where not), "period",
/// "impacts_per_period", "section_phase", "section_state" {position_m, velocity_mps, and a box of
/// its own's box_position_m, box_velocity_mps},
/// "multipliers" [[re, im], ...] largest modulus first, "multiplier_moduli", "stable",
/// "newton_residual", "newton_iterations", "min_impact_speed_mps", "guess", the orbit's impacts
/// over its period as arrays ("impact_time_s", "impact_phase", "impact_speed_mps",
/// "rebound_speed_mps"), "inputs", "git_revision".
nlohmann::ordered_json to_json(const Rig& rig, const OrbitResult& result);

/// "hertzdash orbit RIG: heading", the orbit's lines and its impacts, or the failure.
std::string orbit_text(const Rig& rig, const OrbitResult& result);

/// "schema_version", "rig", "method", "parameter", "start" {period, section_phase, guess},
/// "failure" (only where no branch was followed), "branch" (one object per point: branch, period,
/// the parameter under its column name with its unit (force_amplitude_N), the section state's
/// coordinates as section_state's, multipliers [[re, im], ...], multiplier_moduli, stable, impacts_per_period,
/// impact_phase (one per impact), min_impact_speed_mps, min_flight_gap_m),
/// "events" ({type, parameter, branch, period}), "ends" (per branch, why it ended), "inputs",
/// "git_revision". An infinite closeness (no impact, no interior minimum) is null.
nlohmann::ordered_json to_json(const Rig& rig, const ContinuationResult& result);

/// "hertzdash continue RIG: heading", the start, the events and each branch's end (the points'
/// count, which the step control's round-off can move, in the JSON only).
std::string continuation_text(const Rig& rig, const ContinuationResult& result);

/// The points as CSV (the JSON's per-point keys as columns, each multiplier as _re and _im) below
/// the provenance, the events and the branches' ends as comments.
CsvWriter continuation_csv(const Rig& rig, const ContinuationResult& result);

/// "schema_version", "rig", "method", "failure" (only where the run stopped or had no start),
/// "periods", "impacts", "section_phase", "exponents_per_period" and "exponents_per_impact"
/// (largest first), "sum_per_impact", "expected_sum_per_impact", "half_difference",
/// "converged", "running" {periods, exponents_per_impact: one array per running point},
/// "inputs", "git_revision".
nlohmann::ordered_json to_json(const Rig& rig, const LyapunovResult& result);

/// "hertzdash lyapunov RIG: heading" and the spectrum's lines.
std::string lyapunov_text(const Rig& rig, const LyapunovResult& result);

/// "schema_version", "rig", "method", "failure" (only where the grid did not run),
/// "section_phase", "position_m" and "velocity_mps" (the cell centres of each axis), "resolution",
/// "cell_transient", "cell_impacts", "attractors" ({index, kind: periodic|rest|no-period, period,
/// impacts_per_period, impact_phase, cells, fraction}), "inside_wall" (cells), "cell" (one array
/// per velocity row of attractor indices, -1 inside a wall), "inputs", "git_revision".
nlohmann::ordered_json to_json(const Rig& rig, const BasinsResult& result);

/// "hertzdash basins RIG: heading", the grid and each attractor with its share of the cells.
std::string basins_text(const Rig& rig, const BasinsResult& result);

/// One row per start (position_m, velocity_mps, attractor, period, impacts_per_period) below the
/// provenance, the attractors as comments.
CsvWriter basins_csv(const Rig& rig, const BasinsResult& result);

}  // namespace hertzdash
