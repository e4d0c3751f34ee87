#pragma once
// The rig `walls` (simulation/shaker/two_walls.hpp, docs/shaker.md): a body between two walls of
// a harmonically driven box (`rig` box) or of the impact damper's primary (`rig` damper), the drop
// test's body, contact, law and e, soft or instantaneous impacts, exact flights. Its inputs are
// model/two_walls_parameters.hpp's and the shaker's frequency, amplitude or gamma, impact counts
// and impact model (model/shaker_parameters.hpp).
#include "hertzdash/simulation/rigs/rig.hpp"

namespace hertzdash {

/// The rig `walls`: results rig, gap_m, frequency_Hz, amplitude_m and gamma (box; gamma null with
/// g = 0), impact_model, damping, integrator_used (soft), period, impacts_per_period,
/// impacts_per_cycle, floor_impacts, ceiling_impacts, e_effective, damper: primary_amplitude_m,
/// primary_amplitude_bare_m, primary_amplitude_rigid_m, and with instantaneous impacts energy_J
/// {initial, final, drive_work, damping_dissipation, impact_loss}; sticking_episodes,
/// impacts_run; one table row per kept impact: impact_time_s, impact_phase, wall (floor,
/// ceiling), impact_speed_mps, rebound_speed_mps, contact_time_s, peak_force_N, box_displacement_m.
const Rig& walls_rig();

}  // namespace hertzdash
