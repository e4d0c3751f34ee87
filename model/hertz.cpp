#include "hertzdash/model/hertz.hpp"

#include <gsl/gsl_sf_gamma.h>

#include <cmath>
#include <numbers>

namespace hertzdash {

double compliance(const Material& m) { return std::isinf(m.E_Pa) ? 0.0 : (1.0 - m.nu * m.nu) / m.E_Pa; }

double hertz_stiffness(double sphere_radius_m, const Material& sphere, const Material& flat) {
  return 4.0 * std::sqrt(sphere_radius_m) / 3.0 / (compliance(sphere) + compliance(flat));
}

double hertz_impact_scale_m(double K, double mass_kg, double v0_mps) {
  return std::pow(mass_kg * v0_mps * v0_mps / K, 0.4);
}

double hertz_peak_pressure_Pa(double K, double sphere_radius_m, double deformation_m) {
  return 3.0 * K * std::sqrt(deformation_m) / (2.0 * std::numbers::pi * sphere_radius_m);
}

double hertz_yield_onset_factor(double nu) {
  auto stress_difference = [nu](double zeta) {  // |sigma_r - sigma_z| / p0 on the axis, z = zeta a
    const double sz = -1.0 / (1.0 + zeta * zeta);
    const double sr = -(1.0 + nu) * (1.0 - zeta * std::atan(1.0 / zeta)) + 0.5 / (1.0 + zeta * zeta);
    return std::abs(sr - sz);
  };
  // Unimodal in zeta on (0, 2) for nu in (-1, 0.5): golden-section search to 1e-10 in zeta.
  const double r = (std::sqrt(5.0) - 1.0) / 2.0;
  double a = 1e-6, b = 2.0;
  double c = b - r * (b - a), d = a + r * (b - a);
  while (b - a > 1e-10) {
    if (stress_difference(c) > stress_difference(d)) b = d;
    else a = c;
    c = b - r * (b - a), d = a + r * (b - a);
  }
  return 1.0 / stress_difference(0.5 * (a + b));
}

UndampedHertzImpact undamped_hertz_impact(double K, double mass_kg, double v0_mps) {
  // Energy: (1/2) m v^2 + (2/5) K x^{5/2} = (1/2) m v0^2. Time to X:
  //   t = int_0^X dx / sqrt(v0^2 - (4K/5m) x^{5/2}) = (X/v0) int_0^1 ds / sqrt(1 - s^{5/2})
  // and with w = s^{5/2}: int = (2/5) B(2/5, 1/2). Contact lasts twice that.
  const double X = undamped_hertz_max_deformation_m(K, mass_kg, v0_mps);
  const double tc = undamped_hertz_contact_time_factor() * X / v0_mps;
  return {X, K * X * std::sqrt(X), tc};
}

double undamped_hertz_max_deformation_m(double K, double mass_kg, double v0_mps) {
  return std::pow(5.0 * mass_kg * v0_mps * v0_mps / (4.0 * K), 0.4);
}

double undamped_hertz_contact_time_factor() {
  static const double factor = 0.8 * gsl_sf_beta(0.4, 0.5);
  return factor;
}

}  // namespace hertzdash
