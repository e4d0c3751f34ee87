#pragma once
// The period of a sequence of impacts on a vibrating wall: the smallest number k of impacts
// after which every kept impact repeats, impact n + k matching impact n for every n of the kept
// window, in
//   - table phase, |phi[n+k] - phi[n]| (on the circle) <= phase_tolerance,
//   - relative impact speed, |v[n+k] - v[n]| <= speed_tolerance * max(|v[n]|, speed scale),
//   - elapsed table cycles, (t[n+k] - t[n]) f an integer p >= 1 to within phase_tolerance, the
//     same p for every n.
// period = p (table cycles) and impacts_per_period = k; both 0 when no k <= half the window fits
// (chaotic, quasi-periodic, or not settled after the transient).
#include <cstddef>
#include <span>

namespace hertzdash {

/// The tolerances of the period detection (see above).
struct PatternTolerance {
  double phase = 1e-6;  ///< table phase, fraction of a cycle
  double speed = 1e-6;  ///< relative to the impact speed (or to speed_scale_mps, if larger)
  double speed_scale_mps = 0;  ///< the sequence's speed scale, g / (2 pi f) for instance [m/s]
};

struct ImpactPattern {
  int period = 0;              ///< table cycles after which the impacts repeat; 0: none found
  int impacts_per_period = 0;  ///< impacts in one period; 0: none found
};

/// The pattern of impacts at times t [s] with relative impact speeds v [m/s] on a wall of
/// frequency f [Hz] (t and v of equal size).
ImpactPattern detect_impact_pattern(std::span<const double> t_s, std::span<const double> v_mps, double frequency_Hz,
                                    const PatternTolerance& tol = {});

}  // namespace hertzdash
