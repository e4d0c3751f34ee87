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
// Flights are exact: y(t) = y0 + u0 (t - t0) - g (t - t0)^2 / 2. The next impact is the first
// root of either gap, h_floor = y - X and h_ceiling = X + gap - y, each found by the shaker's
// safe bracketing (simulation/shaker/safe_root.hpp) with |h''| <= g + |X''|max, where
// |X''(t)| <= |Z| wn^2 + |Q| w^2 for every t after the flight's start (model/forced_oscillator.hpp;
// A w^2 for the driven box): every point each search passes is certified free of a root of its
// own gap, so the earlier of the two first roots (the ceiling's searched only up to the floor's)
// is the first impact on either wall, and no grazing impact on either is missed. The search runs
// span by span (100 drive cycles each) and gives up, with a warning, after 10000 cycles of flight.
// Impacts:
//   - instantaneous, Newton's law with e at relative speed v_r = V - u (the box's velocity V,
//     the body's u): box rig, the box's motion prescribed, u+ = V + e (V - u) (the shaker's map);
//     damper, momentum conserved, m u + M V = m u+ + M V+, and u+ - V+ = -e (u - V):
//       u+ = u + M (1 + e)(V - u)/(m + M),   V+ = V - m (1 + e)(V - u)/(m + M),
//     loss (1 - e^2) m M (V - u)^2 / (2 (m + M)); the same formulas on either wall.
//   - soft, box rig: the harmonic wall (model/contact_environments.hpp) on the floor, and on
//     the ceiling the same wall with its signs reversed (sigma = -1): the overlap x = y - X - gap obeys
//     x'' = -g - X''(t) - F/m, the floor's x'' = g + X'' - F/m with g -> -g and A -> -A.
//   - soft, damper: the contact force acts on body and primary, whose motion is integrated with
//     the contact (the sprung primary, model/contact_environments.hpp); the
//     closed form takes over from the primary's state at separation.
// Carried body: a rebound slower than stick_speed = 1e-6 (g + A w^2) T (box) or
// 1e-6 (g + |Q| w^2) T (damper; T = 1/f), or more than max_impacts_per_cycle impacts in one
// drive cycle (chatter, with a warning), leaves the body on that wall, carried while the wall
// pushes it: the floor while X'' >= -g, the ceiling while X'' <= -g. A carried body moves with the
// box; the damper's primary is then the oscillator of mass M + m under F0 sin(w t) - m g (the
// body's weight), entered with the momentum-conserving common velocity. The body leaves where
// the contact force m (X'' + g) changes sign (a safe root of X'' + g, |d^2/dt^2 (X'' + g)| <=
// |X''''|max), and the search for the next impact on that wall starts where X'' + g changes
// sign again (before it the gap's h'' > 0 keeps the body clear of it). As the gap shrinks with
// e -> 0 the body is carried nearly all the time: the damper tends to the oscillator of mass M + m.
// Start: the primary at rest at X = 0 (damper), the body at rest at mid-gap, at t = 0.
// Damper energy account (instantaneous impacts; NaN with soft ones): the drive's work W = int F0 sin(w t) X' dt and
// the primary's damping D = int c X'^2 dt over every flight and carry (8-point Gauss-Legendre on
// pieces of at most 1/16 of the shorter of the drive's and the primary's periods), and the impact
// losses L, so that W - D - L = E(end) - E(0), E = M X'^2/2 + k X^2/2 + m u^2/2 + m g y.
#include "hertzdash/model/drop_test_setup.hpp"
#include "hertzdash/model/forced_oscillator.hpp"
#include "hertzdash/model/wall_motion.hpp"
#include "hertzdash/ode/ode_system.hpp"
#include "hertzdash/simulation/run/solver_settings.hpp"
#include "hertzdash/simulation/shaker/impact_pattern.hpp"
#include "hertzdash/simulation/shaker/shaker.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace hertzdash {

enum class TwoWallsRig { box, damper };
const char* to_string(TwoWallsRig r);
/// The rig spelled `name`; InvalidParameter("rig", ...) otherwise.
TwoWallsRig parse_two_walls_rig(std::string_view name);

enum class Wall : int { floor = 0, ceiling = 1 };
const char* to_string(Wall w);

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
struct TwoWallsImpact {
  double time_s = 0;
  double phase = 0;  ///< of the drive, in [0, 1)
  Wall wall = Wall::floor;
  double impact_speed_mps = 0, rebound_speed_mps = 0;
  double contact_time_s = 0, peak_force_N = 0;  ///< 0 for instantaneous impacts
  double box_displacement_m = 0;                ///< X at the impact [m]
};

/// The damper's energy account over the run (see the header) [J].
struct EnergyAccount {
  double initial_J = 0, final_J = 0, drive_work_J = 0, damping_dissipation_J = 0, impact_loss_J = 0;
};

struct TwoWallsRun {
  TwoWallsRig rig = TwoWallsRig::box;
  ShakerImpactModel impact_model = ShakerImpactModel::instantaneous;
  std::vector<TwoWallsImpact> impacts;  ///< the kept impacts
  ImpactPattern pattern;                ///< period (drive cycles) and impacts per period of the kept impacts
  double impacts_per_cycle = 0;         ///< impacts_per_period / period (0: no pattern)
  long floor_impacts = 0, ceiling_impacts = 0;  ///< of the kept impacts
  double e_effective = 0;               ///< mean rebound/impact speed of the kept impacts (NaN: none)
  long impacts_run = 0;
  long sticking_episodes = 0;           ///< times the body was carried by a wall
  /// damper: the primary's amplitude, (max X - min X)/2 over the kept window (from the first to
  /// the last kept impact; X at its extremes, the roots of X' located between samples 64 times a
  /// cycle, and at every impact's onset and end; not within soft contacts) [m]; NaN without one.
  double primary_amplitude_m = 0;
  double primary_amplitude_bare_m = 0;   ///< damper: |Q| of the primary alone (closed form) [m]
  double primary_amplitude_rigid_m = 0;  ///< damper: |Q| of mass M + m, the body carried (closed form) [m]
  EnergyAccount energy;                  ///< damper, instantaneous impacts (NaN: soft impacts)
  double end_time_s = 0;
  std::vector<std::string> warnings;
  std::string end_reason;
  IntegratorKind integrator_used = IntegratorKind::gbs8_regularized;  ///< soft impacts only
  IntegrationStats work;
};

/// The run of the validated `setup` (its body mass m, contact, law inputs, e, gravity g >= 0; not
/// its height) with the law `law` (soft impacts) in the box of `options`.
TwoWallsRun run_two_walls(const DropTestSetup& setup, std::string_view law, const SolverSettings& solver,
                          const TwoWallsOptions& options);

}  // namespace hertzdash
