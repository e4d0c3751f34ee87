#pragma once
// The rate of change of a contact force along the motion: the peak-force event
// function of every system that locates the force maximum.
//
// For a force F(q, v) of a position coordinate q and the deformation rate v = x',
// differentiated along the independent variable s of the system:
//   dF/ds = F_q dq/ds + F_v dv/ds
//  - physical variables (model/drop_test.hpp): q = x, s = t, so dF/dt = F_x x' + F_v x'';
//  - regularising variables (model/contact_system.hpp, and the forward
//    sensitivities of validation/common/contact_sensitivity.cpp): q = u = x^{1/2}, s = tau with
//    dt = 2u dtau, so dF/dtau = F_u v + F_v 2u x'' = 2u dF/dt: the same zeros inside the
//    contact, and finite at u = 0 where F_x (and so dF/dt) is not.
// A force maximum is a zero through which the rate decreases, which is how every
// integrator's events fire.
//
// In the physical variables the partial derivatives come from central differences of the
// law's force (contact_force_rate below) with relative steps 1e-6 of the impact's scales
// (truncation ~1e-12 relative); in the regularising variables, for a law that declares
// force_of_root, exactly from one evaluation on jets (model/force_jet.hpp). Differentiating
// along the state's partials, not along a time shift, keeps the rate nonzero wherever x' or x''
// is, so the root finder never meets a flat zero (at the undamped turning point F_x x' is tiny
// but not zero, while a time-shifted difference cancels exactly).
#include <algorithm>

namespace hertzdash {

/// dF/ds = F_q dq/ds + F_v dv/ds (see above) [N per unit of s].
constexpr double force_rate(double F_q, double F_v, double dq_ds, double dv_ds) noexcept {
  return F_q * dq_ds + F_v * dv_ds;
}

/// dF/dt = F_x x' + F_v x'' [N/s] of a force F = force_at(x, v) defined for x >= 0, at
/// deformation x >= 0, rate v and acceleration a, by central differences (one-sided at
/// x = 0) with steps 1e-6 max(x, 1e-6 X*) and 1e-6 V* from the impact's scales X* [m], V* [m/s].
template <class ForceAt>
double contact_force_rate(const ForceAt& force_at, double x, double v, double a, double x_scale_m, double v_scale_mps) {
  const double dx = 1e-6 * std::max(x, 1e-6 * x_scale_m), dv = 1e-6 * v_scale_mps;
  const double x_lo = std::max(x - dx, 0.0);
  const double F_x = (force_at(x + dx, v) - force_at(x_lo, v)) / (x + dx - x_lo);
  const double F_v = (force_at(x, v + dv) - force_at(x, v - dv)) / (2 * dv);
  return force_rate(F_x, F_v, v, a);
}

}  // namespace hertzdash
