#pragma once
// The nylon hemisphere on its piezoelectric load cell (Fig. 4 of the paper): a mass m_h on
// a spring k_cell with a dashpot c_cell = 2 zeta_cell sqrt(k_cell m_h), on a rigid base.
//
// The hemisphere's displacement w (downward positive) is measured from its static
// equilibrium under its own weight, which the cell's preload carries, so gravity leaves its
// equation:  m_h w'' = F_contact - k_cell w - c_cell w'.
// The cell measures the force it transmits beyond the preload, k_cell w + c_cell w' [N];
// with k_cell = +inf the hemisphere is fixed (w = 0) and the cell measures the contact
// force itself. The paper states neither k_cell nor its damping: data/assumptions.csv
// holds the values assumed and their ranges.
#include <cmath>

namespace hertzdash {

/// Constant parameters of the hemisphere and cell.
struct LoadCell {
  LoadCell(double mass_kg, double stiffness, double damping_ratio)
      : hemisphere_mass_kg(mass_kg),
        stiffness_N_per_m(stiffness),
        damping_N_s_per_m(std::isinf(stiffness) ? 0.0 : 2.0 * damping_ratio * std::sqrt(stiffness * mass_kg)) {}

  double hemisphere_mass_kg;   ///< m_h [kg] (Table 1: 7.8 g)
  double stiffness_N_per_m;    ///< k_cell [N/m]; +inf: the hemisphere fixed on a rigid base
  double damping_N_s_per_m;    ///< c_cell [N s/m]

  bool rigid_base() const { return std::isinf(stiffness_N_per_m); }
  /// Force transmitted to the base beyond the preload [N], at hemisphere state (w, w').
  /// On a rigid base the cell carries the contact force itself: callers use that (this returns 0).
  double force_N(double w_m, double wdot_mps) const {
    return rigid_base() ? 0.0 : stiffness_N_per_m * w_m + damping_N_s_per_m * wdot_mps;
  }
  /// Spring energy plus the hemisphere's kinetic energy [J].
  double energy_J(double w_m, double wdot_mps) const {
    if (rigid_base()) return 0.0;
    return 0.5 * stiffness_N_per_m * w_m * w_m + 0.5 * hemisphere_mass_kg * wdot_mps * wdot_mps;
  }
};

}  // namespace hertzdash
