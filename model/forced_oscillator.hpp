#pragma once
// A damped linear oscillator under a harmonic force, in closed form: the primary of the impact
// damper (a box on a spring, simulation/shaker/two_walls.hpp) between impacts, and, with no
// spring response, the harmonically driven box. Displacement X [m] from the static equilibrium,
//   M X'' + c X' + k X = F0 sin(w t) + Fc,     c = 2 zeta sqrt(k M),   0 <= zeta < 1,
// (Fc a constant force: the weight m g of a body the box carries). Exact solution from
// (t0, X0, V0), homogeneous plus particular, written with complex amplitudes:
//   X(t) = Re(Z e^{lambda (t - t0)}) + Re(Q e^{i w t}) + Fc / k,
//   lambda = -zeta wn + i wn sqrt(1 - zeta^2),   wn = sqrt(k / M),
//   Q = -i F0 / (k - M w^2 + i c w)    (F0 sin(w t) = Re(-i F0 e^{i w t})),
// with Z fixed by X(t0) = X0 and X'(t0) = V0. The n-th derivative is
// Re(Z lambda^n e^{lambda tau}) + Re(Q (i w)^n e^{i w t}), so for t >= t0
//   |X^(n)(t)| <= |Z| wn^n + |Q| w^n            (|lambda| = wn, |e^{lambda tau}| <= 1),
// the bound the safe bracketing of the next impact uses. The steady amplitude is |Q| =
// F0 / sqrt((k - M w^2)^2 + (c w)^2) (Den Hartog, Mechanical Vibrations, 1956, sec. 2.5).
// A prescribed harmonic box motion s(t) = A sin(w t) is the same form with Z = 0 and Q = -i A:
// `prescribed()`.
#include <cmath>
#include <complex>

namespace hertzdash {

/// The primary oscillator: mass [kg] > 0, stiffness [N/m] > 0, damping ratio in [0, 1), harmonic
/// force F0 sin(w t) [N] at w [rad/s], constant force [N].
struct ForcedOscillator {
  double mass_kg = 1, stiffness_N_per_m = 1, damping_ratio = 0, force_amplitude_N = 0, omega_rad_per_s = 1,
         constant_force_N = 0;

  double natural_omega_rad_per_s() const { return std::sqrt(stiffness_N_per_m / mass_kg); }
  double damping_N_s_per_m() const { return 2.0 * damping_ratio * std::sqrt(stiffness_N_per_m * mass_kg); }
  /// Q: the particular solution's complex amplitude [m] (see above).
  std::complex<double> particular_amplitude() const {
    const double w = omega_rad_per_s;
    return std::complex<double>(0, -force_amplitude_N) /
           std::complex<double>(stiffness_N_per_m - mass_kg * w * w, damping_N_s_per_m() * w);
  }
  /// The steady amplitude |Q| [m] of X under the harmonic force.
  double steady_amplitude_m() const { return std::abs(particular_amplitude()); }
};

/// The motion X(t) of a ForcedOscillator from (t0, X0, V0), or a prescribed harmonic motion.
class OscillatorMotion {
 public:
  OscillatorMotion() = default;
  /// The oscillator `o` at X(t0) = X0 [m], X'(t0) = V0 [m/s].
  OscillatorMotion(const ForcedOscillator& o, double t0_s, double X0_m, double V0_mps)
      : Q_(o.particular_amplitude()), offset_m_(o.constant_force_N / o.stiffness_N_per_m), omega_(o.omega_rad_per_s),
        t0_s_(t0_s) {
    const double wn = o.natural_omega_rad_per_s();
    lambda_ = {-o.damping_ratio * wn, wn * std::sqrt(1.0 - o.damping_ratio * o.damping_ratio)};
    // Re Z = X0 - Xp(t0) - Fc/k;  Re(Z lambda) = Re Z Re lambda - Im Z Im lambda = V0 - Xp'(t0).
    const double a = X0_m - particular(0, t0_s) - offset_m_, b = V0_mps - particular(1, t0_s);
    Z_ = {a, (a * lambda_.real() - b) / lambda_.imag()};
  }
  /// s(t) = A sin(w t): Q = -i A, no homogeneous part.
  static OscillatorMotion prescribed(double amplitude_m, double omega_rad_per_s) {
    OscillatorMotion m;
    m.Q_ = {0, -amplitude_m};
    m.omega_ = omega_rad_per_s;
    m.lambda_ = {-1, 0};
    return m;
  }

  /// The n-th time derivative of X at t [s] (n = 0: X [m]).
  double derivative(int n, double t) const {
    const std::complex<double> e = std::exp(lambda_ * (t - t0_s_));
    return (Z_ * std::pow(lambda_, n) * e).real() + particular(n, t) + (n == 0 ? offset_m_ : 0.0);
  }
  double position_m(double t) const { return derivative(0, t); }
  double velocity_mps(double t) const { return derivative(1, t); }
  double acceleration_mps2(double t) const { return derivative(2, t); }
  /// A bound on |X^(n)(t)| for every t >= t0 (see the header), n >= 1.
  double derivative_bound(int n) const {
    return std::abs(Z_) * std::pow(std::abs(lambda_), n) + std::abs(Q_) * std::pow(omega_, n);
  }

 private:
  double particular(int n, double t) const {
    return (Q_ * std::pow(std::complex<double>(0, omega_), n) * std::exp(std::complex<double>(0, omega_ * t))).real();
  }
  std::complex<double> Z_{}, Q_{}, lambda_{-1, 0};
  double offset_m_ = 0, omega_ = 1, t0_s_ = 0;
};

}  // namespace hertzdash
