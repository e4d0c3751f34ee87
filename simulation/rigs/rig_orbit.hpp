#pragma once
// `hertzdash orbit RIG`: a periodic orbit of a registered rig on the impact-sequence driver, its
// Floquet multipliers and its stability (docs/orbits.md). The rig's inputs are resolved and
// checked as its own run checks them (run_rig), its sequence taken from Rig::sequence; then
//   - the guess: the rig's own run (its transient and kept impacts, from its start) settles on an
//     attractor, whose period and impact phases give N and the section phase, and whose state
//     flowed to the section starts Newton (simulation/orbits/section_guess.hpp); or the given
//     guess-position and guess-velocity at the given section-phase (period default 1);
//   - shooting on the stroboscopic map over N cycles, with the monodromy from saltation matrices
//     (simulation/orbits/stroboscopic_map.hpp, periodic_orbit.hpp), in the rig's scales: its
//     speed scale v_s and v_s / f for the position.
// Instantaneous impacts of a prescribed box only (the shaker, the oscillator): soft contacts
// need the contact's variational equations, not yet built, and are refused naming `impact-model`.
#include "hertzdash/simulation/orbits/periodic_orbit.hpp"
#include "hertzdash/simulation/rigs/rig.hpp"

#include <optional>
#include <string>
#include <vector>

namespace hertzdash {

/// What to look for, from the declared options of `orbit` (options/command_options.cpp).
struct OrbitRequest {
  std::optional<int> period;
  std::optional<double> section_phase, guess_position_m, guess_velocity_mps;
  ShootingOptions shooting;
};
/// The request of the options given by key ("period", "section-phase", ...); InvalidParameter
/// naming a key outside its declared range, or a guess without its other half or its phase.
OrbitRequest orbit_request(const RigInputs& given);

/// The orbit found, or why not (orbit.converged false: the output stands, as a failed fit's).
struct OrbitResult {
  std::string heading;        ///< the rig's ("instantaneous impacts, e = 0.5")
  Parameters inputs;          ///< the rig's run's, then the request's
  std::string guess;          ///< where Newton started, in words
  int period = 0;             ///< drive cycles N
  double section_phase = 0;   ///< in [0, 1)
  Eigen::VectorXd scale;      ///< the state's scales, Newton's measure (position [m], velocity [m/s])
  PeriodicOrbit orbit;
};

/// The orbit of `rig` (see above). InvalidParameter for bad input, a rig without a sequence or
/// soft impacts; a guess the rig's run cannot give (no period, a sticking attractor) is a failure
/// in the result, not an exception.
OrbitResult run_orbit(const Rig& rig, const RunOptions& options, const PaperParameters& paper, const RigInputs& inputs,
                      const OrbitRequest& request);

}  // namespace hertzdash
