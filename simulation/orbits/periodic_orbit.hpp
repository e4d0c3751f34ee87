#pragma once
// A periodic orbit of a stroboscopic map (simulation/orbits/stroboscopic_map.hpp) by shooting:
// Newton's method on G(z) = P^N(z) - z with the map's own monodromy M, (M - I) dz = -G, stable
// and unstable orbits alike. The residual is measured in the rig's scales, |G_i| / scale_i (the
// shaker: g T^2 for the position, g T for the speed); a step whose image fails (inside a wall, a
// sticking episode) or whose residual does not fall is halved, at most 30 times.
// Floquet multipliers: the eigenvalues of M at the orbit, largest modulus first; the orbit is
// stable where every |lambda| < 1 - 1e-9 (a multiplier within 1e-9 of the unit circle is a
// bifurcation, not a verdict).
#include "hertzdash/simulation/orbits/stroboscopic_map.hpp"

#include <complex>
#include <string>
#include <vector>

namespace hertzdash {

struct ShootingOptions {
  double tolerance = 1e-11;  ///< on the scaled residual max_i |G_i| / scale_i
  int max_iterations = 40;
};

/// What shooting found.
struct PeriodicOrbit {
  bool converged = false;
  std::string failure;                       ///< why not, where not converged
  Eigen::VectorXd state;                     ///< z at the section
  Eigen::MatrixXd monodromy;                 ///< dP^N/dz there
  std::vector<std::complex<double>> multipliers;  ///< eigenvalues of the monodromy, largest |.| first
  bool stable = false;                       ///< every |multiplier| < 1 - 1e-9
  double residual = 0;                       ///< the scaled residual at `state`
  int iterations = 0;                        ///< Newton steps taken
  std::vector<SequenceImpact> impacts;       ///< the orbit's impacts over its N periods
  double min_impact_speed_mps = 0;           ///< the slowest of them
  double min_flight_gap_m = 0;               ///< its closest approach to a wall in flight (SectionImage)
};

/// The Floquet multipliers of the square `monodromy`, largest modulus first (section_algebra.hpp).
std::vector<std::complex<double>> floquet_multipliers(const Eigen::MatrixXd& monodromy);

/// Every multiplier's modulus below 1 - 1e-9 (see above).
bool is_stable(const std::vector<std::complex<double>>& multipliers);

/// Newton from `guess`, residuals measured in `scale` (one positive entry per state component).
PeriodicOrbit find_periodic_orbit(const StroboscopicMap& map, const Eigen::VectorXd& guess, const Eigen::VectorXd& scale,
                                  const ShootingOptions& options = {});

}  // namespace hertzdash
