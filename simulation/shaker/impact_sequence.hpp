#pragma once
// One impact-sequence driver for every rig whose body flies between impacts: the shaker (a body
// on a vibrating wall, simulation/shaker/shaker.hpp), the driven box and the impact damper (a
// body between two walls, two_walls.hpp) and the impact oscillator with a stop
// (simulation/rigs/oscillator_rig.hpp).
// A rig describes two bodies and the walls, and the driver runs the sequence:
//   - the body, mass m, a linear oscillator m y'' + c y' + k y = F0 sin(w t + phi) + Fc (k = 0: a
//     free flight, gravity Fc = -m g; the oscillator: its spring, dashpot and drive);
//   - the box that carries the walls, X(t): prescribed (the shaker's and the driven box's
//     A sin(w t), the oscillator's stop at rest) or itself an oscillator of mass M (the damper's
//     primary), changed by the impacts;
//   - one or two walls, wall j at y = X + offset_j, the body on the side sigma_j (+1: above it, a
//     floor; -1: below it, a ceiling or a stop), the gap h_j = sigma_j (y - X - offset_j) >= 0.
// Flights are exact: both bodies in closed form (model/forced_oscillator.hpp), from their state
// after each impact. The next impact is the earliest first root of the gaps, each found by safe
// bracketing (simulation/shaker/safe_root.hpp) with |h_j''| <= |y''|max + |X''|max, the bounds of
// the closed forms for every t after the flight's start: every point a search passes is certified
// free of a root of its own gap (the later walls searched only up to an earlier wall's root), so no
// impact, grazing ones included, is missed. The search runs span by span (100 drive cycles plus 4
// of the longest natural period) and gives up, with a warning, after 10000 cycles of flight.
// Impacts, at relative speed v = sigma (V - u) (the box's velocity V, the body's u):
//   - instantaneous, Newton's law with e: a prescribed box, u+ = V + e (V - u) (the bouncing-ball
//     map; v+ = -e v- at a stop at rest); a box of mass M, momentum conserved,
//       u+ = u + M (1 + e)(V - u)/(m + M),   V+ = V - m (1 + e)(V - u)/(m + M),
//     loss (1 - e^2) mu (V - u)^2 / 2, mu = m M / (m + M) (mu = m for a prescribed box);
//   - soft: a contact run the rig gives (any law, any integrator in regularising variables), which
//     returns the rebound, the contact time, the peak force and, for a box of mass M, its state at
//     separation, from which the closed forms take over.
// Carried body: a rebound slower than stick_speed = 1e-6 of the rig's speed scale, or more than
// max_impacts_per_cycle impacts in one drive cycle (chatter, with a warning), leaves the body on
// that wall, carried while the wall pushes it: while sigma N >= 0, N = m X'' + c X' + k (X +
// offset) - F0 sin(w t + phi) - Fc the force the wall exerts on the body moving with it (N =
// m (X'' + g) for a flight). A carried body moves with the box; a box of mass M then moves as the
// oscillator of both (model/forced_oscillator.hpp, carrying()), entered with the momentum-
// conserving common velocity. The body leaves where N changes sign (a safe root, |N''| bounded by
// the closed forms' bounds), and the search for the next impact on that wall starts where the gap's
// h'' = sigma (y'' - X'') changes sign (before it h = h' = 0 and h'' >= 0 keep the body clear).
// End: after `transient` plus `impacts` impacts, or at `end_time_s` if set (the state then, in
// flight or carried, is the result's end state: the stroboscopic map of simulation/orbits/).
// Kept window: the impacts after the first `transient`, from the transient-th impact (the start if
// transient = 0) to the end of the run. Its period: simulation/shaker/impact_pattern.hpp.
// Energy account (a box of mass M or at rest; instantaneous impacts; NaN with soft ones): the drive's
// work W = int F0 sin(w t + phi) v dt and the dashpots' dissipation D = int c v^2 dt of each body,
// over every flight and carry (8-point Gauss-Legendre on pieces of at most 1/16 of the shorter of
// the drive's and the natural periods), and the impact losses L (the joining of a carried body
// included), so that W - D - L = E(end) - E(0), E the sum of M v^2/2 + k x^2/2 - Fc x.
// Sampled coordinate (the damper's primary X, the oscillator's body y): its extremes over the
// kept window, X at the roots of X' located between samples 64 times a drive cycle and at every
// impact's onset and end (not within soft contacts).
#include "hertzdash/model/forced_oscillator.hpp"
#include "hertzdash/ode/ode_system.hpp"
#include "hertzdash/simulation/run/soft_contact.hpp"
#include "hertzdash/simulation/run/soft_contact_tangent.hpp"
#include "hertzdash/simulation/run/solver_settings.hpp"
#include "hertzdash/simulation/shaker/impact_pattern.hpp"

