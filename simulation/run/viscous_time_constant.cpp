#include "hertzdash/simulation/run/viscous_time_constant.hpp"

#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/run/gsl_root.hpp"

#include <fmt/format.h>

#include <cmath>

namespace hertzdash {

double reference_velocity_mps(const DropTestSetup& s) {
  return s.damping.reference_velocity_mps > 0 ? s.damping.reference_velocity_mps : approach_speed(s);
}

DropTestSetup viscous_calibration_setup(const DropTestSetup& s) {
  DropTestSetup c = s;
  c.impact_velocity_mps = reference_velocity_mps(s);
  c.gravity_mps2 = 0.0;
  c.elastic_rod.reset();
  validate(c);
  return c;
}

double solve_viscous_time_constant_s(const std::function<double(double)>& e_of_A, double e_target,
                                     double time_scale_s) {
  require_in_open_closed("restitution", e_target, 0.0, 1.0);
  if (e_target == 1.0) return 0.0;
  auto residual = [&](double A) { return e_of_A(A) - e_target; };
  double lo = 0.0, hi = time_scale_s;
  for (int doublings = 0; residual(hi) > 0; ++doublings) {
    if (doublings == 60)
      throw InvalidParameter("restitution", format_value(e_target),
                             fmt::format("reachable by the viscoelastic law at its reference speed (e_effective is "
                                         "still {:.6g} at A = {:.3g} s)",
                                         e_of_A(hi), hi));
    lo = hi;
    hi *= 2.0;
  }
  return brent_root(residual, lo, hi, 1e-12, "viscous time constant calibration");
}

}  // namespace hertzdash
