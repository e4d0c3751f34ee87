#pragma once
// Hertz contact of a sphere on a flat, eq. (3) of Hongo et al.
#include <cmath>

namespace hertzdash {

/// Elastic constants of an isotropic body.
struct Material {
  double E_Pa;  ///< Young's modulus [Pa]; +inf for a rigid body
  double nu;    ///< Poisson ratio [-], in (-1, 0.5)
};

/// A body's share of the compliance sum of eq. (3): (1 - nu^2)/E [1/Pa]; 0 for a rigid
/// body (E = +inf).
double compliance(const Material& m);

/// Hertz stiffness of a sphere of radius R on a flat, eq. (3):
///   K = (4 sqrt(R) / 3) * ((1 - nu_s^2)/E_s + (1 - nu_w^2)/E_w)^{-1}   [N/m^{3/2}]
/// so that the elastic contact force is K x^{3/2} for a deformation x [m].
/// A rigid body (E = +inf) contributes nothing to the compliance sum.
double hertz_stiffness(double sphere_radius_m, const Material& sphere, const Material& flat);

/// The Hertz spring, eq. (3): F = K x^{3/2} [N] for a deformation x >= 0 [m] and the stiffness
/// K [N/m^{3/2}] of hertz_stiffness(). The laws whose dashpot also carries x^{1/2} (the paper's,
/// kuwabara-kono) write K x^{1/2} (x + tau xdot) instead, to take one square root.
inline double hertz_spring_force(double K, double x) noexcept { return K * x * std::sqrt(x); }

/// Deformation scale of a Hertz impact of mass m [kg] at speed v0 [m/s]:
/// X* = (m v0^2 / K)^{2/5} [m], the only length that m, K and v0 form.
double hertz_impact_scale_m(double K, double mass_kg, double v0_mps);

/// Peak pressure of the Hertz contact at deformation x [m] on a sphere of radius R [m] [Pa]:
///   p0 = 3 P / (2 pi a^2),  P = K x^{3/2},  a^2 = R x   =>   p0 = 3 K x^{1/2} / (2 pi R)
/// (= (2 E*/pi) (x/R)^{1/2} with K = (4/3) E* R^{1/2}). P is the elastic (Hertz) force: the
/// pressure field of the Hertz solution carries that force, not the dashpot's.
double hertz_peak_pressure_Pa(double K, double sphere_radius_m, double deformation_m);

/// p0 / Y at the onset of yield beneath a Hertz point contact on a body of Poisson ratio nu
/// (K. L. Johnson, Contact Mechanics, CUP 1985, eq. 3.45 and sec. 6.2): on the axis, at depth
/// z = zeta a,
///   sigma_z / p0 = -1 / (1 + zeta^2),
///   sigma_r / p0 = sigma_theta / p0 = -(1 + nu) (1 - zeta atan(1/zeta)) + (1/2) / (1 + zeta^2),
/// and the von Mises (here also Tresca) stress |sigma_r - sigma_z| is largest below the surface;
/// yield begins where that largest value reaches Y. Johnson's 1.60 (0.48 a deep) at nu = 0.3;
/// 1.74 at 0.4.
double hertz_yield_onset_factor(double nu);

/// The Hertz peak pressure at which yield begins in a body of yield stress Y [Pa] and Poisson
/// ratio nu [Pa]: hertz_yield_onset_factor(nu) Y.
inline double hertz_yield_onset_pressure_Pa(double yield_stress_Pa, double nu) {
  return hertz_yield_onset_factor(nu) * yield_stress_Pa;
}

/// Hertz theory replaces the sphere by the paraboloid z = r^2 / (2R). At the edge of the
/// contact, r = a = sqrt(R x), the sphere lies at R - sqrt(R^2 - a^2) = (a^2 / 2R)(1 + a^2/(4R^2)
/// + ...): the relative departure of the true profile from the assumed one is, to first order,
///   a^2 / (4 R^2) = x / (4 R)   [-]
/// for a deformation x [m] of a sphere of radius R [m]. It measures how far the contact is from
/// the small-deformation limit the theory is derived in (a << R).
inline double hertz_profile_error(double deformation_m, double sphere_radius_m) {
  return deformation_m / (4 * sphere_radius_m);
}

/// The profile error above which a run is flagged as outside the small-deformation limit:
/// 1 %, i.e. a/R = 0.2, x/R = 0.04. (The paper's steel rod from 20 mm: x/R = 0.019, 0.5 %.)
inline constexpr double hertz_profile_error_limit = 0.01;

/// Closed forms of the undamped Hertz impact (no gravity) at approach speed v0 [m/s]
/// for a mass m [kg]; energy balance (1/2) m v0^2 = (2/5) K X^{5/2} gives the
/// maximum deformation, and the half-period integral gives the contact time.
struct UndampedHertzImpact {
  double max_deformation_m;  ///< X = (5 m v0^2 / (4 K))^{2/5}
  double peak_force_N;       ///< K X^{3/2}
  double contact_time_s;     ///< (4/5) B(2/5, 1/2) X / v0  ~= 2.9432 X / v0
};
UndampedHertzImpact undamped_hertz_impact(double K, double mass_kg, double v0_mps);

/// The undamped maximum deformation X of undamped_hertz_impact alone [m] (one pow), for the
/// state scales the systems compute at every impact.
double undamped_hertz_max_deformation_m(double K, double mass_kg, double v0_mps);

/// The undamped contact time over X / v0, (4/5) B(2/5, 1/2) = 2.9432 [-] (computed once).
double undamped_hertz_contact_time_factor();

}  // namespace hertzdash
