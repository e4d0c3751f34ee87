#pragma once
// The paper's law: Hertz spring plus an equivalent viscous dashpot, eqs. (2), (5), (6), (11), (12).
#include "hertzdash/model/damping/damping_law.hpp"

#include <cmath>

namespace hertzdash {

/// Natural frequency of the Hertz contact at amplitude X [rad/s], eqs. (7)-(9) corrected
/// (erratum; paper/sections/differences.tex): (1/2) m (X w)^2 = (2/5) K X^{5/2}  =>  w = sqrt((4K/(5m)) X^{1/2}).
inline double hertz_natural_frequency(double K, double mass_kg, double amplitude_m) {
  return std::sqrt(4.0 * K / (5.0 * mass_kg) * std::sqrt(amplitude_m));
}

/// Peak deformation estimated from the mean of the kinetic energies before and after
/// impact, eq. (10): (1/2)(m v0^2/2 + m v0^2 e^2/2) = (2/5) K X^{5/2} [m].
inline double paper_peak_deformation(double K, double mass_kg, double v0_mps, double e) {
  return std::pow(5.0 * mass_kg * v0_mps * v0_mps * (1.0 + e * e) / (8.0 * K), 0.4);
}

/// Peak deformation of the undamped Hertz impact with kinetic energy (1/2) m v^2:
/// (1/2) m v^2 = (2/5) K X^{5/2}  =>  X = (5 m v^2 / (4K))^{2/5} [m]. With v = v0 this is the
/// `impact-energy` variant (e = 1 in eq. 10); with v = e v0 the `rebound-energy` variant.
inline double energy_peak_deformation(double K, double mass_kg, double speed_mps) {
  return std::pow(5.0 * mass_kg * speed_mps * speed_mps / (4.0 * K), 0.4);
}

/// Eq. (9) as transcribed (the erratum): sqrt(4K/(5m)) X^{1/2}, the X^{1/2} outside the
/// radical. Dimensionally wrong: with K in N/m^{3/2}, m in kg and X in m the result has
/// units s^{-1} m^{1/4}; it is evaluated numerically in SI units, as the literal
/// formula would be, only to show what the misprint would have done.
inline double as_printed_natural_frequency(double K, double mass_kg, double amplitude_m) {
  return std::sqrt(4.0 * K / (5.0 * mass_kg)) * std::sqrt(amplitude_m);
}

/// d ln(omega_n) / d ln(v0) of a variant at fixed K, m and e: X grows as v0^{4/5} (eq. 10 and both
/// energy variants), omega_n as X^{1/4} (eq. 9 corrected) or X^{1/2} (as printed); an iterated
/// variant's omega_n is given to the law (its fixed point), so the law holds it fixed.
constexpr double paper_law_natural_frequency_speed_exponent(OmegaNVariant v) {
  switch (v) {
    case OmegaNVariant::paper:
    case OmegaNVariant::impact_energy:
    case OmegaNVariant::rebound_energy: return 0.2;
    case OmegaNVariant::as_printed: return 0.4;
    case OmegaNVariant::self_consistent:
    case OmegaNVariant::contact_time: return 0.0;
  }
  return 0.0;
}

/// omega_n [rad/s] of the paper's law for one impact, by the chosen variant (OmegaNVariant).
/// The iterated variants (self-consistent, contact-time) take the given
/// settings.omega_n_rad_per_s, which their fixed-point iteration supplies
/// (simulation/run/omega_n_fixed_point.hpp); throws InvalidParameter if it is not > 0.
inline double paper_law_natural_frequency(const ImpactConditions& c, const DampingSettings& s) {
  const double K = c.K, m = c.mass_kg, v0 = c.v0_mps, e = c.restitution;
  switch (s.omega_n) {
    case OmegaNVariant::paper: return hertz_natural_frequency(K, m, paper_peak_deformation(K, m, v0, e));
    case OmegaNVariant::impact_energy: return hertz_natural_frequency(K, m, energy_peak_deformation(K, m, v0));
    case OmegaNVariant::rebound_energy: return hertz_natural_frequency(K, m, energy_peak_deformation(K, m, e * v0));
    case OmegaNVariant::as_printed: return as_printed_natural_frequency(K, m, paper_peak_deformation(K, m, v0, e));
    case OmegaNVariant::self_consistent:
    case OmegaNVariant::contact_time:
      require_positive(std::string("omega_n_rad_per_s (") + to_string(s.omega_n) +
                           " variant, set by its fixed-point iteration)",
                       s.omega_n_rad_per_s, "rad/s");
      return s.omega_n_rad_per_s;
  }
  return NAN;
}

/// F = K x^{3/2} + c_e xdot,  c_e = 2 K x^{1/2} zeta / omega_n      (eqs. 2, 5, 12)
/// zeta from e by eq. (6); omega_n by eq. (11) (= eqs. 9 and 10 combined), fixed per
/// impact from that impact's approach speed v0; other omega_n assumptions by
/// DampingSettings::omega_n (paper_law_natural_frequency).
class HongoPaper {
 public:
  static constexpr LawInfo info{
      "hongo",
      "T. Hongo, H. Sato, Y. Iwata, T. Komatsuzaki, Y. Hongo, Analysis of elastic impact system "
      "composed of a ball and walls, JSME conference paper, eqs. (2)-(12).",
      "F = K x^{3/2} + (2 K x^{1/2} zeta / omega_n) xdot",
      "zeta = ln(1/e)/pi (eq. 6); omega_n = sqrt((4K/5m) (5 m v0^2 (1+e^2)/(8K))^{1/5}) (eq. 11)",
      "paper: elastic bodies whose e does not depend on impact speed",
      true};
  /// The law's two modelling choices (fields of DampingSettings: the omega_n fixed point of
  /// simulation/ reads them too).
  static constexpr ParameterDecl parameters[] = {
      {.key = "zeta",
       .type = ParameterType::text,
       .choices = "paper, exact",
       .default_value = "paper",
       .default_source = "the paper's eq. (6)",
       .help = "Damping ratio from e: paper (eq. 6, ln(1/e)/pi) or exact (the linear oscillator's half cycle)"},
      {.key = "omega-n",
       .type = ParameterType::text,
       .choices = "paper, impact-energy, rebound-energy, self-consistent, contact-time, as-printed",
       .default_value = "paper",
       .default_source = "the paper's eq. (11)",
       .help = "Natural frequency assumption: paper (eq. 11), impact-energy, rebound-energy, self-consistent, "
               "contact-time (both iterated to a fixed point), as-printed (the eq. 9 erratum)"},
  };

