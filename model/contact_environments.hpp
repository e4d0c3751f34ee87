#pragma once
// What the other body does during a contact: the environments of the contact system
// (model/contact_system.hpp, which states what an environment declares). Each gives the
// forcing a of the relative motion x'' = a - F/mu, its reduced mass mu and its extra state z
// with dz/dt = r, for a body of mass m [kg], overlap x = u^2 [m] and its rate v = x' [m/s]
// (approaching positive), F >= 0 the compressive contact force [N]. A drive's phase w t is
// carried as S = sin(w t), C = cos(w t) (dS/dt = w C, dC/dt = -w S), so that a and r are
// polynomials in the state and the Taylor row takes every environment.
#include "hertzdash/model/forced_oscillator.hpp"
#include "hertzdash/model/wall_motion.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>

namespace hertzdash {

/// The drop test: a fixed wall under gravity g [m/s^2] (model/drop_test.hpp's x'' = g - F/m).
/// mu = m; no extra state; lands the maximum compression; the observation time only observes.
struct FixedWall {
  double gravity_mps2 = 0;

  static constexpr int extra_dimension = 0;
  static constexpr bool lands_max_compression = true;
  static constexpr bool stops_at_observation_time = false;
  double reduced_mass_kg(double m) const { return m; }
  template <class Y, class F> auto rates(const Y&, const F&, double) const { return std::tuple{gravity_mps2}; }
  std::array<double, 0> initial_extra() const { return {}; }
  std::array<double, 0> extra_scale(double, double) const { return {}; }
};

/// The impact damper's wall: the floor (sigma = +1, x = X - y) or ceiling (sigma = -1, x = y - X -
/// gap) of the box of the primary `o` (mass M on the spring k, damping c, driven by F0 sin(w t);
/// simulation/shaker/two_walls.hpp), whose motion the contact force moves too: with the
/// primary's free acceleration P = (F0 S - c V - k X)/M,
///   M X'' = M P - sigma F,   m y'' = -m g + sigma F,   so   x'' = sigma (P + g) - F/mu,
///   a = sigma (P + g),   mu = m M / (m + M),   z = (X, V, S, C),
///   r = (V, P - sigma F/M, w C, -w S),
/// from X0, V0 at t_onset [s]; scales (max(|X0|, X), max(|V0|, v0), 1, 1). The observation time stops.
struct SprungPrimary {
  ForcedOscillator primary;
  double gravity_mps2 = 0, sigma = 1, t_onset_s = 0, X0_m = 0, V0_mps = 0;

