#pragma once
// Two spheres head-on (the rig `spheres`, docs/balls.md): the contact of spheres a and b is that
// of one body of the reduced mass on one sphere of the reduced radius against a flat, E* mixing
// their materials by eq. (3) (Johnson, Contact Mechanics, 1985, sec. 4.2 and 11.1): with x the
// approach of their centres, m* x'' = -F(x, x') holds for the relative motion, F = K x^{3/2} + dashpot,
// K = (4/3) E* sqrt(R*).
#include "hertzdash/model/drop_test_setup.hpp"
#include "hertzdash/model/hertz.hpp"

#include <cmath>
#include <numbers>

namespace hertzdash {

/// The mass of a solid sphere of radius R [m] and density rho [kg/m^3]: (4/3) pi R^3 rho [kg].
inline double sphere_mass_kg(double radius_m, double density_kg_per_m3) {
  return 4.0 / 3.0 * std::numbers::pi * std::pow(radius_m, 3) * density_kg_per_m3;
}

struct Sphere {
  double radius_m;    ///< R [m]
  double mass_kg;     ///< m [kg]
  Material material;  ///< E [Pa], nu
};

/// m* = m_a m_b / (m_a + m_b) [kg].
inline double reduced_mass_kg(const Sphere& a, const Sphere& b) { return a.mass_kg * b.mass_kg / (a.mass_kg + b.mass_kg); }

/// R* = R_a R_b / (R_a + R_b) [m].
inline double reduced_radius_m(const Sphere& a, const Sphere& b) {
  return a.radius_m * b.radius_m / (a.radius_m + b.radius_m);
}

/// The velocities after an impact of restitution e, in the frame where b rests before and a
/// approaches it at v [m/s] (positive towards b): momentum m_a v = m_a v_a + m_b v_b and the
/// rebound v_b - v_a = e v give v_a = v (m_a - e m_b)/(m_a + m_b), v_b = v m_a (1 + e)/(m_a + m_b).
struct VelocitiesAfter {
  double a_mps, b_mps;
};
inline VelocitiesAfter velocities_after(const Sphere& a, const Sphere& b, double v_mps, double e) {
  const double M = a.mass_kg + b.mass_kg;
  return {v_mps * (a.mass_kg - e * b.mass_kg) / M, v_mps * a.mass_kg * (1 + e) / M};
}

/// The contact of spheres a and b at relative speed v as the drop test's single impact: mass m*,
/// sphere radius R*, the sphere's material a's, the flat's b's, no gravity, onset at v. The law's
/// inputs (e, its constants), the yield stress (a's) and the tension clamp are `base`'s.
/// Throws InvalidParameter as validate() does.
inline DropTestSetup two_spheres_contact(const DropTestSetup& base, const Sphere& a, const Sphere& b, double v_mps) {
  DropTestSetup s = base;
  s.mass_kg = reduced_mass_kg(a, b);
  s.ball_radius_m = reduced_radius_m(a, b);
  s.ball = a.material;
  s.rod = b.material;
  s.height_m = 0;
  s.impact_velocity_mps = v_mps;
  s.gravity_mps2 = 0;
  s.rod_preset.clear();
  s.restitution_of_other_pair = false;
  validate(s);
  return s;
}

}  // namespace hertzdash