#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hertzdash {

enum class ShakerImpactModel { soft, instantaneous };
/// "soft" or "instantaneous".
const char* to_string(ShakerImpactModel m);
/// The model spelled `name`; InvalidParameter("impact-model", ...) otherwise.
ShakerImpactModel parse_shaker_impact_model(std::string_view name);

/// How long a soft contact is followed [drive cycles]: one that lasts longer ends the run (the
/// sequence's) or fails the map's image (simulation/orbits/stroboscopic_map.cpp).
inline constexpr double soft_contact_window_cycles = 2;
/// That window [s] for a drive of frequency f [Hz].
inline double soft_contact_window_s(double frequency_Hz) { return soft_contact_window_cycles / frequency_Hz; }
/// The most impacts one drive cycle may hold before the body is taken as carried (chatter).
inline constexpr int max_impacts_per_cycle = 10000;
/// The most impacts (transient plus kept) of one run.
inline constexpr int max_shaker_impacts = 10000000;
/// Throws InvalidParameter naming `impacts` (in [1, max_shaker_impacts]) or `transient`.
void validate_impact_counts(int impacts, int transient);

/// A wall of the rig (see above); the first is Wall::floor in the impacts, the second Wall::ceiling.
enum class Wall : int { floor = 0, ceiling = 1 };
const char* to_string(Wall w);
struct SequenceWall {
  const char* name = "wall";  ///< in warnings
  double sigma = 1;           ///< +1: the body above it; -1: below it
  double offset_m = 0;        ///< its position on the box [m]
};

/// What one soft contact gave.
struct SoftImpact {
  bool separated = false;        ///< false: still in contact at the observation time
  double contact_time_s = 0;     ///< onset to separation [s]
  double rebound_speed_mps = 0;  ///< the relative speed at separation, away from the wall [m/s]
  double peak_force_N = 0;
  double X_m = 0, V_mps = 0;  ///< a box of mass M: its state at separation
  IntegrationStats work;
  double hertz_speed_limit_mps = std::numeric_limits<double>::infinity();  ///< where the contact model ends (SoftContactOutcome) [m/s]
};
/// One soft contact's outcome (simulation/run/soft_contact.hpp) as the sequence takes it (a box's
/// state at separation is the caller's to set).
template <class Env> SoftImpact soft_impact(const SoftContactOutcome<Env>& c) {
  return SoftImpact{.separated = c.separated, .contact_time_s = c.contact_time_s,
                    .rebound_speed_mps = c.rebound_speed_mps, .peak_force_N = c.peak_force_N, .work = c.work,
                    .hertz_speed_limit_mps = c.hertz_speed_limit_mps};
}
/// The contact with wall `wall` beginning at t_onset [s] at relative speed v0 > 0 [m/s], the box at
/// X [m], V [m/s], followed for at most t_obs [s].
using SoftImpactRun =
    std::function<SoftImpact(Wall wall, double t_onset_s, double v0_mps, double X_m, double V_mps, double t_obs_s)>;

/// The soft contact with wall `wall` beginning at t_onset [s] at relative speed v0 > 0 [m/s], a box
/// of its own at X [m], V [m/s] (a prescribed box ignores them), and its derivatives with respect
/// to (t_onset, v0) and a box of its own's (X, V) (simulation/run/soft_contact_tangent.hpp): what
/// simulation/orbits/ needs for a soft orbit's monodromy.
using SoftTangentRun =
    std::function<ContactTangent(Wall wall, double t_onset_s, double v0_mps, double X_m, double V_mps, double t_obs_s)>;