  static constexpr int extra_dimension = 4;
  /// (X, V) at onset are the contact's inputs (model/contact_tangent_system.hpp).
  static constexpr int onset_state_dimension = 2;
  static constexpr bool lands_max_compression = false;
  static constexpr bool stops_at_observation_time = true;
  double reduced_mass_kg(double m) const { return m * primary.mass_kg / (m + primary.mass_kg); }
  template <class Y, class F> auto rates(const Y& y, const F& force, double) const {
    const double inverse_M = 1.0 / primary.mass_kg, w = primary.omega_rad_per_s;
    const auto P = (primary.force_amplitude_N * y[5] - primary.damping_N_s_per_m() * y[4] -
                    primary.stiffness_N_per_m * y[3]) * inverse_M;
    return std::tuple{sigma * (P + gravity_mps2), y[4], P - sigma * inverse_M * force, w * y[6], -w * y[5]};
  }
  std::array<double, 4> initial_extra() const {
    const double theta = primary.omega_rad_per_s * t_onset_s;
    return {X0_m, V0_mps, std::sin(theta), std::cos(theta)};
  }
  /// d z0 / d t_onset [1/s] (model/contact_tangent_system.hpp): the drive's phase alone.
  std::array<double, 4> initial_extra_onset_derivative() const {
    const double w = primary.omega_rad_per_s;
    return {0.0, 0.0, w * std::cos(w * t_onset_s), -w * std::sin(w * t_onset_s)};
  }
  std::array<double, 4> extra_scale(double X, double v0) const {
    return {std::max(std::abs(X0_m), X), std::max(std::abs(V0_mps), v0), 1.0, 1.0};
  }
};

/// A contact forced harmonically at w [rad/s], in one of two settings that share the drive's phase
/// z = (S, C) = (sin, cos)(w t), from w t_onset [s], scale (1, 1), and mu = m:
///  - a wall in the prescribed motion s(t) = A sin(w t) (model/wall_motion.hpp) under gravity g
///    (harmonic_wall): the floor (sigma = +1, overlap x = s - y, body height y): m y'' = -m g + F
///    gives x'' = g + s''(t) - F/m; the ceiling of a box (sigma = -1, x = y - s - gap, pushed down:
///    m y'' = -m g - F) x'' = -(g + s''(t)) - F/m; so, with s'' = -A w^2 S, a = sigma (g - A w^2 S).
///    The shaker's floor (simulation/shaker/shaker.hpp), the driven box's floor and ceiling
///    (simulation/shaker/two_walls.hpp).
///  - a body that is itself a linear oscillator, m x'' + c x' + k x = F0 cos(w t) (no gravity; the
///    oscillator rig), striking a fixed stop at x = d on its positive side: overlap x - d = u^2,
///    v = x' (approaching positive), the stop's force F pushing the body back:
///    m x'' = F0 cos(w t) - c v - k (d + u^2) - F, so a = (F0 C - c v - k (d + u^2)) / m.
/// One environment with both terms,
///   a = sigma (g - A w^2 S) + (F0 C - c v - k (d + u^2)) / m,
/// in which the other setting's coefficients are zero and add exact zeros, so each law's unit
/// compiles one soft contact for the two (simulation/run/law_runs.hpp). The observation time stops.
struct HarmonicForcing {
  double stiffness_N_per_m = 0, damping_N_s_per_m = 0, force_amplitude_N = 0, omega_rad_per_s = 0,
         stop_m = 0, t_onset_s = 0;
  double wall_peak_acceleration_mps2 = 0, gravity_mps2 = 0, sigma = 1;

  static constexpr int extra_dimension = 2;
  static constexpr int onset_state_dimension = 0;  ///< a drive's phase only (model/contact_tangent_system.hpp)
  static constexpr bool lands_max_compression = false;
  static constexpr bool stops_at_observation_time = true;
  double reduced_mass_kg(double m) const { return m; }
  template <class Y, class F> auto rates(const Y& y, const F&, double inverse_m) const {
    const double w = omega_rad_per_s;
    return std::tuple{sigma * (gravity_mps2 - wall_peak_acceleration_mps2 * y[3]) +
                          (force_amplitude_N * y[4] - damping_N_s_per_m * y[1] -
                           stiffness_N_per_m * (stop_m + y[0] * y[0])) * inverse_m,
                      w * y[4], -w * y[3]};
  }
  std::array<double, 2> initial_extra() const {
    return {std::sin(omega_rad_per_s * t_onset_s), std::cos(omega_rad_per_s * t_onset_s)};
  }
  /// d z0 / d t_onset [1/s] (model/contact_tangent_system.hpp)
  std::array<double, 2> initial_extra_onset_derivative() const {
    const double w = omega_rad_per_s;
    return {w * std::cos(w * t_onset_s), -w * std::sin(w * t_onset_s)};
  }
  std::array<double, 2> extra_scale(double, double) const { return {1.0, 1.0}; }
};

/// The wall in the motion `motion` under gravity g [m/s^2], the floor (sigma = +1) or the ceiling
/// (sigma = -1), the contact beginning at t_onset [s] (HarmonicForcing).
inline HarmonicForcing harmonic_wall(const HarmonicWallMotion& motion, double gravity_mps2, double sigma,
                                     double t_onset_s) {
  return {.omega_rad_per_s = motion.omega_rad_per_s(), .t_onset_s = t_onset_s,
          .wall_peak_acceleration_mps2 = motion.peak_acceleration_mps2(), .gravity_mps2 = gravity_mps2,
          .sigma = sigma};
}

}  // namespace hertzdash
