#pragma once
// What `hertzdash orbit RIG` and Python's hertzdash.orbit() print (simulation/rigs/rig_orbit.hpp,
// docs/orbits.md): the orbit as JSON and as text.
#include "hertzdash/simulation/rigs/rig_orbit.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace hertzdash {

/// "schema_version", "rig", "method", "converged" (and "failure" where not), "period",
/// "impacts_per_period", "section_phase", "section_state" {position_m, velocity_mps},
/// "multipliers" [[re, im], ...] largest modulus first, "multiplier_moduli", "stable",
/// "newton_residual", "newton_iterations", "min_impact_speed_mps", "guess", the orbit's impacts
/// over its period as arrays ("impact_time_s", "impact_phase", "impact_speed_mps",
/// "rebound_speed_mps"), "inputs", "git_revision".
nlohmann::ordered_json to_json(const Rig& rig, const OrbitResult& result);

/// "hertzdash orbit RIG: heading", the orbit's lines and its impacts, or the failure.
std::string orbit_text(const Rig& rig, const OrbitResult& result);

}  // namespace hertzdash
