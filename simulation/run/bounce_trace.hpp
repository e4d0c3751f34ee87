#pragma once
// The time series of a rigid-model bounce sequence (`hertzdash bounce --trace`): every impact's
// contact phase at the integrator's steps and every flight between them sampled in closed form,
// on the sequence's clock. The contact phases are the sequence's own impacts run again with the
// trace recorded: the same set-up, approach speed, law and solver give the same steps
// (tests/test_bounce_trace.cpp checks the onsets and peak forces against the sequence's).
// The elastic rod's flights are integrated with the rod ringing, which a re-run of each impact
// would not reproduce: its sequence has no trace (InvalidParameter).
#include "hertzdash/model/drop_test_setup.hpp"
#include "hertzdash/simulation/run/bounce_sequence.hpp"
#include "hertzdash/simulation/run/impact_summary.hpp"
#include "hertzdash/simulation/run/solver_settings.hpp"

#include <string_view>
#include <vector>

namespace hertzdash {

/// Samples of each flight, evenly spaced in time between a separation and the next onset.
inline constexpr int bounce_flight_samples = 100;

/// The trace of `sequence`, run by run_bounce_sequence(setup, law, solver, ...): contact phases
/// and flights in time order, t_s from the release (as the sequence's onset times), x_m < 0 in
/// flight (the gap), rod displacement from the release. Ends at the last separation (or the last
/// sample of a contact that did not separate). Throws InvalidParameter("rod-model", ...) for the
/// elastic rod.
std::vector<TraceSample> bounce_trace(const BounceSequence& sequence, const DropTestSetup& setup,
                                      std::string_view law, const SolverSettings& solver);

}  // namespace hertzdash