  HongoPaper(const ImpactConditions& c, const DampingSettings& s)
      : K_(c.K),
        zeta_(zeta_from_restitution(c.restitution, s.zeta_form)),
        omega_n_(paper_law_natural_frequency(c, s)),
        tau_(2.0 * zeta_ / omega_n_),
        dtau_dv0_(-paper_law_natural_frequency_speed_exponent(s.omega_n) * tau_ / c.v0_mps) {}

  double force(double x, double xdot) const noexcept { return K_ * std::sqrt(x) * (x + tau_ * xdot); }
  /// The same at u = x^{1/2}: K u (u^2 + tau xdot) [N] (RootPolynomialLaw)
  template <class T>
  auto force_of_root(const T& u, const T& xdot) const noexcept { return K_ * u * (u * u + tau_ * xdot); }

  /// dF/dv0 = K u xdot dtau/dv0 [N s/m], dtau/dv0 = -p tau / v0 with p = d ln(omega_n)/d ln(v0)
  /// (paper_law_natural_frequency_speed_exponent) (SpeedDerivativeLaw)
  double force_speed_derivative(double u, double xdot) const noexcept { return K_ * u * xdot * dtau_dv0_; }

  /// tau = 2 zeta / omega_n [s], so that c_e = K tau x^{1/2} (eq. 5): the law's one
  /// coefficient besides K.
  double time_constant_s() const noexcept { return tau_; }

  /// The force at u = x^{1/2} >= 0 for given (K, tau) and its partial derivatives, for
  /// forward sensitivities (validation/common/contact_sensitivity.cpp):
  ///   F = K u (u^2 + tau xdot),   F_u = K (3u^2 + tau xdot),   F_xdot = K tau u,
  ///   F_K = u (u^2 + tau xdot),   F_tau = K u xdot.
  struct Gradient {
    double F, F_u, F_xdot, F_K, F_tau;
  };
  static Gradient gradient_of_root(double K, double tau_s, double u, double xdot) noexcept {
    const double spring_and_dashpot = u * (u * u + tau_s * xdot);
    return {K * spring_and_dashpot, K * (3.0 * u * u + tau_s * xdot), K * tau_s * u, spring_and_dashpot, K * u * xdot};
  }

  std::vector<NamedValue> coefficients() const {
    return {{"zeta", zeta_}, {"omega_n_rad_per_s", omega_n_}, {"c_e_coefficient_N_s_per_m_1_5", K_ * tau_}};
  }

 private:
  double K_;
  double zeta_;
  double omega_n_;
  double tau_;  ///< 2 zeta / omega_n [s]: c_e = K tau x^{1/2}
  double dtau_dv0_;  ///< d tau / d v0 [s^2/m]
};

}  // namespace hertzdash
