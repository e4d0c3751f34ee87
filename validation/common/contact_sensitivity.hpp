#pragma once
// Forward sensitivities of the paper's impact by CVODES.
//
// The contact phase alone, from onset (free fall before it is exact: v0 = sqrt(2 g h)):
//   x' = v,   v' = g - (K/m) x^{1/2} (x + tau v),    x(0) = 0,  v(0) = v0,        (eqs. 1, 2, 5)
// tau = 2 zeta / omega_n [s], so that c_e = K tau x^{1/2}. Its parameters are
//   q = (K [N/m^{3/2}], tau [s], m [kg], v0 [m/s]);
// v0 enters only through the initial condition. CVODES integrates the state with its
// sensitivities s_i = dy/dq_i (Adams, simultaneous fixed-point corrector, sensitivities in
// the error test), from the sensitivity equations s_i' = J s_i + df/dq_i with
//   J = [[0, 1], [-(K/m)(3/2 x^{1/2} + tau v / (2 x^{1/2})), -(K/m) tau x^{1/2}]].
// J is singular at x = 0, but J s is not: s_x = O(t) and x^{1/2} = O(t^{1/2}), so the
// term tau v s_x / (2 x^{1/2}) = O(t^{1/2}) and is set to its limit 0 at x = 0. At
// separation s_x is not zero, and the term grows like (t_c - t)^{-1/2}: integrable (s_v stays
// finite), resolved by CVODES's error control with very small last steps. The test checks
// the result against central differences of the full simulation.
//
// Event-defined outputs and their derivatives (the event time moves with q):
//   separation, g = x = 0:    dt_c/dq = -s_x / x'          at t_c
//                             v_r = -v(t_c):  dv_r/dq = -(s_v + v'(t_c) dt_c/dq)
//   peak force, dF/dt = 0:    dP/dq = F_x s_x + F_v s_v + dF/dq|_explicit   (the event-time
//                             term vanishes because dF/dt = 0 there)
//   max compression, v = 0:   dX/dq = s_x                                   (likewise)
// Roots are located by CVODES on g0 = x, g1 = v and g2 = x^{1/2} dF/dt / K
//   = (3/2 x + tau v / 2) v + tau x v'   (same roots as dF/dt for x > 0, finite at x = 0),
// computed as dF/dtau / (2K) by model/force_rate.hpp. The force and every partial
// derivative come from the paper's law itself (HongoPaper::gradient_of_root).
// Every SUNDIALS return code is checked (std::runtime_error naming the call and flag).
#include <array>

namespace hertzdash {

/// Constant inputs of the contact phase.
struct ContactPhaseParameters {
  double K;             ///< Hertz stiffness [N/m^{3/2}]
  double tau_s;         ///< 2 zeta / omega_n [s]
  double mass_kg;       ///< m
  double v0_mps;        ///< approach speed at onset, > 0
  double gravity_mps2;  ///< g, acting during contact
};

/// Index of a parameter q in the gradients below.
enum ContactParameter : int { q_K = 0, q_tau = 1, q_mass = 2, q_v0 = 3 };
using ContactGradient = std::array<double, 4>;  ///< d(output)/dq, q = (K, tau, m, v0)

struct ContactPhaseSensitivities {
  double contact_time_s = 0, rebound_velocity_mps = 0, peak_force_N = 0, max_deformation_m = 0;
  ContactGradient d_contact_time{}, d_rebound_velocity{}, d_peak_force{}, d_max_deformation{};
  long steps = 0;
};

struct ContactSensitivityOptions {
  double rtol = 1e-10;
  /// Absolute tolerance relative to the impact's scales (as SolverSettings::atol): atol X for
  /// x and atol v0 for x', X the undamped Hertz maximum compression at v0.
  double atol = 1e-12;
};

/// Integrates the contact phase with CVODES forward sensitivities up to separation.
/// Throws std::runtime_error on a solver failure or if the rod does not separate.
ContactPhaseSensitivities contact_phase_sensitivities(const ContactPhaseParameters& p,
                                                      const ContactSensitivityOptions& options = {});

}  // namespace hertzdash
