#pragma once
// Mindlin and Deresiewicz's partial slip (J. Appl. Mech. 20 (1953) 327) in Thornton's incremental
// form (J. Appl. Mech. 58 (1991) 1097; Di Renzo and Di Maio, Chem. Eng. Sci. 59 (2004) 525, model
// "HMD"): the annulus of microslip grows with the tangential force and softens the contact, and
// the slipped annulus carries mu times the normal force's change,
//   dT = -8 G* a theta ds + sigma mu (1 - theta) dF_n,   sigma = -sign s   (first loading, dF_n > 0),
//   theta^3 = 1 - |T| / (mu F_n)               first loading,
//   theta^3 = 1 - |T - T*| / (2 mu F_n)        after a reversal of the slip at T*, with T* moving
//                                              with the cone: T* (F_n / F_n*) (Thornton's rule),
// so that under a constant normal force N the first loading is Mindlin's curve T = mu N (1 - (1 -
// 16 G* a delta / (3 mu N))^{3/2}) and the unloading from T* Masing's doubled copy of it; at the cone
// (theta = 0) T follows the cone, gross sliding. The term in the normal force's change is kept
// where Thornton's loading rule is unambiguous, a growing normal force before the slip first
// reverses; elsewhere the spring and the cone alone (a simplification of Thornton's unloading and
// reloading terms: taken along the friction's direction there as well, the term gave the sphere
// tangential energy at 1 degree of incidence, and along the force's own direction the integration
// ran out of steps). While the overlap falls, T shrinks with the contact radius a beside the
// spring (dT += T da/a, as mindlin-rescale): without it the softened spring returned more than it
// had stored after reversals of the slip (head-on, the test-4 alumina sphere at 3.9 m/s under
// tsuji-dem at e = 0.98, spin 100 rad/s, mu = 1: the sphere left spinning at 124 rad/s; now at 91).
// The energy bound of mindlin-rescale is not proven for this stiffness (8 G* a theta is not
// proportional to a): no positive work is observed over the rig test's grid. As mu grows the coupling term tends to T dF_n/(3 F_n), the
// secant spring's own change with the normal force, not to 0: this form is not the incremental
// no-slip spring in that limit (mindlin-no-slip is).
#include "hertzdash/model/tangential/tangential_model.hpp"

#include <algorithm>
#include <cmath>

namespace hertzdash {

/// theta^3 of the state (see above); 1 without a cone.
inline double mindlin_deresiewicz_theta3(const TangentialState& s) {
  if (!(s.cone_N > 0)) return 1.0;
  // After a reversal the turning point scales with the cone (Thornton): held fixed while the cone
  // shrank, theta reached 0 inside the cone and froze T at a value that could push the slip along.
  const double turn = s.turn_cone_N > 0 ? s.turn_force_N * s.cone_N / s.turn_cone_N : s.turn_force_N;
  const double excess = s.reversed ? std::abs(s.force_N - turn) / (2 * s.cone_N) : std::abs(s.force_N) / s.cone_N;
  return std::max(0.0, 1 - excess);
}

inline constexpr TangentialModelInfo mindlin_deresiewicz{
    .name = "mindlin-deresiewicz",
    .citation = "Mindlin and Deresiewicz, J. Appl. Mech. 20 (1953) 327; Thornton, J. Appl. Mech. 58 (1991) 1097",
    .formula = "k_t = 8 G* a theta, theta^3 = 1 - |T|/(mu F_n), after a reversal 1 - |T - T*|/(2 mu F_n)",
    .stiffness_N_per_m =
        [](const TangentialPair& p, const TangentialState& s) {
          return 8 * p.shear_modulus_Pa * std::sqrt(p.radius_m * s.overlap_m) * std::cbrt(mindlin_deresiewicz_theta3(s));
        },
    .remembers_reversals = true,
    .normal_coupling = [](const TangentialState& s) { return s.reversed ? 0.0 : 1 - std::cbrt(mindlin_deresiewicz_theta3(s)); },
    .rescales_with_contact_radius = true};

}  // namespace hertzdash
