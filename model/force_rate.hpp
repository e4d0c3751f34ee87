#pragma once
// The rate of change of a contact force along the motion: the peak-force event
// function of every system that locates the force maximum.
//
// For a force F(q, v) of a position coordinate q and the deformation rate v = x',
// differentiated along the independent variable s of the system:
//   dF/ds = F_q dq/ds + F_v dv/ds
//  - physical variables (model/drop_test.hpp): q = x, s = t, so dF/dt = F_x x' + F_v x'';
//  - regularising variables (model/regularized_contact.hpp, and the forward
//    sensitivities of simulation/contact_sensitivity.cpp): q = u = x^{1/2}, s = tau with
//    dt = 2u dtau, so dF/dtau = F_u v + F_v 2u x'' = 2u dF/dt: the same zeros inside the
//    contact, and finite at u = 0 where F_x (and so dF/dt) is not.
// A force maximum is a zero through which the rate decreases, which is how every
// integrator's events fire.

namespace hertzdash {

/// dF/ds = F_q dq/ds + F_v dv/ds (see above) [N per unit of s].
constexpr double force_rate(double F_q, double F_v, double dq_ds, double dv_ds) noexcept {
  return F_q * dq_ds + F_v * dv_ds;
}

}  // namespace hertzdash
