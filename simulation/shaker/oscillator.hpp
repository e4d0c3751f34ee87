#pragma once
// The impact oscillator with a stop: the drop test's body, mass m, on a spring k with a dashpot
// c = 2 zeta sqrt(k m), driven by F cos(w t), w = 2 pi f, against a stop at x = d > 0,
//   m x'' + c x' + k x = F cos(w t)   (x < d),
// each impact on the stop instantaneous, v+ = -e v- (Newton's law, e the set-up's restitution),
// or soft, the contact of the drop test's body and law. A rig on the impact-sequence driver
// (simulation/shaker/impact_sequence.hpp: the body its oscillator, F cos(w t) = F sin(w t + pi/2),
// the box a wall at rest, the stop a wall at offset d the body meets from below); between impacts
// x is the closed form of model/forced_oscillator.hpp. Without the stop the steady response is
//   x = |X| cos(w t - psi),   |X| = (F / k) / sqrt((1 - r^2)^2 + (2 zeta r)^2),
//   tan psi = 2 zeta r / (1 - r^2),   r = w / wn,   wn = sqrt(k / m)
// (Den Hartog, Mechanical Vibrations, 1956, sec. 2.5), so the body reaches the stop once d < |X|
// (or earlier, in the transient from the start). A body left at rest on the stop (a rebound
// slower than 1e-6 (F + k d) / (m f), or chatter) stays there while F cos(w t) >= k d.
// Start: x0, v0 at t = 0 (at rest at x = 0 by default). Reported besides the impacts: the body's
// amplitude (max x - min x)/2 and the drive phase of max x over the kept window, and the energy
// account W - D - L = E(end) - E(0), E = m v^2/2 + k x^2/2 (the driver's).
#include "hertzdash/model/drop_test_setup.hpp"
#include "hertzdash/simulation/run/solver_settings.hpp"
#include "hertzdash/simulation/shaker/impact_sequence.hpp"

#include <string_view>

namespace hertzdash {

struct OscillatorOptions {
  double stiffness_N_per_m = 1e4;   ///< k [N/m] > 0
  double damping_ratio = 0.05;      ///< zeta in [0, 1)
  double force_amplitude_N = 10;    ///< F [N] >= 0
  double frequency_Hz = 20;         ///< f [Hz] > 0
  double stop_distance_m = 0.002;   ///< d [m] > 0
  double start_position_m = 0;      ///< x0 [m] < d
  double start_velocity_mps = 0;    ///< v0 [m/s]
  int impacts = 100;                ///< impacts kept and reported, >= 1
  int transient = 1000;             ///< impacts run first and discarded, >= 0
  ShakerImpactModel impact_model = ShakerImpactModel::instantaneous;
  PatternTolerance pattern;  ///< its speed_scale_mps is set by the run when 0 ((F + k d) / (m f))
};

/// Throws InvalidParameter naming `stiffness`, `damping-ratio`, `force-amplitude`, `frequency`,
/// `stop-distance`, `start-position`, `start-velocity`, `impacts` or `transient`.
void validate(const OscillatorOptions& o);

/// The driver's result (its amplitude and peak phase the body's) and:
struct OscillatorRun : ImpactSequence {
  ShakerImpactModel impact_model = ShakerImpactModel::instantaneous;
  double steady_amplitude_m = 0;  ///< |X|, the steady amplitude without the stop (closed form) [m]
};

/// The run of the validated `setup` (its body mass, contact, law inputs and e; not its gravity or
/// height) with the law `law` (soft impacts) against the stop of `options`.
OscillatorRun run_oscillator(const DropTestSetup& setup, std::string_view law, const SolverSettings& solver,
                             const OscillatorOptions& options);

}  // namespace hertzdash
