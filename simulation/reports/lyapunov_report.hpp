#pragma once
// What `hertzdash lyapunov RIG` and Python's hertzdash.lyapunov() print
// (simulation/rigs/rig_lyapunov.hpp, docs/orbits.md): the spectrum as JSON and as text.
#include "hertzdash/simulation/rigs/rig_lyapunov.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace hertzdash {

/// "schema_version", "rig", "method", "failure" (only where the run stopped or had no start),
/// "periods", "impacts", "section_phase", "exponents_per_period" and "exponents_per_impact"
/// (largest first), "sum_per_impact", "expected_sum_per_impact", "half_difference",
/// "converged", "running" {periods, exponents_per_impact: one array per running point},
/// "inputs", "git_revision".
nlohmann::ordered_json to_json(const Rig& rig, const LyapunovResult& result);

/// "hertzdash lyapunov RIG: heading" and the spectrum's lines.
std::string lyapunov_text(const Rig& rig, const LyapunovResult& result);

}  // namespace hertzdash
