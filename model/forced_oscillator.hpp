#pragma once
// A damped linear oscillator under a harmonic force, in closed form: the primary of the impact
// damper (a box on a spring, simulation/shaker/two_walls.hpp) between impacts, the impact
// oscillator's body between impacts (simulation/rigs/oscillator_rig.hpp), with no spring a body in
// free flight under gravity, and, with no response of its own, the harmonically driven box.
// Displacement X [m] (the damper's from the static equilibrium),
//   M X'' + c X' + k X = F0 sin(w t + phi) + Fc,     c = 2 zeta sqrt(k M),   0 <= zeta < 1,
// (Fc a constant force: the weight of the body or of a body the box carries). Exact solution
// from (t0, X0, V0), homogeneous plus particular, written with complex amplitudes:
//   X(t) = Re(Z e^{lambda (t - t0)}) + Re(Q e^{i w t}) + Fc / k,
//   lambda = -zeta wn + i wn sqrt(1 - zeta^2),   wn = sqrt(k / M),
//   Q = -i F0 e^{i phi} / (k - M w^2 + i c w)    (F0 sin(w t + phi) = Re(-i F0 e^{i phi} e^{i w t})),
// with Z fixed by X(t0) = X0 and X'(t0) = V0. The n-th derivative is
// Re(Z lambda^n e^{lambda tau}) + Re(Q (i w)^n e^{i w t}), so for t >= t0
//   |X^(n)(t)| <= |Z| wn^n + |Q| w^n            (|lambda| = wn, |e^{lambda tau}| <= 1),
// the bound the safe bracketing of the next impact uses. Without a spring (k = 0, hence c = 0:
// a free body) the homogeneous part is the flight a + b tau + Fc tau^2 / (2 M), Q as above, and
// |X''(t)| <= |Fc| / M + |Q| w^2, |X^(n)| <= |Q| w^n for n >= 3. The steady amplitude is |Q| =
// F0 / sqrt((k - M w^2)^2 + (c w)^2) (Den Hartog, Mechanical Vibrations, 1956, sec. 2.5).
// A prescribed harmonic box motion s(t) = A sin(w t) is the same form with Z = 0 and Q = -i A:
// `prescribed()` (A = 0: a wall at rest).
#include <cmath>
#include <complex>
#include <numbers>

namespace hertzdash {

/// The oscillator: mass [kg] > 0, stiffness [N/m] >= 0, damping ratio in [0, 1), harmonic force
/// F0 sin(w t + phi) [N] at w [rad/s] > 0 with phase phi [rad], constant force [N]. The damper's
/// soft contact (SprungPrimary, model/contact_environments.hpp) reads phi = 0.
struct ForcedOscillator {
  double mass_kg = 1, stiffness_N_per_m = 1, damping_ratio = 0, force_amplitude_N = 0, omega_rad_per_s = 1,
         constant_force_N = 0, force_phase_rad = 0;

