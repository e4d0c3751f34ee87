#pragma once
// The impact damper's symmetric orbit in closed form, for tests (tests/test_two_walls.cpp,
// tests/test_orbit_damper.cpp).
#include "hertzdash/model/forced_oscillator.hpp"

#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

namespace hertzdash::test {

/// The symmetric period-1 motion of the impact damper with two impacts a cycle (Masri and
/// Caughey, J. Appl. Mech. 33 (1966) 586), horizontal box (g = 0), derived here in closed form.
/// The body hits the floor at t0 and the ceiling at t0 + T/2, moving at +u1 between them and -u1
/// after; the primary's motion is antisymmetric, X(t + T/2) = -X(t). Each impact gives the
/// primary an impulse, I = M (V+ - V-) = -2 m u1 at the floor (momentum conserved: the body's
/// velocity changes by +2 u1), -I at the ceiling: a train of alternating impulses every T/2. The
/// steady response to it, with h(t) = e^{-sigma t} sin(wd t) / (M wd) the impulse response and
/// lambda = -sigma + i wd (sigma = zeta wn), is for 0 <= t' = t - t0 < T/2
///   X_I(t') = I sum_{n>=0} (-1)^n h(t' + n T/2) = I Im(e^{lambda t'} / (1 + e^{lambda T/2})) / (M wd)
/// (a geometric series), and X = Re(Q e^{i w t}) + X_I (Q the bare steady amplitude,
/// model/forced_oscillator.hpp). With psi = w t0 + arg Q, P = |Q| cos psi = Re(Q e^{i w t0}),
/// Pv = -w |Q| sin psi = Re(i w Q e^{i w t0}), D = 1 + e^{lambda T/2} and
///   A1 = Im(1/D) / (M wd),  B1 = Im(lambda / D) / (M wd),  B2 = Im(lambda e^{lambda T/2} / D) / (M wd)
/// (B1 + B2 = 1/M): X(t0) = P + I A1, V+ = X'(t0+) = Pv + I B1, V- = X'(t0-) = -X'(t0 + T/2 -)
/// = Pv - I B2 (e^{i w T/2} = -1). Two conditions fix t0 and u1:
///   travel: u1 T/2 = X(t0 + T/2) + gap - X(t0) = gap - 2 X(t0)  =>  u1 (1 - 8 m A1 / T) = (2 gap - 4 P) / T,
///   Newton:  u1 - V+ = -e(-u1 - V-)                               =>  u1 (1 - e + 2 m (B1 - e B2)) = (1 + e) Pv,
/// so with D1 = 1 - 8 m A1 / T and D3 = 1 - e + 2 m (B1 - e B2), eliminating u1:
///   a sin psi + b cos psi = 2 gap,  a = -D1 (1 + e) w |Q| T / D3,  b = 4 |Q|,
/// psi = atan2(a, b) +- acos(2 gap / hypot(a, b)); the physical root has u1 > 0. The floor impact's
/// relative speed is V- + u1 and its drive phase w t0 / (2 pi) mod 1; the ceiling's the same, half a
/// cycle later. In the limit M -> inf (the driven box) this is the box's symmetric orbit.
/// One root: the floor impact's drive phase and relative speed, and the state just after it
/// (the body at the floor, y = X(t0), moving at u1; the primary at X(t0), V+).
struct SymmetricOrbit {
  bool found = false;
  double phase = 0, speed_mps = 0;
  double X_m = 0, V_after_mps = 0, u_after_mps = 0;
};
/// Both roots psi (the + sign first), each found where u1 > 0.
inline std::vector<SymmetricOrbit> masri_caughey_orbits(const ForcedOscillator& o, double m, double e, double gap, double f) {
  using C = std::complex<double>;
  const double pi = std::numbers::pi, w = 2 * pi * f, T = 1 / f, M = o.mass_kg, wn = o.natural_omega_rad_per_s();
  const double wd = wn * std::sqrt(1 - o.damping_ratio * o.damping_ratio);
  const C lambda(-o.damping_ratio * wn, wd), Q = o.particular_amplitude(), E = std::exp(lambda * (T / 2)), D = 1.0 + E;
  const double A1 = (1.0 / D).imag() / (M * wd), B1 = (lambda / D).imag() / (M * wd),
               B2 = (lambda * E / D).imag() / (M * wd);
  const double D1 = 1 - 8 * m * A1 / T, D3 = 1 - e + 2 * m * (B1 - e * B2);
  const double a = -D1 * (1 + e) * w * std::abs(Q) * T / D3, b = 4 * std::abs(Q), R = std::hypot(a, b);
  std::vector<SymmetricOrbit> out;
  if (2 * gap > R) return out;
  for (const double sign : {1.0, -1.0}) {
    const double psi = std::atan2(a, b) + sign * std::acos(2 * gap / R);
    const double u1 = (1 + e) * (-w * std::abs(Q) * std::sin(psi)) / D3;
    if (!(u1 > 0)) continue;
    const double theta = psi - std::arg(Q), I = -2 * m * u1;
    const C q = Q * std::exp(C(0, theta));
    const double P = q.real(), Pv = (C(0, w) * q).real();
    const double phase = theta / (2 * pi) - std::floor(theta / (2 * pi));
    out.push_back({true, phase, u1 + Pv - I * B2, P + I * A1, Pv + I * B1, u1});  // V- = Pv - I B2
  }
  return out;
}

/// The last root found (the one with u1 > 0 where only one has it), or found = false.
inline SymmetricOrbit masri_caughey(const ForcedOscillator& o, double m, double e, double gap, double f) {
  const std::vector<SymmetricOrbit> roots = masri_caughey_orbits(o, m, e, gap, f);
  return roots.empty() ? SymmetricOrbit{} : roots.back();
}


}  // namespace hertzdash::test
