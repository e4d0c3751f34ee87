#pragma once
// Natural frequencies of a free-free uniform solid round rod: how Table 3 of Hongo et al.
// relates a rod's Young's modulus to its measured natural frequency ("E from the natural
// frequency", section 3.1), used to check the printed pairs (f, E) against Table 1.
//
// First flexural mode, Euler-Bernoulli beam with free ends:
//   f1 = (beta1 L)^2 / (2 pi L^2) * sqrt(E I / (rho A))        [Hz]
//   beta1 L = 4.730040745: the first non-zero root of cos(bL) cosh(bL) = 1
//   I = pi d^4 / 64, A = pi d^2 / 4, so I/A = d^2/16,
//   rho = m / (A L) from the rod's mass and dimensions (Table 1).
// First longitudinal mode of a free-free bar:  f1 = sqrt(E / rho) / (2 L)   [Hz].
// Reference checked against: S. Timoshenko, D. H. Young, W. Weaver, Vibration Problems in
// Engineering, 4th ed., Wiley (1974), sections 5.2 (bars) and 5.8 (free-free beam).
#include <cmath>
#include <numbers>

namespace hertzdash {

/// A solid round rod (Table 1 row): constant for a calculation.
struct RodGeometry {
  double diameter_m;  ///< d [m] > 0
  double length_m;    ///< L [m] > 0
  double mass_kg;     ///< m [kg] > 0
};

/// First free-free flexural eigenvalue beta1 L [-]: cos(bL) cosh(bL) = 1.
inline constexpr double free_free_beta1_L = 4.730040744862704;

/// Density rho = m / (A L) [kg/m^3], A = pi d^2 / 4.
inline double rod_density_kg_per_m3(const RodGeometry& r) {
  return r.mass_kg / (std::numbers::pi * r.diameter_m * r.diameter_m / 4.0 * r.length_m);
}

/// sqrt(I/A) = d/4 for a solid circle [m] (radius of gyration of the section).
inline double rod_radius_of_gyration_m(const RodGeometry& r) { return r.diameter_m / 4.0; }

/// The factor f1 / sqrt(E/rho) of the first flexural mode [1/m]:
/// (beta1 L)^2 / (2 pi L^2) * sqrt(I/A).
inline double flexural_frequency_factor_per_m(const RodGeometry& r) {
  return free_free_beta1_L * free_free_beta1_L / (2.0 * std::numbers::pi * r.length_m * r.length_m) *
         rod_radius_of_gyration_m(r);
}

/// First free-free flexural natural frequency f1 [Hz] for a modulus E [Pa].
inline double flexural_frequency_hz(const RodGeometry& r, double E_Pa) {
  return flexural_frequency_factor_per_m(r) * std::sqrt(E_Pa / rod_density_kg_per_m3(r));
}

/// The modulus E [Pa] whose first flexural frequency is f1 [Hz] (inverse of the above).
inline double modulus_from_flexural_frequency_Pa(const RodGeometry& r, double f1_hz) {
  const double c = f1_hz / flexural_frequency_factor_per_m(r);
  return rod_density_kg_per_m3(r) * c * c;
}

/// First free-free longitudinal natural frequency f1 = sqrt(E/rho) / (2L) [Hz].
inline double longitudinal_frequency_hz(const RodGeometry& r, double E_Pa) {
  return std::sqrt(E_Pa / rod_density_kg_per_m3(r)) / (2.0 * r.length_m);
}

/// The modulus E = rho (2 L f1)^2 [Pa] whose first longitudinal frequency is f1 [Hz].
inline double modulus_from_longitudinal_frequency_Pa(const RodGeometry& r, double f1_hz) {
  const double c = 2.0 * r.length_m * f1_hz;
  return rod_density_kg_per_m3(r) * c * c;
}

}  // namespace hertzdash
