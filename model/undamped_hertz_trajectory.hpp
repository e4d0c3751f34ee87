#pragma once
// The undamped Hertz impact's state at any time inside the contact, in closed form.
//
// Equation: m x'' = -K x^{3/2}, x(0) = 0, x'(0) = v0 > 0 (no gravity), the system of
// undamped_hertz_impact() in model/hertz.hpp. Energy gives x' = v0 sqrt(1 - (x/X)^{5/2})
// with X = (5 m v0^2 / (4K))^{2/5}, so during compression
//   t(x) = int_0^x dx'/x'(x') = (X/v0) (2/5) B(2/5, 1/2) I_w(2/5, 1/2),  w = (x/X)^{5/2},
// (substitution w = s^{5/2}; I is GSL's regularised incomplete beta function), and the
// motion is symmetric about the turning time tc/2. x(t) follows by inverting t(x) by
// bisection, which is monotone and converges to the last bit of s = x/X in 64 halvings.
// Used as the exact reference of the convergence study; checked there and in the tests
// against t(X) = tc/2 of undamped_hertz_impact().
#include "hertzdash/model/hertz.hpp"

#include <gsl/gsl_sf_gamma.h>

#include <cmath>

namespace hertzdash {

struct ContactState {
  double x_m;     ///< deformation [m]
  double xdot_mps;  ///< deformation rate [m/s], positive while compressing
};

/// State of the undamped impact a time t_s in [0, tc] after contact onset.
inline ContactState undamped_hertz_state_at(double K, double mass_kg, double v0_mps, double t_s) {
  const UndampedHertzImpact u = undamped_hertz_impact(K, mass_kg, v0_mps);
  const double X = u.max_deformation_m, half = 0.5 * u.contact_time_s;
  const double since_start = t_s <= half ? t_s : u.contact_time_s - t_s;  // symmetric about tc/2
  // Time from onset to s = x/X, as a fraction of the compression time tc/2 (= I_w at s = 1).
  auto fraction = [](double s) { return gsl_sf_beta_inc(0.4, 0.5, std::pow(s, 2.5)); };
  const double target = since_start / half;
  double lo = 0.0, hi = 1.0;
  for (int i = 0; i < 64; ++i) {
    const double mid = 0.5 * (lo + hi);
    (fraction(mid) < target ? lo : hi) = mid;
  }
  const double s = 0.5 * (lo + hi);
  const double speed = v0_mps * std::sqrt(std::max(0.0, 1.0 - std::pow(s, 2.5)));
  return {s * X, t_s <= half ? speed : -speed};
}

}  // namespace hertzdash
