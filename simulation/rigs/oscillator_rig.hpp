#pragma once
// The impact oscillator with a stop (docs/shaker.md): the drop test's body, mass m, on a spring k
// with a dashpot c = 2 zeta sqrt(k m), m x'' + c x' + k x = F cos(2 pi f t), against a stop at
// x = d > 0 met instantaneously, v+ = -e v-, or with the drop test's soft contact (HarmonicForcing,
// model/contact_environments.hpp). A rig on the impact-sequence driver (simulation/shaker/
// impact_sequence.hpp): the body its oscillator (F sin(w t + pi/2)), the box at rest, the stop a
// wall at d met from below. Without the stop x = |X| cos(w t - psi), |X| = (F / k) /
// sqrt((1 - r^2)^2 + (2 zeta r)^2), tan psi = 2 zeta r / (1 - r^2), r = w / sqrt(k / m).
#include "hertzdash/simulation/rigs/rig.hpp"
#include "hertzdash/simulation/shaker/impact_sequence.hpp"

namespace hertzdash {

/// k [N/m], zeta, F [N], f [Hz], d [m], the start x0 < d [m], v0 [m/s] at t = 0.
struct OscillatorOptions {
  double stiffness_N_per_m = 1e4, damping_ratio = 0.05, force_amplitude_N = 10, frequency_Hz = 20;
  double stop_distance_m = 0.002, start_position_m = 0, start_velocity_mps = 0;
  int impacts = 100, transient = 1000;
  ShakerImpactModel impact_model = ShakerImpactModel::soft;
  PatternTolerance pattern;  ///< its speed_scale_mps is set by the run when 0 ((F + k d) / (m f))
};

/// The driver's result (amplitude and peak phase the body's x; energy m v^2/2 + k x^2/2) and:
struct OscillatorRun : ImpactSequence {
  ShakerImpactModel impact_model = ShakerImpactModel::soft;
  double steady_amplitude_m = 0;  ///< |X| without the stop (closed form) [m]
};

/// The run of the validated `setup` (its mass, contact, law inputs and e; not its gravity or
/// height) with the law `law` (soft impacts) against the stop of `options`; InvalidParameter
/// naming `stiffness`, `damping-ratio`, `force-amplitude`, `frequency`, `stop-distance`,
/// `start-position`, `impacts` or `transient`.
OscillatorRun run_oscillator(const DropTestSetup& setup, std::string_view law, const SolverSettings& solver,
                             const OscillatorOptions& options);

/// The sequence of a run_oscillator() call, validated as it validates.
SequenceSetUp make_oscillator_sequence(const DropTestSetup& setup, std::string_view law, const SolverSettings& solver,
                                       const OscillatorOptions& options);

/// The rig `oscillator`: inputs the options above and the drop test's body, contact and law;
/// results period, impacts_per_period, e_effective, amplitude_m, peak_phase, steady_amplitude_m,
/// energy_J, sticking_episodes, impacts_run; the shaker's per-impact table.
const Rig& oscillator_rig();

}  // namespace hertzdash
