#pragma once
// A body bouncing on a harmonically vibrating wall (the shaker): the wall moves as
// s(t) = A sin(2 pi f t) (model/wall_motion.hpp), the body flies freely between impacts (exact
// parabolas; the next impact is the first root of the gap, simulation/shaker/impact_sequence.hpp),
// and each impact is either
//   - soft: the contact of the drop test's body and law, integrated with the wall's motion as a
//     forcing (model/contact_environments.hpp, simulation/run/soft_contact.hpp), or
//   - instantaneous: Newton's law at an instantaneous impact, relative rebound speed = e times
//     the relative impact speed, u+ = s' + e (s' - u-), the textbook bouncing-ball map (Holmes,
//     J. Sound Vib. 84 (1982) 173; Luck and Mehta, Phys. Rev. E 48 (1993) 3988; Tufillaro,
//     Abbott and Reilly 1992, ch. 3), with e = the set-up's restitution,
// through the same code and outputs, so that a result can be shown with and without the
// contact's duration.
//
// Start: the body released from rest at height h0 above the wall's mean position at the table
// phase phi0 (time phi0 / f). Default: where Gamma >= pi (1 - e)/(1 + e), the apex of the
// instantaneous map's period-1 orbit for the set-up's e (phi0 = theta*/(2 pi) + 1/2,
// h0 = A sin theta* + g T^2 / 8, cos theta* = pi (1 - e)/(Gamma (1 + e)), T = 1/f; docs/shaker.md),
// else phi0 = 0, h0 = A + g T^2 / 8. h0 = 0 (with any phase) puts the body at rest on the wall,
// carried until the wall first pulls away from it. Where attractors coexist (for e = 0.5 a
// chattering, sticking orbit beside the bouncing ones) the start picks one.
// The sequence is run by the impact-sequence driver (simulation/shaker/impact_sequence.hpp: the
// flight a free body under gravity, the box the prescribed wall, one wall, the floor).
// Sticking: a body whose relative rebound speed (instantaneous) or impact speed (soft) falls
// below stick_speed = 1e-6 g/f rests on the wall and is carried while the wall pushes it
// (s'' > -g), until the wall's acceleration falls below -g (sin(w t) >= 1/Gamma), then released
// with the wall's velocity: the end of a chatter sequence (impacts accumulating in finite time,
// each rebound e times the last) or of a contact that does not rebound. Never more than
// max_impacts_per_cycle impacts in one table cycle (more is chatter the threshold did not stop:
// the body is carried, with a warning); a body that cannot leave the wall (Gamma <= 1) ends the
// run with a warning. The soft model's resting contact is approximated by the rigid carry (its
// static deformation, (m (g + s'')/K)^{2/3}, is left out).
#include "hertzdash/model/drop_test_setup.hpp"
#include "hertzdash/model/wall_motion.hpp"
#include "hertzdash/simulation/run/solver_settings.hpp"
#include "hertzdash/simulation/shaker/impact_sequence.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hertzdash {

struct ShakerOptions {
  HarmonicWallMotion wall;
  int impacts = 100;    ///< impacts kept and reported, >= 1
  int transient = 1000; ///< impacts run first and discarded, >= 0
  ShakerImpactModel impact_model = ShakerImpactModel::soft;
  std::optional<double> start_height_m;  ///< h0 [m] >= 0 (see above); unset: the default above
  std::optional<double> start_phase;     ///< phi0 in [0, 1) (see above); unset: the default above
  PatternTolerance pattern;  ///< its speed_scale_mps is set to g / f by the run when 0
};

/// Throws InvalidParameter naming `frequency`, `amplitude`, `impacts`, `transient`, `height` or
/// `start-phase`.
void validate(const ShakerOptions& o);

/// One kept impact (its wall always the floor). Speeds relative to the wall, positive.
using ShakerImpact = SequenceImpact;

/// The driver's result (its energy and sampled amplitude not kept) and:
struct ShakerRun : ImpactSequence {
  double gamma = 0;  ///< A (2 pi f)^2 / g
  ShakerImpactModel impact_model = ShakerImpactModel::soft;
};

/// The start (h0 [m], phi0) of `options` for restitution e and gravity g (see above).
struct ShakerStart {
  double height_m, phase;
};
ShakerStart shaker_start(const ShakerOptions& options, double e, double gravity_mps2);

/// The sequence of a run_shaker() call, validated as it validates.
SequenceSetUp make_shaker_sequence(const DropTestSetup& setup, std::string_view law, const SolverSettings& solver,
                                    const ShakerOptions& options);

/// The run of the validated `setup` (its body, contact, law inputs, restitution e and gravity
/// g > 0; its drop height is not read) with the registered law `law` (soft model) on the wall
/// of `options`.
ShakerRun run_shaker(const DropTestSetup& setup, std::string_view law, const SolverSettings& solver,
                     const ShakerOptions& options);

}  // namespace hertzdash
