#pragma once
// A wall (the flat the body strikes) moved by a prescribed harmonic motion, and the free flight
// of a body above it: the rig of a ball on a vibrating table (the "bouncing ball", Holmes 1982;
// Luck and Mehta 1993; Tufillaro, Abbott and Reilly, An Experimental Approach to Nonlinear
// Dynamics and Chaos, 1992, ch. 3). Heights upward positive, t [s]:
//   wall:    s(t) = A sin(w t),  w = 2 pi f,   s' = A w cos(w t),   s'' = -A w^2 sin(w t)
//   flight:  y(t) = y0 + u0 (t - t0) - g (t - t0)^2 / 2   (exact: gravity only)
//   gap:     h(t) = y(t) - s(t),   h'' = -g + A w^2 sin(w t),   |h''| <= g + A w^2 = g (1 + Gamma)
// with the dimensionless acceleration Gamma = A w^2 / g. In contact the overlap x = s - y obeys
//   m x'' = m (g + s''(t)) - F(x, x')
// (body: m y'' = -m g + F): the drop test's equation with the wall's acceleration as an extra,
// prescribed forcing m s''(t) (model/contact_environments.hpp).
// A body resting on the wall (x' = 0, no impact) is carried while the wall pushes it,
// s''(t) > -g, and leaves it where the wall's acceleration falls below -g: sin(w t) > 1/Gamma,
// never if Gamma <= 1.
#include <cmath>
#include <numbers>

namespace hertzdash {

/// s(t) = A sin(2 pi f t): amplitude A [m] >= 0, frequency f [Hz] > 0.
struct HarmonicWallMotion {
  double amplitude_m = 0;
  double frequency_Hz = 1;

  double omega_rad_per_s() const { return 2.0 * std::numbers::pi * frequency_Hz; }
  double period_s() const { return 1.0 / frequency_Hz; }
  double position_m(double t) const { return amplitude_m * std::sin(omega_rad_per_s() * t); }
  double velocity_mps(double t) const { return amplitude_m * omega_rad_per_s() * std::cos(omega_rad_per_s() * t); }
  double acceleration_mps2(double t) const {
    const double w = omega_rad_per_s();
    return -amplitude_m * w * w * std::sin(w * t);
  }
  /// The peak acceleration A w^2 [m/s^2].
  double peak_acceleration_mps2() const {
    const double w = omega_rad_per_s();
    return amplitude_m * w * w;
  }
  /// The table phase of time t in [0, 1): the fraction of a cycle since the last upward zero of s.
  double phase(double t) const {
    const double c = t * frequency_Hz;
    const double p = c - std::floor(c);
    return p < 1.0 ? p : 0.0;
  }
};

/// Gamma = A w^2 / g, the wall's peak acceleration in units of gravity g [m/s^2] > 0.
inline double shaker_gamma(const HarmonicWallMotion& wall, double gravity_mps2) {
  return wall.peak_acceleration_mps2() / gravity_mps2;
}

/// The amplitude A [m] of the motion at frequency f [Hz] whose Gamma = A (2 pi f)^2 / g is `gamma`.
inline double shaker_amplitude_m(double gamma, double frequency_Hz, double gravity_mps2) {
  const double w = 2.0 * std::numbers::pi * frequency_Hz;
  return gamma * gravity_mps2 / (w * w);
}

/// The middle of the window of Gamma in which the bouncing-ball map with restitution e has a
/// stable period-1 orbit (one impact per wall period; Holmes 1982, Luck and Mehta 1993): the
/// orbit appears at gamma_1 = pi (1 - e)/(1 + e) and doubles its period at
/// gamma_2 = sqrt(gamma_1^2 + (2 (1 + e^2)/(1 + e)^2)^2); (gamma_1 + gamma_2)/2.
inline double period_one_middle_gamma(double e) {
  const double g1 = std::numbers::pi * (1 - e) / (1 + e), s = 2 * (1 + e * e) / ((1 + e) * (1 + e));
  return 0.5 * (g1 + std::sqrt(g1 * g1 + s * s));
}

}  // namespace hertzdash
