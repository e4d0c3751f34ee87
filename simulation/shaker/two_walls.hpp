#pragma once
// A body between two walls: a box of clearance `gap` (the body's free travel between floor and
// ceiling) along the vertical (gravity g >= 0 pulls the body toward the floor; g = 0 is a
// horizontal box). The box's floor is at X(t), its ceiling at X(t) + gap, the body at y(t)
// (floor contact at y = X, ceiling contact at y = X + gap). Two rigs:
//   - box: the box moves as X(t) = A sin(w t), the shaker's wall (simulation/shaker/shaker.hpp)
//     with a ceiling;
//   - damper: the impact damper (Masri and Caughey, J. Appl. Mech. 33 (1966) 586; Masri, J.
//     Acoust. Soc. Am. 45 (1969) 1111): the box is the primary mass M on a spring k with damping
//     ratio zeta, driven by F0 sin(w t), M X'' + c X' + k X = F0 sin(w t) (X from the static
//     equilibrium); between impacts X is the closed form of model/forced_oscillator.hpp.
// The sequence is run by the impact-sequence driver (simulation/shaker/impact_sequence.hpp: the
// body a free flight under gravity, y(t) = y0 + u0 (t - t0) - g (t - t0)^2 / 2, the box prescribed
// or the primary, the floor at X and the ceiling at X + gap), which states the next-impact search
// on both walls, the impacts (instantaneous: Newton's law with e, momentum conserved against the
// damper's primary, loss (1 - e^2) m M (V - u)^2 / (2 (m + M)); the same formulas on either
// wall), sticking, chatter and the energy account.
// Soft impacts (simulation/run/soft_contact.hpp):
//   - box rig: the harmonic wall (model/contact_environments.hpp) on the floor, and on the ceiling
//     the same wall with its signs reversed (sigma = -1): the overlap x = y - X - gap obeys
//     x'' = -g - X''(t) - F/m, the floor's x'' = g + X'' - F/m with g -> -g and A -> -A.
//   - damper: the contact force acts on body and primary, whose motion is integrated with
//     the contact (the sprung primary, model/contact_environments.hpp); the
//     closed form takes over from the primary's state at separation.
// Carried body: a rebound slower than stick_speed = 1e-6 (g + A w^2) T (box) or
// 1e-6 (g + |Q| w^2) T (damper; T = 1/f) leaves the body on that wall, carried while the wall
// pushes it: the floor while X'' >= -g, the ceiling while X'' <= -g. The damper's primary is then
// the oscillator of mass M + m under F0 sin(w t) - m g (the body's weight). As the gap shrinks
// with e -> 0 the body is carried nearly all the time: the damper tends to the oscillator of mass
// M + m.
// Start: the primary at rest at X = 0 (damper), the body at rest at mid-gap, at t = 0.
// Damper energy account (instantaneous impacts; NaN with soft ones): W - D - L = E(end) - E(0),
// E = M X'^2/2 + k X^2/2 + m u^2/2 + m g y (the driver's account).
#include "hertzdash/model/drop_test_setup.hpp"
#include "hertzdash/model/forced_oscillator.hpp"
#include "hertzdash/model/wall_motion.hpp"
#include "hertzdash/simulation/run/solver_settings.hpp"
#include "hertzdash/simulation/shaker/impact_sequence.hpp"
#include "hertzdash/simulation/shaker/shaker.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace hertzdash {

enum class TwoWallsRig { box, damper };
const char* to_string(TwoWallsRig r);
/// The rig spelled `name`; InvalidParameter("rig", ...) otherwise.
TwoWallsRig parse_two_walls_rig(std::string_view name);

struct TwoWallsOptions {
  TwoWallsRig rig = TwoWallsRig::box;
  double gap_m = 0.01;  ///< the body's free travel [m] > 0
  /// box: X(t) = A sin(w t); damper: only its frequency is read (the force's).
  HarmonicWallMotion drive;
  /// damper: the primary (its omega is set from drive.frequency_Hz by the run; its constant force is not read).
  ForcedOscillator primary;
  int impacts = 100;    ///< impacts kept and reported, >= 1
  int transient = 1000; ///< impacts run first and discarded, >= 0
  ShakerImpactModel impact_model = ShakerImpactModel::instantaneous;
  PatternTolerance pattern;  ///< its speed_scale_mps is set by the run when 0 (g / f, or the box's speed scale)
};

/// Throws InvalidParameter naming `gap`, `frequency`, `amplitude`, `primary-mass`,
/// `primary-stiffness`, `primary-damping-ratio`, `force-amplitude`, `impacts` or `transient`.
void validate(const TwoWallsOptions& o);

/// One kept impact. Speeds relative to the box, positive.
using TwoWallsImpact = SequenceImpact;

/// The driver's result (its `amplitude_m` the primary's, `energy` the damper's) and:
struct TwoWallsRun : ImpactSequence {
  TwoWallsRig rig = TwoWallsRig::box;
  ShakerImpactModel impact_model = ShakerImpactModel::instantaneous;
  double impacts_per_cycle = 0;                 ///< impacts_per_period / period (0: no pattern)
  long floor_impacts = 0, ceiling_impacts = 0;  ///< of the kept impacts
  /// damper: the primary's amplitude, (max X - min X)/2 over the kept window; NaN without one [m].
  double primary_amplitude_m = 0;
  double primary_amplitude_bare_m = 0;   ///< damper: |Q| of the primary alone (closed form) [m]
  double primary_amplitude_rigid_m = 0;  ///< damper: |Q| of mass M + m, the body carried (closed form) [m]
};

/// The run of the validated `setup` (its body mass m, contact, law inputs, e, gravity g >= 0; not
/// its height) with the law `law` (soft impacts) in the box of `options`.
/// The sequence of a run_two_walls() call, validated as it validates.
SequenceSetUp make_two_walls_sequence(const DropTestSetup& setup, std::string_view law, const SolverSettings& solver,
                                      const TwoWallsOptions& options);

TwoWallsRun run_two_walls(const DropTestSetup& setup, std::string_view law, const SolverSettings& solver,
                          const TwoWallsOptions& options);

}  // namespace hertzdash
