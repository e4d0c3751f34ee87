#pragma once
// What a tangential contact model declares (model/tangential/registry.hpp lists the registered
// ones; model/oblique_contact.hpp runs them): its name and citation, the formula in words, and
// its tangential stiffness k_t(x) [N/m] at the normal overlap x [m] for the pair. The force is
// carried as a state T [N] (the spring's force, incremental: dT/dt = -k_t(x) s while the contact
// sticks, s the contact point's slip velocity), bounded by the Coulomb cone |T| <= mu F_n
// (model/oblique_contact.hpp): the DEM codes' spring with a Coulomb limit.
#include <cmath>
#include <string_view>

namespace hertzdash {

/// The pair's elastic constants a tangential model reads.
struct TangentialPair {
  double shear_modulus_Pa = 0;          ///< G* = (2 - nu1)/G1 + (2 - nu2)/G2 inverted [Pa] (Mindlin 1949)
  double radius_m = 0;                  ///< R* [m], the normal contact's
  double linear_stiffness_N_per_m = 0;  ///< k_t of a linear spring [N/m] (linear-spring only)
};

/// What a model's stiffness may read at an instant of the contact.
struct TangentialState {
  double overlap_m = 0;      ///< x >= 0 [m]
  double force_N = 0;        ///< the spring's force T [N]
  double cone_N = 0;         ///< mu F_n [N]
  double turn_force_N = 0;   ///< T where the slip last reversed [N] (a model with memory)
  double turn_cone_N = 0;    ///< mu F_n there [N]
  bool reversed = false;     ///< the slip has reversed since onset
};

struct TangentialModelInfo {
  std::string_view name, citation, formula;
  /// k_t [N/m] in the state `s`.
  double (*stiffness_N_per_m)(const TangentialPair& pair, const TangentialState& s);
  /// The model reads turn_force_N and reversed: the contact records each reversal of the slip.
  bool remembers_reversals = false;
  /// The share c in [0, 1] of the cone's growth that the force follows beside the spring,
  /// dT/dt = -k_t s + c sigma mu dF_n/dt where dF_n/dt > 0 (sigma: friction's direction, -sign s);
  /// null: 0.
  double (*normal_coupling)(const TangentialState& s) = nullptr;
  /// While the overlap falls the force shrinks with the contact radius a = sqrt(R x) beside the
  /// spring, dT/dt = -k_t s + T (da/dt)/a = -k_t s + T x'/(2 x) (the rescaling of LAMMPS's
  /// `mindlin_rescale`): with k_t proportional to a the spring then returns at most what it stored.
  bool rescales_with_contact_radius = false;
  /// Coulomb's law holds at every point of the contact, not on the total force: the contact is
  /// integrated resolved over its area (model/oblique_contact_mdr.hpp), and stiffness_N_per_m is the
  /// whole contact's while it sticks (the other fields unread).
  bool resolves_contact_area = false;
};

/// G* of Mindlin's tangential compliance: 1/G* = (2 - nu1)/G1 + (2 - nu2)/G2, G = E/(2 (1 + nu))
/// [Pa]; a rigid body (E = +inf) contributes nothing.
inline double tangential_shear_modulus_Pa(double E1_Pa, double nu1, double E2_Pa, double nu2) {
  auto share = [](double E, double nu) { return std::isinf(E) ? 0.0 : (2 - nu) * 2 * (1 + nu) / E; };
  return 1 / (share(E1_Pa, nu1) + share(E2_Pa, nu2));
}

}  // namespace hertzdash
