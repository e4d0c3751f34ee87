#pragma once
// The exact restitution of the Hunt-Crossley form, derived once for the tests that use it
// (tests/test_damping_law_restitution.cpp, tests/test_chung_ooi.cpp).
#include <gsl/gsl_sf_lambert.h>

#include <cmath>

namespace hertzdash::test {

// Exact restitution of the Hunt-Crossley form F = K x^{3/2} (1 + chi x'), no gravity,
// tension allowed. With v = x' as a function of x the equation of motion is
//   m v dv/dx = -K x^{3/2} (1 + chi v)   =>   v dv / (1 + chi v) = -(K/m) x^{3/2} dx.
// Integrate over the whole contact, from (x = 0, v = v0) through maximum compression
// back to (x = 0, v = -vr): the right side depends on x alone, and x goes 0 -> X -> 0,
// so its integral vanishes. With H(v) = v/chi - ln(1 + chi v)/chi^2 (an antiderivative
// of v/(1 + chi v)), H(v0) = H(-vr). In a = chi v0 and b = chi vr:
//   a - ln(1 + a) = -b - ln(1 - b).
// With u = 1 - b: u - ln u = (1 + a) - ln(1 + a), i.e. (-u) e^{-u} = -(1 + a) e^{-(1 + a)}.
// So -u is a value of Lambert's W at z = -(1 + a) e^{-(1 + a)} in (-1/e, 0). The branch
// W_{-1} gives -u = -(1 + a), the trivial solution b = -a (the approach itself); the
// principal branch gives the rebound, u = -W0(z) in (0, 1). Hence
//   e_effective = vr / v0 = b / a = (1 + W0(-(1 + a) e^{-(1 + a)})) / a,
// a function of a = chi v0 alone. During restitution v runs from 0 to -vr, so
// 1 + chi v >= 1 - b = u > 0: the force never turns tensile and the tension clamp
// changes nothing (checked too).
inline double hunt_crossley_form_restitution(double a) {
  if (a == 0.0) return 1.0;
  return (1.0 + gsl_sf_lambert_W0(-(1.0 + a) * std::exp(-(1.0 + a)))) / a;
}

}  // namespace hertzdash::test
