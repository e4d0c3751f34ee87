#pragma once
// The soft contacts of a rig whose walls move as prescribed (the shaker's table, the driven box's
// floor and ceiling, the oscillator's stop): each contact runs in the environment the rig gives
// for its wall and onset time (HarmonicForcing, model/contact_environments.hpp).
#include "hertzdash/model/drop_test_setup.hpp"
#include "hertzdash/simulation/run/solver_settings.hpp"
#include "hertzdash/simulation/shaker/impact_sequence.hpp"

#include <functional>
#include <string_view>

namespace hertzdash {

/// The environment of wall `wall` for a contact beginning at t_onset [s].
using HarmonicEnvironment = std::function<HarmonicForcing(Wall wall, double t_onset_s)>;

/// Soft impacts for `out`: the sequence's contacts of law `law` on `setup` (spec.soft, sharing the
/// contact's ownership), the same contacts with their tangents (spec.soft_tangent, empty for a law
/// without dF/dv0), the integrator they use and the speed at which the Hertz model ends.
/// `command` names the caller in refusals (make_soft_contact).
void set_harmonic_soft_contacts(SequenceSetUp& out, std::string_view law, const DropTestSetup& setup,
                                const SolverSettings& solver, std::string_view command, HarmonicEnvironment environment);

}  // namespace hertzdash
