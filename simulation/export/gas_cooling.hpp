#pragma once
// The cooling of a homogeneous granular gas predicted from hertzdash's e(g), any law: the kinetic
// theory of simulation/export/granular_gas.hpp with the restitution a function of the normal
// relative speed g (Brilliantov and Poeschel, Kinetic Theory of Granular Gases, Oxford 2004, ch. 6-7).
//
// A collision at normal relative speed g loses (m/4) (1 - e(g)^2) g^2. For a Maxwellian, the normal
// component of the relative velocity along any direction k is Gaussian with variance s^2 = 2T/m, so
// integrating the collision rate (1/2) n^2 sigma^2 chi (g.k) over directions k (4 pi times the mean
// over a Gaussian component, g.k > 0 only) gives the loss per unit volume
//   L(T) = (pi/2) m n^2 sigma^2 chi int_0^inf p(g) g^3 (1 - e(g)^2) dg,   p(g) = exp(-g^2/(2 s^2)) / sqrt(2 pi s^2),
// and the temperature (energy per degree of freedom, (3/2) n T per volume) falls as dT/dt = -2 L / (3 n).
// A constant e gives int = s^3 sqrt(2/pi) (1 - e^2): Haff's dT/dt = -B T^{3/2}. Kuwabara and Kono's
// viscoelastic law has 1 - e ~ C1 A (K/m*)^{2/5} g^{1/5} at small g, so 1 - e^2 ~ T^{1/10} late in the
// cooling, dT/dt ~ -T^{8/5} and T ~ t^{-5/3} (Schwager and Poeschel, Phys. Rev. E 57 (1998) 650).
#include "hertzdash/simulation/export/engine_contact.hpp"

#include <vector>

namespace hertzdash {

/// The restitution of a contact over relative speed, tabulated by hertzdash (the pair impact of
/// `contact` at log-spaced speeds) and interpolated linearly in (log g, log(1 - e)); beyond the table
/// the end segments extend as power laws (1 - e ~ g^{1/5} for kuwabara-kono at small g).
class RestitutionCurve {
 public:
  /// Speeds from g_min to g_max [m/s], `points` of them (>= 2).
  RestitutionCurve(const EngineContact& contact, double g_min_mps, double g_max_mps, int points);
  double operator()(double g_mps) const;
  /// Wall time per impact of the tabulation [s] (hertzdash's accurate solver: gbs8 at rtol 1e-10).
  double seconds_per_impact() const { return seconds_per_impact_; }

 private:
  std::vector<double> log_g_, log_one_minus_e_;
  bool elastic_ = false;  ///< e = 1 at every speed (no damping)
  double seconds_per_impact_ = 0;
};

/// dT/dt [J/s] at temperature T [J] of the gas of identical spheres of mass m [kg], diameter sigma [m],
/// number density n [1/m^3] and contact correlation chi, with the restitution curve e.
double cooling_rate_J_per_s(double T_J, double mass_kg, double diameter_m, double number_density_per_m3, double chi,
                            const RestitutionCurve& e);

struct CoolingSample {
  double time_s, temperature_J;
};

/// T(t) from T(t0) = T0 by the ODE above (RK4 in y = T^{-1/2}, which Haff's law makes linear in t),
/// at `samples` times from t0 to t1.
std::vector<CoolingSample> predicted_cooling(double T0_J, double t0_s, double t1_s, int samples, double mass_kg,
                                             double diameter_m, double number_density_per_m3, double chi,
                                             const RestitutionCurve& e);

}  // namespace hertzdash