  double natural_omega_rad_per_s() const { return std::sqrt(stiffness_N_per_m / mass_kg); }
  double damping_N_s_per_m() const { return 2.0 * damping_ratio * std::sqrt(stiffness_N_per_m * mass_kg); }
  /// Q: the particular solution's complex amplitude [m] (see above).
  std::complex<double> particular_amplitude() const {
    const double w = omega_rad_per_s;
    return std::complex<double>(0, -1) * std::polar(force_amplitude_N, force_phase_rad) /
           std::complex<double>(stiffness_N_per_m - mass_kg * w * w, damping_N_s_per_m() * w);
  }
  /// The n-th time derivative of the harmonic force at t [s]: F0 w^n sin(w t + phi + n pi/2) [N/s^n].
  double force_derivative(int n, double t) const {
    return force_amplitude_N * std::pow(omega_rad_per_s, n) *
           std::sin(omega_rad_per_s * t + force_phase_rad + n * std::numbers::pi / 2);
  }
  /// Its energy M v^2/2 + k x^2/2 - Fc x at displacement x [m] and velocity v [m/s] [J].
  double energy_J(double x_m, double v_mps) const {
    return 0.5 * mass_kg * v_mps * v_mps + 0.5 * stiffness_N_per_m * x_m * x_m - constant_force_N * x_m;
  }
  /// The steady amplitude |Q| [m] of X under the harmonic force.
  double steady_amplitude_m() const { return std::abs(particular_amplitude()); }
};

/// `box` carrying `body` (both moving as one, the body at X + offset_m): masses, springs, dashpots
/// and forces added, the body's spring force at the offset, -k_body offset, in the constant force
/// (both driven at the box's w).
inline ForcedOscillator carrying(const ForcedOscillator& box, const ForcedOscillator& body, double offset_m) {
  ForcedOscillator joint = box;
  joint.mass_kg += body.mass_kg;
  joint.stiffness_N_per_m += body.stiffness_N_per_m;
  const double c = box.damping_N_s_per_m() + body.damping_N_s_per_m();
  joint.damping_ratio = joint.stiffness_N_per_m > 0 ? c / (2.0 * std::sqrt(joint.stiffness_N_per_m * joint.mass_kg)) : 0;
  const std::complex<double> F =
      std::polar(box.force_amplitude_N, box.force_phase_rad) + std::polar(body.force_amplitude_N, body.force_phase_rad);
  joint.force_amplitude_N = std::abs(F);
  joint.force_phase_rad = std::arg(F);
  joint.constant_force_N += body.constant_force_N - body.stiffness_N_per_m * offset_m;
  return joint;
}

/// The motion X(t) of a ForcedOscillator from (t0, X0, V0), or a prescribed harmonic motion.
class OscillatorMotion {
 public:
  OscillatorMotion() = default;
  /// The oscillator `o` at X(t0) = X0 [m], X'(t0) = V0 [m/s].
  OscillatorMotion(const ForcedOscillator& o, double t0_s, double X0_m, double V0_mps)
      : Q_(o.particular_amplitude()), omega_(o.omega_rad_per_s), t0_s_(t0_s) {
    const double a = X0_m - particular(0, t0_s), b = V0_mps - particular(1, t0_s);
    if (!(o.stiffness_N_per_m > 0)) {  // a free body: Z holds the flight's a + i b
      free_ = true;
      Z_ = {a, b};
      acceleration_ = o.constant_force_N / o.mass_kg;
      return;
    }
    const double wn = o.natural_omega_rad_per_s();
    offset_m_ = o.constant_force_N / o.stiffness_N_per_m;
    lambda_ = {-o.damping_ratio * wn, wn * std::sqrt(1.0 - o.damping_ratio * o.damping_ratio)};
    // Re Z = X0 - Xp(t0) - Fc/k;  Re(Z lambda) = Re Z Re lambda - Im Z Im lambda = V0 - Xp'(t0).
    Z_ = {a - offset_m_, ((a - offset_m_) * lambda_.real() - b) / lambda_.imag()};
  }
  /// s(t) = A sin(w t): Q = -i A, no homogeneous part.
  static OscillatorMotion prescribed(double amplitude_m, double omega_rad_per_s) {
    OscillatorMotion m;
    m.Q_ = {0, -amplitude_m};
    m.omega_ = omega_rad_per_s;
    return m;
  }

  /// The n-th time derivative of X at t [s] (n = 0: X [m]).
  double derivative(int n, double t) const {
    const double tau = t - t0_s_;
    if (free_) {
      const double flight = n == 0   ? Z_.real() + tau * (Z_.imag() + 0.5 * acceleration_ * tau)
                            : n == 1 ? Z_.imag() + acceleration_ * tau
                            : n == 2 ? acceleration_
                                     : 0.0;
      return flight + particular(n, t);
    }
    return (Z_ * power(lambda_, n) * std::exp(lambda_ * tau)).real() + particular(n, t) + (n == 0 ? offset_m_ : 0.0);
  }
  double position_m(double t) const { return derivative(0, t); }
  double velocity_mps(double t) const { return derivative(1, t); }
  double acceleration_mps2(double t) const { return derivative(2, t); }
  /// A bound on |X^(n)(t)| for every t >= t0 (see the header), n >= 2 (n >= 1 with a spring).
  double derivative_bound(int n) const {
    const double homogeneous = free_ ? (n == 2 ? std::abs(acceleration_) : 0.0) : std::abs(Z_) * std::pow(std::abs(lambda_), n);
    return homogeneous + std::abs(Q_) * std::pow(omega_, n);
  }

 private:
  static std::complex<double> power(std::complex<double> z, int n) {
    std::complex<double> p = 1;
    for (int i = 0; i < n; ++i) p *= z;
    return p;
  }
  double particular(int n, double t) const {
    return (Q_ * power(std::complex<double>(0, omega_), n) * std::exp(std::complex<double>(0, omega_ * t))).real();
  }
  std::complex<double> Z_{}, Q_{}, lambda_{-1, 0};
  double offset_m_ = 0, omega_ = 1, t0_s_ = 0, acceleration_ = 0;
  bool free_ = false;
};

}  // namespace hertzdash
