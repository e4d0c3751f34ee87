#pragma once
// `hertzdash continue RIG`: the branches of a rig's periodic orbits in one of its numeric inputs
// (docs/orbits.md). The rig's orbit at `from` is found as `hertzdash orbit RIG` finds it
// (simulation/rigs/rig_orbit.hpp, its guess from the rig's own run at `from` or the given one),
// then followed towards `to` by pseudo-arclength continuation with its folds, period doublings
// (and their doubled branches), Neimark-Sacker points and grazings
// (simulation/orbits/continuation.hpp). The parameter is any number the rig's command takes: one
// of the rig's own inputs (gamma, frequency, force-amplitude, stop-distance, ...) or an option of
// its run (restitution, gravity, ...); refused: an integer count (impacts, transient), an input of
// the rig's run's start only (start-*, height), and restitution where it moves another input's
// default (the shaker without gamma or amplitude: gamma's default depends on e), which must then
// be given.
#include "hertzdash/simulation/orbits/continuation.hpp"
#include "hertzdash/simulation/rigs/rig_orbit.hpp"

#include <string>

namespace hertzdash {

struct ContinuationRequest {
  std::string parameter;
  double from = 0, to = 0;
  int max_points = 2000;
  OrbitRequest orbit;  ///< the first branch's start
};
/// The request of the options given by key (`continue`'s declarations, command_options.cpp);
/// InvalidParameter naming a key outside its range, a missing `parameter`, `from` or `to`, or
/// `from` equal to `to`.
ContinuationRequest continuation_request(const RigInputs& given);

struct ContinuationResult {
  std::span<const std::string_view> coordinates;  ///< the section state's (section_coordinates)
  std::string heading;     ///< the rig's
  Parameters inputs;       ///< the rig's run's at `from`, then the request's
  std::string parameter;   ///< the key continued in
  std::string column;      ///< its name with its unit, as a column ("force_amplitude_N", "gamma")
  OrbitStart start;        ///< where the first branch started
  std::string failure;     ///< empty: continued; else why no branch (no orbit at `from`)
  Continuation continuation;
};

/// The branches of `rig` (see above). InvalidParameter for bad input, including a parameter the
/// rig does not take or a value of it out of its range at `from` or `to`.
ContinuationResult run_continuation(const Rig& rig, const RunOptions& options, const PaperParameters& paper,
                                    const RigInputs& inputs, const ContinuationRequest& request);

}  // namespace hertzdash
