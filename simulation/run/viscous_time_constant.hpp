#pragma once
// The material time constant A [s] of a viscoelastic law (MaterialTimeConstantLaw,
// model/damping/damping_law.hpp) from a restitution measured at one speed.
//
// A material constant cannot follow from e alone: e of such a law depends on the impact
// speed. What a drop test gives is e at one speed, so the calibration is
//   e_effective(A; v_ref) = e,
// in the contact in which every law's e_effective is defined (calibrate_restitution.hpp):
// the set-up's bodies as the rigid model, gravity off, approach speed v_ref. e_effective falls
// monotonically from 1 at A = 0, so the root is bracketed by doubling from the contact's own
// time scale X*/v_ref and found by GSL's Brent solver to 1e-12 in A relative. The runs use
// gbs8 in the regularising variables at rtol 1e-12, so A is a property of the law and the
// measurement, not of the integrator the user chose for the run.
#include "hertzdash/model/drop_test_setup.hpp"

#include <functional>

namespace hertzdash {

/// The speed at which the set-up's time constant is calibrated [m/s]:
/// damping.reference_velocity_mps if set (> 0), else the set-up's approach speed.
double reference_velocity_mps(const DropTestSetup& s);

/// The contact of the calibration: s as a rigid-model contact phase (rigid bodies keep their
/// moduli, so K is the run's), gravity off, approach speed reference_velocity_mps(s).
DropTestSetup viscous_calibration_setup(const DropTestSetup& s);

/// Solve e_of_A(A) = e_target for A >= 0, e_of_A decreasing from 1 at A = 0; `time_scale_s`
/// starts the bracket. e_target = 1 gives 0. Throws InvalidParameter("restitution", ...)
/// when no A reaches the target (e_of_A stays above it for A up to 2^60 time scales).
double solve_viscous_time_constant_s(const std::function<double(double)>& e_of_A, double e_target,
                                     double time_scale_s);

}  // namespace hertzdash
