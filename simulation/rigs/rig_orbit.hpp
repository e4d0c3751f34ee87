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
// A prescribed box only (the shaker, the walls' driven box, the oscillator). Impacts instantaneous
// (the default of `orbit`, `continue` and `lyapunov`: saltation matrices) or soft (the contacts'
// variational equations, simulation/run/soft_contact_tangent.hpp), the latter with a law that
// declares dF/dv0, else refused naming `damping`.
#include "hertzdash/simulation/orbits/periodic_orbit.hpp"
#include "hertzdash/simulation/rigs/rig.hpp"

#include <optional>
#include <string>
#include <vector>

namespace hertzdash {

/// The impact model `orbit` and `continue` default to, and the help of `impact-model` there.
inline constexpr std::string_view orbit_impact_model = "instantaneous";
inline constexpr RigOptionNote orbit_impact_model_note{
    "impact-model", "Impact model: instantaneous, or soft (a law that declares dF/dv0; the soft options are "
                    "those of the rig's own command; docs/orbits.md) (default: instantaneous)"};

/// What to look for, from the declared options of `orbit` (options/command_options.cpp).
struct OrbitRequest {
  std::optional<int> period;
  std::optional<double> section_phase, guess_position_m, guess_velocity_mps;
  std::optional<double> guess_box_position_m, guess_box_velocity_mps;  ///< a box of its own's
  ShootingOptions shooting;
};
/// The request of the options given by key ("period", "section-phase", ...); InvalidParameter
/// naming a key outside its declared range, or a guess without its other half or its phase.
OrbitRequest orbit_request(const RigInputs& given);

/// Where Newton starts (see above): the period, section phase and state, or why there is none.
struct OrbitStart {
  int period = 0;
  double section_phase = 0;
  Eigen::VectorXd state;
  std::string guess;    ///< where it comes from, in words
  std::string failure;  ///< empty: a start
};
/// The start for the sequence `spec` and `request`; InvalidParameter naming a guess's half that
/// the box (of its own or not) wants or does not take.
OrbitStart orbit_start(const ImpactSequenceSpec& spec, const OrbitRequest& request);
/// The scales of the rig's state: v_s / f for a position [m], v_s for a velocity [m/s]; the box's
/// (a box of its own) as the body's.
Eigen::VectorXd orbit_scales(const ImpactSequenceSpec& spec);
/// The rig's sequence from validated inputs, refused (InvalidParameter) where `orbit` and
/// `continue` cannot take it: a rig without one, soft impacts of a law without dF/dv0, a box of its own.
RigSequence orbit_sequence(const Rig& rig, const RunOptions& options, const PaperParameters& paper, const RigInputs& inputs);

/// The orbit found, or why not (orbit.converged false: the output stands, as a failed fit's).
struct OrbitResult {
  std::span<const std::string_view> coordinates;  ///< the section state's (section_coordinates)
  std::string heading;        ///< the rig's ("instantaneous impacts, e = 0.5")
  Parameters inputs;          ///< the rig's run's, then the request's
  std::string method;         ///< how the monodromy is computed (monodromy_method)
  std::string guess;          ///< where Newton started, in words
  int period = 0;             ///< drive cycles N
  double section_phase = 0;   ///< in [0, 1)
  Eigen::VectorXd scale;      ///< the state's scales, Newton's measure (position [m], velocity [m/s])
  PeriodicOrbit orbit;
};

/// The orbit of `rig` (see above). InvalidParameter for bad input, a rig without a sequence or
/// a soft law without dF/dv0; a guess the rig's run cannot give (no period, a sticking attractor) is a failure
/// in the result, not an exception.
OrbitResult run_orbit(const Rig& rig, const RunOptions& options, const PaperParameters& paper, const RigInputs& inputs,
                      const OrbitRequest& request);

}  // namespace hertzdash