/// A rig's sequence (see above). The oscillators' w is the drive's.
struct ImpactSequenceSpec {
  ForcedOscillator body{};                      ///< mass m > 0
  std::optional<OscillatorMotion> prescribed{}; ///< the box's motion if prescribed, else:
  ForcedOscillator box{};                       ///< the box as an oscillator of mass M (X0, V0 at t0)
  std::vector<SequenceWall> walls{};            ///< one or two
  double frequency_Hz = 1;                    ///< the drive's: phases, cycles, the pattern
  double speed_scale_mps = 1;  ///< stick_speed is 1e-6 of it; the pattern's speed scale if it has none
  double t0_s = 0, y0_m = 0, u0_mps = 0, X0_m = 0, V0_mps = 0;  ///< the start: in flight at (y0, u0), or
  int carried_by = -1;                                         ///< >= 0: carried by that wall
  int impacts = 100, transient = 1000;
  std::optional<double> end_time_s{};  ///< set: the run also ends there [s] (> t0)
  double restitution = 1;   ///< instantaneous impacts' e
  SoftImpactRun soft{};    ///< set: soft impacts
  /// Soft impacts: the same contacts with their tangents, for simulation/orbits/ (the driver does
  /// not read it); empty for a law without dF/dv0.
  SoftTangentRun soft_tangent{};
  /// Soft impacts: the speed at which the undamped Hertz deformation reaches the ball radius
  /// (HertzScale::speed_at_bound_mps of a valid set-up) [m/s]; impacts at or beyond it are counted
  /// in the warning, touches too slow for a contact run (below stick_speed) included.
  double hertz_speed_limit_mps = std::numeric_limits<double>::infinity();
  PatternTolerance pattern{};
  bool energy = false;      ///< keep the energy account (a box of mass M or at rest)
  enum class Sampled { none, box, body } sampled = Sampled::none;
};

/// One kept impact. Speeds relative to the box, positive.
struct SequenceImpact {
  double time_s = 0;
  double phase = 0;  ///< of the drive, in [0, 1)
  Wall wall = Wall::floor;
  double impact_speed_mps = 0, rebound_speed_mps = 0;
  double contact_time_s = 0, peak_force_N = 0;  ///< 0 for instantaneous impacts
  double box_displacement_m = 0;                ///< X at the impact [m]
};

/// The energy account over the run (see above) [J].
struct EnergyAccount {
  double initial_J = 0, final_J = 0, drive_work_J = 0, damping_dissipation_J = 0, impact_loss_J = 0;
};

/// A run's result: the fields every rig reports.
struct ImpactSequence {
  std::vector<SequenceImpact> impacts;  ///< the kept impacts
  ImpactPattern pattern;                ///< period (drive cycles) and impacts per period of the kept impacts
  double e_effective = 0;               ///< mean rebound/impact speed ratio of the kept impacts (NaN: none)
  long impacts_run = 0;                 ///< transient and kept
  long sticking_episodes = 0;           ///< times the body was carried by a wall (a carried start included)
  double amplitude_m = 0;  ///< the sampled coordinate's (max - min)/2 over the kept window [m] (NaN: none)
  double peak_phase = 0;   ///< the drive phase of its maximum (NaN: none)
  EnergyAccount energy;    ///< zero without an account, NaN with soft impacts
  double end_time_s = 0;
  double end_position_m = 0, end_velocity_mps = 0;  ///< the body's state at end_time_s
  double end_box_position_m = 0, end_box_velocity_mps = 0;  ///< the box's, X and V, at end_time_s
  bool end_carried = false;                         ///< the body was on a wall at end_time_s
  std::vector<std::string> warnings;  ///< chatter caps, a body that never leaves, a flight without impact
  std::string end_reason;
  IntegratorKind integrator_used = IntegratorKind::gbs8_regularized;  ///< soft impacts only
  IntegrationStats work;                                              ///< every soft contact
};

ImpactSequence run_impact_sequence(const ImpactSequenceSpec& spec);

/// A rig's sequence and, with soft impacts, the integrator its contacts use. The spec's
/// soft-contact callback shares ownership of its contact, so a copy of the spec outlives the
/// function that made it (simulation/orbits/ runs one many times); copies share that contact and
/// must not run at the same time.
struct SequenceSetUp {
  ImpactSequenceSpec spec;
  std::optional<IntegratorKind> integrator_used;
};

}  // namespace hertzdash
