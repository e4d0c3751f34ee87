#pragma once
// What `hertzdash walls` computes and reports (simulation/shaker/two_walls.hpp): a body between
// two walls of a harmonically driven box or of the impact damper's primary, resolved from the
// drop test's options (body, contact, law, e, solver), the shaker's (frequency, amplitude or
// gamma, impact counts, impact model: model/shaker_parameters.hpp) and the two walls' own
// (model/two_walls_parameters.hpp); its JSON.
#include "hertzdash/io/provenance.hpp"
#include "hertzdash/simulation/options/run_options.hpp"
#include "hertzdash/simulation/shaker/two_walls.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace hertzdash {

/// The options as given (unset: the declaration's default).
struct TwoWallsInputs {
  std::optional<double> frequency_Hz, amplitude_m, gamma, impacts, transient;
  std::optional<double> gap_m, primary_mass_kg, primary_stiffness_N_per_m, primary_damping_ratio, force_amplitude_N;
  std::optional<std::string> rig, impact_model;
};

struct TwoWallsCommandRun {
  DropTestSetup setup;
  std::string law;
  SolverSettings solver;
  TwoWallsOptions options;
  Parameters inputs;  ///< describe_run() and the two walls' options
  TwoWallsRun run;
};

/// Resolve, validate and run. InvalidParameter for bad options: `amplitude` with `gamma`,
/// `gamma` with gravity 0, the box's options with `rig` damper and the primary's with `rig` box,
/// `height` or `impact-velocity` (the body starts at rest at mid-gap), a non-integer count.
TwoWallsCommandRun run_two_walls_command(const RunOptions& options, const PaperParameters& paper,
                                         const TwoWallsInputs& inputs);

/// `walls --json`: "rig", "gap_m", "frequency_Hz", "amplitude_m" and "gamma" (box; gamma null
/// with g = 0), "impact_model", "damping", "integrator_used" (soft), "period",
/// "impacts_per_period", "impacts_per_cycle", "floor_impacts", "ceiling_impacts", "e_effective",
/// damper: "primary_amplitude_m", "primary_amplitude_bare_m", "primary_amplitude_rigid_m", and
/// with instantaneous impacts "energy_J" {initial, final, drive_work, damping_dissipation,
/// impact_loss}; the kept impacts as
/// arrays "impact_time_s", "impact_phase", "wall", "impact_speed_mps", "rebound_speed_mps",
/// "contact_time_s", "peak_force_N", "box_displacement_m"; "sticking_episodes", "impacts_run",
/// "end_reason", "warnings", "work" (soft), "inputs", "git_revision", "schema_version".
nlohmann::ordered_json to_json(const TwoWallsCommandRun& run);

}  // namespace hertzdash
