#pragma once
// One oblique impact of a sphere on a flat (model/oblique_contact.hpp): any registered damping law
// normal to the surface, any registered tangential model (model/tangential/registry.hpp) along it,
// friction and spin, integrated by adaptive Dormand-Prince 5(4) in the regularising variables at
// the run's tolerances (the stick/slip switch rules out the extrapolation rows). The normal law is
// calibrated at the normal speed v cos(theta), as a head-on impact at that speed (kuwabara-kono's
// time constant the same way).
#include "hertzdash/model/drop_test_setup.hpp"
#include "hertzdash/ode/ode_system.hpp"
#include "hertzdash/simulation/run/solver_settings.hpp"

#include <cmath>
#include <optional>
#include <string>

namespace hertzdash {

/// A second sphere the first strikes, instead of a flat: its radius, mass and material, moment of
/// inertia factor and spin at onset (counted so that the contact point's slip is
/// w1 - w2 + R1 omega1 + R2 omega2).
struct SecondSphere {
  double radius_m = 0, mass_kg = 0;
  Material material;
  double inertia_factor = 0.4;
  double spin_rad_per_s = 0;
};

/// The default cells over the contact radius of a model resolved over the contact area: at 200 the
/// slip after is within about 2e-5 of its limit (second order, tests/test_oblique_mdr.cpp).
inline constexpr int default_contact_cells = 200;

struct ObliqueImpactSpec {
  DropTestSetup setup;  ///< validated: the sphere (mass, radius, material), the flat, e and the law's inputs
  std::string law;      ///< a registered damping law
  std::string tangential_model = "mindlin-no-slip";
  double friction = 0;                 ///< Coulomb's mu >= 0
  double incidence_angle_deg = 0;      ///< from the normal, in [0, 90)
  double speed_mps = 0;                ///< the centre's speed at onset, > 0
  double spin_rad_per_s = 0;           ///< omega0, the contact point sliding at w + R omega
  double inertia_factor = 0.4;         ///< kappa = I/(m R^2), (0, 1]: 2/5 solid, 2/3 thin shell
  double tangential_damping_ratio = 0; ///< zeta_t >= 0 of a tangential dashpot, eta = 2 zeta_t sqrt(k_t m_t) (model/oblique_contact.hpp)
  std::optional<double> linear_stiffness_N_per_m;  ///< linear-spring's k_t (default: Mindlin's 8 G* a at the
                                                   ///< undamped Hertz maximum overlap of the normal impact)
  /// The cells over the contact radius of a model resolved over the contact area (cattaneo-mindlin-mdr,
  /// model/oblique_contact_mdr.hpp), in [1, 512]; its error falls as their square (tests/test_oblique_mdr.cpp).
  int contact_cells = default_contact_cells;
  /// A second sphere instead of the flat (setup.rod then unread): speed_mps and the angle are the
  /// first sphere's velocity relative to it, from the line of centres.
  std::optional<SecondSphere> second;
  SolverSettings solver;
};

struct ObliqueImpactResult {
  bool separated = false;
  double contact_time_s = 0;
  double normal_restitution = 0;          ///< normal rebound over approach speed (relative, for two spheres)
  /// The (first) sphere's centre's tangential velocity and spin after; for two spheres in the frame
  /// where the second rested before.
  double tangential_velocity_after_mps = 0, spin_after_rad_per_s = 0;
  /// The second sphere's tangential velocity and spin after (NaN against a flat).
  double second_tangential_velocity_after_mps = NAN, second_spin_after_rad_per_s = NAN;
  double tangential_restitution = 0;      ///< relative tangential velocity of the centres after over before (NaN where 0 before)
  double rebound_angle_deg = 0;           ///< atan(s_after / v_n,after): the contact point's velocity (relative)
  double centre_rebound_angle_deg = 0;    ///< atan(w_after / v_n,after)
  double sliding_fraction = 0;            ///< of the contact time on the Coulomb cone
  double tangential_work_J = 0;           ///< int T s dt: the tangential force's work on the sphere
  double peak_normal_force_N = 0;
  double linear_stiffness_N_per_m = 0;    ///< the k_t a linear spring used (0 for other models)
  IntegrationStats work;
};

/// Mindlin's 8 G* a at the undamped Hertz maximum overlap of the normal impact at v cos(theta): the
/// linear spring's k_t where none is given.
double matched_linear_stiffness_N_per_m(const ObliqueImpactSpec& spec);

/// Throws InvalidParameter naming `tangential-model`, `friction`, `incidence-angle`,
/// `impact-velocity`, `inertia-factor`, `contact-cells`, `tangential-stiffness` or `damping` (an unknown law).
ObliqueImpactResult run_oblique_impact(const ObliqueImpactSpec& spec);

}  // namespace hertzdash
